#!/usr/bin/python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""Plot bulk damage and top-wall load against phi for
CSV files written by parse_output.py --csv.
usage: plot_runs.py OUT.png LABEL=FILE.csv [LABEL=FILE.csv ...]"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

fig, ax = plt.subplots(1, 2, figsize=(11, 4))
for arg in sys.argv[2:]:
    label, f = arg.split('=', 1)
    d = np.genfromtxt(f, delimiter=',', names=True)
    x = d['phi']
    ax[0].plot(x, d['bulk_damage'], label=label)
    ax[1].plot(x, d['top_reaction_y_Nm'] / 1e3, label=label)
ax[0].set_xlabel('phi (grain area / container area)'); ax[0].set_ylabel('bulk damage')
ax[1].set_xlabel('phi (grain area / container area)'); ax[1].set_ylabel('top wall load (kN/m)')
ax[0].legend(); ax[0].grid(alpha=.3); ax[1].grid(alpha=.3)
fig.tight_layout(); fig.savefig(sys.argv[1], dpi=110)
