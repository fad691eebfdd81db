# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# compute peridem/fragments, peridem/grain, peridem/bed

# cut pieces across subdomain boundaries: the gtest program on 2, 3 and 4 ranks
foreach(_np 2 3 4)
  add_test(NAME mpi${_np}.compute_peridem_fragments
    COMMAND ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:test_compute_peridem_fragments>)
endforeach()

# a pulverised grain: the fragments equal an independent union-find over the
# dumped bonds (unittest/scripts/fragments_union_find.py), on 1 and 3 ranks
foreach(_np 1 3)
  set(_dir ${CMAKE_CURRENT_BINARY_DIR}/fragments_pulverise_${_np})
  file(MAKE_DIRECTORY ${_dir})
  add_test(NAME fragments.pulverise_union_find_np${_np}
    COMMAND bash -c "${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem> -in ${_in}/fragments/pulverise.in -log none -screen none && python3 ${PERIDEM_RUN}/fragments_union_find.py ."
    WORKING_DIRECTORY ${_dir})
endforeach()

# bad input gets a clear error
set(_fbox ${_in}/fragments/box.in)
peridem_add_error_test(fragments_negative_min ${_fbox}
  "Illegal compute peridem/fragments command: min nodes -1 must not be negative"
  -var compute "peridem/fragments min nodes -1")
peridem_add_error_test(fragments_min_kind ${_fbox}
  "Illegal compute peridem/fragments command: min mass: expected nodes or volume"
  -var compute "peridem/fragments min mass 2")
peridem_add_error_test(fragments_unknown_keyword ${_fbox}
  "Illegal compute peridem/fragments command: unknown keyword every"
  -var compute "peridem/fragments every 10")
peridem_add_error_test(fragments_atom_style ${_in}/fragments/atomic.in
  "compute peridem/fragments requires atom style peridem"
  -var compute "peridem/fragments")

# compute peridem/grain: hand values on 2 and 4 ranks; bad input
foreach(_np 2 4)
  add_test(NAME mpi${_np}.compute_peridem_grain
    COMMAND ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:test_compute_peridem_grain>)
endforeach()
peridem_add_error_test(grain_not_peridem_compute ${_fbox}
  "compute peridem/grain: damage compute k is a compute ke, not peridem/damage"
  -var before "compute k all ke" -var compute "peridem/grain damage k" -var thermo "c_c[1][1]")
peridem_add_error_test(grain_fragments_not_peridem ${_fbox}
  "compute peridem/grain: fragments compute k is a compute ke, not peridem/fragments"
  -var before "compute k all ke" -var compute "peridem/grain fragments k" -var thermo "c_c[1][1]")
peridem_add_error_test(grain_missing_compute ${_fbox}
  "compute peridem/grain: damage compute nope does not exist"
  -var compute "peridem/grain damage nope" -var thermo "c_c[1][1]")
peridem_add_error_test(grain_atom_style ${_in}/fragments/atomic.in
  "compute peridem/grain requires atom style peridem"
  -var compute "peridem/grain")

# compute peridem/bed: hand values on 2 ranks; bad input
add_test(NAME mpi2.compute_peridem_bed
  COMMAND ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:test_compute_peridem_bed>)
peridem_add_error_test(bed_no_region ${_fbox}
  "compute peridem/bed: region nope does not exist" -var compute "peridem/bed nope")
peridem_add_error_test(bed_bad_top ${_fbox}
  "Illegal compute peridem/bed command: top lid: expected surface, max, region or v_name"
  -var before "region r block -3 3 -3 3 -0.5 0.5" -var compute "peridem/bed r top lid")
peridem_add_error_test(bed_bad_bin ${_fbox}
  "Illegal compute peridem/bed command: bin -1 must be positive"
  -var before "region r block -3 3 -3 3 -0.5 0.5" -var compute "peridem/bed r bin -1")
peridem_add_error_test(bed_unbounded_region ${_fbox}
  "compute peridem/bed: region r has no bounding box"
  -var before "region r plane 0 0 0 0 1 0" -var compute "peridem/bed r")
peridem_add_error_test(bed_atom_style ${_in}/fragments/atomic.in
  "compute peridem/bed requires atom style peridem" -var compute "peridem/bed r")

# python/peridem_post.py: crack angle of synthetic bands to 0.5 degree,
# readers, plots (Debian's python3 has numpy and, if installed, matplotlib)
find_program(PERIDEM_POST_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
add_test(NAME python.peridem_post
  COMMAND ${PERIDEM_POST_PYTHON} ${PERIDEM_RUN}/test_post.py)

# compute peridem/stress and peridem/contacts: the gtests on 2 ranks
add_test(NAME mpi2.compute_peridem_stress
  COMMAND ${PERIDEM_RUN}/mpirun.sh 2 $<TARGET_FILE:test_compute_peridem_stress>)
