# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# The energy dissipated by contact damping and friction (pair_style peridem/contact and fix
# peridem/wall) equals the mechanical energy lost to 1e-3 (dissipation/balance.in; measured
# 6e-8 to 1.6e-4), for a grain held by stuck contacts below the friction limit (tan(theta) =
# 0.35 mu), pushed to slide to rest, or dragged by a sliding wall, on 1 and 2 ranks, newton on
# and off: the ranks split the grains and their contacts at x = 0. The power at the velocities
# the forces take, v(n - 1/2), which the styles counted before, missed by 18 % to 630 % (all
# but the three wall cases with regularized friction, where it was within 2e-4).
set(_balance ${PERIDEM_RUN}/expect_pass.sh ${PERIDEM_RUN}/mpirun.sh)

# held: on the fixed slab grain (several partners per node) and on a wall at g = 10, on a free
# grain at g = 3, there also with the dashpot between grain centres instead of nodal damping
# (Jha et al. 2021, eq. 26-30: its nodal shares count); pushed at 0.5 along the surface
# (theta 0, g = 10), sliding to rest; dragged by a wall that starts sliding at 0.3 (the wall's
# work, from the grain's momentum, less the change of energy)
set(_stuck "-var theta 10")
set(_centroid "-var theta 10 -var damping \"centroid 0.8 100 kappa 1000\"")
set(_slide "-var theta 0 -var v0 0.5 -var pre 0 -var hold 3000")
set(_shear "-var theta 0 -var shear 0.3 -var pre 0 -var hold 3000")
foreach(_case "stuck;grain;10" "stuck;wall;10" "stuck;pile;3" "centroid;pile;3" "slide;grain;10"
        "slide;wall;10" "shear;wall;10")
  list(GET _case 0 _what)
  list(GET _case 1 _partner)
  list(GET _case 2 _g)
  foreach(_law regularized coulomb)
    set(_name ${_what}_${_partner}_${_law})
    set(_args "-var partner ${_partner} -var law ${_law} -var g ${_g} ${_${_what}}")
    if(_partner STREQUAL "wall" OR _name STREQUAL "slide_grain_coulomb")
      # reproducible across the decompositions: the same thermo output, the dissipated energy
      # among it, on 1 and 2 ranks, newton on and off (run_variants.sh)
      add_test(NAME dissipation.${_name}
        COMMAND ${PERIDEM_RUN}/run_variants.sh $<TARGET_FILE:lmp_peridem> ${_in}/dissipation
                balance.in ${CMAKE_CURRENT_BINARY_DIR}/dissipation/${_name} "${_args}"
                "1" "2" "2 -var newton off")
    else()
      # stick and slip amplify the round-off of the sums (a summation order of its own per
      # decomposition) until the runs part: each run closes its own balance
      separate_arguments(_list UNIX_COMMAND "${_args}")
      foreach(_np 1 2)
        add_test(NAME dissipation.${_name}_np${_np}
          COMMAND ${_balance} ${_np} $<TARGET_FILE:lmp_peridem> -in ${_in}/dissipation/balance.in
                  -log none -echo none ${_list})
      endforeach()
      add_test(NAME dissipation.${_name}_np2_newton_off
        COMMAND ${_balance} 2 $<TARGET_FILE:lmp_peridem> -in ${_in}/dissipation/balance.in
                -log none -echo none ${_list} -var newton off)
    endif()
  endforeach()
endforeach()
