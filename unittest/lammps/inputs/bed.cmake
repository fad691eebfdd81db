# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# create_peridem_bed

# the packed-bed example: the same bed and grains on 1 and 2 ranks
peridem_add_example_test(packed_bed packed-bed in.bed 1 2)

# bad input: clear errors naming the command and the bad value
set(_b ${_in}/bed/bed_box.in)
set(_r "radius uniform 0.4 0.6 seed 1")
# checked before the radii are drawn (issue 27): against the distribution's smallest radius
peridem_add_error_test(bed_container_too_small ${_b}
  "create_peridem_bed: container x extent 0.5 is too small for a disk of radius 0.4, the smallest of the distribution"
  -var bed "count 10 ${_r} box 0 0.5 0 10")
peridem_add_error_test(bed_zero_radius ${_b}
  "create_peridem_bed: smallest radius 0 must be > 0"
  -var bed "count 10 radius uniform 0 0.6 seed 1")
peridem_add_error_test(bed_negative_radius ${_b}
  "create_peridem_bed: radius -0.5 in the list must be > 0"
  -var bed "count 10 radius list 0.5 -0.5 seed 1")
peridem_add_error_test(bed_inverted_range ${_b}
  "create_peridem_bed: inverted radius range: 0.8 > 0.4"
  -var bed "count 10 radius normal 0.6 0.1 0.8 0.4 seed 1")
peridem_add_error_test(bed_unreachable_fraction ${_b}
  "create_peridem_bed: the disks need a packing fraction of .* beyond the densest packing"
  -var bed "count 1000 ${_r}")
# issue 27: the count is range-checked (atom IDs are 32-bit here) and checked against the
# container before any radius is drawn (it used to abort with std::bad_alloc, or draw 1e8 radii
# first); "at least" marks the check before drawing
peridem_add_error_test(bed_count_beyond_int64 ${_b}
  "create_peridem_bed: count must be an integer from 1 to 2147483647, not 4294967306"
  -var bed "count 4294967306 ${_r}")
peridem_add_error_test(bed_count_beyond_tagint ${_b}
  "create_peridem_bed: count must be an integer from 1 to 2147483647, not 2147483648"
  -var bed "count 2147483648 ${_r}")
peridem_add_error_test(bed_count_unfit_before_drawing ${_b}
  "create_peridem_bed: the disks need a packing fraction of at least 1.0053[0-9]*e\\+06 \\(100000000 disks of radius >= 0.4\\) to fit"
  -var bed "count 100000000 ${_r}")
peridem_add_error_test(bed_too_high ${_b}
  "create_peridem_bed: the jammed bed of 55 disks is .* high, more than the container's 10"
  -var bed "count 55 ${_r}")
peridem_add_error_test(bed_unknown_distribution ${_b}
  "create_peridem_bed: unknown radius distribution 'lognormal'"
  -var bed "count 10 radius lognormal 0.5 0.1 seed 1")
peridem_add_error_test(bed_no_seed ${_b}
  "create_peridem_bed: no random seed given"
  -var bed "count 10 radius uniform 0.4 0.6")
peridem_add_error_test(bed_rc_too_large ${_b}
  "create_peridem_bed: contact_radius 0.8.* leaves nothing of the smallest disk"
  -var bed "count 10 ${_r} contact_radius 0.8")
peridem_add_error_test(bed_unknown_shape ${_b}
  "create_peridem_grains: unknown shape 'blob'"
  -var bed "count 10 ${_r} labels blob 1" -var grains "blob")
peridem_add_error_test(bed_no_label_lines ${_b}
  "create_peridem_grains: no line of the positions file has label 'hexagon'"
  -var bed "count 10 ${_r} labels disk 1" -var grains "hexagon")
# the time it took is wall time (MPI_Wtime), and the log says so
add_test(NAME bed.log_says_wall_time
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "^  create_peridem_bed wall time = [0-9.]+ seconds"
          $<TARGET_FILE:lmp_peridem> -in ${_b} -log none -echo screen
          -var bed "count 10 ${_r} labels disk 1"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# these write and read bed_error.txt in the same folder: never at the same time (ctest -j)
# label *: one shape on every line of a bed with several labels (10 disks labelled disk and
# hexagon become 10 squares)
add_test(NAME bed_label_star_places_every_line
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "Created 10 peridem grains \\(IDs 1 to 10\\)"
          $<TARGET_FILE:lmp_peridem> -in ${_b} -log none -echo none
          -var bed "count 10 ${_r} labels disk 1 hexagon 1" -var grains "square label *")
set_tests_properties(error.bed_unknown_shape error.bed_no_label_lines bed.log_says_wall_time
  bed_label_star_places_every_line PROPERTIES RESOURCE_LOCK bed_error_txt)
peridem_add_error_test(bed_rattlers_value ${_b}
  "create_peridem_bed: rattlers must be grow or keep, got 'shake'"
  -var bed "count 10 ${_r} rattlers shake")
peridem_add_error_test(bed_layout_value ${_b}
  "create_peridem_bed: layout must be jammed or rows, got 'grid'"
  -var bed "count 10 ${_r} layout grid")
peridem_add_error_test(bed_negative_gap ${_b}
  "create_peridem_bed: gap must be >= 0, got -0.1"
  -var bed "${_r} layout rows gap -0.1")
peridem_add_error_test(bed_rows_3d ${_in}/bed/bed_box3d.in
  "create_peridem_bed: layout rows is 2d only"
  -var bed "${_r} layout rows")
peridem_add_error_test(bed_tolerance_out_of_range ${_b}
  "create_peridem_bed: packing tolerance 0.5 must be in \\(0, 0.1\\)"
  -var bed "count 10 ${_r} tolerance 0.5")

# lid NAME: the bed's lid height (the "# bed" header's top) as an internal-style variable,
# reset by the next bed; an existing variable of another style is refused
add_test(NAME bed_lid_variable
  COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3 ${PERIDEM_RUN}/bed_lid_check.py
          $<TARGET_FILE:lmp_peridem> ${_in}/bed/bed_lid.in
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
peridem_add_error_test(bed_lid_not_internal ${_in}/bed/bed_lid.in
  "create_peridem_bed: lid variable top exists and is not internal-style"
  -var pre "variable top equal 1")
set_tests_properties(bed_lid_variable error.bed_lid_not_internal PROPERTIES RESOURCE_LOCK bed_lid_txt)
peridem_add_error_test(bed_lid_bad_name ${_b}
  "create_peridem_bed: lid needs a variable name \\(letters, digits, _\\), got 'a-b'"
  -var bed "count 10 ${_r} lid a-b")
