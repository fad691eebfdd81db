# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# restart files of an older PERIDEM format are refused with a clear message
# (restart_format/make_old.in wrote them with the build of commit 970bea6)
peridem_add_error_test(restart_old_bond ${_in}/restart_format/read_old.in
  "bond_style peridem: the restart file was written by an older PERIDEM"
  -var file ${_in}/restart_format/old_bond.restart)
peridem_add_error_test(restart_old_pair ${_in}/restart_format/read_old.in
  "pair_style peridem/contact: the restart file was written by an older PERIDEM"
  -var file ${_in}/restart_format/old_pair.restart)

# pair_style peridem/contact writes its parameters field by field (formats 2 and 3); a file of
# format 1 (the raw struct, v1_pair.restart written by the build of commit 63560cc) is refused
peridem_add_error_test(restart_format1_pair ${_in}/restart_format/read_old.in
  "pair_style peridem/contact: the restart file was written by an older PERIDEM"
  -var file ${_in}/restart_format/v1_pair.restart)

# a bed compacted by a moving lid (the soak's input on 12 grains: contact with
# nodal damping and friction, gravity, fix peridem/wall, broken bonds) continues
# through a run boundary and a restart file as one uninterrupted run, on 1 and 2
# ranks; the centroid variant damps between grain centres (13 broken bonds)
foreach(_np 1 2)
  add_test(NAME restart.bed_continue_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
            -in ${_in}/bed_restart.in -log none -echo none
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -var tag np${_np}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  # the processors split the bed (x): contacts on both ranks
  if(_np EQUAL 2)
    add_test(NAME restart.bed_continue_split_np2
      COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:lmp_peridem>
              -in ${_in}/bed_restart.in -log none -echo none
              -var potentials ${PROJECT_SOURCE_DIR}/potentials -var tag split_np2
              -var procs "2 1 1"
      WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  endif()
  add_test(NAME restart.bed_continue_centroid_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
            -in ${_in}/bed_restart.in -log none -echo none
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -var tag centroid_np${_np}
            -var damping "centroid 0.8 100"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  # the onset of Jha et al.'s code (bounding radii): centroid_bounding travels in the restart
  add_test(NAME restart.bed_continue_bounding_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
            -in ${_in}/bed_restart.in -log none -echo none
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -var tag bounding_np${_np}
            -var damping "centroid 0.8 100 centroid_bounding 1.01"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
