# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# fix peridem/bonds forces a neighbour-list rebuild at the step after a bond
# breaks, in every run: a grain struck hard enough to break
# bonds ends with the same energy and bonds with LAMMPS's default neighbour
# settings, with a rebuild at every step, and split into two runs.
# Before the fix: +10.7% energy, 76 bonds too many broken (2d); 7e-7 in 3d.
foreach(_case "2;3;1000;200" "3;6;600;150")
  list(GET _case 0 _dim)
  list(GET _case 1 _v)
  list(GET _case 2 _steps)
  list(GET _case 3 _split)
  add_test(NAME contact_after_break_${_dim}d
    COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in strike_check.in
            -log none -echo none -var dim ${_dim} -var v ${_v} -var steps ${_steps}
            -var split ${_split}
    WORKING_DIRECTORY ${_in}/breakage)
endforeach()
# state-based grains: the section carries the weighted volume m too
foreach(_np 1 2)
  add_test(NAME data_file_keeps_lps_weighted_volume_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np}
            $<TARGET_FILE:lmp_peridem> -in data_damage.in -log none -echo none -var lps 1
            -var out ${CMAKE_CURRENT_BINARY_DIR}/data_damage_lps_np${_np}
    WORKING_DIRECTORY ${_in}/breakage)
endforeach()

# write_data + read_data keep the broken count and Z per node (before
# the fix: 0 of 220 broken bonds read back), on 1 and 2 ranks
foreach(_np 1 2)
  add_test(NAME data_file_keeps_damage_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np}
            $<TARGET_FILE:lmp_peridem> -in data_damage.in -log none -echo none
            -var out ${CMAKE_CURRENT_BINARY_DIR}/data_damage_np${_np}
    WORKING_DIRECTORY ${_in}/breakage)
endforeach()

# nodes leaving the box: a strip thrown out of an open
# container is deleted with its bonds and counted with 'lost delete' (1 and
# 2 ranks); without it the run stops naming the node and its grain (before:
# LAMMPS's "Lost atoms" / "Bond atoms missing")
foreach(_np 1 2)
  add_test(NAME escaped_nodes_deleted_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np}
            $<TARGET_FILE:lmp_peridem> -in escape.in -log none -echo none
    WORKING_DIRECTORY ${_in}/breakage)
endforeach()
# ... and without walls, where the user lets atoms go (thermo_modify lost ignore or warn):
# deleted with their bonds by fix PERIDEM_ESCAPES and counted, on 1 and 2 ranks
foreach(_np 1 2)
  add_test(NAME escaped_nodes_deleted_without_walls_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np}
            $<TARGET_FILE:lmp_peridem> -in escape_no_walls.in -log none -echo none
    WORKING_DIRECTORY ${_in}/breakage)
endforeach()
add_test(NAME escaped_nodes_deleted_without_walls_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh
          --regex "WARNING: fix PERIDEM_ESCAPES: [0-9]+ nodes left the box in this run and were deleted with their bonds \\(thermo_modify lost warn"
          $<TARGET_FILE:lmp_peridem> -in escape_no_walls.in -log none -echo none -var lost warn
  WORKING_DIRECTORY ${_in}/breakage)
add_test(NAME error.escaped_node_named_without_walls
  COMMAND ${PERIDEM_RUN}/expect_error.sh
          "atom [0-9]+ of grain 1 left the simulation box through yhi .*thermo_modify lost ignore"
          $<TARGET_FILE:lmp_peridem> -in escape_no_walls.in -log none -echo none -var lost error
  WORKING_DIRECTORY ${_in}/breakage)
# ... and through a lid the strip is fast enough to cross (yhi at 1.0: deleted
# at steps 90-100 once wholly beyond it, before it would reach the box edge)
add_test(NAME escaped_nodes_beyond_wall_deleted
  COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in escape.in -log none
          -echo none -var top "yhi 1.0"
  WORKING_DIRECTORY ${_in}/breakage)
add_test(NAME error.escaped_node_named
  COMMAND ${PERIDEM_RUN}/expect_error.sh
          "atom [0-9]+ of grain 1 left the simulation box through yhi at .*lost delete"
          $<TARGET_FILE:lmp_peridem> -in escape.in -log none -echo none -var lost warn
  WORKING_DIRECTORY ${_in}/breakage)
# reading it back wrongly: LAMMPS names the section; a wrong property kind is named
add_test(NAME error.data_file_damage_without_fix
  COMMAND ${PERIDEM_RUN}/expect_error.sh "Unknown identifier in data file: PeridemDamage"
          $<TARGET_FILE:lmp_peridem> -in data_damage.in -log none -echo screen
          -var out ${CMAKE_CURRENT_BINARY_DIR}/data_damage_nofix -var readfix ""
  WORKING_DIRECTORY ${_in}/breakage)
add_test(NAME error.data_file_damage_integer_property
  COMMAND ${PERIDEM_RUN}/expect_error.sh "per-atom property peridem_nbroken must be a d_ vector"
          $<TARGET_FILE:lmp_peridem> -in data_damage.in -log none -echo screen
          -var out ${CMAKE_CURRENT_BINARY_DIR}/data_damage_int
          -var props "i_peridem_nbroken d_peridem_zbroken"
  WORKING_DIRECTORY ${_in}/breakage)
# a spoiled PeridemDamage section (unittest/scripts/spoil_damage_section.py): a count beyond
# the grain (1e6: before, 500,145 broken bonds), a line given twice in place of another (before,
# 145.5 broken bonds where 150 are right, without a word), a negative weighted volume (before,
# replaced by a recomputed one), and vectors named otherwise (before, all damage silently 0)
# _data_damage_case(NAME CHECK...): data_damage.in read back into folder NAME, checked by
# CHECK (a script and its regex) and given the remaining arguments
function(_data_damage_case name)
  cmake_parse_arguments(_c "" "" "CHECK;ARGS" ${ARGN})
  add_test(NAME ${name}
    COMMAND ${_c_CHECK} $<TARGET_FILE:lmp_peridem> -in data_damage.in -log none -echo screen
            -var out ${CMAKE_CURRENT_BINARY_DIR}/${name} -var scripts ${PERIDEM_RUN} ${_c_ARGS}
    WORKING_DIRECTORY ${_in}/breakage)
endfunction()
_data_damage_case(error.data_file_damage_huge_count
  CHECK ${PERIDEM_RUN}/expect_error.sh
        "fix PERIDEM_BONDS: atom [0-9]+ has 1000000 broken bonds in the data file, more than the [0-9]+ other nodes of its grain"
  ARGS -var spoil huge)
_data_damage_case(data_file_damage_line_twice_warns
  CHECK ${PERIDEM_RUN}/expect_pass.sh --regex
        "WARNING: fix PERIDEM_BONDS: the broken bond counts of 1 grains \\(first: grain [0-9]+\\) in the data file sum to an odd number"
  ARGS -var spoil twice -var compare 0)
_data_damage_case(error.data_file_damage_negative_wvolume
  CHECK ${PERIDEM_RUN}/expect_error.sh
        "fix PERIDEM_LPS: invalid weighted volume -2 of atom [0-9]+ in the data file"
  ARGS -var lps 1 -var spoil wvolume)
_data_damage_case(data_file_damage_misnamed_warns
  CHECK ${PERIDEM_RUN}/expect_pass.sh --regex
        "WARNING: fix PERIDEM_BONDS: per-atom property nbroken looks like the damage of a PeridemDamage section but is not read"
  ARGS -var props "d_nbroken d_zbroken" -var compare 0)
# ... and the m column of the state-based grains (before, m silently summed again over the
# bonds left, so the damaged nodes' dilation changed)
_data_damage_case(data_file_lps_misnamed_warns
  CHECK ${PERIDEM_RUN}/expect_pass.sh --regex
        "WARNING: fix PERIDEM_LPS: per-atom property wvolume looks like the weighted volume m of a PeridemDamage section but is not read"
  ARGS -var lps 1 -var props "d_peridem_nbroken d_peridem_zbroken d_wvolume" -var compare 0)
