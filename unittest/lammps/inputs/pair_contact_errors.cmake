# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# pair_style peridem/contact: bad input ends the run with a clear error
# (Rc > horizon is a documented warning, doc/pair_peridem_contact.rst)

function(peridem_contact_error name regex)
  peridem_add_error_test(contact_${name} ${_in}/pair_contact_error.in "${regex}" ${ARGN})
endfunction()
set(_ok "Kn 1 Rc 0.2")
peridem_contact_error(rc_zero "pair_coeff: Rc \\(contact radius\\) must be > 0, not 0"
  -var coeff "* * Kn 1 Rc 0")
peridem_contact_error(rc_negative "pair_coeff: Rc \\(contact radius\\) must be > 0, not -0.1"
  -var coeff "* * Kn 1 Rc -0.1")
peridem_contact_error(rc_factor_zero "pair_coeff: Rc_factor .* must be > 0, not 0"
  -var coeff "* * Kn 1 Rc_factor 0 spacing 0.1")
peridem_contact_error(mu_negative "pair_coeff: friction coefficient mu must be >= 0, not -0.3"
  -var coeff "* * ${_ok} friction coulomb -0.3")
peridem_contact_error(mu_negative_regularized "friction coefficient mu must be >= 0, not -1e-3"
  -var coeff "* * ${_ok} friction regularized -1e-3")
peridem_contact_error(rd_above "pair_coeff: damping ratio r_d must lie in \\[0, 1\\], not 1.5"
  -var coeff "* * ${_ok} damping nodal 1.5")
peridem_contact_error(rd_below "pair_coeff: damping ratio r_d must lie in \\[0, 1\\], not -0.1"
  -var coeff "* * ${_ok} damping nodal -0.1")
peridem_contact_error(no_volumes
  "pair_style peridem/contact requires atom style peridem \\(per-atom volume"
  -var atomstyle bond -var coeff "* * ${_ok}")
peridem_contact_error(damping_needs_vel "needs ghost velocities: use comm_modify vel yes"
  -var vel no -var coeff "* * ${_ok} damping nodal 0.5")
peridem_contact_error(friction_needs_vel "needs ghost velocities: use comm_modify vel yes"
  -var vel no -var coeff "* * ${_ok} friction regularized 0.5")
peridem_contact_error(special_12 "requires special_bonds lj 0.0 for 1-2 pairs"
  -var special "lj/coul 1.0 1.0 1.0" -var coeff "* * ${_ok}")
peridem_contact_error(special_13 "requires special_bonds lj weights 1.0 for 1-3 and 1-4 pairs"
  -var special "lj/coul 0.0 0.0 1.0" -var coeff "* * ${_ok}")
peridem_contact_error(special_lj_only
  "requires special_bonds coul weights 1.0 for 1-3 and 1-4 pairs too \\(now 0 and 0\\)"
  -var special "lj 0.0 1.0 1.0" -var coeff "* * ${_ok}")
peridem_contact_error(self_value "pair_style peridem/contact: self must be yes or no, not maybe"
  -var settings "self maybe" -var coeff "* * ${_ok}")
peridem_contact_error(unknown_keyword "pair_coeff: unknown keyword stiffness"
  -var coeff "* * ${_ok} stiffness 3")
peridem_contact_error(mix_laws "types 1 and 2 use different damping or friction laws"
  -var coeff "1 1 ${_ok} damping nodal 0.5" -var extra "pair_coeff 2 2 ${_ok} friction coulomb 0.5")

# Rc larger than the horizon: a warning naming both values, the run goes on
add_test(NAME contact_rc_above_horizon_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex
          "WARNING: pair_coeff: contact radius Rc = 0.5 is larger than the horizon 0.3"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/pair_contact_error.in -log none
          -var coeff "* * Kn 1 Rc 0.5 horizon 0.3")
# centroid_range: only with damping centroid, never below R_c, not for walls
peridem_contact_error(centroid_range_without_centroid
  "pair_coeff: centroid_range 0.3 needs damping centroid eps_n C"
  -var coeff "* * Kn 1 horizon 0.5 Rc 0.2 centroid_range 0.3")
peridem_contact_error(centroid_range_below_rc
  "pair_coeff: centroid_range 0.1 must be >= the contact radius Rc = 0.2"
  -var coeff "* * Kn 1 horizon 0.5 Rc 0.2 damping centroid 0.9 100 centroid_range 0.1")
peridem_contact_error(centroid_range_zero "pair_coeff: centroid_range must be > 0, not 0"
  -var coeff "* * Kn 1 horizon 0.5 Rc 0.2 damping centroid 0.9 100 centroid_range 0")
peridem_add_error_test(centroid_range_in_wall ${_in}/wall_error.in
  "fix peridem/wall: centroid_range belongs to damping centroid, which is available in pair_coeff"
  -var wall "ylo 0.0 Kn 1 Rc 0.5 horizon 1 centroid_range 0.6" -var nsteps 0)
# centroid_bounding: only with damping centroid, not with centroid_range, not for walls
peridem_contact_error(centroid_bounding_without_centroid
  "pair_coeff: centroid_bounding 1.01 needs damping centroid eps_n C"
  -var coeff "* * Kn 1 horizon 0.5 Rc 0.2 centroid_bounding 1.01")
peridem_contact_error(centroid_bounding_and_range
  "pair_coeff: centroid_bounding and centroid_range exclude each other"
  -var coeff "* * Kn 1 horizon 0.5 Rc 0.2 damping centroid 0.9 100 centroid_range 0.3 centroid_bounding 1.01")
peridem_contact_error(centroid_bounding_zero "pair_coeff: centroid_bounding must be > 0, not 0"
  -var coeff "* * Kn 1 horizon 0.5 Rc 0.2 damping centroid 0.9 100 centroid_bounding 0")
peridem_add_error_test(centroid_bounding_in_wall ${_in}/wall_error.in
  "fix peridem/wall: centroid_bounding belongs to damping centroid, which is available in pair_coeff"
  -var wall "ylo 0.0 Kn 1 Rc 0.5 horizon 1 centroid_bounding 1.01" -var nsteps 0)
# centroid_range of unlike types without their own pair_coeff: the mean of
# the two reaches (R_c where a type has no range), like R_c itself
add_test(NAME contact_centroid_range_mixed
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex
          "peridem/contact 1 2: .*mixed from types 1 and 2.*grains touch below 0.25\\)"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/pair_contact_error.in -log none -echo none
          -var coeff "1 1 Kn 1 horizon 0.5 Rc 0.2 damping centroid 0.9 100 centroid_range 0.3"
          -var extra "pair_coeff 2 2 Kn 1 horizon 0.5 Rc 0.2 damping centroid 0.9 100"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# centroid_bounding F: the dashpot between the centres of two disks closer than b + b' + F R_c
# (bounding radii) and farther apart than R_c node to node equals eq. 26-29 (computed in the
# input); nothing beyond the onset, for receding disks, or with the node onset; 1 and 2 ranks
foreach(_np 1 2)
  foreach(_case "gap2:-var;gap;2" "gap3.5:-var;gap;3.5" "recede:-var;gap;2;-var;v;-0.1"
                "node:-var;gap;2;-var;onset;node")
    string(REPLACE ":" ";" _parts "${_case}")
    list(GET _parts 0 _name)
    list(REMOVE_AT _parts 0)
    add_test(NAME contact_centroid_bounding_${_name}_np${_np}
      COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex PERIDEM-CENTROID-BOUNDING
              ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
              -in ${_in}/pair_centroid_bounding.in ${_parts} -var tag ${_name}_np${_np}
              -var potentials ${PROJECT_SOURCE_DIR}/potentials -log none)
    set_tests_properties(contact_centroid_bounding_${_name}_np${_np} PROPERTIES TIMEOUT 120)
  endforeach()
endforeach()
