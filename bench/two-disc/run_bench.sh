#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: the two-disc drop (in.drop: 242 nodes, 20,000 steps, dt 3e-7 s)
# on 1 rank, best of `repeats`, interleaved with PERIDEM_BENCH_BASE (another
# build, e.g. /work/main/build) when given. Prints a markdown table: time
# per step (wall, and CPU = wall x LAMMPS's "CPU use": the machine is
# shared), node-steps/s (wall and CPU), bond updates/s, contact pair
# evaluations/s (neighbour pairs x steps / loop time), memory per node and
# per bond, and the ratio to the PeriDEM reference code's 7.9e4 node-steps/s
# on one thread (measured on this machine when the performance work began; the
# reference code is not built here).
# Usage: bench/two-disc/run_bench.sh [build dir] [repeats] [steps]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
repeats="${2:-5}"
steps="${3:-20000}"
base=${PERIDEM_BENCH_BASE:-}
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
require_current_build "$build"
[ -z "$base" ] || require_current_build "$(realpath "$base")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/bench/two-disc/in.drop" "$work/"
cd "$work"
builds=("this|$build")
[ -n "$base" ] && builds+=("base|$(realpath "$base")")
declare -A best=()
for _ in $(seq "$repeats"); do
  for b in "${builds[@]}"; do
    IFS='|' read -r name bd <<< "$b"
    mpirun -np 1 "$bd/lmp_peridem" -in in.drop -var potentials "$here/potentials" -var steps "$steps" \
      -log log.bench -screen none
    line=$(awk '/^Loop time of/ {l=$4; n=$(NF-1)} /% CPU use/ {c=$1/100}
                /^Total # of neighbors/ {p=$NF} /Per MPI rank memory allocation/ {m=$(NF-1)}
                /^ +[0-9]+ +[0-9]+ +[0-9]+ / {nb=$3} END {print l, c, n, p, m, nb}' log.bench)
    if [ -z "${best[$name]:-}" ] || python3 -c "import sys; sys.exit(0 if ${line%% *} < ${best[$name]%% *} else 1)"; then
      best[$name]="$line"
    fi
  done
done
echo "| build | nodes | bonds | us/step (wall, best) | us/step (CPU) | node-steps/s (wall) | node-steps/s (CPU) | bond updates/s | contact pairs/s | KiB/node | B/bond | x reference code (CPU) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for b in "${builds[@]}"; do
  IFS='|' read -r name bd <<< "$b"
  python3 - "$name" "$steps" ${best[$name]} <<'PY'
import sys
name, steps = sys.argv[1], int(sys.argv[2])
loop, cpu, nat, pairs, mem, nbond = map(float, sys.argv[3:])
ns, nsc = nat * steps / loop, nat * steps / (loop * cpu)
print(f"| {name} | {int(nat)} | {int(nbond)} | {loop/steps*1e6:.1f} | {loop*cpu/steps*1e6:.1f} | {ns:.3g} | {nsc:.3g} | "
      f"{nbond*steps/loop:.3g} | {pairs*steps/loop:.3g} | {mem*1024/nat:.1f} | {mem*1024*1024/nbond:.0f} | {nsc/7.9e4:.0f}x |")
PY
done
