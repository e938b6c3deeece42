#!/usr/bin/env python3
"""Writes the primary rays of a raycast scene's perspective camera (one per pixel centre) as
`raycast cast --binary` input: 8 little-endian float64 per ray, row by row from the top.

    camera_rays.py SCENE.yaml WIDTH HEIGHT > rays.bin

The camera follows docs/rendering.md: vertical fov in degrees, position, look_at, up."""
import math
import struct
import sys

import yaml


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def main():
    scene_path, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    with open(scene_path) as f:
        cam = yaml.safe_load(f)["camera"]
    pos, look, up = cam["position"], cam["look_at"], cam.get("up", [0, 1, 0])
    fov = cam.get("fov", 40)
    w = normalize([look[i] - pos[i] for i in range(3)])  # forward
    u = normalize(cross(w, up))  # right (right-handed: forward x up)
    v = cross(u, w)  # true up
    half_h = math.tan(math.radians(fov) / 2)
    half_w = half_h * width / height
    out = sys.stdout.buffer
    rec = struct.Struct("<8d")
    for j in range(height):
        y = (1 - 2 * (j + 0.5) / height) * half_h
        row = bytearray()
        for i in range(width):
            x = (2 * (i + 0.5) / width - 1) * half_w
            d = [w[k] + x * u[k] + y * v[k] for k in range(3)]
            row += rec.pack(pos[0], pos[1], pos[2], d[0], d[1], d[2], 0.0, math.inf)
        out.write(row)


if __name__ == "__main__":
    main()
