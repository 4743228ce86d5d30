// Strict JSON reading for user input, independent of what the document means: parsing with
// line:column errors, and a Field view that pairs a JSON value with its place in the file
// ("blocks[3].vertices[0]") so that every type or range check can say where it failed.
// All failures are thrown as InputError("<source>: <place>: <message>").
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/input_error.hpp"
#include "kinematics/types.hpp"

namespace dda::input {

// 1-based line and column of a 1-based byte position in `text` (nlohmann reports errors as a
// byte count). Columns count UTF-8 characters, which is what an editor shows.
struct TextPosition {
  std::size_t line = 1;
  std::size_t column = 1;
};
TextPosition position_of_byte(std::string_view text, std::size_t byte);

// Parses `text` as one JSON value. Stricter than nlohmann's default in two ways that matter
// for hand-written input: a key repeated in one object is an error (nlohmann would silently
// keep the last one), and a number too large for a double is reported at its place.
nlohmann::json parse_strict_json(const std::string& text, const std::string& source);

// Places in a document, as printed in messages: "control.time_step", "blocks[3]",
// "materials[\"my rock\"]" (keys that are not plain identifiers are quoted; a key longer
// than kShownCharacters is cut as shown_text cuts it, and always quoted).
std::string member_path(std::string_view parent, std::string_view key);
std::string element_path(std::string_view parent, std::size_t index);

// Text from the input echoed in a message (a key, a name, a line of a record) is cut to this
// many characters: a key of 100 000 characters used to be printed whole, once per message.
inline constexpr std::size_t kShownCharacters = 80;
// `text` if it has at most kShownCharacters characters (UTF-8 characters, never a part of
// one); otherwise its first kShownCharacters characters, "..." and the full length:
// "aaaa... (100000 characters)".
std::string shown_text(std::string_view text);
// `text` in double quotes with JSON escapes, cut as shown_text cuts it, the note outside the
// quotes: "\"aaaa...\" (100000 characters)".
std::string quoted_text(std::string_view text);
// The names in `names`, each as quoted_text gives it, separated by ", ": at most
// kShownNames of them, then "and N more".
inline constexpr std::size_t kShownNames = 20;
std::string quoted_name_list(const std::vector<std::string>& names);

// Shortest text that reads back as the same double ("0.1", "-1", "1e+300", "inf").
std::string format_number(double x);

// A JSON value and where it is. Cheap to copy; refers to the parsed document and the source
// name, which must outlive it.
class Field {
 public:
  Field(const nlohmann::json& value, std::string path, const std::string& source);

  const std::string& path() const { return path_; }
  const nlohmann::json& value() const { return *value_; }

  // Throws InputError "<source>: <path>: <message>".
  [[noreturn]] void fail(std::string_view message) const;

  // ---- objects ----
  // Requires an object whose keys are all in `known` (unknown keys are usually typos, which
  // must not be silently ignored).
  void expect_keys(std::initializer_list<std::string_view> known) const;
  bool has(std::string_view key) const;
  Field member(std::string_view key) const;  // required key
  // The place of `key` in this object whether it is there or not, for a message about a key
  // the user left out (its value reads as null).
  Field place(std::string_view key) const;
  std::optional<Field> optional_member(std::string_view key) const;
  std::vector<std::pair<std::string, Field>> members() const;  // requires an object

  // ---- lists ----
  // Requires a list of at least `min_count` elements; `what` names the elements in the
  // message ("a block", "a vertex").
  std::vector<Field> elements(std::size_t min_count, std::string_view what) const;

  // ---- scalars ----
  bool is_string() const { return value_->is_string(); }
  bool is_list() const { return value_->is_array(); }
  double number() const;  // finite
  int integer() const;    // a whole number that fits an int (1e3 is accepted, 2.5 is not)
  bool boolean() const;
  std::string string() const;
  // Fixed-length lists of numbers; `shape` is shown in messages, e.g. "[x, y]".
  Vec2 vec2(std::string_view shape) const;
  Vec3 vec3(std::string_view shape) const;
  Eigen::Vector4d vec4(std::string_view shape) const;

  // "a string (\"abc\")", "a list", "the number -1", ... for "expected X, got Y".
  std::string describe() const;

 private:
  [[noreturn]] void fail_type(std::string_view expected) const;
  std::vector<double> numbers(std::size_t count, std::string_view shape) const;

  const nlohmann::json* value_;
  std::string path_;
  const std::string* source_;
};

// ---- numbers with a range: one wording for every reader ----
double positive_number(const Field& f);      // > 0
double non_negative_number(const Field& f);  // >= 0
// lo <= x <= hi, with each end optionally excluded; `range` is the range as the user reads
// it ("greater than -1 and less than 0.5").
double number_in_range(const Field& f, double lo, bool lo_open, double hi, bool hi_open,
                       std::string_view range);
int integer_at_least(const Field& f, int lo);

// A name written into a CSV file's rows (a monitor's, a bolt's): not empty, no comma, quote
// or line break, and none of `taken`. `kind` ("monitor") and `file` ("monitors.csv") word
// the messages.
std::string csv_name(const Field& f, std::string_view kind, std::string_view file,
                     const std::vector<std::string>& taken);

// `"a", "b"` for the "known: ..." part of a message.
std::string quoted_list(std::initializer_list<std::string_view> names);

// The largest input file read (scenes, models, material-point specs, acceleration records):
// 64 MiB. The largest scene the repository makes, models/slope.json cut into 1965 blocks, is
// 0.52 MB (264 bytes a block), so this holds some 250 000 such blocks, far more than a run
// can take in a day; parsed, a document takes several times its size in memory.
inline constexpr std::uintmax_t kLargestInputBytes = std::uintmax_t{64} << 20;

// The whole text of an input file. Throws InputError "<path>: ..." naming the path and the
// reason, before reading anything, when it is not a regular file (a directory, a device such
// as /dev/zero or /dev/urandom, a pipe: each could be read for ever or until memory runs
// out) or is larger than kLargestInputBytes; and when it cannot be opened or read. `kind`
// says what the file should have been ("a scene file").
std::string read_input_file(const std::string& path, std::string_view kind);

}  // namespace dda::input
