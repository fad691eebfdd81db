# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/plate-hole (ParticLS, Sec. 5.4): a state-based plate with a central hole pulled
# at both ends. elastic: at rest, the strain at the hole's top and bottom edge over the
# far-field strain is the finite-width Kirsch factor (Howland/Peterson, 3.135 at d/W = 0.2)
# within 5 % at three meshes; onset: with breakage, the first bonds break at the hole's
# top and bottom, not at the loaded ends (2 ranks).
add_test(NAME plate_hole_elastic
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/plate-hole/check_plate_hole.py
          --lmp $<TARGET_FILE:lmp_peridem> --test elastic --n 40,80,120
          --out ${CMAKE_CURRENT_BINARY_DIR}/plate_hole_elastic)
add_test(NAME plate_hole_onset
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/plate-hole/check_plate_hole.py
          --lmp $<TARGET_FILE:lmp_peridem> --test onset --n 80 --np 2
          --out ${CMAKE_CURRENT_BINARY_DIR}/plate_hole_onset)
set_tests_properties(plate_hole_elastic plate_hole_onset PROPERTIES TIMEOUT 600)
