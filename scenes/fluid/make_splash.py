#!/usr/bin/python3
"""Writes the particles of scenes/fluid.yaml: a drop's splash on a shallow pool (a crown with
spikes, a central jet, flying droplets), as binary PLY files splash_NNNN.ply.

    /usr/bin/python3 make_splash.py            # frame 0 only (the committed file)
    /usr/bin/python3 make_splash.py 48         # frames 0..47, for `raycast render --frames 0-47`

Positions lie on a jittered lattice of spacing h / 1.3 (h = 0.02, the scene's smoothing_length),
so that the splatted density of the bulk is close to the rest density.
"""
import sys

import numpy as np

H = 0.02
S = H / 1.3


def lattice(lo, hi, rng):
    axes = [np.arange(a, b, S) for a, b in zip(lo, hi)]
    g = np.stack(np.meshgrid(*axes, indexing='ij'), -1).reshape(-1, 3)
    return g + rng.normal(0, 0.08 * S, g.shape)


def frame(k, frames):
    rng = np.random.default_rng(1000 + k)
    phase = 0.35 + 0.5 * k / max(frames, 1)           # time since impact, 0..1
    parts = []
    # the pool: a shallow disk of water, depressed under the crown
    pool = lattice((-0.75, 0.0, -0.75), (0.75, 0.045, 0.75), rng)
    r = np.hypot(pool[:, 0], pool[:, 2])
    crater = 0.6 * phase * 0.5
    pool = pool[(r < 0.75) & ~((r < crater) & (pool[:, 1] > 0.02))]
    parts.append(pool)
    # the crown: a thin wall flaring outwards, its rim broken into spikes
    radius = 0.12 + 0.3 * phase
    height = 0.28 * np.sin(np.pi * min(phase, 0.95)) + 0.04
    n_theta = int(2 * np.pi * radius / (0.8 * S))
    theta = np.linspace(0, 2 * np.pi, n_theta, endpoint=False)
    spikes = 22
    for layer in range(2):
        for y in np.arange(0.03, height, 0.8 * S):
            flare = radius + 0.25 * (y / height) ** 2 * height + layer * 0.9 * S
            top = height * (0.8 + 0.2 * np.cos(spikes * theta) ** 8)
            keep = y < top
            pts = np.stack([flare * np.cos(theta), np.full_like(theta, y), flare * np.sin(theta)], -1)
            parts.append(pts[keep] + rng.normal(0, 0.06 * S, pts[keep].shape))
    # droplets leaving the spike tips and a central jet, ballistic
    tips = np.arange(spikes) * 2 * np.pi / spikes
    drops = []
    for i, a in enumerate(tips):
        for j in range(3):
            t = phase * (0.6 + 0.2 * j)
            out = radius + 0.1 + 0.5 * t
            y = height + 0.9 * t - 1.6 * t * t + 0.04 * j
            if y > 0.05:
                drops.append((out * np.cos(a + 0.03 * j), y, out * np.sin(a + 0.03 * j), 1.6 * S))
    jet_h = 0.55 * np.sin(np.pi * min(1, phase * 1.2))
    for y in np.arange(0.03, jet_h, S):
        w = 0.05 * (1 - 0.6 * y / max(jet_h, 1e-6))
        drops.append((0, y, 0, w))
    drops.append((0, jet_h + 0.06, 0, 0.035))
    for x, y, z, rad in drops:
        ball = lattice((-rad, -rad, -rad), (rad + S / 2, rad + S / 2, rad + S / 2), rng)
        ball = ball[np.linalg.norm(ball, axis=1) <= rad]
        if len(ball) == 0:
            ball = np.zeros((1, 3))
        parts.append(ball + (x, y, z))
    return np.concatenate(parts).astype('<f4')


def write_ply(path, p):
    with open(path, 'wb') as f:
        f.write(b'ply\nformat binary_little_endian 1.0\ncomment a splash for scenes/fluid.yaml\n')
        f.write(b'element vertex %d\nproperty float x\nproperty float y\nproperty float z\n' % len(p))
        f.write(b'end_header\n')
        f.write(p.tobytes())


if __name__ == '__main__':
    frames = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    for k in range(frames):
        p = frame(k, frames)
        write_ply('splash_%04d.ply' % k, p)
        print('splash_%04d.ply: %d particles' % (k, len(p)))
