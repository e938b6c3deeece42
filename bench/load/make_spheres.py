#!/usr/bin/python3
"""Writes a scene of N spheres (default 100,000), one object a line, for the load benchmark
(docs/performance.md "Loading large scenes").

    bench/load/make_spheres.py big.yaml [--count N] [--seed S]

The spheres sit at random in a cube of side 200 with radii in [0.05, 0.5], each with one of four
named materials; a camera, a light and a floor complete the scene so that it also renders.
"""
import argparse
import random


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("--count", type=int, default=100_000)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    names = ["red", "green", "blue", "white"]
    lines = [
        f"# {args.count} random spheres: bench/load/make_spheres.py",
        "camera: {type: perspective, position: [0, 150, -350], look_at: [0, 0, 0], "
        "up: [0, 1, 0], fov: 45}",
        "image: {width: 640, height: 480}",
        "materials:",
        "  red:   {color: [0.9, 0.2, 0.2], specular: 0.4, shininess: 40}",
        "  green: {color: [0.2, 0.9, 0.3], specular: 0.4, shininess: 40}",
        "  blue:  {color: [0.2, 0.3, 0.9], specular: 0.4, shininess: 40}",
        "  white: {color: [0.9, 0.9, 0.9], reflection: 0.3}",
        "lights:",
        "  - {type: point, position: [-300, 400, -300], color: [1, 1, 1], intensity: 1.0}",
        "objects:",
        "  - {name: floor, plane: {normal: [0, 1, 0], point: [0, -101, 0]}, material: white}",
    ]
    for _ in range(args.count):
        x, y, z = (rng.uniform(-100, 100) for _ in range(3))
        r = rng.uniform(0.05, 0.5)
        m = rng.choice(names)
        lines.append(f"  - {{sphere: {{center: [{x:.4f}, {y:.4f}, {z:.4f}], radius: {r:.4f}}}, "
                     f"material: {m}}}")
    with open(args.output, "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
