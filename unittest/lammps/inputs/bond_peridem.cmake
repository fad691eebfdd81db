# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# bond_style peridem and compute peridem/damage

# damage counts on 2 MPI ranks (the partner of a broken bond on the other rank)
add_test(NAME mpi2.compute_peridem_damage
  COMMAND ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:test_compute_peridem_damage>)

# bad input gets a clear error
function(peridem_bond_error name data case regex)
  peridem_add_error_test(bond_${name} ${_in}/bond_error.in "${regex}" -var inputs ${_in}
    -var data ${data} -var case ${case} -var potentials ${PROJECT_SOURCE_DIR}/potentials)
endfunction()
peridem_bond_error(negative_E bond_cases.data bond_coeff_negative_E.lmp
  "bond_coeff: E \\(Young's modulus\\) must be > 0 for bond_style peridem, not -1e9")
peridem_bond_error(zero_Gc bond_cases.data bond_coeff_zero_Gc.lmp
  "bond_coeff: Gc \\(fracture energy\\) must be > 0 for bond_style peridem, not 0")
peridem_bond_error(missing_Gc bond_cases.data bond_coeff_missing_Gc.lmp
  "bond_coeff: bond_style peridem with K needs Gc")
peridem_bond_error(missing_horizon bond_cases.data bond_coeff_missing_horizon.lmp
  "bond_coeff: bond_style peridem needs a horizon")
peridem_bond_error(negative_horizon bond_cases.data bond_coeff_negative_horizon.lmp
  "bond_coeff: horizon must be > 0")
peridem_bond_error(two_sources bond_cases.data bond_coeff_both_sources.lmp "needs exactly one of")
peridem_bond_error(unknown_keyword bond_cases.data bond_coeff_unknown_key.lmp
  "bond_coeff: unknown keyword stiffness")
peridem_bond_error(no_coeffs bond_cases.data bond_coeff_missing.lmp "Bond coeffs are not set")
peridem_bond_error(longer_than_horizon bond_cases.data bond_too_long.lmp
  "bond between atoms 1 and 2 \\(type 1\\) has reference length 0.1 longer than the horizon 0.05")
peridem_bond_error(between_grains bond_cross_grain.data bond_ok.lmp
  "bond between atoms 2 and 3 joins grains 1 and 2")
peridem_bond_error(unknown_material bond_cases.data bond_material_unknown.lmp "M7")
peridem_bond_error(bad_break bond_cases.data bond_style_bad_break.lmp
  "bond_style peridem: break must be tension, absolute or off, not sometimes")
peridem_add_error_test(bond_wrong_atom_style ${_in}/bond_wrong_atom_style.in
  "bond_style peridem requires atom style peridem")
peridem_add_error_test(bond_material_units ${_in}/bond_material_lj.in
  "material file .*peridem_M1.peridem is in units si but the simulation uses units lj"
  -var inputs ${_in} -var potentials ${PROJECT_SOURCE_DIR}/potentials)

# bonds across grains are accepted when asked for
add_test(NAME bond_cohesive_allowed
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-COHESIVE-OK" $<TARGET_FILE:lmp_peridem>
          -in ${_in}/bond_error.in -log none -var inputs ${_in}
          -var data bond_cross_grain.data -var case bond_cohesive.lmp)

# the stock peri/pmb example rebuilt with bond_style peridem: 1 and 2 ranks agree
peridem_add_example_test(peri_impact peri-impact in.peri_impact 1 2)
peridem_bond_error(user_bonds_fix bond_cases.data bond_user_fix.lmp
  "fix peridem/bonds is created by bond_style peridem \\(as fix PERIDEM_BONDS\\); do not define it yourself \\(fix mine\\)")

# nodes kept grain by grain on 2 ranks: nodes migrate between the ranks, and are put in
# order again at every reneighbouring, with ghosts present
add_test(NAME mpi2.atom_order
  COMMAND ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:test_atom_order>)
