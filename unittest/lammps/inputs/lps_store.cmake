# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# The weighted volume m of bond_style peridem/lps moved from fix PERIDEM_BONDS to fix
# PERIDEM_LPS. Files of the older layout (lps_store/make_old.in: m the third value of fix
# PERIDEM_BONDS's restart record, the fourth column of the PeridemDamage section) still hand m
# over: a run continued from them is the straight run, exactly on 1 rank and to round-off on 2
# (the file spreads the nodes over the ranks otherwise). With m summed again over the bonds left
# the damaged nodes' dilation changes and the bond style warns (--absent). The data file is
# text and reads on any LAMMPS; the binary restart file only on the LAMMPS that wrote it.
# LAMMPS 4 Feb 2025's write_data prints per-atom values with 16 significant digits (a node
# volume of 0.010000000000000002 as 0.01, where 29 Sep 2021 prints 17): there the file this
# build writes continues the run to round-off (measured: 6e-14 in the summed dilation).
foreach(_np 1 2)
  set(_tol 0)
  if(_np EQUAL 2)
    set(_tol 1e-10)
  elseif(NOT LAMMPS_VERSION EQUAL 20210929)
    set(_tol 1e-12)
  endif()
  foreach(_kind data restart)
    set(_name lps_store.old_${_kind}_np${_np})
    if(_kind STREQUAL restart AND NOT LAMMPS_VERSION EQUAL 20210929)
      add_test(NAME ${_name}
        COMMAND sh -c "echo 'skipped: lps_store/old.restart was written by LAMMPS 29 Sep 2021 (20210929), not by ${LAMMPS_VERSION}, whose binary restart files may differ'; exit 77")
      set_tests_properties(${_name} PROPERTIES SKIP_RETURN_CODE 77)
      continue()
    endif()
    add_test(NAME ${_name}
      COMMAND ${PERIDEM_RUN}/expect_pass.sh --absent "have no weighted volume"
              ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem> -in continue.in
              -log none -echo none -var kind ${_kind} -var tol ${_tol}
              -var out ${CMAKE_CURRENT_BINARY_DIR}/lps_store_${_kind}_np${_np}
      WORKING_DIRECTORY ${_in}/lps_store)
  endforeach()
endforeach()
