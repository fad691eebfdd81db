#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Benchmark: LAMMPS's examples/peri/in.peri.lps (3487 nodes, horizon 3
# lattice spacings, 1000 steps) with stock pair_style peri/lps, and the same
# problem with bond_style peridem/lps (examples/peri-lps-impact), on 1 and 2
# MPI ranks, in one run (bench/peri-pmb/run_bench.sh does the work).
# Usage: bench/peri-lps/run_bench.sh [build dir] [repeats]
here="$(cd "$(dirname "$0")/../.." && pwd)"
PERIDEM_BENCH_STOCK=/usr/share/lammps/examples/peri/in.peri.lps \
PERIDEM_BENCH_EXAMPLE=peri-lps-impact/in.peri_lps_impact \
PERIDEM_BENCH_STYLES="peri/lps|bond_style peridem/lps" \
  exec "$here/bench/peri-pmb/run_bench.sh" "$@"
