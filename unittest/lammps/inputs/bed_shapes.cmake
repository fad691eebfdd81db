# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/bed-settling/in.shapes (Bhattacharya & Lipton 2023, §7.2-7.3, Table 3), reduced:
# the four shapes of §7.2 from one bed of 60 security disks in a 10 mm container, h = eps/5 = R_c,
# the text's material, contact and 70 ns step, settle under g = 5000 m/s^2 until at rest
# (kinetic energy below 1 % of its peak and every grain slower than 0.05 m/s); then
# check_shapes.py: every bed settled and compacted, the plus bed is the loosest (rings counted
# with their holes, as Table 3), the
# compaction by gravity orders plus > square > perturbed disk > ring as in Table 3, and the
# ring bed's with-holes fraction is its material fraction over 1 - tau^2 (README.md)
set(_dir ${CMAKE_CURRENT_BINARY_DIR}/bed_shapes)
file(MAKE_DIRECTORY ${_dir})
foreach(_shape perturbed_disk square plus ring)
  add_test(NAME bed_shapes_settle_${_shape}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-SETTLED ${_shape} at step"
            $<TARGET_FILE:lmp_peridem>
            -in ${PROJECT_SOURCE_DIR}/examples/bed-settling/in.shapes -log ${_dir}/log.${_shape}
            -echo none -var potentials ${PROJECT_SOURCE_DIR}/potentials -var shape ${_shape}
            -var count 60 -var W 10e-3 -var res 5 -var maxsteps 200000
    WORKING_DIRECTORY ${_dir})
  set_tests_properties(bed_shapes_settle_${_shape} PROPERTIES TIMEOUT 600
    FIXTURES_SETUP bed_shapes)
endforeach()
add_test(NAME bed_shapes_table3_order
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/bed-settling/check_shapes.py ${_dir} --check)
set_tests_properties(bed_shapes_table3_order PROPERTIES FIXTURES_REQUIRED bed_shapes)

# examples/bed-compaction/in.compaction (Bhattacharya & Lipton 2023, §7.4.1, Fig. 14), reduced:
# plus and square beds of 40 grains in an 8 mm container, h = eps/5 = R_c, the authors' bond
# constants (-var material authors), the text's contact and 70 ns step, pressed by the top wall
# at 1 m/s to phi 0.95; then check_shapes.py: damage starts in the plus bed before the square bed, the
# wall load rises before the first break, damage never decreases and grows (README.md)
foreach(_shape plus square)
  add_test(NAME bed_shapes_compaction_${_shape}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-DONE at step"
            $<TARGET_FILE:lmp_peridem>
            -in ${PROJECT_SOURCE_DIR}/examples/bed-compaction/in.compaction
            -log ${_dir}/compaction.${_shape} -echo none
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -var shape ${_shape} -var res 5
            -var count 40 -var W 8e-3 -var material authors -var stop_damage 0.99
            -var stop_phi 0.95 -var maxsteps 200000
    WORKING_DIRECTORY ${_dir}/compaction_${_shape})
  file(MAKE_DIRECTORY ${_dir}/compaction_${_shape})
  set_tests_properties(bed_shapes_compaction_${_shape} PROPERTIES TIMEOUT 600
    FIXTURES_SETUP bed_compaction_shapes)
endforeach()
add_test(NAME bed_shapes_compaction_onset_order
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
          ${PROJECT_SOURCE_DIR}/examples/bed-compaction/check_shapes.py
          ${_dir}/compaction.plus ${_dir}/compaction.square)
set_tests_properties(bed_shapes_compaction_onset_order PROPERTIES
  FIXTURES_REQUIRED bed_compaction_shapes)
# the check can fail: with the two beds' logs swapped it reports the onset order
add_test(NAME bed_shapes_compaction_onset_order_swapped
  COMMAND /usr/bin/python3 ${PROJECT_SOURCE_DIR}/examples/bed-compaction/check_shapes.py
          ${_dir}/compaction.square ${_dir}/compaction.plus)
set_tests_properties(bed_shapes_compaction_onset_order_swapped PROPERTIES
  FIXTURES_REQUIRED bed_compaction_shapes
  PASS_REGULAR_EXPRESSION "PERIDEM-FAIL damage onset: plus at phi 0[.]7[0-9]+ not before square")
