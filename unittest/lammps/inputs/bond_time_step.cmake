# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Without a contact pair the bond styles print their own time-step estimate and warn above
# it: one disk struck by a radial velocity field (bond_time_step.in). At 2.8 times the
# critical step the energy grows 1900-17000 times and nearly every bond breaks; at 0.5
# times it stays within 1 % with no broken bond and no warning.
foreach(_style peridem peridem/lps)
  string(REPLACE "/" "_" _name ${_style})
  add_test(NAME bond.time_step_warns_${_name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh
            --regex "WARNING: bond_style ${_style}: time step .* exceeds the bonds' recommended"
            $<TARGET_FILE:lmp_peridem> -in ${_in}/bond_time_step.in -log none -echo none
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -var style ${_style}
            -var factor 2.8 -var steps 25)
  add_test(NAME bond.time_step_stable_${_name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh
            $<TARGET_FILE:lmp_peridem> -in ${_in}/bond_time_step.in -log none -echo none
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -var style ${_style} -var factor 0.5)
  set_tests_properties(bond.time_step_stable_${_name} PROPERTIES
    FAIL_REGULAR_EXPRESSION "WARNING: bond_style")
endforeach()

# a state of bond_style peridem with broken bonds, restarted under bond_style peridem/lps:
# the weighted volumes of the damaged nodes come from their intact bonds, and it says so
add_test(NAME bond.lps_after_bond_based_restart_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh
          --regex "WARNING: bond_style peridem/lps: 309 nodes with broken bonds have no weighted volume"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/bond_time_step.in -log none -echo none
          -var potentials ${PROJECT_SOURCE_DIR}/potentials -var factor 2.8 -var steps 25
          -var then_lps 1
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
