# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Damaged restart files (one value of atom 1 changed, unittest/scripts/damage_restart.py)
# stop with a message naming what is wrong: before, a bond type beyond the types read the
# coefficient arrays out of bounds (a crash in BondPeridemLPS::stability_springs), x0 = 1e30
# along a periodic axis hung in LAMMPS's minimum image, and NaN volumes or weighted volumes
# ran on (the Z of fix PERIDEM_BONDS's record, m of fix PERIDEM_LPS's). The global sections too: the LPS shear modulus (12.96 MPa, M1) and the first
# setting after the LPS restart tag. LAMMPS's own restart reading (counts, bond partners, special lists) is trusted
# input and not checked here (doc/errors.md).
set(_damaged_cases
  "tag\;0\;Invalid atom ID 0 in restart file"
  "molecule\;-3\;Invalid grain ID -3 of atom 1 in restart file"
  "double:12960000\;nan\;bond_style peridem/lps: the restart file holds shear modulus nan"
  "int_after:0x50444c01:1\;7\;bond_style peridem: the restart file holds setting 7"
  "bond_type\;1000\;Invalid bond 1 \\(type 1000"
  "vfrac\;nan\;Invalid volume nan or mass"
  "x0z\;1e30\;more than one box length outside the periodic box along z"
  "fixblock:3:2\;nan\;fix PERIDEM_BONDS: invalid damage state of atom 1"
  "fixblock:2:1\;nan\;fix PERIDEM_LPS: invalid weighted volume nan of atom 1 in restart file"
  "fixblock:8:2\;inf\;fix PERIDEM_VHISTORY: invalid velocity history of atom 1")
foreach(_case ${_damaged_cases})
  list(GET _case 0 _field)
  list(GET _case 1 _value)
  list(GET _case 2 _regex)
  string(REGEX REPLACE "[^a-z0-9]" "_" _name "${_field}")
  add_test(NAME restart.damaged_${_name}
    COMMAND ${PERIDEM_RUN}/damaged_restart_test.sh $<TARGET_FILE:lmp_peridem>
            ${_in}/restart_damaged ${PROJECT_SOURCE_DIR}/potentials
            ${CMAKE_CURRENT_BINARY_DIR}/restart_damaged_${_name} ${_field} ${_value} "${_regex}")
endforeach()
