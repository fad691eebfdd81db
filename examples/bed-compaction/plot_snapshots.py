#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Fig. 13 of Bhattacharya & Lipton (2023) from in.compaction runs with -var dump yes: per run
(a folder with log.lammps and nodes.STEP.dump), the nodes coloured by damage at the paper's two
moments: the last dump before the first broken bond (the bed compressed, no damage yet) and
the first dump with bulk damage >= 0.2 (the last dump if the run never gets there).

For ring beds (--holes), also the fraction of the rings' hole area that other grains' material
fills, per dump: the rings' holes are disks of radius gamma r (r: the grain's security-disk
radius in bed.txt, which is the ring's outer radius) around the mean position of each ring's
nodes; the filled area is the node area (h^2, h from the log) of the nodes of other grains
inside them. A crushed ring's centre is still its nodes' mean: late values measure material
gathered where the ring was.

    plot_snapshots.py LABEL=DIR [LABEL=DIR ...] [-o snapshots.png] [--holes GAMMA]
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from peridem_post import column, read_dump, read_thermo  # noqa: E402


def dumps_of(folder):
    files = glob.glob(os.path.join(folder, "nodes.*.dump"))
    return sorted(files, key=lambda f: int(re.findall(r"nodes\.(\d+)\.dump", f)[0]))


def step_of(path):
    return int(re.findall(r"nodes\.(\d+)\.dump", path)[0])


def two_moments(folder):
    """(dump before damage, dump at bulk damage 0.2 or the last) and their thermo rows"""
    rows = {int(r["Step"]): r for r in read_thermo(os.path.join(folder, "log.lammps"))}
    files = [f for f in dumps_of(folder) if step_of(f) in rows]
    first_break = next((s for s in sorted(rows) if rows[s]["c_dmg[2]"] > 0.5), None)
    before = [f for f in files if first_break is None or step_of(f) < first_break]
    late = [f for f in files if rows[step_of(f)]["c_dmg"] >= 0.2] or files[-1:]
    return (before[-1], rows[step_of(before[-1])]), (late[0], rows[step_of(late[0])])


def hole_fill(folder, gamma):
    """rows (step, phi, bulk damage, filled fraction of the rings' hole area)"""
    radii = [float(l.split()[3]) for l in open(os.path.join(folder, "bed.txt"))
             if l.strip() and not l.startswith("#")]
    log = open(os.path.join(folder, "log.lammps")).read()
    h = float(re.findall(r"h = ([0-9.eE+-]+) m", log)[0])
    rows = {int(r["Step"]): r for r in read_thermo(os.path.join(folder, "log.lammps"))}
    out = []
    for f in dumps_of(folder):
        snap = read_dump(f)[-1]
        x, y, mol = column(snap, "x"), column(snap, "y"), column(snap, "mol").astype(int)
        filled = holes = 0.0
        for g in np.unique(mol):
            mine = mol == g
            cx, cy = x[mine].mean(), y[mine].mean()
            r_in = gamma * radii[g - 1]
            inside = (~mine) & ((x - cx) ** 2 + (y - cy) ** 2 < r_in * r_in)
            filled += inside.sum() * h * h
            holes += np.pi * r_in * r_in
        r = rows.get(step_of(f))
        out.append((step_of(f), r["c_bed"] if r else float("nan"),
                    r["c_dmg"] if r else float("nan"), filled / holes))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("runs", nargs="+", help="LABEL=DIR")
    ap.add_argument("-o", "--output", default=None)
    ap.add_argument("--holes", type=float, default=None, help="ring thinness gamma")
    ap.add_argument("--size", type=float, default=2.0)
    a = ap.parse_args()
    runs = [spec.partition("=")[::2] for spec in a.runs]
    if a.holes is not None:
        for label, folder in runs:
            print(f"{label}: step, phi, bulk damage, filled fraction of the rings' hole area")
            for step, phi, dmg, fill in hole_fill(folder, a.holes):
                print(f"  {step} {phi:.4f} {dmg:.4f} {fill:.4f}")
    if not a.output:
        return 0
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(runs), figsize=(2.6 * len(runs) + 0.6, 6.2), squeeze=False,
                             sharex="col", sharey="col")
    for col, (label, folder) in enumerate(runs):
        for row, (path, thermo) in enumerate(two_moments(folder)):
            snap = read_dump(path)[-1]
            ax = axes[row][col]
            sc = ax.scatter(column(snap, "x") * 1e3, column(snap, "y") * 1e3, s=a.size,
                            c=column(snap, "c_dmg[1]"), cmap="jet", vmin=0, vmax=1,
                            marker="s", linewidths=0)
            ax.set_aspect("equal")
            ax.set_title(f"{label}\nphi {thermo['c_bed']:.2f}, t {thermo['Time'] * 1e3:.2f} ms, "
                         f"damage {thermo['c_dmg']:.3f}", fontsize=7)
            ax.set_xticks([])
            ax.set_yticks([])
    fig.colorbar(sc, ax=axes.ravel().tolist(), shrink=0.6, label="node damage")
    fig.savefig(a.output, dpi=130)
    print(f"wrote {a.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
