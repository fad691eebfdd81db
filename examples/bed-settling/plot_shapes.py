#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Settled beds of in.shapes side by side (Bhattacharya & Lipton 2023, Fig. 12b-e): the nodes of
each shape's final dump (settle.SHAPE.final.dump), coloured by grain, with the settled fraction
from its log in the title.

    plot_shapes.py DIR [-o settled_shapes.png] [--ymax MM] [--size S]
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
sys.path.insert(0, HERE)
from check_shapes import SHAPES, read  # noqa: E402
from peridem_post import column, read_dump  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("-o", "--output", default="settled_shapes.png")
    ap.add_argument("--ymax", type=float, default=None, help="upper y limit (mm)")
    ap.add_argument("--size", type=float, default=0.3, help="marker size")
    ap.add_argument("--prefix", default="log.")
    a = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = [s for s in SHAPES if os.path.exists(os.path.join(a.dir, f"settle.{s}.final.dump"))]
    if not panels:
        print(f"no settle.SHAPE.final.dump in {a.dir}")
        return 1
    snaps = {s: read_dump(os.path.join(a.dir, f"settle.{s}.final.dump"))[-1] for s in panels}
    xmax = max(column(snaps[s], "x").max() for s in panels) * 1e3
    ymax = a.ymax or max(column(snaps[s], "y").max() for s in panels) * 1e3 * 1.03
    width = 2.6 * xmax / ymax * len(panels) + 0.5
    fig, axes = plt.subplots(1, len(panels), figsize=(max(width, 6), 4.5), squeeze=False)
    rng = np.random.default_rng(1)
    colours = rng.random((100000, 3)) * 0.75 + 0.15
    for ax, s in zip(axes[0], panels):
        snap = snaps[s]
        x, y = column(snap, "x") * 1e3, column(snap, "y") * 1e3
        mol = column(snap, "mol").astype(int)
        ax.scatter(x, y, s=a.size, c=colours[mol % len(colours)], marker="s", linewidths=0)
        r = read(os.path.join(a.dir, a.prefix + s))
        title = s.replace("_", " ")
        if r and r["settled"]:
            title += f"\nphi {r['phi']:.3f}" + (f"\n({r['phi_holes']:.3f} with holes)"
                                                 if r["phi_holes"] > r["phi"] * 1.001 else "")
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlim(0, xmax)
        ax.set_ylim(0, ymax)
        ax.set_xlabel("x (mm)")
    axes[0][0].set_ylabel("y (mm)")
    fig.tight_layout()
    fig.savefig(a.output, dpi=130)
    print(f"wrote {a.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
