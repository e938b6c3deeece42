#!/usr/bin/python3
"""Reference crossings of rays with the iso-surface of a trilinearly interpolated grid, in exact
rational arithmetic (fractions), independent of the engine's method.

Writes two grids as raw float32 + JSON sidecar (a sphere's signed distance and a sum of Gaussians)
and, for each, rays with their first crossing t >= 0 (or inf). Along a ray the field is piecewise
cubic, with breaks where the ray crosses a grid plane; each piece's cubic comes from four exact
evaluations of the trilinear field (Lagrange), and its roots are isolated with Sturm sequences and
bisected to 2^-80. Run from this folder: /usr/bin/python3 make_reference.py
"""
import json
import math
import random
import struct
from fractions import Fraction as F

N = 13
LO = F(-3, 2)
CELL = F(1, 4)


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def make_grid(fn):
    vals = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                p = [float(LO + CELL * c) for c in (i, j, k)]
                vals.append(f32(fn(*p)))
    return vals


def sphere(x, y, z):
    return 1.1 - math.sqrt(x * x + y * y + z * z)


GAUSS = [((-0.4, 0.1, 0.2), 0.35), ((0.5, -0.2, -0.1), 0.3), ((0.05, 0.45, -0.4), 0.25)]


def gaussians(x, y, z):
    return sum(math.exp(-((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) / (2 * s * s))
               for c, s in GAUSS)


def field(vals, p):
    """Exact trilinear field at rational point p (0 outside the grid)."""
    g = [(p[a] - LO) / CELL for a in range(3)]
    if any(x < 0 or x > N - 1 for x in g):
        return F(0)
    c = [min(int(math.floor(x)), N - 2) for x in g]
    u = [g[a] - c[a] for a in range(3)]
    r = F(0)
    for k in (0, 1):
        for j in (0, 1):
            for i in (0, 1):
                w = (u[0] if i else 1 - u[0]) * (u[1] if j else 1 - u[1]) * (u[2] if k else 1 - u[2])
                r += w * F(vals[((c[2] + k) * N + c[1] + j) * N + c[0] + i])
    return r


def poly_eval(p, x):
    r = F(0)
    for a in reversed(p):
        r = r * x + a
    return r


def lagrange(xs, ys):
    """Coefficients (low first) of the cubic through 4 points."""
    coef = [F(0)] * 4
    for i in range(4):
        basis = [F(1)]
        den = F(1)
        for j in range(4):
            if j == i:
                continue
            basis = [F(0)] + basis
            for m in range(len(basis) - 1):
                basis[m] -= xs[j] * basis[m + 1]
            den *= xs[i] - xs[j]
        for m in range(4):
            coef[m] += ys[i] * basis[m] / den
    return coef


def trim(p):
    while p and p[-1] == 0:
        p = p[:-1]
    return p


def polyrem(a, b):
    a = a[:]
    while len(trim(a)) >= len(b):
        a = trim(a)
        q = a[-1] / b[-1]
        sh = len(a) - len(b)
        for m in range(len(b)):
            a[sh + m] -= q * b[m]
        a = a[:-1]
    return trim(a)


def sturm(p):
    p = trim(p)
    seq = [p]
    d = trim([m * p[m] for m in range(1, len(p))])
    if not d:
        return seq
    seq.append(d)
    while True:
        r = polyrem(seq[-2], seq[-1])
        if not r:
            break
        seq.append([-c for c in r])
    return seq


def sign_changes(seq, x):
    s = [poly_eval(p, x) for p in seq]
    s = [v for v in s if v != 0]
    return sum(1 for a, b in zip(s, s[1:]) if (a > 0) != (b > 0))


def first_crossing(p, a, b, inside_at_a):
    """First x in (a, b] where the class (p > 0) differs from inside_at_a, or None."""
    p = trim(p)
    if not p:
        return None if not inside_at_a else a
    if len(p) == 1:
        return None if (p[0] > 0) == inside_at_a else a
    seq = sturm(p)
    # split (a, b] into pieces holding at most one distinct root each, in order
    stack = [(a, b)]
    while stack:
        lo, hi = stack.pop(0)
        n = sign_changes(seq, lo) - sign_changes(seq, hi)
        if n == 0:
            if (poly_eval(p, hi) > 0) != inside_at_a:
                return lo  # class changed exactly at lo
            continue
        if n > 1 and hi - lo > F(1, 2 ** 90):
            mid = (lo + hi) / 2
            stack[:0] = [(lo, mid), (mid, hi)]
            continue
        if (poly_eval(p, hi) > 0) == inside_at_a:
            continue  # an even-multiplicity touch (or roots that cancel)
        while hi - lo > F(1, 2 ** 80):
            mid = (lo + hi) / 2
            if (poly_eval(p, mid) > 0) == inside_at_a:
                lo = mid
            else:
                hi = mid
        return hi
    return None


def reference_t(vals, iso, o, d):
    o = [F(x) for x in o]
    d = [F(x) for x in d]
    # box chord
    t0, t1 = F(-10 ** 9), F(10 ** 9)
    hi_box = LO + CELL * (N - 1)
    for a in range(3):
        if d[a] == 0:
            if o[a] < LO or o[a] > hi_box:
                return None
            continue
        n, f = (LO - o[a]) / d[a], (hi_box - o[a]) / d[a]
        if n > f:
            n, f = f, n
        t0, t1 = max(t0, n), min(t1, f)
    if t0 > t1:
        return None
    start = max(t0, F(0))
    if start > t1:
        return None
    breaks = {start, t1}
    for a in range(3):
        if d[a] == 0:
            continue
        for i in range(N):
            t = (LO + CELL * i - o[a]) / d[a]
            if start < t < t1:
                breaks.add(t)
    breaks = sorted(breaks)
    at = lambda t: [o[a] + t * d[a] for a in range(3)]
    inside = field(vals, at((breaks[0] + breaks[1]) / 2 if len(breaks) > 1 else breaks[0])) > iso \
        if start == t0 else field(vals, at(start)) > iso
    if start == t0 and inside:
        return start  # enters through the grid's face
    for lo, hi in zip(breaks, breaks[1:]):
        xs = [lo + (hi - lo) * m / 3 for m in range(4)]
        mid = (lo + hi) / 2
        g = [(at(mid)[a] - LO) / CELL for a in range(3)]
        c = [min(int(math.floor(x)), N - 2) for x in g]

        def cell_field(t):
            gg = [(at(t)[a] - LO) / CELL - c[a] for a in range(3)]
            r = F(0)
            for k in (0, 1):
                for j in (0, 1):
                    for i in (0, 1):
                        w = (gg[0] if i else 1 - gg[0]) * (gg[1] if j else 1 - gg[1]) * \
                            (gg[2] if k else 1 - gg[2])
                        r += w * F(vals[((c[2] + k) * N + c[1] + j) * N + c[0] + i])
            return r
        p = lagrange(xs, [cell_field(x) - iso for x in xs])
        r = first_crossing(p, lo, hi, inside)
        if r is not None:
            return r
    if inside:
        return t1  # leaves through the grid's face
    return None


def dyadic(x, bits=12):
    return round(x * 2 ** bits) / 2 ** bits


def rays(rng):
    out = []
    c = float(CELL)
    # special rays: along grid planes, through nodes, from inside, axis-parallel
    out.append((-3.0, 0.0, 0.0, 1.0, 0.0, 0.0))           # along a node line
    out.append((-3.0, 0.25, 0.0, 1.0, 0.0, 0.0))          # along another node line
    out.append((-3.0, 0.125, 0.0, 1.0, 0.0, 0.0))         # in a grid plane, between node lines
    out.append((-2.0, -2.0, -2.0, 1.0, 1.0, 1.0))         # diagonal through nodes
    out.append((-2.0, -1.75, -2.0, 1.0, 1.0, 1.0))        # parallel to it, through edges
    out.append((0.0, 0.0, 0.0, 1.0, 0.0, 0.0))            # starting inside, on a node
    out.append((0.1, 0.2, -0.05, 0.3, -1.0, 0.7))         # starting inside
    out.append((0.0, 0.0, -3.0, 0.0, 0.0, 1.0))
    out.append((0.0, 1.0999, -3.0, 0.0, 0.0, 1.0))        # nearly grazing the sphere's top
    out.append((0.0, 0.9, -3.0, 0.0, 0.0, 2.5))           # d not unit length
    out.append((-3.0, 0.0, 1.0, 1.0, 0.0, 0.0))
    for _ in range(40):
        o = [dyadic(rng.uniform(-2.5, 2.5)) for _ in range(3)]
        tgt = [dyadic(rng.uniform(-0.8, 0.8)) for _ in range(3)]
        d = [tgt[a] - o[a] for a in range(3)]
        if all(x == 0 for x in d):
            continue
        out.append(tuple(o) + tuple(d))
    return out


def write(name, vals, iso, rng):
    with open(name + '.raw', 'wb') as f:
        f.write(struct.pack('<%df' % len(vals), *vals))
    hi = float(LO + CELL * (N - 1))
    with open(name + '.json', 'w') as f:
        json.dump({"dims": [N, N, N], "min": [float(LO)] * 3, "max": [hi] * 3, "type": "float32"}, f)
        f.write('\n')
    with open(name + '_rays.txt', 'w') as f:
        f.write('# ox oy oz dx dy dz t (first crossing t >= 0 of field > %r; inf: none)\n' % iso)
        f.write('iso %r\n' % iso)
        for r in rays(rng):
            t = reference_t(vals, F(iso), r[:3], r[3:])
            ts = 'inf' if t is None else repr_fraction(t)
            f.write(' '.join(repr(x) for x in r) + ' ' + ts + '\n')


def repr_fraction(t):
    # 25 significant digits from the exact rational
    s = '-' if t < 0 else ''
    t = abs(t)
    if t == 0:
        return '0'
    e = math.floor(math.log10(t.numerator) - math.log10(t.denominator))
    m = t / F(10) ** e
    while m >= 10:
        m /= 10
        e += 1
    while m < 1:
        m *= 10
        e -= 1
    digits = int(m * 10 ** 24)
    ds = str(digits)
    return '%s%s.%se%d' % (s, ds[0], ds[1:], e)


if __name__ == '__main__':
    rng = random.Random(10)
    write('sphere_sdf', make_grid(sphere), 0.0, rng)
    write('gaussians', make_grid(gaussians), 0.5, rng)
