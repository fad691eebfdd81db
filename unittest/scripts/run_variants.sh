#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# run_variants.sh LMP EXAMPLE_DIR INPUT OUT_DIR "COMMON ARGS" "NP [ARGS]"...
# Runs the example once per variant (a rank count and more lmp arguments),
# each in a fresh copy of the example directory, and requires the thermo
# output of every run to equal that of the first (thermo_compare.py; more options of it in
# PERIDEM_THERMO_COMPARE_ARGS).
set -eu
lmp="$(realpath "$1")"; src="$2"; input="$3"; out="$4"; read -r -a common <<< "$5"; shift 5
source "$(dirname "$0")/mpi_env.sh"
here="$(cd "$(dirname "$0")" && pwd)"
logs=()
k=0
for variant in "$@"; do
  read -r -a words <<< "$variant"
  np="${words[0]}"; extra=("${words[@]:1}")
  dir="$out/run$k"; k=$((k + 1))
  rm -rf "$dir"; mkdir -p "$dir"
  cp -r "$src"/. "$dir"/
  (cd "$dir" && mpirun -np "$np" "$lmp" -in "$input" -var potentials "$here/../../potentials" \
     -log log.lammps -echo none -screen none "${common[@]}" "${extra[@]}") || {
    echo "FAIL: $input on $variant exited with $?"; tail -n 30 "$dir/log.lammps"; exit 1; }
  echo "ran: np $variant"
  logs+=("$dir/log.lammps")
done
read -r -a compare_args <<< "${PERIDEM_THERMO_COMPARE_ARGS:-}"
python3 "$here/thermo_compare.py" "${compare_args[@]}" "${logs[@]}"
