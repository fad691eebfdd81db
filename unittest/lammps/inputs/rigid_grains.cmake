# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/rigid-grains: bond-less grains of create_peridem_grains moved by fix rigid/small
# beside breakable grains (check_rigid.py; bounds justified in its docstring and README.md)
# drop: the undamped rigid square on a floor of nodes and on a fix peridem/wall conserves
#   KE + gravity + contact energy to 1e-4 (dt 1e-3) and 2.5e-5 (dt 5e-4) of its largest KE,
#   the error shrinking >= 3x when dt halves
# crush: the breakable disk under the rigid square is damaged (> 0.1) while the square's node
#   distances stay the same to 1e-12 (1 and 2 ranks)
# ranks: the drop's centre and energy on 1 and 2 ranks agree to 1e-10
set(_rigid ${PROJECT_SOURCE_DIR}/examples/rigid-grains/check_rigid.py)
foreach(_case drop crush ranks)
  add_test(NAME rigid_grains_${_case}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-PASS rigid grains ${_case}" /usr/bin/python3 ${_rigid} ${_case}
            --lmp $<TARGET_FILE:lmp_peridem> --out ${CMAKE_CURRENT_BINARY_DIR}/rigid_grains_${_case} --np 2)
  set_tests_properties(rigid_grains_${_case} PROPERTIES TIMEOUT 120)
endforeach()
add_test(NAME rigid_grains_crush_np1
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-PASS rigid grains crush" /usr/bin/python3 ${_rigid} crush
          --lmp $<TARGET_FILE:lmp_peridem> --out ${CMAKE_CURRENT_BINARY_DIR}/rigid_grains_crush_np1 --np 1)
set_tests_properties(rigid_grains_crush_np1 PROPERTIES TIMEOUT 120)
# the mixed bed on 2 ranks: the top wall reaches 3.8 and the breakable grains' bulk damage
# exceeds 0.1 (measured 0.232; 1 and 2 ranks agree to 3e-7 in the wall load: breakage in a
# bed of 25 grains amplifies round-off, so no bit-for-bit comparison)
add_test(NAME rigid_grains_mixed_bed_np2
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-MIXED wall 3\\.8[0-9]* load [0-9.]+ damage 0\\.[1-9]"
          ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:lmp_peridem>
          -in ${PROJECT_SOURCE_DIR}/examples/rigid-grains/in.mixed_bed -var picture no -log none -echo none
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(rigid_grains_mixed_bed_np2 PROPERTIES TIMEOUT 120)
