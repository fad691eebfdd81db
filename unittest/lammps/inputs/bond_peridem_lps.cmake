# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# bond_style peridem/lps (state-based grains), compute peridem/dilation and
# the per-type break keyword of both bond styles

# bad input gets a clear error (peridem_bond_error is in bond_peridem.cmake)
peridem_bond_error(lps_negative_K bond_cases.data lps_negative_K.lmp
  "bond_coeff: K \\(bulk modulus\\) must be > 0 for bond_style peridem/lps, not -1e9")
peridem_bond_error(lps_zero_G bond_cases.data lps_zero_G.lmp
  "bond_coeff: G \\(shear modulus\\) must be > 0 for bond_style peridem/lps, not 0")
peridem_bond_error(lps_zero_Gc bond_cases.data lps_zero_Gc.lmp
  "bond_coeff: Gc \\(fracture energy\\) must be > 0 for bond_style peridem/lps, not 0")
peridem_bond_error(lps_negative_horizon bond_cases.data lps_negative_horizon.lmp
  "bond_coeff: horizon must be > 0 for bond_style peridem/lps, not -0.3")
peridem_bond_error(lps_missing_K bond_cases.data lps_missing_K.lmp
  "bond_coeff: bond_style peridem/lps needs K \\(bulk modulus\\)")
peridem_bond_error(lps_missing_G bond_cases.data lps_missing_G.lmp
  "bond_coeff: bond_style peridem/lps needs G \\(shear modulus\\)")
peridem_bond_error(lps_missing_horizon bond_cases.data lps_missing_horizon.lmp
  "bond_coeff: bond_style peridem/lps needs a horizon")
peridem_bond_error(lps_missing_Gc bond_cases.data lps_missing_Gc.lmp
  "bond_coeff: bond_style peridem/lps needs Gc \\(fracture energy, PeriDEM eq. 10\\) or s0")
peridem_bond_error(lps_Gc_and_s0 bond_cases.data lps_Gc_and_s0.lmp
  "bond_coeff: give Gc or s0, not both")
peridem_bond_error(lps_bond_based_c bond_cases.data lps_bond_based_c.lmp
  "bond_coeff: c is a bond-based coefficient; bond_style peridem/lps is state-based")
peridem_bond_error(lps_micromodulus bond_cases.data lps_micromodulus.lmp
  "bond_coeff: micromodulus is a bond-based coefficient; bond_style peridem/lps is state-based")
peridem_bond_error(bond_state_based_G bond_cases.data bond_state_based_G.lmp
  "bond_coeff: G is a state-based coefficient; bond_style peridem is bond-based")
peridem_bond_error(lps_bad_influence bond_cases.data lps_bad_influence.lmp
  "bond_coeff: influence must be conic, constant or inverse, not gaussian")
peridem_bond_error(lps_bad_plane bond_cases.data lps_bad_plane.lmp
  "bond_style peridem/lps: plane must be strain, stress or 3d, not sheet")
peridem_bond_error(lps_bad_break bond_cases.data lps_bad_break.lmp
  "bond_coeff: break must be yes or no, not maybe")
peridem_bond_error(bond_bad_break_coeff bond_cases.data bond_bad_break_coeff.lmp
  "bond_coeff: break must be yes or no, not sometimes")
peridem_bond_error(lps_material_and_K bond_cases.data lps_material_and_K.lmp
  "bond_coeff: bond_style peridem/lps takes material FILE NAME or K and G, not both")
peridem_bond_error(lps_material_no_G bond_cases.data lps_material_no_G.lmp
  "bond_coeff: bond_style peridem/lps needs K and G \\(or any two of E, nu, K, G\\); material X of .*lps_E_only.peridem has not both")
peridem_bond_error(lps_dilation_needs_lps bond_cases.data lps_dilation_needs_lps.lmp
  "compute peridem/dilation needs bond_style peridem/lps")

# a material file gives K, G, Gc, horizon and the influence function
add_test(NAME bond_lps_material
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex PERIDEM-LPS-OK
          $<TARGET_FILE:lmp_peridem> -in ${_in}/bond_error.in -log none -var inputs ${_in}
          -var data bond_cases.data -var case lps_ok.lmp -var potentials ${PROJECT_SOURCE_DIR}/potentials)

# in.peri.lps rebuilt with bond_style peridem/lps (a smaller target, a slower
# indenter that still breaks bonds): 1, 2 and 4 ranks, newton_bond on and
# off, and restarts in the middle on 2 ranks, all give the thermo output
# (energy, bond virial, summed dilation, damage) of the 1-rank run
add_test(NAME example.peri_lps_impact_ranks
  COMMAND ${PERIDEM_RUN}/run_variants.sh $<TARGET_FILE:lmp_peridem>
          ${PROJECT_SOURCE_DIR}/examples/peri-lps-impact in.peri_lps_impact
          ${CMAKE_CURRENT_BINARY_DIR}/examples/peri_lps_impact_ranks
          "-var radius 0.003 -var vy -20"
          "1" "2" "4" "2 -var newton off" "4 -var newton off"
          "2 -var restart 1" "2 -var restart 1 -var newton off")
# The shear virial c_vir[4] is zero by symmetry: its values (1e-12 against 0.1 for the
# others) are round-off of sums over 1243 nodes, which the order of the nodes in memory
# changes (ranks, restarts): an absolute floor of 1e-10, the relative tolerance (1e-9) of
# the other virial components
set_tests_properties(example.peri_lps_impact_ranks PROPERTIES TIMEOUT 600
  ENVIRONMENT "PERIDEM_THERMO_COMPARE_ARGS=--atol 1e-10")

# with create_peridem_grains, cut_peridem_bonds and pair_style peridem/contact
# (2d, material M1, the paper's 3d constants): runs, the notch counts as
# broken bonds, the grains dilate on contact; 1 and 2 ranks
foreach(_np 1 2)
  add_test(NAME bond_lps_grains_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
            -in ${_in}/lps_grains.in -log none -echo none -var potentials ${PROJECT_SOURCE_DIR}/potentials
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
