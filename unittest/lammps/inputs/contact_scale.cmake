# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# contact at the papers' scale: the K_n form of the dimension,
# start-up checks, Bhattacharya & Lipton's (2023) bed at its time step

# Kn_form: bad values and a form that makes no sense for the dimension
set(_cs ${_in}/contact_scale_error.in)
peridem_add_error_test(kn_form_unknown ${_cs}
  "pair_coeff: Kn_form must be eps4 or eps5, not eps3"
  -var coeff "* * Kn 1 Rc 0.5 Kn_form eps3")
peridem_add_error_test(kn_form_missing ${_cs}
  "pair_coeff: Kn_form needs eps4 or eps5" -var coeff "* * Kn 1 Rc 0.5 Kn_form")
peridem_add_error_test(kn_form_eps4_in_3d ${_cs}
  "pair_coeff: Kn_form eps4 \\(force per unit thickness\\) is for 2d simulations only; a 3d simulation uses eps5"
  -var dim 3 -var coeff "* * Kn 1 Rc 0.5 Kn_form eps4")
peridem_add_error_test(kn_form_eps4_in_3d_wall ${_cs}
  "fix peridem/wall: Kn_form eps4 \\(force per unit thickness\\) is for 2d simulations only"
  -var dim 3 -var wall "zlo 0.0 Kn 1 Rc 0.5 Kn_form eps4")
peridem_add_error_test(kn_form_unknown_wall ${_cs}
  "fix peridem/wall: Kn_form must be eps4 or eps5, not 4"
  -var wall "ylo 0.0 Kn 1 Rc 0.5 Kn_form 4")

# the log states K_n and its form: 2D default eps4, 3D eps5, eps5 on request in 2D;
# K_n = 18 k/(pi eps^p) from a material (M2 of Bhattacharya & Lipton 2023, k = 2 GPa, eps = 0.5 mm):
# 18 2e9/(pi 0.5e-3^4) = 1.8335e+23, 18 2e9/(pi 0.5e-3^5) = 3.6669e+26
set(_gs "material ${PROJECT_SOURCE_DIR}/potentials/grain_shape_2023_table2.peridem M2")
foreach(_case "2;;1.833464944418[0-9]*e\\+23 \\(Kn_form eps4: 18 k/\\(pi eps\\^4\\), 2d per unit thickness"
              "2;Kn_form eps5;3.666929888837[0-9]*e\\+26 \\(Kn_form eps5: 18 k/\\(pi eps\\^5\\)"
              "3;;3.666929888837[0-9]*e\\+26 \\(Kn_form eps5")
  list(GET _case 0 _dim)
  list(GET _case 1 _form)
  list(GET _case 2 _regex)
  string(REPLACE " " "_" _tag "${_dim}d${_form}")
  add_test(NAME contact_kn_form_log_${_tag}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "fix peridem/wall wall: Kn = ${_regex}"
            $<TARGET_FILE:lmp_peridem> -in ${_cs} -log none -echo none -var dim ${_dim} -var units si
            -var coeff "* * ${_gs} Rc 1 ${_form}" -var wall "xlo -1 ${_gs} Rc 1 ${_form}")
endforeach()

# start-up checks: a node already within Rc of a wall (warning with the count and grain),
# a node wholly beyond a wall at the first step (an error naming the placement, not the time
# step), and the neighbour skin that overflows LAMMPS's list (warning with a skin that fits)
add_test(NAME contact_startup_wall_overlap_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "WARNING: fix peridem/wall wall: 1 nodes and walls are closer than the contact radius Rc = 0.5 at the first step \\(e.g. grain 1 / wall ylo\\)"
          $<TARGET_FILE:lmp_peridem> -in ${_cs} -log none -echo none -var wall "ylo 0.8 Kn 1 Rc 0.5")
add_test(NAME contact_startup_grain_overlap_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "WARNING: pair_style peridem/contact: [0-9]+ node pairs of different grains are closer than the contact radius Rc = 0.3 at the first step \\(e.g. grain 1 / grain 2"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_startup.in -log none -echo none)
set_tests_properties(contact_startup_grain_overlap_warns PROPERTIES
  FAIL_REGULAR_EXPRESSION "grain 1 / grain 3")
# the warning, then LAMMPS's own error
add_test(NAME contact_startup_skin_overflow_warns
  COMMAND ${PERIDEM_RUN}/expect_error.sh
          --warning "pair_style peridem/contact: the neighbour list reaches 10.3 \\(cutoff 0.3 \\+ neighbor skin 10\\).*more than neigh_modify one 2000"
          "Neighbor list overflow"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_startup.in -log none -echo none -var skin 10 -var big 1)
set_tests_properties(contact_startup_skin_overflow_warns PROPERTIES TIMEOUT 60)

# Bhattacharya & Lipton's (2023) bed (Sec. 7.3: M2, eps = 0.5 mm, h = eps/8, R_c = eps/5, mu = 0.8,
# r_d = 0.8, g = 5000 m/s^2) at its time step 70 ns, reduced to 4 grains of radius
# 0.2-0.25 mm (the 24-grain bed is examples/bed-settling): with the 2D form it settles (kinetic
# energy 100x below its peak, no node faster than 3x free fall), with eps5 it blows up and the
# time-step estimate warns
set(_bed ${PROJECT_SOURCE_DIR}/examples/bed-settling/in.bed)
set(_small -var nx 2 -var ny 2 -var rmin 2e-4 -var rmax 2.5e-4 -var chunk 500
           -var potentials ${PROJECT_SOURCE_DIR}/potentials)
# <name>_eps4_settles and <name>_eps5_unstable for the bed of in.bed with the given variables
function(peridem_bed_pair name)
  add_test(NAME ${name}_eps4_settles
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex PERIDEM-SETTLED
            $<TARGET_FILE:lmp_peridem> -in ${_bed} -log none -echo none ${ARGN} -var maxsteps 60000
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${name}_eps4_settles PROPERTIES
    FAIL_REGULAR_EXPRESSION "PERIDEM-UNSTABLE|PERIDEM-NOT-SETTLED|exceeds the recommended" TIMEOUT 300)
  add_test(NAME ${name}_eps5_unstable
    COMMAND ${PERIDEM_RUN}/expect_pass.sh --regex "PERIDEM-UNSTABLE at step"
            $<TARGET_FILE:lmp_peridem> -in ${_bed} -log none -echo none ${ARGN} -var kn_form eps5
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${name}_eps5_unstable PROPERTIES
    FAIL_REGULAR_EXPRESSION "PERIDEM-SETTLED|PERIDEM-NOT-SETTLED" TIMEOUT 300)
endfunction()
peridem_bed_pair(bed_gs_70ns ${_small})
add_test(NAME bed_gs_70ns_eps5_warns
  COMMAND ${PERIDEM_RUN}/expect_pass.sh
          --regex "WARNING: pair_style peridem/contact: time step 7e-08 exceeds the recommended"
          $<TARGET_FILE:lmp_peridem> -in ${_bed} -log none -echo none ${_small} -var kn_form eps5
          -var maxsteps 0
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(bed_gs_70ns_eps5_warns PROPERTIES TIMEOUT 120)

# the time-step estimate against the measured stability threshold on Jha et al.'s (2021)
# two-particle drop (h = 0.1423 mm, damping centroid 0.8 100), with K_n eps^5 (its Table 2)
# and eps^4: stable at the critical estimate, unstable at twice it (bisected thresholds
# 1.4x and 1.3x the estimate, doc/pair_peridem_contact.rst)
add_test(NAME timestep_estimate_vs_threshold_drop
  COMMAND python3 ${PROJECT_SOURCE_DIR}/bench/timestep/bisect_dt.py
          --lmp $<TARGET_FILE:lmp_peridem> --cases rest5,rest4 --check 2.0)
set_tests_properties(timestep_estimate_vs_threshold_drop PROPERTIES
  FAIL_REGULAR_EXPRESSION "PERIDEM-FAIL|Traceback" TIMEOUT 300)

# the estimate against thresholds the test measures itself, on Bhattacharya & Lipton's (2023) small
# bed (walls, damping 0.8, friction 0.8): eps5 (contact-limited: node pairs and walls), eps4
# (bond-limited) and state-based grains (bond_style peridem/lps, the LPS spring bound): each
# run stable at the critical estimate and unstable at twice it, i.e. estimate < threshold <
# 2 x estimate (bisected: 1.56-1.64, 1.42-1.45, 1.43-1.48; doc/pair_peridem_contact.rst).
# The previous wall and contact terms (a node pressed onto the wall plane, the ball full of
# partners) gave 3.6x on eps5: the 2x run was stable and this test failed.
add_test(NAME timestep_estimate_vs_threshold_bed
  COMMAND python3 ${PROJECT_SOURCE_DIR}/bench/timestep/bisect_dt.py
          --lmp $<TARGET_FILE:lmp_peridem> --cases bed5,bed4,bed4lps --check 2.0)
set_tests_properties(timestep_estimate_vs_threshold_bed PROPERTIES
  FAIL_REGULAR_EXPRESSION "PERIDEM-FAIL|Traceback" TIMEOUT 300)

# a 20-grain bed (5 x 4 security disks, radii 0.2-0.3 mm, 996 nodes) with the Sec. 7.3
# parameters at 70 ns: settles (kinetic energy 100x below its peak, step 28,000 when written),
# and with eps5 is detected as unstable
set(_bed20 -var nx 5 -var ny 4 -var rmin 2e-4 -var rmax 3e-4 -var chunk 500
           -var potentials ${PROJECT_SOURCE_DIR}/potentials)
peridem_bed_pair(bed20_gs_70ns ${_bed20})

# the neighbour overflow seen with sub-mm spacings: a 3d grain at h = 0.04 mm with LAMMPS's SI
# default skin (1 mm) overflows; the warning comes first and names a skin that fits
add_test(NAME contact_startup_skin_overflow_warns_3d_si
  COMMAND ${PERIDEM_RUN}/expect_error.sh
          --warning "pair_style peridem/contact: the neighbour list reaches 0.001038 \\(cutoff 3.8e-05 \\+ neighbor skin 0.001\\).*Use a smaller skin \\(neighbor 0.000[0-9]+ bin"
          "Neighbor list overflow"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/contact_skin_3d_si.in -log none -echo none)
set_tests_properties(contact_startup_skin_overflow_warns_3d_si PROPERTIES TIMEOUT 120)

# issue 27, item 8: a wall with its own, stiffer Kn enters pair_style peridem/contact's
# time-step estimate (it used the pair's Kn for the walls too)
add_test(NAME contact.time_step_sees_wall_kn
  COMMAND ${PERIDEM_RUN}/expect_pass.sh
          --regex "types 1 1: time step estimate 1.05e-07 \\(critical 1.313e-07: bonds 1.147e-06, contact 1.322e-07 .*; walls with their own law: Kn = 1e\\+26, Rc = 0.0009\\)"
          $<TARGET_FILE:lmp_peridem> -in ${_in}/catalogue/base.in -log none -echo screen
          -var input_dir ${PROJECT_SOURCE_DIR}/unittest/force-styles/tests -var pair_style peridem/contact -var pre "pair_coeff * * Kn 1e23 Rc 9e-4"
          -var bad "fix w all peridem/wall xlo -1e-2 Kn 1e26 Rc 9e-4")
