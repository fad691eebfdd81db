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
import collections
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def last_frame(path):
    """Rows of the last snapshot of a LAMMPS text dump."""
    rows, frame = [], None
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM: TIMESTEP"):
                frame = []
                rows = frame
            elif line.startswith("ITEM:"):
                continue
            elif frame is not None:
                frame.append(line.split())
    return rows


d = sys.argv[1] if len(sys.argv) > 1 else "."
# dump.nodes: a header block (timestep, number, box) then "id mol x y"
nodes = [r for r in last_frame(os.path.join(d, "dump.nodes")) if len(r) == 4]
grain = {int(r[0]): int(r[1]) for r in nodes}
xy = {int(r[0]): (float(r[2]), float(r[3])) for r in nodes}
sums = collections.defaultdict(lambda: [0.0, 0.0, 0])
for i, (x, y) in xy.items():
    s = sums[grain[i]]
    s[0] += x
    s[1] += y
    s[2] += 1
centre = {g: (s[0] / s[2], s[1] / s[2]) for g, s in sums.items()}

# dump.chains: "atom1 atom2 dist force" per node pair in the neighbour list
force = collections.defaultdict(float)
for r in last_frame(os.path.join(d, "dump.chains")):
    if len(r) != 4:
        continue
    a, b, f = int(r[0]), int(r[1]), float(r[3])
    if f > 0.0 and grain[a] != grain[b]:
        force[tuple(sorted((grain[a], grain[b])))] += f

fig, ax = plt.subplots(figsize=(5, 6))
ax.scatter([p[0] * 1e3 for p in xy.values()], [p[1] * 1e3 for p in xy.values()], s=1.5,
           color="0.75", linewidths=0)
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
