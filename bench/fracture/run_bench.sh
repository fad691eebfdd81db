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
#   kw       examples/kalthoff-winkler (h = 1 mm): the plate struck at 32 m/s / not struck (v 0)
#   notch    examples/notch-fracture (m = 5): the notched grain struck / the same with
#            bonds that cannot break (Gc 1e12)
#   bed      bench/fracture/in.crush: 40 grains (2950 nodes) crushed by a lid at 20 m/s /
#            the lid at rest
# Prints per run: ns per bond-step of the bond style's own time (Bond section over the mean
# bond count and the steps), ms per step, the shares of Bond, Pair, Neigh, Modify, Comm and
# Output in the loop, neighbour builds, bonds broken, and builds per broken bond.
# Usage: bench/fracture/run_bench.sh [build dir] [repeats] [steps]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-3}"
steps="${3:-2000}"
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
require_current_build "$build"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp -r "$here/examples/kalthoff-winkler" "$here/examples/notch-fracture" "$work/"
mkdir -p "$work/crush" && cp "$here/bench/fracture/in.crush" "$work/crush/"

# name|folder|input|variables
# name|folder|input|time step of the input (steps: the input takes -var steps)|variables
cases=(
  "kw struck|kalthoff-winkler|in.kalthoff_winkler|1.8e-7|-var v 32"
  "kw quiet|kalthoff-winkler|in.kalthoff_winkler|1.8e-7|-var v 0"
  "notch struck|notch-fracture|in.notch_fracture|1.5e-8|"
  "notch quiet|notch-fracture|in.notch_fracture|1.5e-8|-var Gc 1e12"
  "bed crushed|crush|in.crush|steps|-var vlid -20"
  "bed held|crush|in.crush|steps|-var vlid 0"
)

# one run of $steps steps (the example included by a wrapper that prints the bond counts):
# loop time, Bond Pair Neigh Comm Modify Output times, builds, bonds at the start and the end
run_one() { # folder input dt vars
  local dir="$work/$1"
  printf 'variable b0 equal 0\ninclude %s\nprint "BENCH-BONDS $(bonds)"\n' "$2" >"$dir/in.bench"
  local length="-var steps $steps"
  [ "$3" = steps ] || length="-var time $(awk -v s="$steps" -v dt="$3" 'BEGIN {printf "%.10g", s * dt}')"
  (cd "$dir" && mpirun -np 1 "$build/lmp_peridem" -in in.bench $4 -var potentials "$here/potentials" \
     $length -log log.bench -screen none >/dev/null 2>&1)
  awk '/^Loop time of/ && $9 + 0 > nsteps {loop = $4; nsteps = $9 + 0}
       /^Bond +\|/ && !b {b = $5} /^Pair +\|/ && !p {p = $5} /^Neigh +\|/ && !n {n = $5}
       /^Comm +\|/ && !c {c = $5} /^Modify +\|/ && !m {m = $5} /^Output +\|/ && !o {o = $5}
       /Neighbor list builds/ && !builds {builds = $5}
       /bonds added/ {b0 += $(NF-2)} /^BENCH-BONDS/ {b1 = $2}
       END {print loop, b, p, n, c, m, o, builds, b0, b1}' "$dir/log.bench"
}
echo "steps $steps, best of $repeats, $(date -u +%F), $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
echo "| run | ns/bond-step (Bond) | ms/step | Bond % | Pair % | Neigh % | Modify % | Comm % | Output % | builds | broken bonds | builds per break |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  IFS='|' read -r name folder input dt vars <<< "$c"
  best=""
  for r in $(seq "$repeats"); do
    line=$(run_one "$folder" "$input" "$dt" "$vars")
    loop=${line%% *}
    if [ -z "$best" ] || awk -v a="$loop" -v b="${best%% *}" 'BEGIN {exit !(a < b)}'; then best="$line"; fi
  done
  echo "$name|$best" | awk -F'|' -v steps="$steps" '{
    split($2, t, " "); loop = t[1]; bondt = t[2]; b0 = t[9]; broken = t[9] - t[10]
    mean = b0 - broken / 2
    printf "| %s | %.2f | %.3f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %d | %d | %s |\n", $1,
      1e9 * bondt / (mean * steps), 1e3 * loop / steps, 100 * bondt / loop, 100 * t[3] / loop,
      100 * t[4] / loop, 100 * t[6] / loop, 100 * t[5] / loop, 100 * t[7] / loop, t[8], broken,
      (broken > 0 ? sprintf("%.3f", t[8] / broken) : "-") }'
done
