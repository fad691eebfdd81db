# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Draw a create_peridem_bed file: security disks coloured by label, or with
a dump of the grains (id mol type x y) their nodes inside the disk outlines.
usage: python3 plot_bed.py bed.txt out.png [grains.dump]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import Circle, Rectangle

bed, rows, header = None, [], []
for line in open(sys.argv[1]):
    if line.startswith("# bed "):
        bed = [float(v) for v in line.split()[2:]]
    if line.startswith("#"):
        header.append(line[2:].strip())
        continue
    w = line.split()
    if w:
        rows.append((float(w[0]), float(w[1]), float(w[3]), w[5]))
labels = sorted({r[3] for r in rows})
colours = dict(zip(labels, plt.cm.tab10.colors))
w, h = bed[1] - bed[0], bed[3] - bed[2]
fig, ax = plt.subplots(figsize=(4, 4 * h / w + 0.6))
nodes = None
if len(sys.argv) > 3:
    lines = open(sys.argv[3]).read().split("\n")
    start = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS"))) + 1
    nodes = [l.split() for l in lines[start:] if l.strip()]
for x, y, r, lab in rows:
    if nodes is None:
        ax.add_patch(Circle((x, y), r, color=colours[lab], lw=0))
    else:
        ax.add_patch(Circle((x, y), r, fill=False, lw=0.4, color="0.5"))
if nodes is not None:
    ax.scatter([float(n[3]) for n in nodes], [float(n[4]) for n in nodes], s=1.0, lw=0,
               c=[plt.cm.tab10.colors[int(n[2]) - 1] for n in nodes])
ax.add_patch(Rectangle((bed[0], bed[2]), w, h, fill=False, lw=1))
pad = 0.01 * max(w, h)
ax.set_xlim(bed[0] - pad, bed[1] + pad)
ax.set_ylim(bed[2] - pad, bed[3] + pad)
ax.set_aspect("equal")
ax.set_title(f"{len(rows)} disks ({', '.join(labels)}); " + header[2].split(";")[0], fontsize=7)
fig.savefig(sys.argv[2], dpi=110, bbox_inches="tight")
