#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Force per unit area on the top wall against its penetration for several runs of
in.compression, beside Jha et al.'s (2021) Fig. 23a, and their table.

    plot_lattice_gmsh.py OUT.png LABEL=RUN_DIR/TAG:W [LABEL=RUN_DIR/TAG:W ...]

Reads RUN_DIR/TAG_compress_load.*.txt of each run (W: the container's width in m, which
turns the load per unit length into a force per unit area). Penetration is counted from
where the averaged load first exceeds 1 kPa, as in plot_compression.py. Prints, for each
run, the force per unit area, the bulk damage and the broken bonds at the paper's four
penetrations.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_compression import ONSET, PAPER, PAPER_TIMES, load_curve  # noqa: E402


def curve(spec):
    label, rest = spec.split("=", 1)
    path, width = rest.rsplit(":", 1)
    d = load_curve(os.path.dirname(path) or ".", os.path.basename(path))
    stress = d[:, 1] / float(width)  # Pa
    k = int(np.argmax(stress > ONSET))
    if stress[k] <= ONSET:
        raise SystemExit(f"{spec}: the load never exceeds {ONSET} Pa")
    pen = (d[k, 3] - d[:, 3]) * 1e3  # mm, the wall's travel since the onset
    return label, pen[k:], stress[k:] / 1e3, d[k:, 4], d[k:, 5]


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(PAPER[:, 0], PAPER[:, 1], "k--", lw=1.2, label="Jha et al. 2021, Fig. 23a (by eye)")
    ax.plot(PAPER_TIMES[:, 0], PAPER_TIMES[:, 1], "ko", mfc="none")
    print("| run | " + " | ".join(f"{p:.2f} mm" for p in PAPER_TIMES[:, 0]) + " |")
    print("|---|" + "---|" * len(PAPER_TIMES))
    print("| paper (kPa) | " + " | ".join(f"{s:.0f}" for s in PAPER_TIMES[:, 1]) + " |")
    for spec in sys.argv[2:]:
        label, pen, kpa, dmg, broken = curve(spec)
        ax.plot(pen, kpa, lw=1.2, label=label)
        cells = []
        for p in PAPER_TIMES[:, 0]:
            if pen.max() < p:
                cells.append("-")
                continue
            j = int(np.argmin(abs(pen - p)))
            cells.append(f"{kpa[j]:.1f} kPa, {dmg[j]:.4f}, {int(broken[j])}")
        print(f"| {label} | " + " | ".join(cells) + " |")
    ax.set_xlabel("penetration of the top wall (mm)")
    ax.set_ylabel("force per unit area (kPa)")
    ax.set_xlim(0, 3.5)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=120)


if __name__ == "__main__":
    main()
