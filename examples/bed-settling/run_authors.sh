#!/bin/bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Table 3 at full scale with the authors' settings (debdeepbh/perigrain scripts/2d_bulk):
# 1490 grains in 50 mm x 100 mm, eps = 1 mm, h = eps/8, R_c = eps/5, dt = 0.2 us, g = 5000 m/s^2,
# no fracture, mu = r_d = 0.9 (its base.conf), one shape after the other on NP ranks.
#   run_authors.sh [LMP] [NP]      (SHAPES="plus ring" to run some; VARS="-var res 4" to add
#                                  variables; legs.txt: rc and wall time)
lmp="${1:-lmp_peridem}"
np="${2:-2}"
here="$(cd "$(dirname "$0")" && pwd)"
for s in ${SHAPES:-perturbed_disk square plus ring}; do
  start=$(date +%s)
  mpirun -np "$np" "$lmp" -in "$here/in.shapes" -var potentials "$here/../../potentials" \
    -var shape "$s" -var eps 1e-3 -var dt 2e-7 -var break no -var mu 0.9 -var rd 0.9 \
    -var chunk 2000 -var maxsteps 300000 -var dump yes ${VARS:-} -log "log.$s" > "out.$s" 2>&1
  echo "$s rc $? wall $(($(date +%s) - start)) s $(date)" >> legs.txt
done
