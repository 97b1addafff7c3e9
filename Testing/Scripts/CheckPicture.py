"""Checks that a PNG an example wrote shows a drawn volume: it exists, is at least 64 pixels on
a side, at least 3 % of its pixels differ from the corner pixel (the background) by more than 8
levels, and at most 60 % of those are saturated (a blank, a uniform or a burnt-out picture fail).
Plain Python (zlib), so that it runs under any interpreter and PYTHONPATH: the pvbatch example's
environment holds ParaView's vtkmodules. Usage: CheckPicture.py FILE.png"""
import struct
import sys
import zlib


def read_png(path):
    """(width, height, rows of RGB tuples) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", chunk)
        elif kind == b"IDAT":
            idat += chunk
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError("not 8-bit RGB(A), non-interlaced")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def main(path):
    try:
        width, height, rows = read_png(path)
    except (OSError, ValueError, zlib.error, TypeError, struct.error) as e:
        print("%s: no readable picture (%s)" % (path, e))
        return 1
    background = rows[0][0]
    drawn = saturated = 0
    for row in rows:
        for rgb in row:
            if max(abs(a - b) for a, b in zip(rgb, background)) > 8:
                drawn += 1
                saturated += 1 if max(rgb) >= 255 else 0
    share = drawn / float(width * height)
    print("%s: %d x %d, %.1f %% drawn, %.1f %% of it saturated"
          % (path, width, height, 100 * share, 100 * saturated / max(drawn, 1)))
    ok = width >= 64 and height >= 64 and share >= 0.03 and saturated <= 0.6 * drawn
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
