#!/usr/bin/env bash
# Quick start: install what is missing, build, and run the bundled example
# examples/grain-block on 2 MPI ranks. Prints where the output went.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PERIDEM_BUILD_DIR:-$here/build}"
"$here/scripts/build.sh"
source "$here/unittest/scripts/mpi_env.sh"
out="$here/out/grain-block"
rm -rf "$out"; mkdir -p "$out"
cp -r "$here/examples/grain-block/." "$out/"
(cd "$out" && mpirun -np 2 "$build/lmp_peridem" -in in.grain_block -log log.lammps -screen none)
echo "PERIDEM example finished: output in $out"
echo "  log (thermo):  $out/log.lammps"
echo "  data file:     $out/grain_block.data"
echo "  restart file:  $out/grain_block.restart"
