#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: fracture-heavy runs beside quiet runs of the same size (issue 33), on 1 rank,
# interleaved, best of `repeats`:
#   kw       examples/kalthoff-winkler (h = 1 mm): the plate struck at 32 m/s / the same with
#            bonds that cannot break (Gc 1e12) / not struck (v 0)
#   notch    examples/notch-fracture (m = 5): the notched grain struck / the same with
#            bonds that cannot break (Gc 1e12)
#   bed      bench/fracture/in.crush: 40 grains (2950 nodes) crushed by a lid at 20 m/s /
#            the same lid with bonds that cannot break (Gc 1e12) / the lid at rest
# Prints per run: ns per bond-step of the bond style's own time (Bond section over the mean
# bond count and the steps), ms per step, the shares of Bond, Pair, Neigh, Modify, Comm and
# Output in the loop, neighbour builds, bonds broken, and builds per broken bond.
# The bonds that cannot break give the quiet run of the same size and load; the run at rest
# the quietest.
# Usage: bench/fracture/run_bench.sh [build dir] [repeats] [steps]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-3}"
steps="${3:-2000}"
# the bond styles' vectorised variant (bond_style peridem/opt), as the figures in README.md;
# PERIDEM_BENCH_SUFFIX="" times the portable plain style
suffix="${PERIDEM_BENCH_SUFFIX--sf opt}"
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
source "$here/bench/fracture/timing.sh"
require_current_build "$build"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp -r "$here/examples/kalthoff-winkler" "$here/examples/notch-fracture" "$work/"
mkdir -p "$work/crush" && cp "$here/bench/fracture/in.crush" "$work/crush/"

# name|folder|input|time step of the input (steps: the input takes -var steps)|variables
cases=(
  "kw struck|kalthoff-winkler|in.kalthoff_winkler|1.8e-7|-var v 32"
  "kw struck, unbreakable|kalthoff-winkler|in.kalthoff_winkler|1.8e-7|-var v 32 -var Gc 1e12"
  "kw quiet|kalthoff-winkler|in.kalthoff_winkler|1.8e-7|-var v 0"
  "notch struck|notch-fracture|in.notch_fracture|1.5e-8|"
  "notch quiet|notch-fracture|in.notch_fracture|1.5e-8|-var Gc 1e12"
  "bed crushed|crush|in.crush|steps|-var vlid -20"
  "bed crushed, unbreakable|crush|in.crush|steps|-var vlid -20 -var Gc 1e12"
  "bed held|crush|in.crush|steps|-var vlid 0"
)

# one run of $steps steps (the example included by a wrapper that prints the bond count at the end)
run_one() { # folder input dt vars
  local dir="$work/$1"
  printf 'variable b0 equal 0\ninclude %s\nprint "BENCH-BONDS $(bonds)"\n' "$2" >"$dir/in.bench"
  local length="-var steps $steps"
  [ "$3" = steps ] || length="-var time $(awk -v s="$steps" -v dt="$3" 'BEGIN {printf "%.10g", s * dt}')"
  (cd "$dir" && mpirun -np 1 "$build/lmp_peridem" $suffix -in in.bench $4 -var potentials "$here/potentials" \
     $length -log log.bench -screen none >/dev/null 2>&1)
  log_timing "$dir/log.bench"
}
echo "steps $steps, best of $repeats, $(date -u +%F), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
table_header
best=()
for r in $(seq "$repeats"); do # interleaved: each repeat runs every case once
  for i in "${!cases[@]}"; do
    IFS='|' read -r name folder input dt vars <<< "${cases[$i]}"
    best[i]=$(best_of "${best[i]:-}" "$(run_one "$folder" "$input" "$dt" "$vars")")
  done
done
for i in "${!cases[@]}"; do table_row "${cases[$i]%%|*}" "$steps" "${best[i]}"; done
