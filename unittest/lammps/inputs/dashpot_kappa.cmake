# ----------------------------------------------------------------------
# PERIDEM - peridynamic grains (PeriDEM) for LAMMPS
#
# Copyright (C) 2026 The PERIDEM developers.
# This software is distributed under the GNU General Public License,
# version 2; see the LICENSE file in the top-level PERIDEM directory.
# SPDX-License-Identifier: GPL-2.0-only
# ----------------------------------------------------------------------
# The restitution and centroid dashpots' kappa and beta (Jha et al. 2021, eq. 23, 28) in the
# log, and the 2d warning when an explicit Kn feeds kappa under the default Kn_form eps4
# (issue 27, item 5). Kn = 18 K/(pi eps^5) of material M1 (K = 0.0216 GPa, eps = 0.6 mm),
# as the PeriDEM paper's inputs give it; Rc = 0.95 h with h = 0.1423 mm. Values computed
# apart (python3): eps5 kappa = K = 2.16e7, eps4 kappa = K/eps = 3.6e10; zeta(0.95) =
# 0.0163250, beta = 2 C zeta sqrt(kappa Rc) sqrt(m_eq): C = 100: 176.431 and 7202.75, C = 1:
# 1.76431 and 72.0275 per sqrt(mass).
set(_cat ${_in}/catalogue)
set(_kn "Kn 1.5915494309189538e24 horizon 0.6e-3 Rc 1.35185e-4")
set(_quiet --absent "WARNING: .*: in 2d an explicit Kn under the default Kn_form eps4")
set(_run2d $<TARGET_FILE:lmp_peridem> -in ${_cat}/base2d.in -log none -echo screen)
# dashpot.<name>: the command <bad> on the empty 2d box (pair_coeff after pair_style
# peridem/contact and comm_modify vel yes, or a fix peridem/wall), expect_pass.sh's checks after
function(peridem_dashpot_pair name bad)
  add_test(NAME dashpot.${name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${ARGN} ${_run2d} -var pre "pair_style peridem/contact"
            -var pre2 "comm_modify vel yes" -var bad "${bad}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()
function(peridem_dashpot_wall name bad)
  add_test(NAME dashpot.${name}
    COMMAND ${PERIDEM_RUN}/expect_pass.sh ${ARGN} ${_run2d} -var bad "${bad}"
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()

# the PeriDEM paper's Kn under the 2d default: kappa = K/eps, warned, beta 40.8x larger
peridem_dashpot_pair(pair_kn_2d_default_warns "pair_coeff * * ${_kn} damping centroid 0.95 100"
  --regex "WARNING: pair_coeff: in 2d an explicit Kn under the default Kn_form eps4 gives the centroid dashpot kappa = pi eps\\^4 Kn/18 = 3.6e\\+10 \\(horizon 0.0006\\).*Give Kn_form eps5 \\(or kappa K\\)"
  --regex "kappa = 3.6e\\+10 \\(pi eps\\^4 Kn/18 from Kn, horizon 0.0006 and Kn_form eps4\\), beta = 7202.75 sqrt\\(M_eq\\) \\(2 C zeta sqrt\\(kappa Rc M_eq\\), zeta = 0.016325 from eps_n, Jha et al. 2021 eq. 28")
peridem_dashpot_wall(wall_kn_2d_default_warns "fix w all peridem/wall ylo -4e-3 ${_kn} damping restitution 0.95 1"
  --regex "WARNING: fix peridem/wall: in 2d an explicit Kn under the default Kn_form eps4 gives the restitution dashpot kappa = pi eps\\^4 Kn/18 = 3.6e\\+10"
  --regex "fix peridem/wall w: .*kappa = 3.6e\\+10 \\(pi eps\\^4 .*\\), beta = 72.0275 sqrt\\(m_eq\\) .*eq. 23. m_eq = harmonic mean of the two node masses, 2 m at a wall")
# Kn_form eps5 (the paper's form): kappa = K, no warning
peridem_dashpot_pair(pair_kn_eps5_no_warning "pair_coeff * * ${_kn} Kn_form eps5 damping centroid 0.95 100" ${_quiet}
  --regex "kappa = 2.16e\\+07 \\(pi eps\\^5 Kn/18 from Kn, horizon 0.0006 and Kn_form eps5\\), beta = 176.431 sqrt\\(M_eq\\)")
peridem_dashpot_wall(wall_kn_eps5_no_warning "fix w all peridem/wall ylo -4e-3 ${_kn} Kn_form eps5 damping restitution 0.95 1"
  ${_quiet} --regex "kappa = 2.16e\\+07 .*beta = 1.76431 sqrt\\(m_eq\\)")
# no explicit Kn: kappa is the material's bulk modulus (either form), no warning
peridem_dashpot_pair(pair_material_no_warning
  "pair_coeff * * material ${PROJECT_SOURCE_DIR}/potentials/peridem_2021_table1.peridem M1 Rc 1.35185e-4 damping centroid 0.95 100"
  ${_quiet} --regex "kappa = 2.16e\\+07 \\(bulk modulus of material M1 of .*peridem_2021_table1.peridem\\), beta = 176.431 sqrt\\(M_eq\\)")
# kappa given: used as given, no warning
peridem_dashpot_pair(pair_kappa_given "pair_coeff * * ${_kn} kappa 2.16e7 damping centroid 0.95 100"
  ${_quiet} --regex "kappa = 2.16e\\+07 \\(kappa given\\), beta = 176.431 sqrt\\(M_eq\\)")
# kappa without a dashpot that uses it would be ignored: refused
peridem_add_error_test(dashpot_kappa_without_damping ${_cat}/base2d.in
  "pair_coeff: kappa 2.16e\\+07 needs damping restitution or centroid"
  -var pre "pair_style peridem/contact" -var bad "pair_coeff * * ${_kn} kappa 2.16e7")
