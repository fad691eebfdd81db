#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Quick start: install what is missing, build, and run the bundled example
# examples/pile (grains of material M1 falling into a box) on 2 MPI ranks.
# Prints where the output went.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PERIDEM_BUILD_DIR:-$here/build}"
"$here/scripts/build.sh"
source "$here/unittest/scripts/mpi_env.sh"
out="$here/out/pile"
rm -rf "$out"; mkdir -p "$out"
cp -r "$here/examples/pile/in.pile" "$out/"
(cd "$out" && mpirun -np 2 "$build/lmp_peridem" -in in.pile -var potentials "$here/potentials" \
   -log log.lammps -screen none)
echo "PERIDEM example finished: output in $out"
echo "  log (thermo):        $out/log.lammps"
echo "  dump (for OVITO):    $out/dump.pile"
echo "  pictures:            $out/pile.00000.png $out/pile.30000.png"
