#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# near_list_compare.sh NP LMP INPUT ARGS...: run INPUT (examples/bed-settling/in.bed) on NP MPI
# ranks with fix peridem/wall's near_list yes and no; the thermo tables must agree to the last
# printed digit, the final PERIDEM- line (kinetic energy to 15 digits) must be the same, and
# the walls must carry a load (thermo column f_box[15] non-zero), or the comparison proves
# nothing.
set -e
run="$(dirname "$0")"
np="$1"; lmp="$2"; input="$3"; shift 3
for near in yes no; do
  "$run/mpirun.sh" "$np" "$lmp" -in "$input" -echo none -log "near_${near}.log" \
    -screen "near_${near}.out" "$@" -var near_list "$near"
  grep PERIDEM- "near_${near}.out" > "near_${near}.end"
done
cat near_yes.end
cmp near_yes.end near_no.end
python3 "$run/thermo_compare.py" near_no.log near_yes.log --rtol 0 --atol 0
python3 - <<'PY'
import sys
load = 0.0
with open("near_yes.log") as f:
    header = None
    for line in f:
        w = line.split()
        if w[:1] == ["Step"]:
            header = w
        elif header and len(w) == len(header) and w[0].isdigit():
            load = max(load, abs(float(w[header.index("f_box[15]")])))
print(f"largest f_box[15] {load}")
sys.exit(0 if load > 0 else 1)
PY
echo PERIDEM-NEAR-LIST-SAME
