# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# Material, polygon and Gmsh files are read on rank 0 and broadcast, and found as LAMMPS
# finds potential files: named without a folder, they come from LAMMPS_POTENTIALS (a folder
# made here, away from the working folder); 1 and 2 ranks
set(_pot_env ${CMAKE_CURRENT_BINARY_DIR}/potentials_env)
file(MAKE_DIRECTORY ${_pot_env})
file(COPY ${PROJECT_SOURCE_DIR}/potentials/peridem_M1.peridem
          ${PROJECT_SOURCE_DIR}/examples/grains-concave/c_slot.poly
          ${PROJECT_SOURCE_DIR}/unittest/core/data/square_hole_v22.msh DESTINATION ${_pot_env})
foreach(_np 1 2)
  add_test(NAME files.found_in_potentials_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np}
            $<TARGET_FILE:lmp_peridem> -in ${_in}/files/found_in_potentials.in -log none
            -var poly c_slot.poly -var msh square_hole_v22.msh
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(files.found_in_potentials_np${_np} PROPERTIES
    ENVIRONMENT LAMMPS_POTENTIALS=${_pot_env})
endforeach()
# without LAMMPS_POTENTIALS the same names are not found: a clear error
peridem_add_error_test(file_not_in_potentials ${_in}/files/found_in_potentials.in
  "create_peridem_grains: cannot open material file 'peridem_M1.peridem' \\(looked for it as given and in LAMMPS_POTENTIALS\\)"
  -var poly c_slot.poly -var msh square_hole_v22.msh)
