#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Snapshots of the notch-fracture runs (examples/notch-fracture/README.md).

    plot_notch.py DUMP [DUMP ...] -o notch_fracture.png [--titles T1 T2 ...]

Each DUMP is a final dump of in.notch_fracture (columns id type mol x y
c_dmg[1] c_frag). One panel per dump: the nodes of grain A coloured by
fragment (pieces of at least 1 % of A's area in colour, debris black), the
impactors grey; a second row colours A by damage.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import peridem_post as pp  # noqa: E402


def main():
    p = argparse.ArgumentParser()
    p.add_argument("dumps", nargs="+")
    p.add_argument("-o", "--output", default="notch_fracture.png")
    p.add_argument("--titles", nargs="*")
    p.add_argument("--min-nodes", type=int, default=0,
                   help="pieces smaller than this are debris (default: 1 %% of A's nodes)")
    a = p.parse_args()
    plt = pp._pyplot()
    n = len(a.dumps)
    fig, axes = plt.subplots(2, n, figsize=(3.0 * n, 6.2), squeeze=False)
    for k, path in enumerate(a.dumps):
        s = pp.read_dump(path)[-1]
        t, x, y = pp.column(s, "type"), pp.column(s, "x") * 1e3, pp.column(s, "y") * 1e3
        d, f = pp.column(s, "c_dmg[1]"), pp.column(s, "c_frag")
        A = t == 1
        ids, counts = np.unique(f[A], return_counts=True)
        big = ids[counts >= (a.min_nodes or 0.01 * A.sum())]
        title = a.titles[k] if a.titles and k < len(a.titles) else os.path.basename(path)
        for row, ax in enumerate(axes[:, k]):
            ax.scatter(x[~A], y[~A], s=1, c="0.75")
            if row == 0:
                colour = np.full(A.sum(), -1.0)
                for j, fid in enumerate(big):
                    colour[f[A] == fid] = j
                deb = colour < 0
                ax.scatter(x[A][~deb], y[A][~deb], s=2, c=colour[~deb] % 10, cmap="tab10",
                           vmin=0, vmax=9)
                ax.scatter(x[A][deb], y[A][deb], s=2, c="k")
                ax.set_title(f"{title}\n{len(big)} fragments, {deb.sum()} debris nodes",
                             fontsize=8)
            else:
                sc = ax.scatter(x[A], y[A], s=2, c=d[A], cmap="viridis", vmin=0, vmax=1)
                ax.set_title("damage", fontsize=8)
            ax.set_aspect("equal")
            ax.set_xlim(-1.6, 1.6)
            ax.set_ylim(-1.6, 1.6)
            ax.tick_params(labelsize=6)
    fig.colorbar(sc, ax=axes[1, :].tolist(), shrink=0.6)
    fig.savefig(a.output, dpi=110)
    print(a.output)


if __name__ == "__main__":
    main()
