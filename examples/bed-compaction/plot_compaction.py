# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Plot a run of in.compaction: the top wall load and the bulk damage against
the volume fraction phi (Bhattacharya & Lipton 2023, Fig. 14), and the nodes
of one dump coloured by Z (compute peridem/damage column 2: the largest
|s|/s0 of a node's bonds, 1 or more where a bond broke).
usage: python3 plot_compaction.py log.lammps out.png nodes.N.dump"""
import os
import sys

import matplotlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from peridem_post import read_thermo  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt

# thermo columns by name (in.compaction: Step Time v_lid c_bed ... c_dmg f_box[21] ...)
curve = read_thermo(sys.argv[1])
phi = [r["c_bed"] for r in curve]
load = [r["f_box[21]"] for r in curve]
damage = [r["c_dmg"] for r in curve]

lines = open(sys.argv[3]).read().split("\n")
head = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
cols = lines[head].split()[2:]
ix, iy, iz = cols.index("x"), cols.index("y"), cols.index("c_dmg[2]")
nodes = [l.split() for l in lines[head + 1:] if l.strip()]
x = [float(n[ix]) * 1e3 for n in nodes]
y = [float(n[iy]) * 1e3 for n in nodes]
z = [min(float(n[iz]), 1.0) for n in nodes]
# colour scale: up to 1 once bonds break, else up to the 99.5th percentile (force chains)
zmax = 1.0 if max(z) >= 1.0 else max(sorted(z)[int(0.995 * (len(z) - 1))], 1e-12)
step = lines[lines.index("ITEM: TIMESTEP") + 1].strip()

fig = plt.figure(figsize=(9, 6))
ax = fig.add_axes([0.05, 0.08, 0.42, 0.86])
sc = ax.scatter(x, y, c=z, s=0.4, cmap="inferno", vmin=0, vmax=zmax, linewidths=0)
ax.set_aspect("equal")
ax.set_xlabel("x (mm)")
ax.set_ylabel("y (mm)")
ax.set_title(f"step {step}: Z = max |s|/s0 (>= 1: a bond broke)", fontsize=9)
fig.colorbar(sc, ax=ax, fraction=0.05)
a1 = fig.add_axes([0.58, 0.56, 0.38, 0.38])
a1.plot(phi, load)
a1.set_ylabel("top wall load (N/m)")
a1.set_xlabel("volume fraction phi")
a2 = fig.add_axes([0.58, 0.08, 0.38, 0.38])
a2.plot(phi, damage)
a2.set_ylabel("bulk damage")
a2.set_xlabel("volume fraction phi")
fig.savefig(sys.argv[2], dpi=110)
print(f"{len(curve)} thermo rows, phi {phi[0]:.3f} to {phi[-1]:.3f}, "
      f"largest load {max(load):.1f} N/m, final bulk damage {damage[-1]:.3g}")
