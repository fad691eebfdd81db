#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Start positions for in.force_chains: disks of three radii (random order)
placed one by one at the lowest position where they rest on the floor, a
wall or two disks already placed, with a gap of 0.2 mm (just beyond the
contact radius), so the bed starts dense and almost settled. Writes
small.txt, medium.txt, large.txt ("x y 0" per grain, metres) for
create_peridem_grains.
usage: make_packing.py [--grains N] [--seed S]"""
import argparse
import itertools
import math
import random

RADII = {"small": 0.8e-3, "medium": 1.0e-3, "large": 1.2e-3}
W, GAP = 14e-3, 0.2e-3

ap = argparse.ArgumentParser()
ap.add_argument("--grains", type=int, default=40)
ap.add_argument("--seed", type=int, default=20261123)
a = ap.parse_args()
rng = random.Random(a.seed)
placed = []  # (x, y, r, size)


def free(x, y, r):
    if x < r + GAP * 0.999 or x > W - r - GAP * 0.999 or y < r + GAP * 0.999:
        return False
    return all(math.hypot(x - xj, y - yj) >= r + rj + GAP * 0.999 for (xj, yj, rj, _) in placed)


def candidates(r):
    lo, hi, y0 = r + GAP, W - r - GAP, r + GAP
    yield lo, y0
    yield hi, y0
    for (xj, yj, rj, _) in placed:
        d = r + rj + GAP
        for xw in (lo, hi):  # a wall and a disk
            if abs(xw - xj) < d:
                yield xw, yj + math.sqrt(d * d - (xw - xj) ** 2)
        if d > abs(yj - y0):  # the floor and a disk
            dx = math.sqrt(d * d - (yj - y0) ** 2)
            yield xj - dx, y0
            yield xj + dx, y0
    for (p, q) in itertools.combinations(placed, 2):  # two disks
        (x1, y1, r1, _), (x2, y2, r2, _) = p, q
        d1, d2 = r + r1 + GAP, r + r2 + GAP
        L = math.hypot(x2 - x1, y2 - y1)
        if L == 0 or L > d1 + d2:
            continue
        t = (d1 * d1 - d2 * d2 + L * L) / (2 * L)
        h2 = d1 * d1 - t * t
        if h2 < 0:
            continue
        h = math.sqrt(h2)
        ex, ey = (x2 - x1) / L, (y2 - y1) / L
        for sgn in (1, -1):
            yield x1 + t * ex - sgn * h * ey, y1 + t * ey + sgn * h * ex


for _ in range(a.grains):
    size = rng.choice(sorted(RADII))
    r = RADII[size]
    best = min(((y, x) for (x, y) in candidates(r) if free(x, y, r)), default=None)
    y, x = best
    placed.append((x, y, r, size))
for size in sorted(RADII):
    with open(size + ".txt", "w") as f:
        f.write("# %s grains, radius %g m (make_packing.py --grains %d --seed %d)\n"
                % (size, RADII[size], a.grains, a.seed))
        for (x, y, r, s) in placed:
            if s == size:
                f.write("%.6e %.6e 0\n" % (x, y))
print("top of the bed: %.3g m" % max(y + r for (x, y, r, s) in placed))
