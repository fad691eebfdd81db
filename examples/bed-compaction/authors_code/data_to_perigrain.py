#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""The reverse of to_lammps_data.py: a 2d bed of ours (a data file written by
write_data of atom_style peridem, e.g. in.authors_bed -var write_bed yes) as
a setup file of the authors' simulate2d (debdeepbh/perigrain all.h5), so that
THEIR code runs on OUR mesh of the same grains.

usage: data_to_perigrain.py TEMPLATE.h5 BED.data OUT.h5

Everything but the grains is copied from TEMPLATE.h5 (one of their setup
files: contact constants, wall, and each grain's cnot, snot, rho, delta,
flags), so the constants stay theirs; per grain (molecule ID, in order)
Pos = x0, Vol = the node volumes, Connectivity = the data file's bonds
(node indices local to the grain, each bond once), zero disp/vel/acc/
extforce, bdry_nodes/bdry_edges = the convex hull's nodes and edges (their
code reads them only with nl_bdry_only = 1).  The number of grains must
equal the template's.
"""
import sys
import numpy as np
import h5py
from scipy.spatial import ConvexHull

template, data, out = sys.argv[1:4]
lines = open(data).read().splitlines()


def section(name, ncols):
    k = [i for i, l in enumerate(lines) if l.split('#')[0].strip() == name]
    if not k:
        return np.zeros((0, ncols))
    k = k[0] + 2
    rows = []
    while k < len(lines) and lines[k].strip():
        rows.append([float(x) for x in lines[k].split()[:ncols]])
        k += 1
    return np.array(rows)


atoms = section('Atoms', 11)      # id mol type vol density x y z x0 y0 z0
bonds = section('Bonds', 4)       # id type i j
atoms = atoms[np.argsort(atoms[:, 0])]
ids = atoms[:, 0].astype(int)
mol = atoms[:, 1].astype(int)
grains = np.unique(mol)
t = h5py.File(template, 'r')
n = int(np.ravel(t['total_particles_univ'])[0])
if len(grains) != n:
    raise SystemExit('%d grains in %s, %d in the template' % (len(grains), data, n))
# local index of each atom within its grain
local = {}
members = {}
for g in grains:
    sel = ids[mol == g]
    members[g] = np.nonzero(mol == g)[0]
    for k, i in enumerate(sel):
        local[i] = (g, k)

with h5py.File(out, 'w') as o:
    for key in t.keys():
        if not key.startswith('P_'):
            t.copy(key, o)
    nb = 0
    for gi, g in enumerate(grains):
        name = 'P_%05d' % (gi + 1)
        tg = t[name]
        G = o.create_group(name)
        for key in ('breakable', 'clamped_nodes', 'cnot', 'delta', 'movable', 'rho', 'snot',
                    'stoppable', 'torque_axis', 'torque_val'):
            tg.copy(key, G)
        rows = members[g]
        pos = atoms[rows][:, 8:10]
        N = len(pos)
        G.create_dataset('Pos', data=pos.astype(np.float64))
        G.create_dataset('Vol', data=atoms[rows][:, 3].reshape(-1, 1).astype(np.float64))
        for key in ('disp', 'vel', 'acc', 'extforce'):
            G.create_dataset(key, data=np.zeros((N, 2)))
        conn = []
        for b in bonds:
            gi1, k1 = local[int(b[2])]
            gi2, k2 = local[int(b[3])]
            if gi1 != g and gi2 != g:
                continue
            if gi1 != gi2:
                raise SystemExit('bond %d joins two grains' % int(b[0]))
            conn.append((min(k1, k2), max(k1, k2)))
        conn = np.array(sorted(conn), dtype=np.int64).reshape(-1, 2)
        nb += len(conn)
        G.create_dataset('Connectivity', data=conn)
        hull = ConvexHull(pos).vertices
        G.create_dataset('bdry_nodes', data=np.array(hull, dtype=np.int64).reshape(-1, 1))
        G.create_dataset('bdry_edges', data=np.array([(hull[k], hull[(k + 1) % len(hull)])
                                                      for k in range(len(hull))], dtype=np.uint64))
print('%s: %d grains, %d nodes, %d bonds (data file: %d)' % (out, len(grains), len(atoms), nb, len(bonds)))
