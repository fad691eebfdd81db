#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: pair_style peridem/contact in a bed of 500 disk grains (66,500+
# nodes, in.bed) settling under gravity in fix peridem/wall walls, on 1 and 2
# MPI ranks. Prints a markdown table for the README: time per step, the
# share of the contact pair style, the neighbour pairs it evaluates and its
# throughput (pair evaluations per second of pair time).
# Usage: bench/contact-bed/run_bench.sh [build dir] [repeats] [steps]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-3}"
steps="${3:-300}"
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
require_current_build "$build"
work="$(mktemp -d)"
cp "$here/bench/contact-bed/in.bed" "$work/"
cd "$work"

echo "| ranks | nodes | bonds | time/step | pair_style share | neighbour pairs (end) | pair evaluations/s |"
echo "|---|---|---|---|---|---|---|"
for np in 1 2; do
  best=""
  for _ in $(seq "$repeats"); do
    mpirun -np "$np" "$build/lmp_peridem" -in in.bed -var steps "$steps" -log log.bench -screen none
    # loop time, pair time (average over ranks), neighbour pairs, atoms, bonds
    line=$(awk '/^Loop time of/ {loop=$4} /^Pair +\|/ {pair=$5} /^Total # of neighbors/ {nb=$NF}
                /^Created .* peridem grains/ {atoms=$(NF-4); bonds=$(NF-2)}
                END {print loop, pair, nb, atoms, bonds}' log.bench)
    if [ -z "$best" ] || python3 -c "import sys; sys.exit(0 if ${line%% *} < ${best%% *} else 1)"; then
      best="$line"
    fi
  done
  python3 - "$np" "$steps" $best <<'PY'
import sys
np_, steps, loop, pair, nb, atoms, bonds = sys.argv[1:]
steps, loop, pair, nb = int(steps), float(loop), float(pair), int(nb)
print(f"| {np_} | {int(atoms):,} | {int(bonds):,} | {loop/steps*1e3:.2f} ms | {pair/loop*100:.1f} % "
      f"| {nb:,} | {nb*steps/pair:.3g} |")
PY
done
rm -rf "$work"
