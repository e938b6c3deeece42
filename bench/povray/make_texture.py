#!/usr/bin/python3
"""Writes bench/scenes/globe.png (and a copy for POV-Ray, bench/povray/globe.png), the image
texture of the benchmark suite's textured scene: 256 x 128 sRGB pixels, coloured bands of
latitude crossed by darker meridians every 16 pixels and a diagonal stripe, so that mapping
errors show. Deterministic.  Run from anywhere: bench/povray/make_texture.py"""
import os
import shutil
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
W, H = 256, 128


def pixel(x, y):
    band = (y * 6) // H
    base = [(230, 80, 60), (240, 170, 40), (90, 190, 80), (60, 160, 220), (120, 90, 210),
            (230, 230, 230)][band]
    if x % 16 == 0 or y % 16 == 0:
        return tuple(c // 3 for c in base)
    if (x + 2 * y) % 64 < 6:
        return (30, 30, 30)
    return base


def main():
    raw = b''.join(b'\0' + bytes(c for x in range(W) for c in pixel(x, y)) for y in range(H))

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))

    png = (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, H, 8, 2, 0, 0, 0)) +
           chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))
    target = os.path.join(HERE, '..', 'scenes', 'globe.png')
    with open(target, 'wb') as f:
        f.write(png)
    shutil.copyfile(target, os.path.join(HERE, 'globe.png'))


main()
