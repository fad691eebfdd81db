#!/usr/bin/env python3
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""run_samples.py LABEL < perf script output (-F comm,time,ip,sym): the shares of the
samples from the run's first step (first sample in FixNVE::initial_integrate) to the end,
grouped by class (fix peridem/wall, the bond style, the pair style, LAMMPS's integration
fixes, neighbour builds, the rest)."""
import collections
import sys

GROUPS = [("walls", "FixPeridemWall"), ("bonds", "BondPeridem"), ("contact", "PairPeridemContact"),
          ("contact", "peridem::contact_force"), ("nve", "FixNVE"), ("gravity", "FixGravity"),
          ("enforce2d", "FixEnforce2D"), ("neighbour", "Neighbor"), ("neighbour", "NPair"),
          ("neighbour", "NTopo"), ("neighbour", "Domain::closest_image")]
rows = []
for line in sys.stdin:
    w = line.split(None, 3)
    if len(w) == 4:
        rows.append((float(w[1].rstrip(":")), w[3]))
start = next(t for t, s in rows if "FixNVE::initial_integrate" in s)
counts = collections.Counter()
n = 0
for t, s in rows:
    if t < start:
        continue
    n += 1
    counts[next((g for g, key in GROUPS if key in s), "other")] += 1
print(f"{sys.argv[1]}: {n} samples in the run; " +
      ", ".join(f"{g} {100 * c / n:.2f} %" for g, c in counts.most_common()))
