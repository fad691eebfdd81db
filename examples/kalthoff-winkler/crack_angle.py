#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Crack angles of the Kalthoff-Winkler runs (examples/kalthoff-winkler).

    crack_angle.py DUMP [--lengths 10 20 30] [--threshold 0.35] [--png kw.png]
                   [--check MIN MAX]
    crack_angle.py --lmp LMP --out DIR [--potentials DIR] [lmp -var options ...]
                   [--lengths ...] [--check MIN MAX]     (runs in.kalthoff_winkler first)

DUMP is the final dump of in.kalthoff_winkler (id x y c_dmg[1], metres).
The cracks start at the notch tips (50, +-25) mm. For each stated crack
length L, the crack nodes (damage >= threshold) in the ring |r - L| < 2 mm
around a tip, on the outer side of its notch (|y| > 25 mm), are binned by
their direction seen from the tip; the crack direction is the peak of that
damage-weighted profile (mean within 5 degrees of it), measured from the
notch direction (+x): the angle of the chord tip -> crack at distance L,
for the upper crack and the mirrored lower crack, and their mean. The principal
axis of all crack nodes within L of the tip (python/peridem_post.crack_angle)
is printed beside it. --check MIN MAX prints PERIDEM-PASS if the mean angle
over the first stated length lies in [MIN, MAX] (else PERIDEM-FAIL).
"""
import argparse
import math
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import peridem_post as pp  # noqa: E402

TIP = (50.0, 25.0)


def crack_direction(x, y, d, L, thr, ring=2.0):
    """Direction (degrees from +x) of the crack of the upper notch at distance L
    from its tip: the peak of the damage-weighted angular profile of the crack
    nodes in the ring |r - L| < ring (5-degree window), so that a fan of
    side branches does not pull the angle as a mean would."""
    r = np.hypot(x - TIP[0], y - TIP[1])
    m = (d >= thr) & (np.abs(r - L) < ring) & (y > TIP[1])
    if m.sum() == 0:
        return None
    th = np.degrees(np.arctan2(y[m] - TIP[1], x[m] - TIP[0]))
    grid = np.arange(0.0, 180.01, 0.5)
    prof = np.array([d[m][np.abs(th - g) < 2.5].sum() for g in grid])
    g0 = grid[np.argmax(prof)]
    near = np.abs(th - g0) < 5.0
    return float(np.average(th[near], weights=d[m][near]))


def angles(x, y, d, L, thr):
    """(crack direction at distance L, principal-axis angle within L) of the
    crack of the upper notch."""
    chord = crack_direction(x, y, d, L, thr)
    if chord is None:
        return None, None
    r = np.hypot(x - TIP[0], y - TIP[1])
    near = (r <= L) & (y > TIP[1]) & (d >= thr)
    try:
        ax = pp.crack_angle(x[near], y[near], d[near], thr)[0]
        ax = ax if ax > 0 else ax + 180.0
    except ValueError:
        ax = float("nan")
    return chord, ax


def main():
    p = argparse.ArgumentParser()
    p.add_argument("dump", nargs="?")
    p.add_argument("--lmp", help="run in.kalthoff_winkler with this binary first")
    p.add_argument("--out", default=".")
    p.add_argument("--potentials",
                   default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                        "potentials"))
    p.add_argument("--var", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                   help="lmp -var NAME VALUE (repeatable)")
    p.add_argument("--lengths", type=float, nargs="+", default=[10.0, 20.0, 30.0])
    p.add_argument("--threshold", type=float, default=0.35)
    p.add_argument("--png")
    p.add_argument("--check", type=float, nargs=2)
    a = p.parse_args()
    if a.lmp:
        here = os.path.dirname(os.path.abspath(__file__))
        os.makedirs(a.out, exist_ok=True)
        for f in ("in.kalthoff_winkler", "kw_plate.poly"):
            shutil.copy(os.path.join(here, f), a.out)
        cmd = [os.path.abspath(a.lmp), "-in", "in.kalthoff_winkler", "-log", "log.lammps",
               "-screen", "none", "-var", "potentials", os.path.abspath(a.potentials),
               "-var", "tag", "run"]
        for name, value in a.var:
            cmd += ["-var", name, value]
        subprocess.run(cmd, cwd=a.out, check=True)
        a.dump = os.path.join(a.out, "dump.kw_run")
    if not a.dump:
        p.error("give a DUMP or --lmp")
    s = pp.read_dump(a.dump)[-1]
    x, y = pp.column(s, "x") * 1e3, pp.column(s, "y") * 1e3
    d = pp.column(s, "c_dmg[1]")
    first = None
    for L in a.lengths:
        up = angles(x, y, d, L, a.threshold)
        lo = angles(x, -y, d, L, a.threshold)
        if up[0] is None or lo[0] is None:
            print(f"L = {L:g} mm: no crack node at that distance")
            continue
        mean = 0.5 * (up[0] + lo[0])
        first = mean if first is None else first
        print(f"L = {L:g} mm: crack angle {mean:.1f} deg (upper {up[0]:.1f}, lower {lo[0]:.1f}; "
              f"principal axis {up[1]:.1f}, {lo[1]:.1f})")
    if a.png:
        plt = pp._pyplot()
        fig, ax = plt.subplots(figsize=(4, 7))
        sc = ax.scatter(x, y, s=1, c=d, cmap="viridis", vmin=0, vmax=1)
        for sgn in (1, -1):
            t = math.radians(68.0)
            ax.plot([TIP[0], TIP[0] + 40 * math.cos(t)], [sgn * TIP[1], sgn * (TIP[1] + 40 * math.sin(t))],
                    "r--", lw=0.8)
        ax.set_title(f"damage, step {s['step']} (dashed: 68 deg)", fontsize=8)
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
        ax.set_ylabel("y (mm)")
        fig.colorbar(sc, ax=ax, shrink=0.6)
        fig.savefig(a.png, dpi=110)
        print(a.png)
    if a.check:
        ok = first is not None and a.check[0] <= first <= a.check[1]
        print(("PERIDEM-PASS" if ok else "PERIDEM-FAIL") +
              f": crack angle over {a.lengths[0]:g} mm = {first} in [{a.check[0]}, {a.check[1]}]")


if __name__ == "__main__":
    main()
