"""Reads the VTK XML PolyData frames dda writes (DIR/vtk/*.vtp), in either encoding:
format="ascii" arrays, or format="appended" arrays after <AppendedData encoding="raw">_,
zlib-compressed in VTK's block layout (header_type UInt64 or UInt32: [blocks, block size,
last block's size or 0 when full, compressed sizes...], then one zlib stream per block).
Standard library only, so that Debian's /usr/bin/python3 runs it; docs/output-format.md.

read_vtp(path) or parse_vtp(bytes) give a dict:
  points      list of (x, y)
  verts, lines, polys   (connectivity, offsets) lists, or None when the piece has none
  point_data, cell_data  {name: (components, [values...])}
"""
import struct
import xml.etree.ElementTree as ET
import zlib

_FORMATS = {"Int32": "i", "Int64": "q", "UInt8": "B", "Float64": "d", "UInt32": "I", "UInt64": "Q",
            "Float32": "f"}


def _header_words(data, at, word, count):
    end = at + word * count
    if end > len(data):
        raise ValueError("appended data end inside an array's header")
    return struct.unpack_from("<%d%s" % (count, "Q" if word == 8 else "I"), data, at)


def _appended_bytes(data, start, word, compressed):
    """One array's bytes at `start` (the byte after "_" plus its offset)."""
    if not compressed:
        (size,) = _header_words(data, start, word, 1)
        return data[start + word:start + word + size]
    blocks, block_size, last = _header_words(data, start, word, 3)
    sizes = _header_words(data, start + 3 * word, word, blocks)
    at = start + (3 + blocks) * word
    out = bytearray()
    for b, packed in enumerate(sizes):
        expected = last if (b == blocks - 1 and last) else block_size
        chunk = zlib.decompress(data[at:at + packed])
        if len(chunk) != expected:
            raise ValueError("block %d inflates to %d bytes, not %d" % (b, len(chunk), expected))
        out += chunk
        at += packed
    return bytes(out)


def parse_vtp(data, name="<bytes>"):
    try:
        return _parse(data)
    except (ValueError, KeyError, struct.error, zlib.error, ET.ParseError) as e:
        raise ValueError("%s: %s" % (name, e)) from e


def _parse(data):
    at = data.find(b"<AppendedData")
    base = None
    if at >= 0:
        close = data.index(b">", at)
        if b'encoding="raw"' not in data[at:close]:
            raise ValueError("AppendedData is not raw")
        base = data.index(b"_", close) + 1
        data_xml = data[:at] + b"</VTKFile>"
    else:
        data_xml = data
    root = ET.fromstring(data_xml)
    if root.get("type") != "PolyData" or root.get("byte_order") != "LittleEndian":
        raise ValueError("not little-endian PolyData")
    word = 8 if root.get("header_type") == "UInt64" else 4
    compressed = root.get("compressor") == "vtkZLibDataCompressor"
    piece = root.find("PolyData/Piece")
    if piece is None:
        raise ValueError("no Piece")

    def values(el):
        kind = el.get("type")
        fmt = _FORMATS[kind]
        if el.get("format") == "ascii":
            cast = float if fmt in "df" else int
            return [cast(v) for v in (el.text or "").split()]
        if el.get("format") != "appended" or base is None:
            raise ValueError("array %s is neither ascii nor appended" % el.get("Name"))
        raw = _appended_bytes(data, base + int(el.get("offset")), word, compressed)
        size = struct.calcsize("<" + fmt)
        if len(raw) % size:
            raise ValueError("array %s is not whole values" % el.get("Name"))
        return list(struct.unpack("<%d%s" % (len(raw) // size, fmt), raw))

    n = int(piece.get("NumberOfPoints"))
    xyz = values(piece.find("Points/DataArray")) if n else []
    if len(xyz) != 3 * n:
        raise ValueError("points hold %d numbers, not 3 x %d" % (len(xyz), n))
    frame = {"points": [(xyz[3 * i], xyz[3 * i + 1]) for i in range(n)]}
    cells = 0
    for kind in ("Verts", "Lines", "Polys"):
        section = piece.find(kind)
        if section is None:
            frame[kind.lower()] = None
            continue
        arrays = {a.get("Name"): values(a) for a in section.findall("DataArray")}
        conn, offsets = arrays["connectivity"], arrays["offsets"]
        if len(offsets) != int(piece.get("NumberOf" + kind)) or (offsets and offsets[-1] != len(conn)):
            raise ValueError("%s: offsets do not match" % kind)
        if any(i < 0 or i >= n for i in conn):
            raise ValueError("%s use a point out of range" % kind)
        frame[kind.lower()] = (conn, offsets)
        cells += len(offsets)
    for section, tuples in (("PointData", n), ("CellData", cells)):
        out = {}
        for a in piece.findall(section + "/DataArray"):
            k = int(a.get("NumberOfComponents", "1"))
            v = values(a)
            if len(v) != k * tuples:
                raise ValueError("array %s holds %d numbers, not %d x %d" % (a.get("Name"), len(v), tuples, k))
            out[a.get("Name")] = (k, v)
        frame["point_data" if section == "PointData" else "cell_data"] = out
    return frame


def read_vtp(path):
    with open(path, "rb") as f:
        return parse_vtp(f.read(), str(path))


def polygons(frame):
    """The polygons of a frame, each a list of (x, y)."""
    conn, offsets = frame["polys"] or ([], [])
    starts = [0] + list(offsets[:-1])
    return [[frame["points"][i] for i in conn[s:e]] for s, e in zip(starts, offsets)]
