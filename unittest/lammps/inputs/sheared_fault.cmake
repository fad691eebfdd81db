# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/sheared-fault (Kiiskinen's thesis, Sec. 4-5): a 20 mm granite block with one jag,
# p = 0.1 sigma_c, sheared for 0.8 ms with contact friction on (2 ranks) and off (1 rank).
# check_fault.py: the periodic seam is bonded (bond count against an independent count) and
# no node is lost, the driven edge feels p on average within 1 %, mu peaks and falls, friction
# off gives a lower mu, and the dissipated energy W - dE is at least the contact dissipation.
add_test(NAME sheared_fault_reduced
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/sheared-fault/check_fault.py
          --lmp $<TARGET_FILE:lmp_peridem> --np 2 --out ${CMAKE_CURRENT_BINARY_DIR}/sheared_fault)
set_tests_properties(sheared_fault_reduced PROPERTIES TIMEOUT 300 PROCESSORS 2)
