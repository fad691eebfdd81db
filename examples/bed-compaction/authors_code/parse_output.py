#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Read a simulate2d run directory (output/hdf5/tc_*.h5, wall_*.h5,
plotinfo.h5; data/hdf5/all.h5) and print, per saved step: step, time
(both counted from the start of this run, also for a resumed run),
top wall position and displacement, phi = sum of node volumes / container
area, bulk damage as the authors define it (read_sim_output.py
'bulk_damage': mean over grains of the mean over nodes of the fraction of
the node's reference bonds lost), the fraction of bonds broken, the top
wall's reaction (N/m; their wall_*.h5 'reaction' rows are left, right,
top, bottom), and the largest node speed.

usage: parse_output.py RUNDIR [--csv OUT.csv] [--every K]
Also prints the Silling-Askari critical step of the setup:
dt_c = min_i sqrt(2 rho / sum_j V_j c/|xi_ij|).
"""
import sys, glob, os, argparse
import numpy as np
import h5py

ap = argparse.ArgumentParser()
ap.add_argument('run')
ap.add_argument('--csv')
ap.add_argument('--every', type=int, default=1)
a = ap.parse_args()

setup = h5py.File(os.path.join(a.run, 'data/hdf5/all.h5'), 'r')
n = int(np.ravel(setup['total_particles_univ'])[0])
ref = []
vol_total = 0.0
dtc = np.inf
nbonds = 0
nnodes = 0
for i in range(n):
    g = setup['P_%05d' % (i + 1)]
    pos = np.array(g['Pos']); vol = np.ravel(np.array(g['Vol']))
    conn = np.array(g['Connectivity']).astype(int)
    c = float(np.ravel(g['cnot'])[0]); rho = float(np.ravel(g['rho'])[0])
    N = len(pos)
    cnt = np.bincount(conn.ravel(), minlength=N) if len(conn) else np.zeros(N)
    ref.append((N, cnt))
    vol_total += vol.sum()
    nbonds += len(conn); nnodes += N
    if len(conn):
        xi = np.linalg.norm(pos[conn[:, 1]] - pos[conn[:, 0]], axis=1)
        k = np.zeros(N)
        np.add.at(k, conn[:, 0], vol[conn[:, 1]] * c / xi)
        np.add.at(k, conn[:, 1], vol[conn[:, 0]] * c / xi)
        k = k[k > 0]
        dtc = min(dtc, np.sqrt(2 * rho / k.max()))
print('# grains %d nodes %d bonds %d grain area %.4g m^2 c %.4g rho %g s0 %.4g dt_c(Silling-Askari) %.4g s'
      % (n, nnodes, nbonds, vol_total, c, rho, float(np.ravel(g['snot'])[0]), dtc))

pi = h5py.File(os.path.join(a.run, 'output/hdf5/plotinfo.h5'), 'r')
dt = float(np.ravel(pi['dt'])[0]); modulo = int(np.ravel(pi['modulo'])[0])
first = int(np.ravel(pi['f_l_counter'])[0])  # resume_ind + 1 for a resumed run
w0 = np.ravel(pi['wall/geom_wall_info'])
files = sorted(glob.glob(os.path.join(a.run, 'output/hdf5/tc_*.h5')))
rows = []
hdr = 'step time_s wall_top_m wall_disp_m phi bulk_damage broken_bond_frac top_reaction_y_N/m max_speed_m/s'
print(hdr)
for f in files[::a.every]:
    cnum = int(os.path.basename(f)[3:8])
    if cnum < first:
        continue  # the state a resumed run started from
    step = (cnum - first + 1) * modulo  # steps since this run started
    try:
        h = h5py.File(f, 'r')
        hw = h5py.File(f.replace('tc_', 'wall_'), 'r')
    except OSError:
        continue
    lrtb = np.ravel(hw['wall_info']); reac = np.array(hw['reaction'])
    dmg = []; alive = 0; vmax = 0.0
    for i in range(n):
        g = h['P_%05d' % i]
        conn = np.array(g['Connectivity']).astype(int)
        N, cnt0 = ref[i]
        cnt = np.bincount(conn.ravel(), minlength=N) if len(conn) else np.zeros(N)
        with np.errstate(invalid='ignore', divide='ignore'):
            d = (cnt0 - cnt) / cnt0
        dmg.append(np.nanmean(d)); alive += len(conn)
        vmax = max(vmax, float(np.max(np.linalg.norm(np.array(g['vel']), axis=1))))
    area = (lrtb[1] - lrtb[0]) * (lrtb[2] - lrtb[3])
    r = (step, step * dt, lrtb[2], w0[2] - lrtb[2], vol_total / area, float(np.mean(dmg)),
         1 - alive / nbonds, reac[2, 1], vmax)
    rows.append(r)
    print('%d %.4g %.5g %.4g %.4f %.4f %.4f %.4g %.4g' % r)
if a.csv:
    np.savetxt(a.csv, np.array(rows), header=hdr.replace(' ', ','), delimiter=',', comments='')
