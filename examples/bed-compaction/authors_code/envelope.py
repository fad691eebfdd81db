#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""The contact envelope of the grains of a 2d data file (atom_style peridem):
what a bed's grains occupy for contact, against what phi counts.

usage: envelope.py Rc FILE.data [FILE.data ...]

Two nodes of different grains touch at distance R_c, so a grain reaches
contact where its nodes' convex hull, grown by R_c/2, meets another's.  Per
file: the sum of the node areas (what phi counts), the sum of the hull
areas, the sum of the envelopes (hull grown by R_c/2: A + P R_c/2 + pi
R_c^2/4, convex grains), and the ratio envelope/node areas, by which phi
is scaled into phi_env = sum of envelopes/container area (a constant per
bed while no grain breaks).  The grains are assumed convex.
"""
import sys
import numpy as np
from scipy.spatial import ConvexHull

Rc = float(sys.argv[1])
r = Rc / 2
print('| data file | grains | nodes | sum node areas (mm^2) | sum hulls (mm^2) | sum envelopes (mm^2) | envelope / node areas |')
print('|---|---|---|---|---|---|---|')
for path in sys.argv[2:]:
    lines = open(path).read().splitlines()
    k = [i for i, l in enumerate(lines) if l.startswith('Atoms')][0] + 2
    rows = []
    while k < len(lines) and lines[k].strip():
        rows.append([float(x) for x in lines[k].split()[:7]])
        k += 1
    a = np.array(rows)
    mol, vol, xy = a[:, 1].astype(int), a[:, 3], a[:, 5:7]
    hull = env = 0.0
    for g in np.unique(mol):
        h = ConvexHull(xy[mol == g])
        hull += h.volume                     # 2d: area
        env += h.volume + h.area * r + np.pi * r * r   # 2d: h.area is the perimeter
    print('| %s | %d | %d | %.4f | %.4f | %.4f | %.4f |' % (path.split('/')[-1], len(np.unique(mol)), len(a),
                                                        vol.sum() * 1e6, hull * 1e6, env * 1e6, env / vol.sum()))
