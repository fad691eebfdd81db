# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/bed-stress (ParticLS, Sec. 5.3): a packing of 22 spheres compressed by the top
# wall; compute peridem/stress gives zero stress before the lid touches, the walls' mean
# load once loaded (within 10 %), a stress that grows with the strain, compressive lateral
# stresses and a fabric along the load (check_uniaxial.py).
add_test(NAME bed_stress_uniaxial
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/bed-stress/check_uniaxial.py
          --lmp $<TARGET_FILE:lmp_peridem> --out ${CMAKE_CURRENT_BINARY_DIR}/bed_stress_uniaxial)
set_tests_properties(bed_stress_uniaxial PROPERTIES TIMEOUT 300)
