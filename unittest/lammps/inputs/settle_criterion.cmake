# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# the documented stop-at-rest recipe (compute peridem/grain velocities, a vector-style variable,
# max(), fix halt): two grains slowed by a drag of known rate stop the run at the step of the
# analytic decay exp(-t), 1 and 2 ranks
foreach(_np 1 2)
  add_test(NAME grain_speed_halts_at_rest_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-STOP step 2310 max grain speed 0\\.099[0-9]+ "
            ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem> -in ${_in}/grain_halt.in
            -log none -echo none)
endforeach()
