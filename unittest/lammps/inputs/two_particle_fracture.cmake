# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# The fracture variants of Jha et al.'s (2021) two-particle tests
# (examples/two-particle-fracture), reduced to the first 250 us (the impact) at
# v0 = 2 and 5 m/s: in §4.2 with different materials the stronger M2 grain
# keeps every bond and its Z (bond stretch over s0) stays below 1, while the M1 grain between
# it and the M2 wall breaks bonds at 5 m/s and more than at 2 m/s (none); in the
# §4.1 drop (M1 on M1) the peak Z grows with v0; a hexagon dropped at 8 m/s
# onto a fixed concave grain (§4.3, Fig. 20) breaks bonds at its corners.
# About 12 s of CPU.
add_test(NAME two_particle_fracture_reduced
  COMMAND ${PERIDEM_RUN}/expect_pass.sh python3 ${PROJECT_SOURCE_DIR}/examples/two-particle-fracture/run_fracture.py
          --lmp $<TARGET_FILE:lmp_peridem> --potentials ${PROJECT_SOURCE_DIR}/potentials
          --series drop2,walldiff,hex --speeds 2,5 --trun 2.5e-4
          --out ${CMAKE_CURRENT_BINARY_DIR}/two-particle-fracture --check)
set_tests_properties(two_particle_fracture_reduced PROPERTIES TIMEOUT 300)
