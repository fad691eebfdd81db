#!/usr/bin/env bash
# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# plugin_vs_driver.sh HOST PLUGIN LMP INPUT POTENTIALS OUT_DIR NP
# Runs INPUT through the plugin host with PLUGIN (every PERIDEM style from
# peridemplugin.so) and through lmp_peridem, on NP ranks, and requires the
# same thermo output (thermo_compare.py) and all styles registered.
set -eu
host="$1"; plugin="$2"; lmp="$3"; input="$4"; pot="$5"; out="$6"; np="$7"
here="$(cd "$(dirname "$0")" && pwd)"
source "$here/mpi_env.sh"
rm -rf "$out"; mkdir -p "$out"; cd "$out"
mpirun -np "$np" "$host" "$plugin" "$input" -var potentials "$pot" -log log.plugin -echo none \
  -screen none > host.out 2>&1 || { echo "FAIL: plugin host exited with $?"; cat host.out; tail -n 20 log.plugin; exit 1; }
cat host.out
grep -q "atom style peridem: registered" host.out || { echo "FAIL: no atom style from the plugin"; exit 1; }
n=$(grep -c "^plugin style: " host.out)
# every style of for_each_style() but the atom style (counted from its list,
# so that a new style needs no edit here)
want=$(grep -c '^ *sink\.\(bond\|pair\|fix\|compute\|command\)(' "$here/../../driver/register_peridem.cpp")
[ "$n" -eq "$want" ] || { echo "FAIL: $n plugin styles registered, expected $want (+ the atom style)"; exit 1; }
grep -q "PLUGIN-HOST-OK" host.out || { echo "FAIL: the input did not complete"; exit 1; }
mpirun -np "$np" "$lmp" -in "$input" -var potentials "$pot" -log log.driver -echo none -screen none
python3 "$here/thermo_compare.py" log.plugin log.driver && echo "PERIDEM-PLUGIN-PASS"
