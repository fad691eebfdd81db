#!/usr/bin/env bash
# Benchmark: LAMMPS's examples/peri/in.peri.pmb (3487 nodes, horizon 3
# lattice spacings, 1000 steps, dumps off) with stock pair_style peri/pmb,
# and the same problem with bond_style peridem (examples/peri-impact), on 1
# and 2 MPI ranks, in one run. Prints a markdown table for the README.
# Usage: bench/peri-pmb/run_bench.sh [build dir] [repeats]
# PERIDEM_BENCH_STOCK, PERIDEM_BENCH_EXAMPLE (folder/input under examples/)
# and PERIDEM_BENCH_STYLES ("stock name|our name") select another pair of
# runs (bench/peri-lps/run_bench.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-3}"
source "$here/unittest/scripts/mpi_env.sh"
stock_input=${PERIDEM_BENCH_STOCK:-/usr/share/lammps/examples/peri/in.peri.pmb}
example=${PERIDEM_BENCH_EXAMPLE:-peri-impact/in.peri_impact}
IFS='|' read -r stock_name our_name <<< "${PERIDEM_BENCH_STYLES:-peri/pmb|bond_style peridem}"
work="$(mktemp -d)"
cp "$here/examples/$(dirname "$example")"/* "$work/"
cp "$stock_input" "$work/in.stock"
cp "$here/examples/$example" "$work/in.peridem"
cd "$work"

# best of $repeats: loop time, memory per rank (MB, max), bonds (for ours)
measure() { # np input
  local best=1e30 mem=0
  for _ in $(seq "$repeats"); do
    mpirun -np "$1" "$build/lmp_peridem" -in "$2" -log log.bench -screen none
    local t
    t=$(awk '/^Loop time of/ {s += $4} END {print s}' log.bench) # all runs of the input
    best=$(python3 -c "print(min($best, $t))")
    mem=$(awk '/Per MPI rank memory allocation/ {print $(NF-1)}' log.bench | tail -n 1)
  done
  echo "$best $mem"
}

bonds=$(mpirun -np 1 "$build/lmp_peridem" -in in.peridem -log log.bonds -screen none; \
        awk '/Added .* bonds/ {print $2}' log.bonds)
natoms=3487
steps=1000
echo "| ranks | stock $stock_name: s/step | $our_name: s/step | speed-up | bond updates/s | memory/node (stock, ours) |"
echo "|---|---|---|---|---|---|"
for np in 1 2; do
  read -r ts ms < <(measure "$np" in.stock)
  read -r to mo < <(measure "$np" in.peridem)
  python3 - "$np" "$ts" "$to" "$ms" "$mo" "$bonds" "$natoms" "$steps" <<'PY'
import sys
np_, ts, to, ms, mo, bonds, natoms, steps = sys.argv[1:]
ts, to, ms, mo = float(ts), float(to), float(ms), float(mo)
bonds, natoms, steps, np_ = int(bonds), int(natoms), int(steps), int(np_)
per_node = lambda mb: mb * np_ * 1024 * 1024 / natoms / 1024
print(f"| {np_} | {ts/steps*1e3:.2f} ms | {to/steps*1e3:.2f} ms | {ts/to:.1f}x | "
      f"{bonds*steps/to:.3g} | {per_node(ms):.1f} KiB, {per_node(mo):.1f} KiB |")
PY
done
rm -rf "$work"
