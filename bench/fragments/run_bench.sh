#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: the cost of compute peridem/fragments called every 100 steps
# in a settling bed of 103,572 nodes (in.fragments_bed), on 1 and 2 MPI
# ranks. Each repeat runs the bed without and with c_frag in the thermo
# output (every 100 steps) side by side; prints per rank count the median
# over repeats of the Output time (where LAMMPS times thermo computes) per
# fragment call, its share of the loop time, and the loop-time ratio.
# Usage: bench/fragments/run_bench.sh [build dir] [repeats] [steps]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-3}"
steps="${3:-300}"
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
require_current_build "$build"
work="$(mktemp -d)"
cp "$here/bench/fragments/in.fragments_bed" "$work/"
cd "$work"

echo "| ranks | nodes | steps | Output per fragment call | Output share with c_frag | without | loop time ratio |"
echo "|---|---|---|---|---|---|---|"
for np in 1 2; do
  rows=()
  for _ in $(seq "$repeats"); do
    for out in none c_frag; do
      mpirun -np "$np" "$build/lmp_peridem" -in in.fragments_bed -var steps "$steps" \
        -var out "$([ $out = none ] && echo '' || echo c_frag)" -log "log.$out" -screen none
    done
    rows+=("$(awk '/^Loop time of/ {loop=$4} /^Output +\|/ {out=$5} END {printf "%s %s ", loop, out}' log.none)$(awk '/^Loop time of/ {loop=$4} /^Output +\|/ {out=$5} /atoms, .* bonds added/ {atoms=$(NF-4)} END {print loop, out, atoms}' log.c_frag)")
  done
  python3 - "$np" "$steps" "${rows[@]}" <<'PY'
import statistics, sys
np_, steps = sys.argv[1], int(sys.argv[2])
rows = [list(map(float, r.split())) for r in sys.argv[3:]]
calls = steps // 100  # thermo every 100 steps; the call at step 0 is in the setup
med = lambda k: statistics.median(k)
per_call = med([(r[3] - r[1]) / calls for r in rows])
share = med([r[3] / r[2] * 100 for r in rows])
base = med([r[1] / r[0] * 100 for r in rows])
ratio = med([r[2] / r[0] for r in rows])
print(f"| {np_} | {int(rows[0][4]):,} | {steps} | {per_call*1e3:.1f} ms | {share:.2f} % | {base:.2f} % | {ratio:.3f} |")
PY
done
rm -rf "$work"
