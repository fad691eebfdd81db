#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: LAMMPS's examples/peri/in.peri.pmb (3487 nodes, horizon 3
# lattice spacings, 1000 steps, dumps off) with stock pair_style peri/pmb,
# and the same problem with bond_style peridem (examples/peri-impact), on 1
# and 2 MPI ranks, in one run, interleaved (stock, ours, opt, base, stock, ...),
# best of `repeats`. Prints a markdown table: time per step (wall time, and
# CPU time = wall x LAMMPS's "CPU use": the machine is shared; best, and the median CPU time
# over the repeats), speed-up,
# bond updates/s, ns per bond of the bond style's own time (Bond section),
# memory per node and per bond.
# Usage: bench/peri-pmb/run_bench.sh [build dir] [repeats]
# PERIDEM_BENCH_BASE: another build (e.g. /work/main/build), run side by side.
# PERIDEM_BENCH_OPT=1: this build with -sf opt too (bond_style peridem/opt), row "opt".
# PERIDEM_BENCH_RANKS (default "1 2"): the rank counts.
# PERIDEM_BENCH_STOCK, PERIDEM_BENCH_EXAMPLE (folder/input under examples/)
# and PERIDEM_BENCH_STYLES ("stock name|our name") select another pair of
# runs (bench/peri-lps/run_bench.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-3}"
base=${PERIDEM_BENCH_BASE:-}
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
require_current_build "$build"
[ -z "$base" ] || require_current_build "$(realpath "$base")"
stock_input=${PERIDEM_BENCH_STOCK:-/usr/share/lammps/examples/peri/in.peri.pmb}
example=${PERIDEM_BENCH_EXAMPLE:-peri-impact/in.peri_impact}
IFS='|' read -r stock_name our_name <<< "${PERIDEM_BENCH_STYLES:-peri/pmb|bond_style peridem}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/examples/$(dirname "$example")"/* "$work/"
cp "$stock_input" "$work/in.stock"
cp "$here/examples/$example" "$work/in.peridem"
cd "$work"

# one run: loop time, CPU fraction, Bond (or Pair for stock) section, memory (MB, max)
run_one() { # np build input [more lmp arguments]
  mpirun -np "$1" "$2/lmp_peridem" -in "$3" "${@:4}" -log log.bench -screen none
  awk '/^Loop time of/ {s += $4} /% CPU use/ {c = $1 + 0}
       /^Bond +\|/ {b += $5} /^Pair +\|/ {p += $5}
       /Per MPI rank memory allocation/ {m = $(NF-1)}
       END {print s, c / 100, (b > 0 ? b : p), m}' log.bench
}

bonds=$(mpirun -np 1 "$build/lmp_peridem" -in in.peridem -log log.bonds -screen none; \
        awk '/Added .* bonds/ {print $2}' log.bonds)
natoms=3487
steps=1000
runs=("stock|$build|in.stock|" "this|$build|in.peridem|")
[ "${PERIDEM_BENCH_OPT:-0}" = 1 ] && runs+=("opt|$build|in.peridem|-sf opt")
[ -n "$base" ] && runs+=("base|$(realpath "$base")|in.peridem|")
echo "| ranks | run | wall ms/step (best) | CPU ms/step | CPU ms/step (median) | speed-up vs stock (wall, CPU) | bond updates/s | ns/bond (bond time) | KiB/node | bytes/bond |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for np in ${PERIDEM_BENCH_RANKS:-1 2}; do
  declare -A best=() cpus=()
  for _ in $(seq "$repeats"); do
    for r in "${runs[@]}"; do
      IFS='|' read -r name bd input extra <<< "$r"
      read -r -a extra_args <<< "$extra"
      line=$(run_one "$np" "$bd" "$input" "${extra_args[@]}")
      cpus[$name]="${cpus[$name]:-} $(awk '{print $1 * $2}' <<< "$line")"
      if [ -z "${best[$name]:-}" ] || python3 -c "import sys; sys.exit(0 if ${line%% *} < ${best[$name]%% *} else 1)"; then
        best[$name]="$line"
      fi
    done
  done
  for r in "${runs[@]}"; do
    IFS='|' read -r name bd input extra <<< "$r"
    python3 - "$np" "$name" "$bonds" "$natoms" "$steps" "${cpus[$name]}" ${best[stock]} ${best[$name]} <<'PY'
import statistics, sys
np_, name, bonds, natoms, steps, cpus = sys.argv[1:7]
ts, cs, _, _ = map(float, sys.argv[7:11])
t, c, bt, mem = map(float, sys.argv[11:15])
bonds, natoms, steps, np_ = int(bonds), int(natoms), int(steps), int(np_)
med = statistics.median(map(float, cpus.split()))
kib = mem * np_ * 1024 / natoms
bpb = mem * np_ * 1024 * 1024 / bonds
print(f"| {np_} | {name} | {t/steps*1e3:.2f} | {t*c/steps*1e3:.2f} | {med/steps*1e3:.2f} | {ts/t:.2f}x, {ts*cs/(t*c):.2f}x | "
      f"{bonds*steps/t:.3g} | {bt/(bonds*steps)*np_*1e9:.2f} | {kib:.1f} | {bpb:.0f} |")
PY
  done
  unset best cpus
done
