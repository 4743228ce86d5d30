#!/usr/bin/python3
"""Independent check of a PNG written by dda (io/png_writer): Python's standard library
parses the chunks, checks every CRC with zlib.crc32 and inflates the image data with
zlib.decompress, which also checks the Adler-32. Usage: check_png.py FILE.png"""
import struct
import sys
import zlib


def main(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "bad signature"
    at, idat, chunks, size = 8, b"", [], None
    while at < len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind = data[at + 4:at + 8]
        body = data[at + 8:at + 8 + length]
        (crc,) = struct.unpack(">I", data[at + 8 + length:at + 12 + length])
        assert zlib.crc32(kind + body) == crc, "bad CRC in %r" % kind
        chunks.append(kind)
        if kind == b"IHDR":
            size = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    assert chunks[0] == b"IHDR" and chunks[-1] == b"IEND", chunks
    width, height, depth, colour, _, _, interlace = size
    assert (depth, colour, interlace) == (8, 2, 0), size
    raw = zlib.decompress(idat)
    assert len(raw) == height * (3 * width + 1), (len(raw), width, height)
    assert all(raw[y * (3 * width + 1)] == 0 for y in range(height)), "row filter not 0"
    print("%s: %d x %d RGB, %d bytes of image data, OK" % (path, width, height, len(raw)))


if __name__ == "__main__":
    main(sys.argv[1])
