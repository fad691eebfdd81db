#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Pictures of examples/cantilever.

    plot_cantilever.py beam cantilever.dump [-o cantilever_beam.png] [--magnify M]
    plot_cantilever.py convergence LOG... [-o cantilever_convergence.png]

*beam*: the nodes at rest, displaced M times (default: 10 % of L at the tip), coloured
by their deflection, with Timoshenko's deflected centre line scaled to the same tip
deflection (the shape of the beam theory; --H and --nu as in the run). *convergence*: D/D_T against
eps/H from the CANTILEVER lines of the logs (one series per dimension, model and load;
m = 3 without volume correction unless --all).
"""
import argparse
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))
from peridem_post import _pyplot, column, read_dump  # noqa: E402


def beam(args):
    plt = _pyplot()
    s = read_dump(args.files[0])[-1]
    x0, y0, z0 = (column(s, c) for c in ("c_ref[1]", "c_ref[2]", "c_ref[3]"))
    ux, uy = column(s, "v_ux"), column(s, "v_uy")
    front = z0 >= z0.max() - 1e-12  # 3d: the face z = H/2
    L = x0.max()
    mag = args.magnify or 0.1 * L / abs(uy.min())
    fig, ax = plt.subplots(figsize=(8, 2.6))
    sc = ax.scatter(x0[front] + mag * ux[front], y0[front] + mag * uy[front], c=uy[front] * 1e6,
                    s=4, cmap="viridis", linewidths=0)
    axis = (np.abs(y0) < 1e-9) & front & (x0 > 0)
    tip = uy[axis][np.argmax(x0[axis])]
    x = np.linspace(0, L, 200)
    wt = x**2 * (6 * L**2 - 4 * L * x + x**2) / 24 + (L * x - x**2 / 2) * args.H**2 * (1 + args.nu) / 5
    xt = x0[axis].max()
    wtip = xt**2 * (6 * L**2 - 4 * L * xt + xt**2) / 24 + (L * xt - xt**2 / 2) * args.H**2 * (1 + args.nu) / 5
    ax.plot(x, mag * tip * wt / wtip, "r--", lw=1, label="Timoshenko's shape")
    ax.legend(loc="lower left", fontsize=7)
    fig.colorbar(sc, ax=ax, label="deflection (um)", shrink=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"at rest, displacements x {mag:.0f}")
    fig.tight_layout()
    fig.savefig(args.output or "cantilever_beam.png", dpi=120)


LINE = re.compile(r"^CANTILEVER (.*)")


def convergence(args):
    plt = _pyplot()
    series = {}
    for path in args.files:
        for line in open(path):
            m = LINE.search(line)
            if not m:
                continue
            w = m.group(1).split()
            f = dict(zip(w[0::2], w[1::2]))
            key = (f["dim"], f["model"], f["m"], f.get("vc", "none"), f.get("load", "bending"))
            if not args.all and (key[2] != "3" or key[3] != "none"):
                continue
            series.setdefault(key, []).append((float(f["m"]) / float(f["n"]),
                                               float(f["timoshenko"])))
    fig, ax = plt.subplots(figsize=(6, 4))
    for key in sorted(series):
        pts = sorted(series[key])
        label = f"{key[0]}d {'bond-based' if key[1] == 'pmb' else 'state-based'}, {key[4]}"
        if key[2] != "3" or key[3] != "none":
            label += f", m = {key[2]}" + (f", vc {key[3]}" if key[3] != "none" else "")
        style = ("o-" if len(pts) > 1 else "o") if key[4] == "bending" else ("s--" if len(pts) > 1 else "s")
        ax.plot(*zip(*pts), style, label=label, ms=4)
    ax.axhline(1.0, color="k", lw=0.8)
    ax.set_xlabel("horizon / beam height (eps / H)")
    ax.set_ylabel("tip displacement / beam theory's")
    ax.set_xlim(left=0)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.output or "cantilever_convergence.png", dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=("beam", "convergence"))
    ap.add_argument("files", nargs="+")
    ap.add_argument("-o", "--output")
    ap.add_argument("--magnify", type=float, default=0.0)
    ap.add_argument("--all", action="store_true",
                    help="convergence: every m and volume correction (default: m = 3, none)")
    ap.add_argument("--H", type=float, default=0.01, help="beam height (beam)")
    ap.add_argument("--nu", type=float, default=1 / 3, help="Poisson ratio (beam; 3d: 1/4)")
    a = ap.parse_args()
    beam(a) if a.what == "beam" else convergence(a)
    return 0


if __name__ == "__main__":
    sys.exit(main())
