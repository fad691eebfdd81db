# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# examples/cantilever (ParticLS, Sec. 5.5): a peridynamic cantilever at rest under a
# uniform body acceleration has the beam's deflected shape, and its tip deflection
# approaches Timoshenko's as h and eps = 3h shrink (check_cantilever.py); two ranks
# give one rank's static state. State-based 3d: the bar's modulus under an axial load
# (its bending deflection approaches Timoshenko's only below eps/H = 3/7: README.md).
set(_cases "pmb 2 bending 5,7 2" "lps 2 bending 11,21 1" "pmb 3 bending 3,5 1"
           "lps 3 axial 3,5 1")
foreach(_case ${_cases})
  separate_arguments(_c UNIX_COMMAND "${_case}")
  list(GET _c 0 _model)
  list(GET _c 1 _dim)
  list(GET _c 2 _load)
  list(GET _c 3 _n)
  list(GET _c 4 _np)
  add_test(NAME cantilever_${_model}_${_dim}d_${_load}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh /usr/bin/python3
            ${PROJECT_SOURCE_DIR}/examples/cantilever/check_cantilever.py
            --lmp $<TARGET_FILE:lmp_peridem> --model ${_model} --dim ${_dim} --load ${_load}
            --n ${_n}
            --np ${_np} --out ${CMAKE_CURRENT_BINARY_DIR}/cantilever_${_model}_${_dim}d_${_load})
  set_tests_properties(cantilever_${_model}_${_dim}d_${_load} PROPERTIES TIMEOUT 600)
endforeach()
