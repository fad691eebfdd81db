#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# damaged_restart_test.sh LMP INPUTS POTENTIALS WORKDIR FIELD VALUE REGEX: writes the restart
# file of INPUTS/make.in in WORKDIR, changes one value of atom 1 (damage_restart.py FIELD
# VALUE) and passes when reading it back (INPUTS/read.in) stops with an ERROR line matching
# REGEX, a non-zero exit and no crash (expect_error.sh); also that the undamaged file reads
# and runs, so that the error comes from the damage.
set -eu
lmp="$1"; inputs="$2"; potentials="$3"; work="$4"; field="$5"; value="$6"; regex="$7"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$work"
cd "$work"
"$lmp" -in "$inputs/make.in" -log none -echo none -var potentials "$potentials" \
  -var file made >/dev/null
"$here/expect_pass.sh" "$lmp" -in "$inputs/read.in" -log none -echo none \
  -var file made.restart >/dev/null
read -r x0 y0 z0 <made.pos
python3 "$here/damage_restart.py" made.restart damaged.restart "$x0" "$y0" "$z0" "$field" "$value"
exec "$here/expect_error.sh" "$regex" timeout 120 "$lmp" -in "$inputs/read.in" -log none \
  -echo none -var file damaged.restart
