#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Draw the contact-force network of in.force_chains: grains as their nodes
(grey), and a line between the centres of every two touching grains, as
thick as the sum of the normal forces of their node pairs (compute
pair/local of pair_style peridem/contact). Reads dump.nodes and dump.chains,
writes force_chains.png (needs matplotlib).
usage: plot_chains.py [DIR]"""
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from peridem_post import column, grain_contact_loads, read_dump  # noqa: E402


d = sys.argv[1] if len(sys.argv) > 1 else "."
# the last snapshot of each dump: dump.nodes "id mol x y", dump.chains "atom1 atom2 dist
# force" per node pair in the neighbour list (pairs without a repulsive force are skipped)
nodes = read_dump(os.path.join(d, "dump.nodes"))[-1]
ids, mol = column(nodes, "id").astype(int), column(nodes, "mol").astype(int)
x, y = column(nodes, "x"), column(nodes, "y")
centre = {int(g): (x[mol == g].mean(), y[mol == g].mean()) for g in np.unique(mol)}
chains = read_dump(os.path.join(d, "dump.chains"))[-1]["data"]
force = grain_contact_loads(ids, mol, None if chains is None else chains[chains[:, -1] > 0.0])[0]

fig, ax = plt.subplots(figsize=(5, 6))
ax.scatter(x * 1e3, y * 1e3, s=1.5, color="0.75", linewidths=0)
fmean = sum(force.values()) / max(len(force), 1)
for (g, h), f in force.items():
    (x1, y1), (x2, y2) = centre[g], centre[h]
    ax.plot([x1 * 1e3, x2 * 1e3], [y1 * 1e3, y2 * 1e3], color="firebrick",
            linewidth=2.5 * f / fmean, solid_capstyle="round")
ax.set_aspect("equal")
ax.set_xlabel("x (mm)")
ax.set_ylabel("y (mm)")
ax.set_title("contact forces between grains (line width ~ force)", fontsize=9)
fig.tight_layout()
out = os.path.join(d, "force_chains.png")
fig.savefig(out, dpi=120)
print("%d grains, %d grain contacts, mean force %.3g: wrote %s" % (len(centre), len(force), fmean, out))
