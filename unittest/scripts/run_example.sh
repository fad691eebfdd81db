#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# run_example.sh LMP EXAMPLE_DIR INPUT OUT_DIR NP NP [NP...]
# Runs the example once per rank count, each in a fresh copy of the example
# directory, and requires the thermo output of every run to equal that of the
# first run (numerically, to 1e-9 relative, see thermo_compare.py).
# PERIDEM_EXAMPLE_ARGS (optional): more lmp arguments, e.g. "-var steps 100".
set -eu
lmp="$(realpath "$1")"; src="$2"; input="$3"; out="$4"; shift 4
source "$(dirname "$0")/mpi_env.sh"
here="$(cd "$(dirname "$0")" && pwd)"
logs=()
read -r -a extra <<< "${PERIDEM_EXAMPLE_ARGS:-}"
for np in "$@"; do
  dir="$out/np$np"
  rm -rf "$dir"; mkdir -p "$dir"
  cp -r "$src"/. "$dir"/
  (cd "$dir" && mpirun -np "$np" "$lmp" -in "$input" -var potentials "$here/../../potentials" -log log.lammps -echo none -screen none "${extra[@]}") || {
    echo "FAIL: $input on $np rank(s) exited with $?"; tail -n 30 "$dir/log.lammps"; exit 1; }
  logs+=("$dir/log.lammps")
done
python3 "$here/thermo_compare.py" "${logs[@]}"
