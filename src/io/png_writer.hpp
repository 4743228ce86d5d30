// A PNG writer for 8-bit RGB images: the chunks are laid out here, the image data deflated
// by zlib (the pictures are flat colours: a 1965-block slope of 4.4 MB raw takes 110 kB).
//
// Layouts followed: PNG, W3C Recommendation "Portable Network Graphics (PNG) Specification
// (Second Edition)" (also RFC 2083); zlib stream, RFC 1950; deflate, RFC 1951.
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

// The bytes of a PNG file holding `image` (colour type 2, bit depth 8, no interlace).
// Throws std::invalid_argument when the image is empty or its pixel buffer has the wrong size.
std::vector<std::uint8_t> encode_png(const Image& image);

// Writes encode_png(image) to `path`, whole (io/output_file.hpp, write_file_whole). Throws
// std::runtime_error naming the path when the file cannot be written.
void write_png(const std::string& path, const Image& image);

}  // namespace dda
