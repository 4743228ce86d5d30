// A dependency-free PNG writer for 8-bit RGB images (no libpng, no zlib). The image data are
// kept uncompressed: the zlib stream inside the IDAT chunk holds only *stored* deflate blocks,
// which every PNG reader accepts. Files are about width * height * 3 bytes, which is fine
// for the block pictures this code writes (a few MB at most).
//
// Layouts followed: PNG, W3C Recommendation "Portable Network Graphics (PNG) Specification
// (Second Edition)" (also RFC 2083); zlib stream, RFC 1950; deflate stored blocks, RFC 1951
// section 3.2.4.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "io/image.hpp"

namespace dda {

// CRC-32 as PNG chunks use it (polynomial 0xEDB88320 reflected, initial and final XOR
// 0xFFFFFFFF; PNG spec section 5.5 / Annex D). Check value: "123456789" -> 0xCBF43926.
std::uint32_t crc32(std::span<const std::uint8_t> data);

// Adler-32 checksum of a zlib stream's uncompressed data (RFC 1950 section 8.2).
std::uint32_t adler32(std::span<const std::uint8_t> data);

// The bytes of a PNG file holding `image` (colour type 2, bit depth 8, no interlace).
// Throws std::invalid_argument when the image is empty or its pixel buffer has the wrong size.
std::vector<std::uint8_t> encode_png(const Image& image);

// Writes encode_png(image) to `path`, whole (io/output_file.hpp, write_file_whole). Throws
// std::runtime_error naming the path when the file cannot be written.
void write_png(const std::string& path, const Image& image);

}  // namespace dda
