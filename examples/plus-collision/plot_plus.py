#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Damage snapshots and softening-zone areas of the plus-collision runs
(examples/plus-collision/README.md).

    plot_plus.py --eps-runs TAG... --h-runs TAG... [-o plus_collision.png]

TAG names the outputs of in.plus_collision (dump.plus_TAG, zone.TAG.txt),
e.g. n30_e4. Top row: damage of the eps runs at the end; bottom: softening
zone area of grain 1 (nodes with nonzero damage) against time for all runs.
Prints the final areas.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import peridem_post as pp  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--eps-runs", nargs="+", required=True)
    p.add_argument("--h-runs", nargs="+", default=[])
    p.add_argument("-o", "--output", default="plus_collision.png")
    a = p.parse_args()
    plt = pp._pyplot()
    n = len(a.eps_runs)
    fig = plt.figure(figsize=(3.2 * max(n, 2), 6.4))
    for k, tag in enumerate(a.eps_runs):
        ax = fig.add_subplot(2, n, k + 1)
        s = pp.read_dump(f"dump.plus_{tag}")[-1]
        x, y = pp.column(s, "x") * 1e3, pp.column(s, "y") * 1e3
        ax.scatter(x, y, s=0.5, c=pp.column(s, "c_dmg[1]"), cmap="viridis", vmin=0, vmax=1)
        ax.set_aspect("equal")
        ax.set_title(tag, fontsize=8)
        ax.tick_params(labelsize=6)
    for k, (runs, what) in enumerate(((a.eps_runs, "fixed h = R/30"), (a.h_runs, "fixed eps = 0.133 R"))):
        if not runs:
            continue
        ax = fig.add_subplot(2, 2, 3 + k)
        for tag in runs:
            _, v = pp.read_ave_time(f"zone.{tag}.txt")
            t = v[:, 0]
            ax.plot(t * 1e6, v[:, 1] * 1e6, label=tag)
            print(f"{tag}: softening zone of grain 1 at {t[-1] * 1e6:.2g} us: {v[-1, 1] * 1e6:.4f} mm^2 "
                  f"(grain 2: {v[-1, 2] * 1e6:.4f}), {int(v[-1, 3])} broken bonds")
        ax.set_xlabel("time (us)", fontsize=8)
        ax.set_ylabel("softening zone area (mm^2)", fontsize=8)
        ax.set_title(what, fontsize=8)
        ax.legend(fontsize=7)
        ax.tick_params(labelsize=7)
    fig.savefig(a.output, dpi=100)
    print(a.output)


if __name__ == "__main__":
    main()
