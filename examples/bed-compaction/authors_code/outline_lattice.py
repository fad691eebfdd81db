#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Square grains of a bed file on our lattice with the outermost nodes ON the
outline, as the authors' gmsh nodes are (our lattice grains put a node at the
centre, so their outermost nodes lie up to a spacing inside the outline).

usage: outline_lattice.py BED.txt RES OUT.in [--eps 5e-4] [--rho 960] [--Rc 1.25e-4]

BED.txt: a bed file ("x y z radius angle label", angle in degrees: our
square's frame, corner at 45 degrees), from create_peridem_bed (radius =
security disk = the square's circumradius with fit enclosing) or from
to_lammps_data.py --bed.  OUT.in gets one create_peridem_grains command per
square line: spacing h_g = s/(2 m), m = round(s/(2 eps/RES)), s = sqrt(2)
radius the side, the side made 1e-9 larger so that the nodes on the outline
are kept, volume exact (cells clipped to the square: the areas of a grain
sum to its area), horizon eps, density rho.  Read it with in.authors_bed
-var grains outline -var include OUT.in.  Prints the range of h_g and the
top wall position 1.01 R_c above the highest corner (in.compaction's lid
rule).
"""
import argparse
import numpy as np

ap = argparse.ArgumentParser()
ap.add_argument('bed')
ap.add_argument('res', type=float)
ap.add_argument('out')
ap.add_argument('--eps', type=float, default=5e-4)
ap.add_argument('--rho', type=float, default=960.0)
ap.add_argument('--Rc', type=float, default=1.25e-4)
a = ap.parse_args()

hs, tops = [], []
with open(a.out, 'w') as o:
    o.write('# %s on a lattice with nodes on the outline, h about eps/%g (outline_lattice.py)\n'
            % (a.bed.split('/')[-1], a.res))
    for line in open(a.bed):
        if line.startswith('#') or not line.strip():
            continue
        v = line.split()
        if len(v) > 5 and v[5] != 'square':
            raise SystemExit('only squares: line with label %s' % v[5])
        x, y, r, ang = float(v[0]), float(v[1]), float(v[3]), float(v[4])
        side = np.sqrt(2.0) * r
        m = max(1, int(round(side / (2 * a.eps / a.res))))
        h = side / (2 * m)
        hs.append(h)
        tops.append(y + r * max(np.sin(np.radians(ang + 45 + 90 * k)) for k in range(4)))
        o.write('create_peridem_grains 1 square side %.17g spacing %.17g horizon %.17g density %.17g '
                'volume exact at %.17g %.17g 0 rotate %.10g\n' % (side * (1 + 1e-9), h, a.eps, a.rho, x, y, ang))
print('grains %d, h from %.4g to %.4g m (eps/%.3g to eps/%.3g), highest corner %.10g, lid %.10g'
      % (len(hs), min(hs), max(hs), a.eps / min(hs), a.eps / max(hs), max(tops), max(tops) + 1.01 * a.Rc))
