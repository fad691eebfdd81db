#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Damage of the plate at a few moments of the fracture run (plate_hole.png).

    plot_plate_hole.py [--dt DT] STEP1 STEP2 ... [--out plate_hole.png]

reads plate_hole.STEP.dump (in.plate_hole -var stage fracture -var dump 1) and draws the
nodes at their current positions coloured by damage (broken-bond fraction).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from peridem_post import column, read_dump  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("steps", type=int, nargs="+")
    ap.add_argument("--dt", type=float, default=None, help="time step (s), for the titles")
    ap.add_argument("--titles", default=None, help="comma-separated titles, one per step")
    ap.add_argument("--out", default="plate_hole.png")
    a = ap.parse_args()
    titles = a.titles.split(",") if a.titles else [""] * len(a.steps)
    fig, axes = plt.subplots(1, len(a.steps), figsize=(3.2 * len(a.steps), 3.4), squeeze=False)
    for ax, step, title in zip(axes[0], a.steps, titles):
        s = read_dump(f"plate_hole.{step}.dump")[-1]
        x, y, d = (column(s, c) * (1e3 if c in "xy" else 1) for c in ("x", "y", "c_dmg[1]"))
        sc = ax.scatter(x, y, c=d, s=0.15, cmap="inferno_r", vmin=0, vmax=0.5, linewidths=0)
        t = f"t = {step * a.dt * 1e3:.2f} ms" if a.dt else f"step {step}"
        ax.set_title(f"{t}\n{title}" if title else t, fontsize=9)
        ax.set_aspect("equal")
        ax.set_xlim(-62, 62)
        ax.set_ylim(-55, 55)
        ax.tick_params(labelsize=7)
        ax.set_xlabel("x (mm)", fontsize=8)
    axes[0][0].set_ylabel("y (mm)", fontsize=8)
    fig.colorbar(sc, ax=axes[0].tolist(), shrink=0.8, label="damage")
    fig.savefig(a.out, dpi=130, bbox_inches="tight")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
