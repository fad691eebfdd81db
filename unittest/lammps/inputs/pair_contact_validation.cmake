# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# pair_style peridem/contact: friction, self-contact, bonded pairs

set(_fric ${PROJECT_SOURCE_DIR}/examples/contact-friction)
set(_self ${PROJECT_SOURCE_DIR}/examples/contact-self)

# (1a) a square grain on a fixed slab, gravity tilted to theta (ramped in):
# stuck for tan(theta)/mu = 0.8, 0.95, sliding for 1.05, 1.25 (mu = 0.5),
# with the regularized law (Bhattacharya & Lipton 2023, eq. 4.3) and plain Coulomb (Jha et al. 2021, eq. 19-20)
foreach(_law regularized coulomb)
  foreach(_case "0.8;21.8014;stick" "0.95;25.4077;stick" "1.05;27.6995;slide" "1.25;32.0054;slide")
    list(GET _case 0 _ratio)
    list(GET _case 1 _theta)
    list(GET _case 2 _expect)
    add_test(NAME contact_incline_${_law}_${_ratio}
      COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_incline_check.in -log none -echo none
              -var law ${_law} -var theta ${_theta} -var expect ${_expect}
      WORKING_DIRECTORY ${_fric})
  endforeach()
endforeach()

# (1b) friction sign: a block pushed along the slab decelerates and stops;
# mechanical energy never increases, the dissipated energy never decreases
# and accounts for the loss to 5%
foreach(_law regularized coulomb)
  add_test(NAME contact_friction_sign_${_law}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_slide_check.in -log none -echo none
            -var law ${_law} -var theta 0 -var v0 0.5 -var ramp_steps 1 -var tilt_steps 1
    WORKING_DIRECTORY ${_fric})
endforeach()

# (1c) the sliding block (theta 35 degrees): same thermo on 1 and 2 ranks
peridem_add_example_test(contact_friction contact-friction in.incline 1 2)

# (2) self-contact: the halves of a cut grain bounce off each other; the
# arms of a crushed X-shaped grain do not interpenetrate; a grain torn apart
# during the run keeps its pieces apart; each the same on 1 and 2 ranks. fix halt
# ends the run with an error when nodes of two pieces come closer than Rc/2 ...
peridem_add_example_test(contact_cut_pieces contact-self in.cut_pieces 1 2)
peridem_add_example_test(contact_plus_crush contact-self in.plus_crush 1 2)
peridem_add_example_test(contact_break_apart contact-self in.break_apart 1 2)
# ... which happens with "pair_style peridem/contact self no": the checks can fail
foreach(_input cut_pieces plus_crush break_apart)
  add_test(NAME contact_${_input}_without_self_contact_fails
    COMMAND ${PERIDEM_RUN}/expect_error.sh "Fix halt condition for fix-id apart met"
            $<TARGET_FILE:lmp_peridem> -in in.${_input} -var self no -log none -echo none
    WORKING_DIRECTORY ${_self})
endforeach()

# intact bond: no contact; bond deleted: self-contact law; other grain: eq. 4.1
add_test(NAME contact_bonded_pair
  COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_bonded_pair.in -log none -echo none
          -var data ${_in}/two_nodes.data)

# compute pair/local (Pair::single): the normal contact force of each pair
# against the closed form and the forces on the atoms
add_test(NAME contact_pair_local
  COMMAND ${PERIDEM_RUN}/expect_pass.sh $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_pair_local.in -log none -echo none
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# examples/force-chains, shortened: the same thermo output on 1 and 2 ranks
add_test(NAME example.force_chains
  COMMAND ${PERIDEM_RUN}/run_example.sh $<TARGET_FILE:lmp_peridem>
          ${PROJECT_SOURCE_DIR}/examples/force-chains in.force_chains
          ${CMAKE_CURRENT_BINARY_DIR}/examples/force_chains 1 2)
set_tests_properties(example.force_chains PROPERTIES ENVIRONMENT "PERIDEM_EXAMPLE_ARGS=-var settle 3000 -var steps 1000")
