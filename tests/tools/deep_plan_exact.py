#!/usr/bin/env python3
"""The exact -ab 2 sensor values of tests/data/scenes/deep_plan.rad (uniform sky and ground of
radiance 1 seen through open window bands; grey plastic surfaces; a convex room, so every
interior point sees both openings unobstructed).

A sensor (-I, facing up) at -ab 2 integrates, over its cosine-weighted hemisphere, radiance 1
where the direction leaves through an opening and, where it meets a surface of reflectance rho,
that surface's exact -ab 1 value rho * F (F: the form factor from the point to the openings, by
Lambert's contour formula). The direct sky part is Lambert's formula itself; the surface part is
a stratified quadrature of N x N directions (concentric map): N=256 and 768 differ by 2e-4
relative in the mean.

usage: deep_plan_exact.py GRID.pts [N] > deep_plan_exact.txt   (needs numpy: python3-numpy)
"""
import sys

import numpy as np

W, H, Z = 60.0, 24.0, 2.7  # the room
Z0, Z1 = 0.9, 2.4  # the window bands, on y = 0 and y = H
RHO = {"ceiling": 0.8, "wall": 0.6}


def form_factor(p, n, rect):
    """Lambert's formula for points p (k x 3) with unit normals n to a planar polygon."""
    s = np.zeros(len(p))
    for i in range(len(rect)):
        a = rect[i][None, :] - p
        b = rect[(i + 1) % len(rect)][None, :] - p
        c = np.cross(a, b)
        lc = np.linalg.norm(c, axis=1)
        g = np.arctan2(lc, np.sum(a * b, axis=1))
        ok = lc > 1e-12
        s += np.where(ok, g * np.sum(n * c, axis=1) / np.where(ok, lc, 1.0), 0.0)
    return np.abs(s) / (2 * np.pi)


def band(y, z0, z1):
    return np.array([(0, y, z0), (W, y, z0), (W, y, z1), (0, y, z1)], float)


def square_to_disk(a, b):
    a, b = 2 * a - 1, 2 * b - 1
    wide = a * a > b * b
    r = np.where(wide, a, b)
    with np.errstate(invalid="ignore", divide="ignore"):
        phi = np.where(wide, np.pi / 4 * (b / np.where(a == 0, 1, a)),
                       np.pi / 2 - np.pi / 4 * (a / np.where(b == 0, 1, b)))
    return r * np.cos(phi), r * np.sin(phi)


def sensor(p, n, rng):
    p = np.asarray(p, float)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    u = ((i + rng.random(i.shape)) / n).ravel()
    v = ((j + rng.random(i.shape)) / n).ravel()
    dx, dy = square_to_disk(u, v)
    dz = np.sqrt(np.maximum(0.0, 1 - dx * dx - dy * dy))
    d = np.stack([dx, dy, dz], 1)
    with np.errstate(divide="ignore", invalid="ignore"):
        tz = np.where(dz > 0, (Z - p[2]) / dz, np.inf)
        tx = np.where(dx > 0, (W - p[0]) / dx, np.where(dx < 0, -p[0] / dx, np.inf))
        ty = np.where(dy > 0, (H - p[1]) / dy, np.where(dy < 0, -p[1] / dy, np.inf))
    t = np.minimum(np.minimum(tz, tx), ty)
    q = p[None, :] + d * t[:, None]
    ceil = (tz <= tx) & (tz <= ty)
    xwall = ~ceil & (tx <= ty)
    ywall = ~ceil & ~xwall
    opening = ywall & (q[:, 2] > Z0) & (q[:, 2] < Z1)
    normal = np.zeros_like(q)
    normal[ceil] = (0, 0, -1)
    normal[xwall] = np.where((d[xwall, 0] > 0)[:, None], [-1.0, 0, 0], [1.0, 0, 0])
    wy = ywall & ~opening
    normal[wy] = np.where((d[wy, 1] > 0)[:, None], [0, -1.0, 0], [0, 1.0, 0])
    rho = np.where(ceil, RHO["ceiling"], RHO["wall"])
    lit = ~opening
    f = form_factor(q[lit], normal[lit], band(0, Z0, Z1)) + form_factor(
        q[lit], normal[lit], band(H, Z0, Z1))
    surfaces = np.zeros(len(t))
    surfaces[lit] = rho[lit] * f
    up = np.array([[0, 0, 1.0]])
    sky = form_factor(p[None, :], up, band(0, p[2], Z1)) + form_factor(
        p[None, :], up, band(H, p[2], Z1))
    return np.pi * (surfaces.mean() + sky[0])


def main():
    grid = [list(map(float, line.split()[:3])) for line in open(sys.argv[1]) if line.strip()]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 768
    rng = np.random.default_rng(20261207)
    print("# exact -ab 2 irradiance (W/m2, every channel) of deep_plan.rad's sensors, N=%d" % n)
    for p in grid:
        print("%.7g" % sensor(p, n, rng))


if __name__ == "__main__":
    main()
