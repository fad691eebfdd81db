#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Convert a setup file of the authors' simulate2d (debdeepbh/perigrain: the
all.h5 that make_setup.py writes) into a data file of atom_style peridem, so
that our package runs on THEIR bed: same nodes, node areas, grains and bonds.

usage: to_lammps_data.py SETUP.h5 OUT.data [--bonds file|none] [--info OUT.txt]
                         [--bed BED.txt]

Layout of their file (exp_dict.Experiment.save; read by their
src/read/load_hdf5.h): P_00001 ... P_%05d (total_particles_univ of them),
one group per grain, with Pos (N x 2, m), Vol (N x 1, node areas m^2),
Connectivity (pairs of node indices local to the grain, each bond once),
rho, cnot, snot, delta; pairwise/ (contact_radius, normal_stiffness,
damping_ratio, friction_coefficient: the last two are overridden by
base.conf's 0.9); wall/geom_wall_info (left, right, top, bottom).

The data file: one atom type, grain ID = the grain's index + 1, volume =
their Vol, density = their rho, x = x0 = their Pos.  --bonds file (the
default) writes their Connectivity as the Bonds section (type 1);
--bonds none writes no bonds (in.authors_bed then creates them from the
horizon, grain by grain).  The converter checks that their connectivity is
exactly the set of node pairs of one grain closer than the horizon, and
prints the container and the counts (also as 'key value' lines to --info,
which in.authors_bed does not need: it reads the numbers as variables).

--bed BED.txt also writes the grains as a bed file of create_peridem_bed's
format ("x y z radius angle label", angle in degrees), for re-meshing THEIR
grains with our lattice at the same places (in.authors_bed -var grains
lattice): centre = the area-weighted mean of the grain's nodes, radius = the
largest distance of a node from it (their polygons' circumradius: their
nodes lie on the outline), angle = the direction of that node minus 45
degrees (our square's corner in its own frame).  Squares (their 'n4') only:
the script stops if a grain is not a square (corner distances differ).

outline_lattice.py turns such a bed file into our lattice grains with nodes
on the outline.
"""
import argparse
import numpy as np
import h5py
from scipy.spatial import cKDTree

ap = argparse.ArgumentParser()
ap.add_argument('setup')
ap.add_argument('out')
ap.add_argument('--bonds', choices=['file', 'none'], default='file')
ap.add_argument('--info')
ap.add_argument('--bed')
a = ap.parse_args()

f = h5py.File(a.setup, 'r')
ngrains = int(np.ravel(f['total_particles_univ'])[0])
scalar = lambda g, k: float(np.ravel(g[k])[0])
left, right, top, bottom = np.ravel(f['wall/geom_wall_info'])
Rc = scalar(f, 'pairwise/contact_radius')
Kn = scalar(f, 'pairwise/normal_stiffness')

atoms = []   # (grain, vol, rho, x, y)
bed = []     # (x, y, radius, angle in degrees)
bonds = []   # (global i, global j), 1-based
offset = 0
c = s0 = eps = rho0 = None
n_horizon_lt = 0
n_mismatch = 0
for g in range(ngrains):
    G = f['P_%05d' % (g + 1)]
    pos = np.array(G['Pos'], dtype=float)
    vol = np.ravel(np.array(G['Vol'], dtype=float))
    conn = np.array(G['Connectivity']).astype(int).reshape(-1, 2)
    rho = scalar(G, 'rho')
    gc, gs, ge = scalar(G, 'cnot'), scalar(G, 'snot'), scalar(G, 'delta')
    if c is None:
        c, s0, eps, rho0 = gc, gs, ge, rho
    elif (gc, gs, ge, rho) != (c, s0, eps, rho0):
        raise SystemExit('grain %d has other constants than grain 1: this converter writes one bond type' % (g + 1))
    # their bonds against every pair of this grain closer than the horizon
    theirs = set(map(tuple, np.sort(conn, axis=1)))
    if len(theirs) != len(conn):
        raise SystemExit('grain %d: a bond listed twice' % (g + 1))
    within = {p for p in cKDTree(pos).query_pairs(eps) if np.linalg.norm(pos[p[0]] - pos[p[1]]) < eps}
    n_horizon_lt += len(within)
    n_mismatch += len(theirs ^ within)
    centre = (vol[:, None] * pos).sum(axis=0) / vol.sum()
    dist = np.linalg.norm(pos - centre, axis=1)
    k = int(np.argmax(dist))
    ang = np.degrees(np.arctan2(*(pos[k] - centre)[::-1]))
    # a square: four nodes at the circumradius, 90 degrees apart
    corners = [np.linalg.norm(pos - (centre + dist[k] * np.array([np.cos(np.radians(ang + 90 * q)),
                                                                  np.sin(np.radians(ang + 90 * q))])),
                              axis=1).min() for q in range(4)]
    bed.append((centre[0], centre[1], dist[k], (ang - 45.0) % 360.0, max(corners) / dist[k]))
    for i in range(len(pos)):
        atoms.append((g + 1, vol[i], rho, pos[i, 0], pos[i, 1]))
    for i, j in sorted(theirs):
        bonds.append((offset + i + 1, offset + j + 1))
    offset += len(pos)

atoms_a = np.array([(x, y) for _, _, _, x, y in atoms])
area = sum(v for _, v, _, _, _ in atoms)
# the box reaches R_c beyond every wall (a wall pushes a node back from up to R_c beyond its
# plane; doc/fix_peridem_wall.rst); the top wall only moves down
lo_x, hi_x, lo_y, hi_y = left - Rc, right + Rc, bottom - Rc, top + Rc
if atoms_a[:, 0].min() <= left or atoms_a[:, 0].max() >= right or \
   atoms_a[:, 1].min() <= bottom or atoms_a[:, 1].max() >= top:
    raise SystemExit('a node lies on or beyond a wall')
maxb = np.bincount(np.ravel(np.array(bonds)), minlength=len(atoms) + 1).max()

nb = len(bonds) if a.bonds == 'file' else 0
with open(a.out, 'w') as o:
    o.write('PERIDEM data file from %s (debdeepbh/perigrain setup): %d grains, %d nodes, '
            'their %d bonds %s\n\n' % (a.setup.split('/')[-1], ngrains, len(atoms), len(bonds),
                                       'in the Bonds section' if nb else 'left out (created from the horizon)'))
    o.write('%d atoms\n1 atom types\n%d bonds\n1 bond types\n\n' % (len(atoms), nb))
    o.write('%.10g %.10g xlo xhi\n%.10g %.10g ylo yhi\n-1e-4 1e-4 zlo zhi\n\n' % (lo_x, hi_x, lo_y, hi_y))
    o.write('Atoms # peridem\n\n')
    for k, (g, v, rho, x, y) in enumerate(atoms):
        o.write('%d %d 1 %.17g %.17g %.17g %.17g 0 %.17g %.17g 0\n' % (k + 1, g, v, rho, x, y, x, y))
    if nb:
        o.write('\nBonds\n\n')
        for k, (i, j) in enumerate(bonds):
            o.write('%d 1 %d %d\n' % (k + 1, i, j))

if a.bed:
    worst = max(b[4] for b in bed)
    if worst > 1e-6:
        raise SystemExit('--bed: a grain is not a square (a corner %.3g of the radius off)' % worst)
    with open(a.bed, 'w') as o:
        o.write('# the grains of %s: x y z circumradius angle(deg, our square frame) label\n'
                % a.setup.split('/')[-1])
        for x, y, r, ang, _ in bed:
            o.write('%.17g %.17g 0 %.17g %.10g square\n' % (x, y, r, ang))

info = [('grains', ngrains), ('nodes', len(atoms)), ('bonds', len(bonds)),
        ('pairs_within_horizon', n_horizon_lt), ('bonds_not_within_horizon_or_missing', n_mismatch),
        ('max_bonds_per_node', int(maxb)), ('node_area_sum', area),
        ('wall_left', left), ('wall_right', right), ('wall_top', top), ('wall_bottom', bottom),
        ('phi0', area / ((right - left) * (top - bottom))),
        ('c', c), ('s0', s0), ('horizon', eps), ('rho', rho0), ('Rc', Rc), ('Kn', Kn),
        ('top_node', atoms_a[:, 1].max()), ('gap_top', top - atoms_a[:, 1].max())]
for k, v in info:
    print('%s %.10g' % (k, v))
if a.info:
    with open(a.info, 'w') as o:
        for k, v in info:
            o.write('%s %.10g\n' % (k, v))
if n_mismatch:
    raise SystemExit('their bonds are not the pairs of one grain within the horizon (%d differ)' % n_mismatch)
