# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# fix peridem/wall and the shared contact keywords (lmp_peridem_contact)

# example: 1 and 2 MPI ranks give the same thermo output
peridem_add_example_test(wall_drop wall-drop in.wall_drop 1 2)

# bad input gets a clear error naming the command and the value
function(peridem_wall_error name wallargs regex)
  peridem_add_error_test(wall_${name} ${_in}/wall_error.in "${regex}"
    -var wall "${wallargs}" -var nsteps 0 ${ARGN})
endfunction()
peridem_wall_error(order "ylo 2.0 yhi 1.0 Kn 1 Rc 0.5"
  "fix peridem/wall: wall ylo at 2 is not below wall yhi at 1")
peridem_wall_error(variable_order "ylo 3.5 yhi v_top Kn 1 Rc 0.5"
  "fix peridem/wall: wall ylo at 3.5 is not below wall yhi at 3 \\(from its variable\\)")
peridem_wall_error(rc_zero "ylo 0.0 Kn 1 Rc 0" "fix peridem/wall: Rc \\(contact radius\\) must be > 0, not 0")
peridem_wall_error(rc_negative "ylo 0.0 Kn 1 Rc -0.1" "Rc \\(contact radius\\) must be > 0, not -0.1")
peridem_wall_error(not_equal_style "ylo 0.0 yhi v_atomic Kn 1 Rc 0.5"
  "fix peridem/wall: variable atomic for wall yhi is not equal-style")
peridem_wall_error(no_variable "ylo 0.0 yhi v_nothing Kn 1 Rc 0.5"
  "variable nothing for wall yhi does not exist")
peridem_wall_error(unknown_wall "ylo 0.0 ymid 1.0 Kn 1 Rc 0.5"
  "fix peridem/wall: unknown wall or keyword ymid")
peridem_wall_error(unknown_velocity_wall "ylo 0.0 velocity top 1.0 Kn 1 Rc 0.5"
  "fix peridem/wall: unknown wall top")
peridem_wall_error(z_in_2d "zlo 0.0 Kn 1 Rc 0.5" "wall zlo needs a 3D simulation")
peridem_wall_error(undefined_moving "ylo 0.0 velocity yhi 1.0 Kn 1 Rc 0.5"
  "wall yhi moves but is not defined")
peridem_wall_error(mu_negative "ylo 0.0 Kn 1 Rc 0.5 friction coulomb -0.3"
  "friction coefficient mu must be >= 0, not -0.3")
peridem_wall_error(rd_range "ylo 0.0 Kn 1 Rc 0.5 damping nodal 1.5"
  "damping ratio r_d must lie in \\[0, 1\\], not 1.5")
peridem_wall_error(eps_range "ylo 0.0 Kn 1 Rc 0.5 horizon 1 damping restitution 0 1"
  "restitution eps_n must lie in \\(0, 1\\], not 0")
peridem_wall_error(restitution_needs_k "ylo 0.0 Kn 1 Rc 0.5 damping restitution 0.9 1"
  "damping restitution needs the bulk modulus")
peridem_wall_error(no_kn "ylo 0.0 Rc 0.5" "give exactly one of 'material FILE NAME' and 'Kn value'")
peridem_wall_error(factor_no_spacing "ylo 0.0 Kn 1 Rc_factor 0.95"
  "Rc_factor needs the node spacing: add 'spacing h'")
peridem_wall_error(unknown_keyword "ylo 0.0 Kn 1 Rc 0.5 stiffness 3"
  "fix peridem/wall: unknown wall or keyword stiffness")
peridem_wall_error(bad_servo "ylo 0.0 yhi 2.0 servo yhi 1.0 -1 0.5 Kn 1 Rc 0.5"
  "servo gain must be > 0, not -1")
peridem_wall_error(shear_normal "ylo 0.0 shear ylo 0.1 0.2 0 Kn 1 Rc 0.5"
  "shear velocity of wall ylo must lie in the wall")
# walls on periodic dimensions are refused, in 2d and 3d
peridem_wall_error(periodic_2d "xlo EDGE ylo 0.0 Kn 1 Rc 0.5"
  "fix peridem/wall: wall xlo is on a periodic dimension \\(x\\); use boundary f, s or m in x"
  -var bnd "p f p")
peridem_wall_error(periodic_3d "ylo 0.0 zhi 0.4 Kn 1 Rc 0.5"
  "fix peridem/wall: wall zhi is on a periodic dimension \\(z\\)"
  -var dim 3 -var bnd "f f p")
# a node completely past a wall (by more than Rc) ends the run by default
peridem_add_error_test(wall_lost_node ${_in}/wall_error.in
  "1 nodes lie more than Rc = 0.5 beyond a wall at the first step \\(e.g. grain 1 / wall yhi\\): a wall placed through a grain"
  -var wall "ylo -1 yhi -0.5 Kn 1 Rc 0.5" -var nsteps 0)

# Rc larger than the horizon: a warning (doc/fix_peridem_wall.rst), the run goes on
add_test(NAME wall_rc_above_horizon_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex
          "WARNING: fix peridem/wall: contact radius Rc = 0.5 is larger than the horizon 0.3"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/wall_error.in -log none -var nsteps 0
          -var wall "ylo 0.0 Kn 1 Rc 0.5 horizon 0.3")

# 'contact pair': the wall takes the pair style's contact law, with the same
# result as the keywords written out
add_test(NAME wall_contact_from_pair
  COMMAND sh -c "$<TARGET_FILE:lmp_peridem> -in ${_in}/wall_contact_pair.in -var mode own -log own.log -screen none && $<TARGET_FILE:lmp_peridem> -in ${_in}/wall_contact_pair.in -var mode pair -log pair.log -screen none && grep -q 'f_box\\[15\\]' pair.log && python3 ${PERIDEM_RUN}/thermo_compare.py own.log pair.log --rtol 0"
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# contact pair with damping centroid: the dashpot between the grain centre and the wall
# (Jha et al. 2021, §3.2) equals eq. 26-29 with M_eq = 2 M at the first step (approach, a
# moving wall) and vanishes for a receding or sliding grain; a damped drop conserves energy
# with the dissipated work counted; 1 and 2 ranks
foreach(_np 1 2)
  foreach(_case approach recede wall slide)
    add_test(NAME wall_centroid_damping_${_case}_np${_np}
      COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-WALL-DAMPING case ${_case}"
              ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
              -in ${_in}/wall_centroid_damping.in -var case ${_case}
              -var potentials ${PROJECT_SOURCE_DIR}/potentials -log none)
    set_tests_properties(wall_centroid_damping_${_case}_np${_np} PROPERTIES TIMEOUT 120)
  endforeach()
  add_test(NAME wall_centroid_energy_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex PERIDEM-WALL-ENERGY
            ${PERIDEM_RUN}/mpirun.sh ${_np} $<TARGET_FILE:lmp_peridem>
            -in ${_in}/wall_centroid_energy.in
            -var potentials ${PROJECT_SOURCE_DIR}/potentials -log none)
  set_tests_properties(wall_centroid_energy_np${_np} PROPERTIES TIMEOUT 300)
endforeach()
peridem_wall_error(contact_pair_without_pair "ylo 0.0 contact pair"
  "fix peridem/wall: contact pair needs pair_style peridem/contact")
peridem_wall_error(contact_pair_and_keywords "ylo 0.0 contact pair Kn 1 Rc 0.5"
  "contact pair takes the contact law from pair_style peridem/contact: give no contact keywords")

# near_list: the walls visit only the nodes near them; the same trajectory as near_list no
# (every node every step) on the 20-grain settling bed of contact_scale.cmake through its first
# wall impacts (3500 steps in runs of 500: each run's setup sorts the atoms), 1 and 2 ranks
foreach(_np 1 2)
  add_test(NAME wall_near_list_bed20_np${_np}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex PERIDEM-NEAR-LIST-SAME
            ${PERIDEM_RUN}/near_list_compare.sh ${_np} $<TARGET_FILE:lmp_peridem>
            ${PROJECT_SOURCE_DIR}/examples/bed-settling/in.bed -var nx 5 -var ny 4 -var rmin 2e-4
            -var rmax 3e-4 -var chunk 500 -var maxsteps 3500
            -var potentials ${PROJECT_SOURCE_DIR}/potentials)
  set_tests_properties(wall_near_list_bed20_np${_np} PROPERTIES
    FAIL_REGULAR_EXPRESSION "PERIDEM-UNSTABLE"
    TIMEOUT 300 WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/near_list_np${_np})
  file(MAKE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/near_list_np${_np})
endforeach()
peridem_wall_error(near_list_value "ylo 0.0 Kn 1 Rc 0.5 near_list maybe"
  "fix peridem/wall: near_list must be no or yes, not maybe")

# a wall less than Rc inside a fixed box face (a wall at EDGE): a node the wall pushes back from
# beyond its plane would leave the box and be lost; warned at the first run. Quiet with Rc of
# room, and at a shrink-wrapped face (boundary m)
set(_tight "walls .* lie less than Rc = 0.5 inside a fixed box face")
add_test(NAME wall_at_fixed_box_face_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh
          --regex "WARNING: fix peridem/wall wall: walls ylo \\(0 inside the face\\), yhi \\(0.3 inside the face\\) lie less than Rc = 0.5 inside a fixed box face"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_scale_error.in -log none -echo none
          -var wall "ylo EDGE yhi 3.7 Kn 1 Rc 0.5")
add_test(NAME wall_with_room_to_box_face_quiet
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "Loop time" --absent "${_tight}"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_scale_error.in -log none -echo none
          -var wall "ylo -0.5 yhi 3.5 Kn 1 Rc 0.5")
add_test(NAME wall_at_shrink_wrapped_face_quiet
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "Loop time" --absent "${_tight}"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_scale_error.in -log none -echo none
          -var wall "ylo -1 Kn 1 Rc 0.5" -var yb m)
