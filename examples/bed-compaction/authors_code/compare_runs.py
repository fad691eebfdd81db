#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Bulk damage and top-wall load against phi, the columns of RESULTS.md, for
runs of in.authors_bed (its -var out file: step time top phi bulk_damage
broken_bonds load ke; or any file whose '#' header names the columns phi,
bulk_damage, broken_bonds, top_wall_load..., as ../shapes_reduced/*.txt) and of the authors' simulate2d (parse_output.py --csv).

usage: compare_runs.py LABEL=FILE[@SCALE] ... [--phi=0.5,0.55,...] [--first-break]

@SCALE multiplies the run's phi by SCALE (e.g. envelope.py's envelope/node
areas ratio, for phi_env).

Each cell is 'bulk damage / load in kN/m' at the saved row whose phi is
nearest to the column's phi (no interpolation; rows every 1000 steps = 0.05 mm
of wall travel, phi steps of 0.002-0.013), as RESULTS.md's table; '-' where
no row is within 0.01.
--first-break adds the phi of the first row with a broken bond.
"""
import sys
import numpy as np

phis = [0.50, 0.55, 0.60, 0.62, 0.65, 0.70, 0.76, 0.85, 0.90, 0.95, 0.974]
runs = []
first_break = False
for arg in sys.argv[1:]:
    if arg.startswith('--phi='):
        phis = [float(x) for x in arg[6:].split(',')]
    elif arg == '--first-break':
        first_break = True
    else:
        label, path = arg.split('=', 1)
        scale = 1.0
        if '@' in path:
            path, scale = path.rsplit('@', 1)
            scale = float(scale)
        runs.append((label, path, scale))


def read_run(path):
    """(phi, damage, broken fraction or count, load N/m) rows, one per step."""
    if path.endswith('.csv'):   # parse_output.py
        d = np.genfromtxt(path, delimiter=',', names=True)
        return d['phi'], d['bulk_damage'], d['broken_bond_frac'], d[d.dtype.names[7]]
    rows = {}
    names = None
    for line in open(path):
        if line.startswith('#') and names is None:
            names = line[1:].split()
            continue
        if line.startswith('#') or not line.strip():
            continue
        v = line.split()
        rows[int(float(v[0]))] = [float(x) for x in v]
    a = np.array([rows[k] for k in sorted(rows)])
    # our load is the force of the nodes on the wall (+ upward on the top wall's outward
    # normal: compressive load > 0); theirs (reaction, y) is the same sign convention
    col = {n: k for k, n in enumerate(names)}
    load_col = [k for k, n in enumerate(names) if n.startswith('top_wall_load')][0]
    return a[:, col['phi']], a[:, col['bulk_damage']], a[:, col['broken_bonds']], a[:, load_col]


hdr = '| run | ' + ' | '.join('%g' % p for p in phis) + ' |' + (' first broken bond at phi |' if first_break else '')
print(hdr)
print('|' + '---|' * (len(phis) + 1 + first_break))
for label, path, scale in runs:
    phi, dmg, brk, load = read_run(path)
    phi = phi * scale
    cells = []
    for p in phis:
        k = int(np.argmin(np.abs(phi - p)))
        if abs(phi[k] - p) > 0.01:
            cells.append('-')
            continue
        cells.append('%.3f / %.1f' % (dmg[k], load[k] / 1e3))
    line = '| %s | %s |' % (label, ' | '.join(cells))
    if first_break:
        k = np.nonzero(brk > 0)[0]
        line += ' %s |' % ('%.3f' % phi[k[0]] if len(k) else '-')
    print(line)
