#!/usr/bin/python3
"""RMSE between two PNG images of the same size: the root mean square, over every pixel and
colour channel, of the difference of their sRGB codes scaled to [0, 1] (8-bit: code / 255,
16-bit: code / 65535).
    bench/povray/rmse.py A.png B.png        -> prints the RMSE
The images are compared pixel by pixel: both renderers put pixel (0, 0) at the top-left corner of
the same view (docs/performance.md). Reads non-interlaced grey/RGB/RGBA PNGs of 8 or 16
bits with zlib (alpha is ignored)."""
import math
import struct
import sys
import zlib


def read_png(path):
    """(width, height, list of per-pixel [r, g, b] floats in [0, 1])."""
    with open(path, 'rb') as f:
        data = f.read()
    if data[:8] != b'\x89PNG\r\n\x1a\n':
        sys.exit('%s: not a PNG' % path)
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            header = struct.unpack('>IIBBBBB', body)
        elif kind == b'IDAT':
            idat.append(body)
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if channels is None or depth not in (8, 16) or interlace:
        sys.exit('%s: unsupported PNG (colour type %d, depth %d)' % (path, colour, depth))
    step = channels * depth // 8
    stride = width * step
    raw = zlib.decompress(b''.join(idat))
    prior = bytearray(stride)
    out = []
    scale = 255.0 if depth == 8 else 65535.0
    for y in range(height):
        kind = raw[y * (stride + 1)]
        row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = row[i - step] if i >= step else 0
            b = prior[i]
            c = prior[i - step] if i >= step else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + ((a + b) >> 1)) & 255
            elif kind == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prior = row
        for x in range(width):
            px = row[x * step:(x + 1) * step]
            if depth == 16:
                px = [px[2 * k] * 256 + px[2 * k + 1] for k in range(channels)]
            if channels <= 2:
                out.append([px[0] / scale] * 3)
            else:
                out.append([px[0] / scale, px[1] / scale, px[2] / scale])
    return width, height, out


def rmse(a, b):
    wa, ha, pa = read_png(a)
    wb, hb, pb = read_png(b)
    if (wa, ha) != (wb, hb):
        sys.exit('size differs: %dx%d against %dx%d' % (wa, ha, wb, hb))
    total = sum((x - y) ** 2 for p, q in zip(pa, pb) for x, y in zip(p, q))
    return math.sqrt(total / (3 * len(pa)))


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    print('%.6f' % rmse(sys.argv[1], sys.argv[2]))
