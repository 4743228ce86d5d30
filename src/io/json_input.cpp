#include "io/json_input.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <utility>

namespace dda::input {

using nlohmann::json;

namespace {

[[noreturn]] void fail_at(const std::string& source, std::string_view place,
                          std::string_view message) {
  std::string text = source;
  text += ": ";
  text += place.empty() ? std::string_view("top level") : place;
  text += ": ";
  text += message;
  throw InputError(text);
}

std::string describe_position(std::string_view text, std::size_t byte) {
  const TextPosition pos = position_of_byte(text, byte);
  return "line " + std::to_string(pos.line) + ", column " + std::to_string(pos.column);
}

// nlohmann's what() reads "[json.exception.parse_error.101] parse error at line 3, column 8:
// syntax error while parsing value - unexpected '}'; ...". Keep only the reason: the position
// is recomputed from the byte offset, and the prefix means nothing to a user.
std::string parse_error_reason(const std::string& what) {
  const std::size_t at = what.find("parse error");
  if (at != std::string::npos) {
    const std::size_t colon = what.find(": ", at);
    if (colon != std::string::npos) return what.substr(colon + 2);
  }
  const std::size_t bracket = what.find("] ");
  return bracket == std::string::npos ? what : what.substr(bracket + 2);
}

// Lists and objects may nest this deep. Scenes, models and specs nest at most 5 deep
// (blocks[i].vertices[j] holds [x, y]); each open level keeps its place in the document as a
// string, so a file of 200 000 opening brackets took memory as the square of its depth
// (gigabytes) before it was refused. 64 leaves room for any future key.
constexpr std::size_t kMaxNesting = 64;

// Builds the document from nlohmann's SAX events (the same result as json::parse), keeping
// track of the place being parsed so that duplicate keys and overflowing numbers are reported
// where they are.
class StrictDocumentBuilder {
 public:
  StrictDocumentBuilder(const std::string& text, const std::string& source)
      : text_(text), source_(source) {}

  json take() { return std::move(root_); }

  // ---- the SAX interface nlohmann::json::sax_parse requires ----
  bool null() { return add(nullptr); }
  bool boolean(bool value) { return add(value); }
  bool number_integer(json::number_integer_t value) { return add(value); }
  bool number_unsigned(json::number_unsigned_t value) { return add(value); }
  bool number_float(json::number_float_t value, const json::string_t& /*text*/) {
    return add(value);
  }
  bool string(json::string_t& value) { return add(std::move(value)); }
  bool binary(json::binary_t& value) { return add(json::binary(std::move(value))); }
  bool start_object(std::size_t /*elements*/) { return open(json::object()); }
  bool start_array(std::size_t /*elements*/) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& key);
  bool parse_error(std::size_t byte, const std::string& last_token, const json::exception& error);

 private:
  struct Frame {
    json* node;        // the object or list being filled (map nodes and the open list's
                       // parents do not move while it is open, so the pointer stays valid)
    std::string path;  // its place in the document
    std::string key;   // objects: the key whose value comes next
  };

  std::string next_value_path() const;
  json* place(json value);
  [[noreturn]] void fail_too_deep() const;
  bool add(json value) {
    place(std::move(value));
    return true;
  }
  bool open(json container) {
    if (stack_.size() >= kMaxNesting) fail_too_deep();
    std::string path = next_value_path();
    json* node = place(std::move(container));
    stack_.push_back(Frame{node, std::move(path), {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }

  const std::string& text_;
  const std::string& source_;
  json root_;
  std::vector<Frame> stack_;
};

// The SAX events carry no position, so the bracket that opens one level too many is found
// by scanning the text (outside strings) to it; this runs only on a file being refused.
void StrictDocumentBuilder::fail_too_deep() const {
  std::size_t depth = 0, byte = 0;
  bool in_string = false, escaped = false;
  for (std::size_t i = 0; i < text_.size(); ++i) {
    const char c = text_[i];
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxNesting) {
        byte = i + 1;
        break;
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  throw InputError(source_ + ": " + describe_position(text_, byte) +
                   ": lists and objects nested more than " + std::to_string(kMaxNesting) +
                   " deep; no input of this program nests more than 5");
}

std::string StrictDocumentBuilder::next_value_path() const {
  if (stack_.empty()) return "";
  const Frame& top = stack_.back();
  return top.node->is_array() ? element_path(top.path, top.node->size())
                              : member_path(top.path, top.key);
}

json* StrictDocumentBuilder::place(json value) {
  if (stack_.empty()) {
    root_ = std::move(value);
    return &root_;
  }
  Frame& top = stack_.back();
  if (top.node->is_array()) {
    top.node->push_back(std::move(value));
    return &top.node->back();
  }
  json& slot = (*top.node)[top.key];
  slot = std::move(value);
  return &slot;
}

bool StrictDocumentBuilder::key(json::string_t& key) {
  Frame& top = stack_.back();
  if (top.node->contains(key)) {
    fail_at(source_, member_path(top.path, key),
            "duplicate key; each key may appear only once in an object");
  }
  top.key = key;
  return true;
}

bool StrictDocumentBuilder::parse_error(std::size_t byte, const std::string& last_token,
                                        const json::exception& error) {
  // 406: a number literal that overflows a double (1e999); nlohmann would otherwise throw it
  // without any position. `byte` is the literal's last character; point at its first.
  constexpr int kNumberOverflow = 406;
  if (error.id == kNumberOverflow) {
    const std::size_t start = byte >= last_token.size() ? byte + 1 - last_token.size() : 1;
    fail_at(source_, next_value_path(),
            "number " + last_token + " is too large to represent (" +
                describe_position(text_, start) + "); numbers must be finite");
  }
  throw InputError(source_ + ": " + describe_position(text_, byte) +
                   ": invalid JSON: " + parse_error_reason(error.what()));
}

bool is_plain_identifier(std::string_view key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '-';
  });
}

// Levenshtein distance, to suggest the known key a misspelt one was meant to be.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string unknown_key_message(std::string_view key,
                                std::initializer_list<std::string_view> known) {
  std::string list;
  std::string_view closest;
  std::size_t best = std::numeric_limits<std::size_t>::max();
  for (std::string_view k : known) {
    list += (list.empty() ? "" : ", ") + std::string(k);
    const std::size_t d = edit_distance(key, k);
    if (d < best) {
      best = d;
      closest = k;
    }
  }
  // Two edits catch the usual slips (a doubled, dropped or swapped letter) without
  // suggesting unrelated words for short keys.
  const bool close_enough = best <= 2 && best < key.size();
  std::string message = "unknown key";
  if (close_enough) message += "; did you mean \"" + std::string(closest) + "\"?";
  if (known.size() == 0) return message + " (no keys are allowed here)";
  return message + " (known keys: " + list + ")";
}

}  // namespace

TextPosition position_of_byte(std::string_view text, std::size_t byte) {
  TextPosition pos;
  // `byte` is 1-based; the characters before it are text[0, byte - 1).
  const std::size_t end = std::min(byte > 0 ? byte - 1 : 0, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++pos.line;
      pos.column = 1;
    } else if ((c & 0xC0) != 0x80) {  // UTF-8 continuation bytes do not start a character
      ++pos.column;
    }
  }
  return pos;
}

json parse_strict_json(const std::string& text, const std::string& source) {
  StrictDocumentBuilder builder(text, source);
  if (!json::sax_parse(text, &builder)) {
    // Not reached: the builder throws on every error. Kept so that a future nlohmann that
    // reports failure differently still gives a message.
    throw InputError(source + ": invalid JSON");
  }
  return builder.take();
}

namespace {

// Bytes of the first `count` UTF-8 characters of `text` (all of it if it has fewer), and the
// number of characters in all. Continuation bytes (10xxxxxx) do not start a character.
std::pair<std::size_t, std::size_t> utf8_prefix(std::string_view text, std::size_t count) {
  std::size_t characters = 0, prefix = text.size();
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;
    if (characters == count) prefix = std::min(prefix, i);
    ++characters;
  }
  return {prefix, characters};
}

}  // namespace

std::string shown_text(std::string_view text) {
  const auto [prefix, characters] = utf8_prefix(text, kShownCharacters);
  if (characters <= kShownCharacters) return std::string(text);
  return std::string(text.substr(0, prefix)) + "... (" + std::to_string(characters) +
         " characters)";
}

std::string csv_name(const Field& f, std::string_view kind, std::string_view file,
                     const std::vector<std::string>& taken) {
  const std::string name = f.string();
  if (name.empty()) f.fail("is empty; give each " + std::string(kind) + " a name");
  if (name.find_first_of(",\"\n\r") != std::string::npos) {
    f.fail("contains a comma, quote or line break, which " + std::string(file) + " cannot hold");
  }
  for (const std::string& t : taken) {
    if (t == name) f.fail(quoted_text(name) + " is already the name of another " + std::string(kind));
  }
  return name;
}

std::string quoted_text(std::string_view text) {
  const auto [prefix, characters] = utf8_prefix(text, kShownCharacters);
  // Strings from a parsed document are valid UTF-8; other text (a line of a CSV record) may
  // not be, and is shown with its invalid bytes replaced rather than failing to print.
  const auto quote = [](std::string_view t) {
    return json(std::string(t)).dump(-1, ' ', false, json::error_handler_t::replace);
  };
  if (characters <= kShownCharacters) return quote(text);
  std::string head = quote(text.substr(0, prefix));
  head.insert(head.size() - 1, "...");
  return head + " (" + std::to_string(characters) + " characters)";
}

std::string quoted_name_list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < kShownNames; ++i) {
    out += (i == 0 ? "" : ", ") + quoted_text(names[i]);
  }
  if (names.size() > kShownNames) {
    out += " and " + std::to_string(names.size() - kShownNames) + " more";
  }
  return out;
}

std::string member_path(std::string_view parent, std::string_view key) {
  if (!is_plain_identifier(key) || key.size() > kShownCharacters) {
    return std::string(parent) + "[" + quoted_text(key) + "]";
  }
  if (parent.empty()) return std::string(key);
  return std::string(parent) + "." + std::string(key);
}

std::string element_path(std::string_view parent, std::size_t index) {
  return std::string(parent) + "[" + std::to_string(index) + "]";
}

std::string format_number(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "infinity" : "-infinity";
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), x);
  return std::string(buffer.data(), result.ptr);
}

// ---------------------------------------------------------------------------------------
// Field

Field::Field(const json& value, std::string path, const std::string& source)
    : value_(&value), path_(std::move(path)), source_(&source) {}

void Field::fail(std::string_view message) const { fail_at(*source_, path_, message); }

void Field::fail_type(std::string_view expected) const {
  fail("expected " + std::string(expected) + ", got " + describe());
}

std::string Field::describe() const {
  switch (value_->type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return value_->get<bool>() ? "true" : "false";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
      return "the number " + value_->dump();
    case json::value_t::number_float:
      return "the number " + format_number(value_->get<double>());
    case json::value_t::string: {
      // Long strings are cut (never inside a UTF-8 character, which json::dump refuses:
      // a 2-byte character at byte 40 used to end the program with exit 1).
      return "a string (" + quoted_text(value_->get_ref<const std::string&>()) + ")";
    }
    case json::value_t::array:
      return "a list of " + std::to_string(value_->size()) + " element(s)";
    case json::value_t::object:
      return "an object";
    default:
      return "a value of type " + std::string(value_->type_name());
  }
}

void Field::expect_keys(std::initializer_list<std::string_view> known) const {
  if (!value_->is_object()) fail_type("an object");
  for (const auto& item : value_->items()) {
    const bool is_known =
        std::find(known.begin(), known.end(), std::string_view(item.key())) != known.end();
    if (!is_known) {
      fail_at(*source_, member_path(path_, item.key()), unknown_key_message(item.key(), known));
    }
  }
}

bool Field::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

Field Field::member(std::string_view key) const {
  if (!value_->is_object()) fail_type("an object");
  const auto it = value_->find(key);
  if (it == value_->end()) fail_at(*source_, member_path(path_, key), "required key is missing");
  return Field(*it, member_path(path_, key), *source_);
}

Field Field::place(std::string_view key) const {
  static const json kAbsent;
  if (has(key)) return member(key);
  return Field(kAbsent, member_path(path_, key), *source_);
}

std::optional<Field> Field::optional_member(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return member(key);
}

std::vector<std::pair<std::string, Field>> Field::members() const {
  if (!value_->is_object()) fail_type("an object");
  std::vector<std::pair<std::string, Field>> out;
  for (const auto& item : value_->items()) {
    out.emplace_back(item.key(), Field(item.value(), member_path(path_, item.key()), *source_));
  }
  return out;
}

std::vector<Field> Field::elements(std::size_t min_count, std::string_view too_few) const {
  if (!value_->is_array()) fail_type("a list");
  if (value_->size() < min_count) {
    fail(std::string(too_few) + " (got " + std::to_string(value_->size()) + ")");
  }
  std::vector<Field> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back((*value_)[i], element_path(path_, i), *source_);
  }
  return out;
}

double Field::number() const {
  if (!value_->is_number()) fail_type("a number");
  const double x = value_->get<double>();
  if (!std::isfinite(x)) fail("must be a finite number, got " + format_number(x));
  return x;
}

int Field::integer() const {
  if (!value_->is_number()) fail_type("an integer");
  const double x = value_->get<double>();
  if (!std::isfinite(x) || x != std::floor(x)) {
    fail("expected an integer, got " + format_number(x));
  }
  if (std::abs(x) > std::numeric_limits<int>::max()) {
    fail("integer is too large, got " + format_number(x));
  }
  return static_cast<int>(x);
}

bool Field::boolean() const {
  if (!value_->is_boolean()) fail_type("true or false");
  return value_->get<bool>();
}

std::string Field::string() const {
  if (!value_->is_string()) fail_type("a string");
  return value_->get<std::string>();
}

std::vector<double> Field::numbers(std::size_t count, std::string_view shape) const {
  if (!value_->is_array()) fail_type("a list " + std::string(shape));
  if (value_->size() != count) {
    fail("expected a list of " + std::to_string(count) + " numbers " + std::string(shape) +
         ", got " + describe());
  }
  std::vector<double> out;
  for (std::size_t i = 0; i < count; ++i) {
    out.push_back(Field((*value_)[i], element_path(path_, i), *source_).number());
  }
  return out;
}

Vec2 Field::vec2(std::string_view shape) const {
  const std::vector<double> v = numbers(2, shape);
  return Vec2(v[0], v[1]);
}

Vec3 Field::vec3(std::string_view shape) const {
  const std::vector<double> v = numbers(3, shape);
  return Vec3(v[0], v[1], v[2]);
}

Eigen::Vector4d Field::vec4(std::string_view shape) const {
  const std::vector<double> v = numbers(4, shape);
  return Eigen::Vector4d(v[0], v[1], v[2], v[3]);
}

// ---------------------------------------------------------------------------------------
// Numbers with a range

double positive_number(const Field& f) {
  const double x = f.number();
  if (x <= 0.0) f.fail("must be positive, got " + format_number(x));
  return x;
}

double non_negative_number(const Field& f) {
  const double x = f.number();
  if (x < 0.0) f.fail("must not be negative, got " + format_number(x));
  return x;
}

double number_in_range(const Field& f, double lo, bool lo_open, double hi, bool hi_open,
                       std::string_view range) {
  const double x = f.number();
  const bool above_lo = lo_open ? x > lo : x >= lo;
  const bool below_hi = hi_open ? x < hi : x <= hi;
  if (!above_lo || !below_hi) {
    f.fail("must be " + std::string(range) + ", got " + format_number(x));
  }
  return x;
}

int integer_at_least(const Field& f, int lo) {
  const int n = f.integer();
  if (n < lo) f.fail("must be at least " + std::to_string(lo) + ", got " + std::to_string(n));
  return n;
}

std::string quoted_list(std::initializer_list<std::string_view> names) {
  std::string out;
  for (std::string_view n : names) out += (out.empty() ? "\"" : ", \"") + std::string(n) + "\"";
  return out;
}

std::string read_input_file(const std::string& path, std::string_view kind) {
  namespace fs = std::filesystem;
  const std::string name = path.empty() ? "(empty file name)" : path;
  // Looked at before opening: opening a pipe with no writer waits for ever, and reading a
  // device such as /dev/zero never ends.
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && status.type() != fs::file_type::not_found) {
    throw InputError(name + ": cannot open file (" + ec.message() + ")");
  }
  if (status.type() == fs::file_type::not_found) {
    throw InputError(name + ": cannot open file (" + std::strerror(ENOENT) + ")");
  }
  if (status.type() == fs::file_type::directory) {
    throw InputError(name + ": cannot open: it is a directory, not " + std::string(kind));
  }
  if (status.type() != fs::file_type::regular) {
    const char* what = status.type() == fs::file_type::character   ? "a character device"
                       : status.type() == fs::file_type::block      ? "a block device"
                       : status.type() == fs::file_type::fifo       ? "a pipe (FIFO)"
                       : status.type() == fs::file_type::socket     ? "a socket"
                                                                    : "not a regular file";
    throw InputError(name + ": not read: it is " + std::string(what) + ", not a regular file; " +
                     std::string(kind) + " must be a regular file (save the input to one first)");
  }
  const auto too_large = [&](const std::string& size) {
    return InputError(name + ": not read: the file is " + size + ", larger than the " +
                      std::to_string(kLargestInputBytes >> 20) + " MiB (" +
                      std::to_string(kLargestInputBytes) +
                      " bytes) this program reads (see docs/scene-format.md, \"Limits\")");
  };
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kLargestInputBytes) throw too_large(std::to_string(size) + " bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open file (" + std::strerror(errno) + ")");
  // Stop as soon as the text passes the limit, so that a file that grew since it was
  // measured is refused all the same rather than read whole.
  std::string text;
  text.reserve(ec ? 0 : static_cast<std::size_t>(size));
  std::array<char, 1 << 16> buffer{};
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    text.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kLargestInputBytes) {
      throw too_large("more than " + std::to_string(kLargestInputBytes) + " bytes");
    }
  }
  if (in.bad()) throw InputError(name + ": cannot read file (" + std::strerror(errno) + ")");
  return text;
}

}  // namespace dda::input
