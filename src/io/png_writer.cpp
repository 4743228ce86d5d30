// PNG file = signature, IHDR, IDAT, IEND (W3C PNG spec, 2nd ed., sections 5 and 11.2).
// Image data: each row is a filter-type byte (0, "None") followed by its RGB bytes (section 7);
// those rows are wrapped in a zlib stream (RFC 1950) of stored deflate blocks (RFC 1951
// section 3.2.4), which goes into one IDAT chunk (readers also accept it split over several).
#include "io/png_writer.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string_view>

#include "io/output_file.hpp"

namespace dda {
namespace {

// The 256 remainders of one byte under the reflected PNG polynomial (PNG spec Annex D).
std::array<std::uint32_t, 256> make_crc_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}

// Appends `value` most significant byte first (PNG and zlib integers are big-endian).
void put_u32_be(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

constexpr std::size_t kMaxStoredBlock = 65535;  // LEN is 16 bits

// Appends a 16-bit value least significant byte first (deflate's LEN and NLEN fields).
void put_u16_le(std::vector<std::uint8_t>& out, std::uint16_t value) {
  out.push_back(static_cast<std::uint8_t>(value & 0xFFU));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
}

// A chunk: 4-byte data length, 4-byte type, data, CRC-32 of type and data (section 5.3).
void put_chunk(std::vector<std::uint8_t>& out, const char (&type)[5],
               std::span<const std::uint8_t> data) {
  put_u32_be(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t type_start = out.size();
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(type[i]));
  out.insert(out.end(), data.begin(), data.end());
  put_u32_be(out, crc32(std::span(out).subspan(type_start)));
}

// Adler-32 over data given in pieces (RFC 1950 section 8.2): a = 1 + sum of bytes,
// b = sum of the a's, both mod 65521.
class Adler32 {
 public:
  void update(std::span<const std::uint8_t> data) {
    // 5552 bytes is the longest run whose sums cannot overflow 32 bits before reduction
    // (zlib's NMAX); reducing at least that often keeps them exact.
    constexpr std::size_t kRun = 5552;
    for (std::size_t start = 0; start < data.size(); start += kRun) {
      const std::size_t end = std::min(data.size(), start + kRun);
      for (std::size_t i = start; i < end; ++i) {
        a_ += data[i];
        b_ += a_;
      }
      a_ %= kModulus;
      b_ %= kModulus;
    }
  }
  std::uint32_t value() const { return (b_ << 16) | a_; }

 private:
  static constexpr std::uint32_t kModulus = 65521;  // largest prime below 2^16
  std::uint32_t a_ = 1;
  std::uint32_t b_ = 0;
};

// Appends a zlib stream (RFC 1950) of stored deflate blocks (RFC 1951 section 3.2.4) whose
// uncompressed data are the image rows, each preceded by its filter byte 0, without
// building those data apart (a large picture is several MB).
//   zlib: CMF 0x78 (deflate, 32 KiB window), FLG 0x01 (no dictionary, level 0, FCHECK
//   making CMF * 256 + FLG a multiple of 31), deflate data, Adler-32 of the raw data.
//   stored block: a byte with BFINAL in bit 0 and BTYPE = 00 (we stay byte aligned, so the
//   rest of that byte is padding), LEN and NLEN = ~LEN little-endian, then LEN raw bytes.
void put_zlib_stored_rows(std::vector<std::uint8_t>& out, const Image& image, std::size_t raw_size) {
  out.push_back(0x78);
  out.push_back(0x01);  // 0x7801 = 31 * 991
  Adler32 adler;
  std::size_t written = 0;   // raw bytes so far
  std::size_t block_left = 0;  // raw bytes still to come in the current stored block
  const auto put_raw = [&](std::span<const std::uint8_t> bytes) {
    while (!bytes.empty()) {
      if (block_left == 0) {
        block_left = std::min(kMaxStoredBlock, raw_size - written);
        out.push_back(written + block_left == raw_size ? 1 : 0);  // BFINAL on the last block
        put_u16_le(out, static_cast<std::uint16_t>(block_left));
        put_u16_le(out, static_cast<std::uint16_t>(~block_left & 0xFFFFU));
      }
      const std::size_t n = std::min(block_left, bytes.size());
      out.insert(out.end(), bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n));
      adler.update(bytes.first(n));
      written += n;
      block_left -= n;
      bytes = bytes.subspan(n);
    }
  };
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  const std::uint8_t filter_none = 0;
  for (int y = 0; y < image.height; ++y) {
    put_raw(std::span(&filter_none, 1));
    put_raw(std::span(image.pixels).subspan(row_bytes * static_cast<std::size_t>(y), row_bytes));
  }
  put_u32_be(out, adler.value());
}

}  // namespace

std::uint32_t crc32(std::span<const std::uint8_t> data) {
  static const std::array<std::uint32_t, 256> table = make_crc_table();
  std::uint32_t c = 0xFFFFFFFFU;
  for (std::uint8_t byte : data) c = table[(c ^ byte) & 0xFFU] ^ (c >> 8);
  return c ^ 0xFFFFFFFFU;
}

std::uint32_t adler32(std::span<const std::uint8_t> data) {
  Adler32 adler;
  adler.update(data);
  return adler.value();
}

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("encode_png: empty image");
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  if (image.pixels.size() != row_bytes * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("encode_png: pixel buffer does not match width x height x 3");

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};  // section 5.2

  // IHDR (section 11.2.2): width, height, bit depth 8, colour type 2 (RGB), compression 0,
  // filter method 0, interlace 0.
  std::vector<std::uint8_t> ihdr;
  put_u32_be(ihdr, static_cast<std::uint32_t>(image.width));
  put_u32_be(ihdr, static_cast<std::uint32_t>(image.height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
  put_chunk(png, "IHDR", ihdr);

  // One IDAT chunk holds the whole zlib stream, written in place: the sizes are known, so
  // the file is built in a single buffer (a chunk may hold up to 2^31 - 1 bytes, section 5.3;
  // that is a picture of about 26000 x 26000 pixels).
  const std::size_t raw_size = (row_bytes + 1) * static_cast<std::size_t>(image.height);
  const std::size_t blocks = (raw_size + kMaxStoredBlock - 1) / kMaxStoredBlock;
  const std::size_t zlib_size = 2 + 5 * blocks + raw_size + 4;
  if (zlib_size > 0x7FFFFFFFU) throw std::invalid_argument("encode_png: image too large for one IDAT chunk");
  png.reserve(png.size() + 12 + zlib_size + 12);
  put_u32_be(png, static_cast<std::uint32_t>(zlib_size));
  const std::size_t type_start = png.size();
  png.insert(png.end(), {'I', 'D', 'A', 'T'});
  put_zlib_stored_rows(png, image, raw_size);
  if (png.size() - type_start - 4 != zlib_size) throw std::logic_error("encode_png: IDAT length miscounted");
  put_u32_be(png, crc32(std::span(png).subspan(type_start)));

  put_chunk(png, "IEND", {});
  return png;
}

void write_png(const std::string& path, const Image& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  // Through a temporary file and a rename: a full disk leaves no part of a picture.
  write_file_whole(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace dda
