# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/compression-502 (Jha et al. 2021, §4.4), reduced: 19 grains of M1 (863
# nodes) settle and are pressed by the top wall at 0.1 m/s; nothing is lost between
# the stages, the wall load rises linearly before the first break and the floor
# carries it too, the first damaged grains carry 1.5x the intact grains' contact
# load, damage grows (check_reduced.py; 1 and 2 ranks)
foreach(_np 1 2)
  add_test(NAME compression_reduced_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
            ${PROJECT_SOURCE_DIR}/examples/compression-502/check_reduced.py
            --lmp $<TARGET_FILE:lmp_peridem> --potentials ${PROJECT_SOURCE_DIR}/potentials
            --out ${CMAKE_CURRENT_BINARY_DIR}/compression_reduced_np${_np} --np ${_np})
  set_tests_properties(compression_reduced_np${_np} PROPERTIES TIMEOUT 600)
endforeach()

# the Gmsh grains of Jha et al.'s code on the bed of the lattice grains: 123 and 91 nodes,
# the same mass, R_c = 0.95 hmin; misspelt -var grains / -var new_bed stop the input
add_test(NAME compression_gmsh_grains
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/compression-502/check_grains.py
          --lmp $<TARGET_FILE:lmp_peridem> --potentials ${PROJECT_SOURCE_DIR}/potentials
          --out ${CMAKE_CURRENT_BINARY_DIR}/compression_gmsh_grains)
set_tests_properties(compression_gmsh_grains PROPERTIES TIMEOUT 300)
