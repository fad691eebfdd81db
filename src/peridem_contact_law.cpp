/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: node-to-node contact law (see peridem_contact_law.h for references and conventions).
#include "peridem_contact_law.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace peridem {

namespace {

inline double dot3(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

[[noreturn]] void bad_param(const std::string &name, double value, const std::string &rule)
{
  std::ostringstream msg;
  msg << "contact parameter " << name << " = " << value << " is invalid: " << rule;
  throw ParameterError(msg.str());
}

} // namespace

/* ---------------------------------------------------------------------------------------
   parameter validation
------------------------------------------------------------------------------------------ */

void check_contact_params(const ContactParams &p)
{
  if (!(p.Kn > 0.0)) bad_param("Kn", p.Kn, "must be > 0");
  if (!(p.Rc > 0.0)) bad_param("Rc", p.Rc, "must be > 0");
  if (!(p.mu >= 0.0)) bad_param("mu", p.mu, "must be >= 0");
  if (p.damping == ContactDamping::Nodal && !(p.r_d >= 0.0 && p.r_d <= 1.0))
    bad_param("r_d", p.r_d, "damping ratio must lie in [0, 1]");
  if (p.damping == ContactDamping::Restitution) {
    if (!(p.eps_n > 0.0 && p.eps_n <= 1.0)) bad_param("eps_n", p.eps_n, "must lie in (0, 1]");
    if (!(p.C > 0.0)) bad_param("C", p.C, "must be > 0");
    if (!(p.kappa_eff > 0.0)) bad_param("kappa_eff", p.kappa_eff, "must be > 0");
  }
}

/* ---------------------------------------------------------------------------------------
   repulsion Bhattacharya & Lipton 2023, eq. (4.1) / Sec. 4.4, damping eq. (4.5) or Jha et al. 2021,
eq. (22)-(25), friction Bhattacharya & Lipton 2023, eq. (4.3) or Jha et al. 2021, eq. (19)-(20)
------------------------------------------------------------------------------------------ */

ContactResult contact_force(const ContactInput &in, const ContactParams &p)
{
  ContactResult res;
  const EffectiveRadius er = effective_contact_radius(p.Rc, in.ref_dist);
  const double r2 = dot3(in.sep, in.sep);
  if (!(r2 < er.radius * er.radius) || r2 == 0.0) return res; // coincident: no direction
  res.contact = true;

  const double r = std::sqrt(r2);
  const double e[3] = {in.sep[0] / r, in.sep[1] / r, in.sep[2] / r};
  const double K = p.Kn * er.stiffness_factor;

  // Repulsion: F_r = -K (R - r) V_i V_j e, E = 1/2 K (R - r)^2 V_i V_j.
  const double fr = repulsion_force(K, er.radius, r, in.vol_i, in.vol_j);
  res.energy = repulsion_energy(K, er.radius, r, in.vol_i, in.vol_j);

  const double m_red = reduced_mass(in.mass_i, in.mass_j);
  const double vn = dot3(in.vrel, e); // > 0: approaching

  // Normal damping: F_d = -c vn e.
  double c = 0.0;
  if (p.damping == ContactDamping::Nodal) {
    // Bhattacharya & Lipton 2023, eq. (4.5) derivation: c = 2 r_d sqrt(k m), k = K V_i V_j, m =
    // m_red (= rho V_x for a rigid partner, which is Bhattacharya & Lipton's (2023) beta_d V_x V_y
    // with beta_d = 2 r_d sqrt(K rho/V_y)).
    c = 2.0 * p.r_d * std::sqrt(K * in.vol_i * in.vol_j * m_red);
  } else if (p.damping == ContactDamping::Restitution) {
    // Jha et al. 2021, eq. (23) with m_eq of eq. (24) (harmonic mean; 2 m_i for a rigid partner).
    c = restitution_damping_coefficient(p.eps_n, p.C, p.kappa_eff, p.Rc,
                                        harmonic_mean(in.mass_i, in.mass_j));
  }
  double fd = 0.0;
  if (c > 0.0 && (vn > 0.0 || !p.damp_approach_only)) fd = -c * vn;

  res.fpair = fr + fd;
  for (int k = 0; k < 3; ++k) {
    res.f_rep[k] = fr * e[k];
    res.f_damp[k] = fd * e[k];
  }

  // Friction: opposes the tangential relative velocity vt = vrel - vn e.
  if (p.friction != ContactFriction::None && p.mu > 0.0) {
    const double vt[3] = {in.vrel[0] - vn * e[0], in.vrel[1] - vn * e[1], in.vrel[2] - vn * e[2]};
    const double vt_norm = std::sqrt(dot3(vt, vt));
    const double fn = in.friction_normal_force >= 0.0 ? in.friction_normal_force : std::fabs(fr);
    const double slip = p.mu * fn; // Coulomb bound mu |F_r|
    if (vt_norm > 0.0 && slip > 0.0) {
      double scale = slip / vt_norm; // slip: -mu|F_r| vt/|vt|
      if (p.friction == ContactFriction::Regularized && in.dt > 0.0) {
        // Bhattacharya & Lipton 2023, eq. (4.3): stick when |vt| <= v_thr = mu|F_r| dt/m; then F =
        // -(1/eps_f) vt with eps_f = dt/m, which stops the relative tangential motion of the pair
        // in one step.
        const double v_thr = slip * in.dt / m_red;
        if (vt_norm <= v_thr) {
          scale = m_red / in.dt;
          res.stick = true;
        }
      }
      for (int k = 0; k < 3; ++k) res.f_fric[k] = -scale * vt[k];
    }
  }

  for (int k = 0; k < 3; ++k) res.f[k] = res.f_rep[k] + res.f_damp[k] + res.f_fric[k];
  res.power = fd * vn + dot3(res.f_fric, in.vrel);
  return res;
}

/* ---------------------------------------------------------------------------------------
   centroid damping Jha et al. 2021, eq. (26)-(27)
------------------------------------------------------------------------------------------ */

double centroid_damping_force(const double sep_c[3], const double vrel_c[3], double beta_bar,
                              bool in_contact, double f[3])
{
  f[0] = f[1] = f[2] = 0.0;
  const double r = std::sqrt(dot3(sep_c, sep_c));
  if (!in_contact || r == 0.0 || beta_bar <= 0.0) return 0.0;
  const double e[3] = {sep_c[0] / r, sep_c[1] / r, sep_c[2] / r};
  const double vn = dot3(vrel_c, e); // = -delta_dot_c
  if (vn <= 0.0) return 0.0;         // only while the centres approach
  for (int k = 0; k < 3; ++k) f[k] = -beta_bar * vn * e[k];
  return -beta_bar * vn * vn;
}

/* ---------------------------------------------------------------------------------------
   stable time step (formulas in the header)
------------------------------------------------------------------------------------------ */

double symmetric_max_eigenvalue(const double *a, int dimension)
{
  if (dimension == 2) {
    const double m = 0.5 * (a[0] + a[1]), d = 0.5 * (a[0] - a[1]);
    return m + std::sqrt(d * d + a[2] * a[2]);
  }
  // 3x3: trigonometric solution of the characteristic polynomial (real symmetric)
  const double xx = a[0], yy = a[1], zz = a[2], xy = a[3], xz = a[4], yz = a[5];
  const double p1 = xy * xy + xz * xz + yz * yz;
  const double q = (xx + yy + zz) / 3.0;
  if (p1 == 0.0) return std::max(xx, std::max(yy, zz));
  const double p2 = (xx - q) * (xx - q) + (yy - q) * (yy - q) + (zz - q) * (zz - q) + 2.0 * p1;
  const double p = std::sqrt(p2 / 6.0);
  const double b[6] = {(xx - q) / p, (yy - q) / p, (zz - q) / p, xy / p, xz / p, yz / p};
  const double detb = b[0] * (b[1] * b[2] - b[5] * b[5]) - b[3] * (b[3] * b[2] - b[5] * b[4]) +
                      b[4] * (b[3] * b[5] - b[1] * b[4]);
  const double r = std::max(-1.0, std::min(1.0, 0.5 * detb));
  return q + 2.0 * p * std::cos(std::acos(r) / 3.0);
}

double wall_contact_stiffness(int dimension, double Kn, double V, double Rc, double d)
{
  if (!(d < Rc)) return 0.0;
  d = std::max(d, 0.0);
  if (dimension == 2) return 2.0 * Kn * V * std::sqrt(Rc * Rc - d * d) * (Rc - d);
  return kPi * Kn * V * (Rc * Rc - d * d) * (Rc - d);
}

namespace {
// The stiffest wall contact a node of volume V (spacing h) meets at the shallow depth of its
// wall's R_c: the pair's law, or each wall's own (fix peridem/wall with Kn, Rc of its own).
double stiffest_wall(const TimeStepInput &in, double V, double h)
{
  auto stiffness = [&](double Kn, double R) {
    const double shallow = R > h ? R - std::sqrt(R * R - h * h) : R;
    return wall_contact_stiffness(in.dimension, Kn, V, R, R - shallow);
  };
  if (in.wall_laws.empty()) return stiffness(in.Kn, in.Rc);
  double k = 0.0;
  for (const auto &law : in.wall_laws) k = std::max(k, stiffness(law[0], law[1]));
  return k;
}
} // namespace

TimeStepEstimate stable_time_step(const TimeStepInput &in)
{
  if (in.dimension != 2 && in.dimension != 3)
    throw ParameterError("stable_time_step: dimension must be 2 or 3");
  TimeStepEstimate out;
  const bool two_d = in.dimension == 2;
  const double eps = in.horizon;

  if (in.c > 0.0) {
    if (!(in.rho > 0.0) || !(eps > 0.0))
      throw ParameterError("stable_time_step: density and horizon must be > 0");
    const bool conic = in.micromodulus == Micromodulus::Conic;
    double integral; // integral over the horizon of w(r)/r dV
    if (two_d)
      integral = conic ? kPi * eps : 2.0 * kPi * eps;
    else
      integral = conic ? 2.0 / 3.0 * kPi * eps * eps : 2.0 * kPi * eps * eps;
    // isotropic family: lambda_max(A) = (1/d) of the row sum
    out.dt_bond = bond_critical_time_step(in.rho, in.c * integral / in.dimension);
  }
  if (in.bond_omega2 > 0.0) out.dt_bond = 2.0 / std::sqrt(in.bond_omega2);

  if (in.Kn > 0.0) {
    const double V = in.node_volume, m = in.min_node_mass, R = in.Rc;
    if (!(V > 0.0) || !(m > 0.0) || !(R > 0.0))
      throw ParameterError("stable_time_step: node volume, node mass and Rc must be > 0");
    const double k = in.Kn * V * V; // one pair spring
    const double h = two_d ? std::sqrt(V) : std::cbrt(V);
    // penetration below which a lattice surface offers at most 2^(d-1) partners
    out.shallow_depth = R > h ? R - std::sqrt(R * R - h * h) : R;
    double n = in.n_contacts; // effective pair springs: omega_c^2 = 2 n k/m
    if (n <= 0.0) {
      const double ball_area = two_d ? kPi * R * R : 4.0 / 3.0 * kPi * R * R * R;
      const double ball = 2.0 * std::ceil(ball_area / V) / in.dimension;
      const double shallow = 2.0 * (two_d ? 2.0 : 4.0);
      double neff = std::min(ball, shallow);
      if (in.walls) neff = std::max(neff, stiffest_wall(in, V, h) / k);
      n = 0.5 * neff;
    }
    out.n_contacts = n;
    const double z = in.damping_ratio;
    out.dt_contact = std::sqrt(2.0 * m / (n * k)) * (std::sqrt(1.0 + z * z) - z);
  }

  const double inv2 = 1.0 / (out.dt_bond * out.dt_bond) + 1.0 / (out.dt_contact * out.dt_contact);
  if (inv2 > 0.0) {
    out.dt_critical = 1.0 / std::sqrt(inv2);
    out.dt_recommended = in.safety * out.dt_critical;
  }
  return out;
}

} // namespace peridem
