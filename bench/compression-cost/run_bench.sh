#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: the cost study of Jha et al. (2021, §4.4, Fig. 24): the first STEPS
# (10,000) steps of examples/compression-502 (stage settle: grains in their rows,
# falling) with 25, 51, 96, 200 and 403 grains, on 1 and 2 ranks, at two
# resolutions: "paper" (h = 0.11 mm, eps = 0.6 mm = 5.5h: 230-250 nodes per grain,
# near the paper's 6515-82430 nodes) and "example" (the example's h = 0.2 mm,
# eps = 3h: about 75 nodes per grain). Prints a markdown table: nodes, bonds, the paper's
# DOF, loop time, node-steps/s (wall and CPU), the contact (Pair), bond and
# neighbour shares of the loop, and node-steps/s per core against the PeriDEM
# reference code's 7.9e4 node-steps/s on one thread (bench/two-disc).
# Usage: bench/compression-cost/run_bench.sh [build dir] [steps] [ranks] [resolutions] [grains]
#   e.g. run_bench.sh build 10000 "1 2" "paper example" "25 51 96 200 403"
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(realpath "${1:-$here/build}")"
steps="${2:-10000}"
ranks="${3:-1 2}"
resolutions="${4:-paper example}"
counts="${5:-25 51 96 200 403}"
source "$here/unittest/scripts/mpi_env.sh"
source "$here/bench/current_build.sh"
require_current_build "$build"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/examples/compression-502/in.compression" "$work/"
cd "$work"
declare -A paper_dof=([25]=13029 [51]=24405 [96]=42900 [200]=84744 [403]=164859)
echo "| resolution | grains | ranks | nodes | bonds | paper's DOF / 2 | loop (s) | node-steps/s (wall) | node-steps/s (CPU) | contact % | bonds % | neighbour % | other fixes % | per core vs reference |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for res in $resolutions; do
  case "$res" in
    paper) h=0.11e-3 ;;
    example) h=0.2e-3 ;;
    *) echo "unknown resolution $res (paper or example)" >&2; exit 1 ;;
  esac
  for n in $counts; do
    for np in $ranks; do
      mpirun -np "$np" "$build/lmp_peridem" -in in.compression -var stage settle \
        -var potentials "$here/potentials" -var count "$n" -var h "$h" -var horizon 0.6e-3 \
        -var t_settle "$(python3 -c "print($steps * 1e-7)")" -var thermo "$steps" -var every 0 \
        -var tag bench -log log.bench -screen none
      python3 - "$res" "$n" "$np" "$steps" "${paper_dof[$n]:-0}" log.bench <<'PY'
import re, sys
res, n, np_, steps, dof, path = sys.argv[1:]
log = open(path).read()
loop = re.search(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", log)
cpu = float(re.search(r"([\d.]+)% CPU use", log).group(1)) / 100
bonds = int(re.search(r"PERIDEM-SETUP stage settle \d+ nodes (\d+) bonds", log).group(1))
share = {m.group(1): float(m.group(2)) for m in
         re.finditer(r"^(\w+)\s+\|.*\|\s+([\d.]+)\s*$", log, re.M)}
t, nodes, nsteps = float(loop.group(1)), int(loop.group(4)), int(loop.group(3))
rate = nodes * nsteps / t
per_core = rate / (cpu * int(np_))
print(f"| {res} | {n} | {np_} | {nodes} | {bonds} | {int(dof) // 2} | {t:.1f} | {rate:.3g} | "
      f"{rate / cpu:.3g} | {share.get('Pair', 0):.0f} | {share.get('Bond', 0):.0f} | "
      f"{share.get('Neigh', 0):.0f} | {share.get('Modify', 0):.0f} | {per_core / 7.9e4:.1f}x |", flush=True)
PY
    done
  done
done
