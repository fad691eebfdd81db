/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Closed forms of the linear spring-dashpot that the contact-law tests compare with; not part
// of the library (nothing in src/ needs them).

#ifndef PERIDEM_TEST_CONTACT_REFERENCE_H
#define PERIDEM_TEST_CONTACT_REFERENCE_H

#include <cmath>

namespace peridem_test {

// Restitution of a linear spring-dashpot with damping ratio zeta < 1:
//  damped the whole contact:    exp(-pi zeta/sqrt(1-zeta^2))
//  damped only while approaching (the rebound is undamped, so the rebound speed is
//  omega_0 * maximum compression):  exp(-zeta/sqrt(1-zeta^2) * atan(sqrt(1-zeta^2)/zeta))
inline double restitution_from_damping_ratio(double zeta, bool approach_only)
{
  if (zeta <= 0.0) return 1.0;
  const double w = std::sqrt(1.0 - zeta * zeta);
  if (!approach_only) return std::exp(-M_PI * zeta / w);
  return std::exp(-zeta / w * std::atan2(w, zeta));
}

// The C that makes Jha et al.'s (2021) eq. (23) reproduce eps_n for an isolated node pair with
// the contact spring k = K_n_eff V_i V_j and reduced mass m_red = m_eq/2 (damped during the
// whole contact): C = sqrt(k m_red/(kappa_eff R_c m_eq)) = sqrt(k/(2 kappa_eff R_c)).
inline double restitution_exact_C(double spring_k, double kappa_eff, double R_c)
{
  return std::sqrt(spring_k / (2.0 * kappa_eff * R_c));
}

} // namespace peridem_test

#endif
