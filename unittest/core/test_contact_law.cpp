/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Tests of the pure contact law (src/peridem_contact_law.h): physics invariants, not just values.
#include "contact_reference.h"
#include "peridem_contact_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>
#include <algorithm>

using namespace peridem;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

ContactParams base_params()
{
  ContactParams p;
  p.Kn = 3.0e3;
  p.Rc = 0.1;
  return p;
}

// Random pair inside the contact radius with random velocities, volumes and masses.
ContactInput random_pair(std::mt19937 &gen, double Rc, bool rigid_partner)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.5, 2.0);
  ContactInput in;
  double n2;
  do {
    for (double &s : in.sep) s = u(gen) * Rc;
    n2 = dot(in.sep, in.sep);
  } while (n2 >= Rc * Rc || n2 < 1e-4 * Rc * Rc);
  for (double &v : in.vrel) v = u(gen);
  in.vol_i = 1e-3 * pos(gen);
  in.vol_j = 1e-3 * pos(gen);
  in.mass_i = 2.0 * in.vol_i * pos(gen);
  in.mass_j = rigid_partner ? kInf : 2.0 * in.vol_j * pos(gen);
  in.dt = 1e-3 * pos(gen);
  return in;
}

ContactInput swapped(const ContactInput &in)
{
  ContactInput s = in;
  for (int k = 0; k < 3; ++k) {
    s.sep[k] = -in.sep[k];
    s.vrel[k] = -in.vrel[k];
  }
  std::swap(s.vol_i, s.vol_j);
  std::swap(s.mass_i, s.mass_j);
  return s;
}

// All damping x friction variants, with some values for their constants.
std::vector<ContactParams> all_variants()
{
  std::vector<ContactParams> out;
  for (auto d : {ContactDamping::None, ContactDamping::Nodal, ContactDamping::Restitution})
    for (auto f : {ContactFriction::None, ContactFriction::Regularized, ContactFriction::Coulomb})
      for (bool approach : {true, false}) {
        ContactParams p = base_params();
        p.damping = d;
        p.r_d = 0.7;
        p.eps_n = 0.6;
        p.C = 2.0;
        p.kappa_eff = 5.0;
        p.damp_approach_only = approach;
        p.friction = f;
        p.mu = 0.5;
        out.push_back(p);
      }
  return out;
}

} // namespace

TEST(ContactLaw, StiffnessForm2dPerUnitThickness)
{
  // 2D default 18 k/(pi eps^4): K_n (R_c - r) V_i V_j with areas V (m^2) is a force per unit
  // thickness (N/m) only if K_n is in Pa/m^4; the eps^5 form is exactly 1/eps times stiffer.
  EXPECT_EQ(default_kn_form(2), KnForm::Eps4);
  EXPECT_EQ(default_kn_form(3), KnForm::Eps5);
  const double k = 2.0e9, eps = 0.5e-3; // M2 of Bhattacharya & Lipton (2023), its Sec. 7.3 horizon
  EXPECT_NEAR(contact_stiffness(k, eps, KnForm::Eps4) / (18.0 * k / (M_PI * std::pow(eps, 4))), 1.0,
              1e-14);
  EXPECT_NEAR(contact_stiffness(k, eps, KnForm::Eps5) / contact_stiffness(k, eps, KnForm::Eps4),
              1.0 / eps, 1e-9);
  // units by scaling: lengths x 10 leave k (Pa) unchanged; a 2D force per thickness scales
  // like stress x length (x 10) and K_n (R_c - r) V^2 scales like K_n x 10^5
  const double F1 = contact_stiffness(k, eps, KnForm::Eps4) * 1.0;
  const double F10 = contact_stiffness(k, 10 * eps, KnForm::Eps4) * std::pow(10.0, 5);
  EXPECT_NEAR(F10 / F1, 10.0, 1e-9);
  const double G10 = contact_stiffness(k, 10 * eps, KnForm::Eps5) * std::pow(10.0, 5);
  EXPECT_NEAR(G10 / (contact_stiffness(k, eps, KnForm::Eps5)), 1.0, 1e-9); // not a force/length
  // the inverse used for restitution damping with a given K_n
  for (KnForm f : {KnForm::Eps4, KnForm::Eps5})
    EXPECT_NEAR(bulk_modulus_from_stiffness(contact_stiffness(k, eps, f), eps, f) / k, 1.0, 1e-14);
  EXPECT_STREQ(kn_form_name(KnForm::Eps4), "eps4");
  EXPECT_STREQ(kn_form_name(KnForm::Eps5), "eps5");
}

TEST(ContactLaw, StiffnessFormula)
{
  // K_n = 18 k/(pi eps^5) (Bhattacharya & Lipton 2023, eq. 4.1, Jha et al. 2021, eq. 36)
  const KnForm p5 = KnForm::Eps5, p4 = KnForm::Eps4;
  EXPECT_DOUBLE_EQ(contact_stiffness(2.0, 1.0, p5), 36.0 / M_PI);
  EXPECT_NEAR(contact_stiffness(2.0, 1.0, p5), 11.459155902616464, 1e-12);
  const double k = 1.6e11, eps = 6.0e-4; // a steel-like grain, horizon 0.6 mm
  EXPECT_NEAR(contact_stiffness(k, eps, p5) / (18.0 * k / (M_PI * std::pow(eps, 5))), 1.0, 1e-14);
  // unlike materials: harmonic mean of the bulk moduli (Jha et al. 2021, eq. 25)
  EXPECT_DOUBLE_EQ(harmonic_mean(1.0, 3.0), 1.5);
  EXPECT_DOUBLE_EQ(contact_stiffness(1.0, 3.0, 0.5, p5), contact_stiffness(1.5, 0.5, p5));
  EXPECT_NEAR(contact_stiffness_mixed(1.0, 0.5, 3.0, 0.5, p5), contact_stiffness(1.5, 0.5, p5),
              1e-9);
  EXPECT_NEAR(contact_stiffness_mixed(1.0, 0.5, 3.0, 0.5, p4), contact_stiffness(1.5, 0.5, p4),
              1e-9);
  // rigid partner limits
  EXPECT_DOUBLE_EQ(harmonic_mean(2.0, kInf), 4.0);
  EXPECT_DOUBLE_EQ(reduced_mass(2.0, kInf), 2.0);
  EXPECT_DOUBLE_EQ(reduced_mass(2.0, 2.0), 1.0);
}

TEST(ContactLaw, RepulsionIsMinusGradientOfEnergy)
{
  std::mt19937 gen(1);
  const ContactParams p = base_params();
  for (double ref : {-1.0, 0.05, 0.2}) { // different grains, self contact |xi| < Rc, > Rc
    for (int trial = 0; trial < 200; ++trial) {
      ContactInput in = random_pair(gen, p.Rc, false);
      in.ref_dist = ref;
      const ContactResult r0 = contact_force(in, p);
      if (!r0.contact) continue;
      // sep = x_j - x_i, so dE/dx_i = -dE/dsep and F_i = -dE/dx_i = +dE/dsep.
      for (int k = 0; k < 3; ++k) {
        const double h = 1e-7 * p.Rc;
        ContactInput a = in, b = in;
        a.sep[k] += h;
        b.sep[k] -= h;
        const double fd = (contact_force(a, p).energy - contact_force(b, p).energy) / (2.0 * h);
        const double scale = std::sqrt(dot(r0.f_rep, r0.f_rep));
        EXPECT_NEAR(r0.f_rep[k], fd, 1e-6 * scale) << "ref " << ref << " k " << k;
      }
      // direction: repulsive (force on i points away from j)
      EXPECT_LE(dot(r0.f_rep, in.sep), 0.0);
    }
  }
}

TEST(ContactLaw, RepulsionValues)
{
  const ContactParams p = base_params();
  ContactInput in;
  in.sep[0] = 0.06; // r = 0.06 < Rc = 0.1
  in.vol_i = 2e-3;
  in.vol_j = 3e-3;
  in.mass_i = in.mass_j = 1.0;
  const ContactResult r = contact_force(in, p);
  EXPECT_NEAR(r.f[0], -3.0e3 * 0.04 * 2e-3 * 3e-3, 1e-15); // -K_n (R_c - r) V_i V_j e
  EXPECT_NEAR(r.energy, 0.5 * 3.0e3 * 0.04 * 0.04 * 6e-6, 1e-18);
  in.sep[0] = 0.1; // r = R_c: no contact
  EXPECT_FALSE(contact_force(in, p).contact);
}

TEST(ContactLaw, SelfContactUsesReferenceDistance)
{
  // Bhattacharya & Lipton 2023, Sec. 4.4: |xi| < R_c: no force until r < |xi|, stiffness K_n
  // R_c/|xi|.
  const ContactParams p = base_params();
  ContactInput in;
  in.vol_i = in.vol_j = 1e-3;
  in.mass_i = in.mass_j = 1.0;
  in.ref_dist = 0.05;
  in.sep[1] = 0.06;
  EXPECT_FALSE(contact_force(in, p).contact);
  in.sep[1] = 0.04;
  ContactResult r = contact_force(in, p);
  EXPECT_NEAR(r.f[1], -p.Kn * (p.Rc / 0.05) * 0.01 * 1e-6, 1e-18);
  // |xi| >= R_c behaves like two different grains (c_w = K_n R_c)
  in.ref_dist = 0.3;
  ContactInput other = in;
  other.ref_dist = -1.0;
  EXPECT_DOUBLE_EQ(contact_force(in, p).f[1], contact_force(other, p).f[1]);
  // continuity in |xi| at |xi| = R_c
  in.ref_dist = p.Rc * (1.0 - 1e-12);
  EXPECT_NEAR(contact_force(in, p).f[1], contact_force(other, p).f[1],
              1e-9 * std::fabs(contact_force(other, p).f[1]));
}

TEST(ContactLaw, NewtonThirdLawAllVariants)
{
  std::mt19937 gen(2);
  for (const ContactParams &p : all_variants())
    for (int trial = 0; trial < 200; ++trial) {
      const ContactInput in = random_pair(gen, p.Rc, false);
      const ContactResult a = contact_force(in, p);
      const ContactResult b = contact_force(swapped(in), p);
      const double scale = std::sqrt(dot(a.f, a.f)) + 1e-300;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.f[k], -b.f[k], 1e-12 * scale);
      EXPECT_NEAR(a.energy, b.energy, 1e-12 * a.energy);
      EXPECT_NEAR(a.power, b.power, 1e-12 * std::fabs(a.power) + 1e-300);
    }
}

TEST(ContactLaw, FrictionAndDampingDissipate)
{
  std::mt19937 gen(3);
  int stick = 0, slip = 0;
  for (const ContactParams &p : all_variants())
    for (bool rigid : {false, true})
      for (int trial = 0; trial < 500; ++trial) {
        ContactInput in = random_pair(gen, p.Rc, rigid);
        if (trial % 3 == 0) // small tangential speeds reach the stick branch
          for (double &v : in.vrel) v *= 1e-5;
        const ContactResult r = contact_force(in, p);
        const double scale = std::sqrt(dot(r.f, r.f) * dot(in.vrel, in.vrel));
        EXPECT_LE(dot(r.f_fric, in.vrel), 1e-14 * scale);
        EXPECT_LE(dot(r.f_damp, in.vrel), 1e-14 * scale);
        EXPECT_LE(r.power, 1e-14 * scale);
        if (p.friction == ContactFriction::Regularized) (r.stick ? stick : slip)++;
      }
  EXPECT_GT(stick, 100);
  EXPECT_GT(slip, 100);
}

TEST(ContactLaw, FrictionOpposesSlidingExample)
{
  // Node i slides in +x over a partner below it (e = -y): friction must point in -x.
  ContactParams p = base_params();
  p.friction = ContactFriction::Coulomb;
  p.mu = 0.3;
  ContactInput in;
  in.sep[1] = -0.08;
  in.vrel[0] = 2.0;
  in.vol_i = in.vol_j = 1e-3;
  in.mass_i = in.mass_j = 1.0;
  ContactResult r = contact_force(in, p);
  const double fn = p.Kn * 0.02 * 1e-6;
  EXPECT_NEAR(r.f_fric[0], -0.3 * fn, 1e-15); // |F_f| = mu |F_r|, Jha et al. 2021, eq. 20
  EXPECT_NEAR(r.f_rep[1], fn, 1e-15);         // pushed up, away from the partner
  p.friction = ContactFriction::Regularized;
  in.dt = 1.0; // large dt: v_thr = mu |F_r| dt/m_red = 1.2e-5 < |vt|, slip
  r = contact_force(in, p);
  EXPECT_FALSE(r.stick);
  EXPECT_NEAR(r.f_fric[0], -0.3 * fn, 1e-15);
}

TEST(ContactLaw, StickStopsWithoutReversal)
{
  // One explicit step with the pair force: the tangential relative velocity shrinks and keeps
  // its direction (stick: exactly zero, slip: reduced by mu|F_r| dt/m_red < |vt|).
  std::mt19937 gen(4);
  ContactParams p = base_params();
  p.friction = ContactFriction::Regularized;
  p.mu = 0.4;
  int nstick = 0;
  for (bool rigid : {false, true})
    for (int trial = 0; trial < 2000; ++trial) {
      ContactInput in = random_pair(gen, p.Rc, rigid);
      const double scale = std::pow(10.0, -6.0 * std::uniform_real_distribution<>(0, 1)(gen));
      for (double &v : in.vrel) v *= scale;
      const ContactResult r = contact_force(in, p);
      double vnew[3];
      const double inv_m = 1.0 / in.mass_i + 1.0 / in.mass_j;
      for (int k = 0; k < 3; ++k) vnew[k] = in.vrel[k] + r.f[k] * in.dt * inv_m;
      const double rr = std::sqrt(dot(in.sep, in.sep));
      const double e[3] = {in.sep[0] / rr, in.sep[1] / rr, in.sep[2] / rr};
      double t0[3], t1[3];
      const double n0 = dot(in.vrel, e), n1 = dot(vnew, e);
      for (int k = 0; k < 3; ++k) {
        t0[k] = in.vrel[k] - n0 * e[k];
        t1[k] = vnew[k] - n1 * e[k];
      }
      const double v0 = std::sqrt(dot(t0, t0));
      EXPECT_GE(dot(t0, t1), -1e-12 * v0 * v0);
      EXPECT_LE(std::sqrt(dot(t1, t1)), v0 * (1.0 + 1e-12));
      if (r.stick) {
        ++nstick;
        EXPECT_LE(std::sqrt(dot(t1, t1)), 1e-10 * v0);
      }
    }
  EXPECT_GT(nstick, 100);
}

// The stick branch is pairwise: each stuck pair removes the whole tangential relative
// velocity, so a node stuck to k rigid partners at once gets k times the force that stops it,
// and its tangential velocity goes from v to -(k - 1) v in one step: k = 2 reverses it (no
// energy lost), k = 3 doubles it (energy fed in, until the pairs slip). pair_style
// peridem/contact counts that work as negative dissipation (its count_work). The law is the
// paper's (Bhattacharya & Lipton 2023, eq. 4.3); this test records the behaviour.
TEST(ContactLaw, StickOfSeveralPartnersOvershoots)
{
  ContactParams p = base_params();
  p.friction = ContactFriction::Regularized;
  p.mu = 0.5;
  const double v = 1e-9, mass = 1.0, dt = 1e-3; // |v| below v_thr = mu |F_r| dt/m: stuck
  for (int k = 1; k <= 4; ++k) {
    // k rigid partners around the node in the y-z plane, the node moving along x
    double f = 0.0;
    for (int n = 0; n < k; ++n) {
      ContactInput in;
      const double a = 2.0 * kPi * n / k;
      in.sep[1] = 0.8 * p.Rc * std::cos(a);
      in.sep[2] = 0.8 * p.Rc * std::sin(a);
      in.vrel[0] = v;
      in.vol_i = in.vol_j = 1e-3;
      in.mass_i = mass;
      in.dt = dt;
      const ContactResult r = contact_force(in, p);
      ASSERT_TRUE(r.stick) << k;
      f += r.f[0];
    }
    EXPECT_NEAR(v + f * dt / mass, -(k - 1) * v, 1e-12 * v) << k;
  }
}

// dissipated_in_step against velocity Verlet itself: a node under a dashpot and a stick force
// that reverses its velocity once it is slow (two stuck partners at once), both taking
// v(n - 1/2) as in the styles. The kinetic energy lost equals the dissipated energy to
// round-off, up to the telescoped term dt^2/(8m) (|F_N|^2 - |F_0|^2); the power at v(n - 1/2)
// counts every reversal as a loss, many times the energy there is.
TEST(ContactLaw, DissipatedInStepClosesVelocityVerletsBalance)
{
  const double m = 2.0, c = 0.3, dt = 1e-2;
  for (bool stick : {false, true}) {
    auto force = [&](double vh) {
      return -c * vh + (stick && std::fabs(vh) < 0.05 ? -2.0 * m * vh / dt : 0.0);
    };
    double v = 1.0, f = force(v);
    const double e0 = 0.5 * m * v * v, f0 = f;
    double previous = f * v, dissipated = 0.0, half_step = 0.0;
    for (int n = 0; n < 5000; ++n) {
      const double vhalf = v + 0.5 * dt * f / m;
      f = force(vhalf);
      v = vhalf + 0.5 * dt * f / m;
      dissipated += dissipated_in_step(previous, f * v, dt);
      half_step -= f * vhalf * dt;
    }
    const double lost = e0 - 0.5 * m * v * v - dt * dt / (8.0 * m) * (f * f - f0 * f0);
    EXPECT_NEAR(dissipated, lost, 1e-12 * e0) << stick;
    if (stick)
      EXPECT_GT(half_step, 10.0 * e0);
    else
      EXPECT_NEAR(half_step, lost, 0.01 * e0); // first order in dt, but near
  }
}

TEST(ContactLaw, DampingOnlyWhileApproaching)
{
  for (auto d : {ContactDamping::Nodal, ContactDamping::Restitution}) {
    ContactParams p = base_params();
    p.damping = d;
    p.r_d = 0.5;
    p.eps_n = 0.7;
    p.kappa_eff = 10.0;
    ContactInput in;
    in.sep[2] = 0.07;
    in.vol_i = in.vol_j = 1e-3;
    in.mass_i = in.mass_j = 1.0;
    in.vrel[2] = 0.5; // approaching: damping pushes i away (-z)
    ContactResult r = contact_force(in, p);
    EXPECT_LT(r.f_damp[2], 0.0);
    EXPECT_LT(r.power, 0.0);
    in.vrel[2] = -0.5; // separating: no damping
    r = contact_force(in, p);
    EXPECT_EQ(r.f_damp[2], 0.0);
    EXPECT_EQ(r.power, 0.0);
    p.damp_approach_only = false; // Kelvin-Voigt option: damps both ways, still dissipative
    r = contact_force(in, p);
    EXPECT_GT(r.f_damp[2], 0.0);
    EXPECT_LT(r.power, 0.0);
  }
}

namespace {

// Head-on collision of two nodes (masses m1, m2) along x integrated with velocity Verlet
// (forces from positions x_{n+1} and the half-step velocities, as in LAMMPS).  Returns the
// coefficient of restitution -v_rel(out)/v_rel(in).
double measure_restitution(const ContactParams &p, double vol, double m1, double m2, double v0)
{
  double x1 = 0.0, x2 = p.Rc * 1.0001, v1 = v0, v2 = 0.0;
  const double k = p.Kn * vol * vol;
  const double dt = 2.0 * M_PI * std::sqrt(reduced_mass(m1, m2) / k) / 20000.0;
  auto force = [&](double &f1) {
    ContactInput in;
    in.sep[0] = x2 - x1;
    in.vrel[0] = v1 - v2;
    in.vol_i = in.vol_j = vol;
    in.mass_i = m1;
    in.mass_j = m2;
    in.dt = dt;
    f1 = contact_force(in, p).f[0];
  };
  double f1;
  force(f1);
  bool touched = false;
  for (int step = 0; step < 1000000; ++step) {
    v1 += 0.5 * dt * f1 / m1;
    v2 -= 0.5 * dt * f1 / m2;
    x1 += dt * v1;
    x2 += dt * v2;
    force(f1);
    v1 += 0.5 * dt * f1 / m1;
    v2 -= 0.5 * dt * f1 / m2;
    if (x2 - x1 < p.Rc) touched = true;
    if (touched && x2 - x1 > p.Rc) break;
  }
  return (v2 - v1) / v0;
}

} // namespace

TEST(ContactLaw, RestitutionFormula)
{
  // Jha et al. 2021, eq. (23) is the linear spring-dashpot relation c = 2 zeta sqrt(k m) with
  // k = kappa_eff R_c and m = m_eq.  For an isolated node pair (spring K_n V^2, reduced mass
  // m_eq/2) it is exact with C = restitution_exact_C; choosing kappa_eff R_c = K_n V^2/2 makes
  // that C equal to 1.
  ContactParams p = base_params();
  p.damping = ContactDamping::Restitution;
  const double vol = 1e-3, m1 = 1.0, m2 = 3.0;
  p.kappa_eff = p.Kn * vol * vol / (2.0 * p.Rc);
  ASSERT_NEAR(peridem_test::restitution_exact_C(p.Kn * vol * vol, p.kappa_eff, p.Rc), 1.0, 1e-14);
  p.C = 1.0;
  std::printf("  eps_n   CoR(damped always)   CoR(approach only)   closed form(approach only)\n");
  for (double eps : {1.0, 0.95, 0.9, 0.85, 0.8}) {
    p.eps_n = eps;
    p.damp_approach_only = false;
    const double cor_full = measure_restitution(p, vol, m1, m2, 1e-3);
    EXPECT_NEAR(cor_full, eps, 1e-3) << "eps_n " << eps;
    p.damp_approach_only = true; // the papers' rule (eq. 22): only while approaching
    const double cor_half = measure_restitution(p, vol, m1, m2, 1e-3);
    const double closed =
        peridem_test::restitution_from_damping_ratio(damping_ratio_from_restitution(eps), true);
    EXPECT_NEAR(cor_half, closed, 1e-3) << "eps_n " << eps;
    EXPECT_GE(cor_half, eps - 1e-6); // damping half the time dissipates less
    std::printf("  %.2f    %.6f             %.6f             %.6f\n", eps, cor_full, cor_half,
                closed);
  }
  // the closed forms themselves
  EXPECT_NEAR(
      peridem_test::restitution_from_damping_ratio(damping_ratio_from_restitution(0.8), false), 0.8,
      1e-14);
  EXPECT_DOUBLE_EQ(restitution_damping_coefficient(1.0, 1.0, 1.0, 1.0, 1.0), 0.0);
}

TEST(ContactLaw, NodalDampingRatio)
{
  // Bhattacharya & Lipton 2023, eq. (4.5): r_d is the damping ratio of the pair (reduced mass);
  // damped both ways the restitution is exp(-pi r_d/sqrt(1 - r_d^2)).
  ContactParams p = base_params();
  p.damping = ContactDamping::Nodal;
  p.damp_approach_only = false;
  for (double rd : {0.0, 0.05, 0.2}) {
    p.r_d = rd;
    const double cor = measure_restitution(p, 1e-3, 1.0, 2.0, 1e-3);
    EXPECT_NEAR(cor, peridem_test::restitution_from_damping_ratio(rd, false), 1e-3) << "r_d " << rd;
  }
}

TEST(ContactLaw, CentroidDamping)
{
  // Jha et al. 2021, eq. (26)-(27): beta_bar delta_dot_c e_c on grain p while approaching.
  const double sep[3] = {0.0, 2.0, 0.0};
  double v[3] = {0.0, 0.3, 0.0}, f[3], g[3];
  const double beta =
      restitution_damping_coefficient(0.9, 100.0, 1e9, 1e-4, harmonic_mean(1.0, 2.0));
  double pw = centroid_damping_force(sep, v, beta, true, f);
  EXPECT_NEAR(f[1], -beta * 0.3, 1e-12 * beta);
  EXPECT_NEAR(pw, -beta * 0.09, 1e-12 * beta);
  const double msep[3] = {0.0, -2.0, 0.0}, mv[3] = {0.0, -0.3, 0.0};
  centroid_damping_force(msep, mv, beta, true, g); // Newton's third law
  EXPECT_DOUBLE_EQ(f[1], -g[1]);
  v[1] = -0.3; // separating
  EXPECT_EQ(centroid_damping_force(sep, v, beta, true, f), 0.0);
  EXPECT_EQ(f[1], 0.0);
  v[1] = 0.3; // grains farther apart than R_c
  EXPECT_EQ(centroid_damping_force(sep, v, beta, false, f), 0.0);
}

namespace {
// A 2d contact without bonds: K_n = 1e20, node spacing h = 1e-4 (V = 1e-8), m = 1.2e-5.
TimeStepInput contact_only_input(double Rc)
{
  TimeStepInput c;
  c.dimension = 2;
  c.Kn = 1e20;
  c.Rc = Rc;
  c.node_volume = 1e-8;
  c.min_node_mass = 1.2e-5;
  return c;
}
} // namespace

TEST(ContactLaw, StableTimeStep)
{
  TimeStepInput in;
  in.dimension = 2;
  in.rho = 1200.0;
  in.c = 5.0e15;
  in.horizon = 6e-4;
  TimeStepEstimate t = stable_time_step(in);
  // isotropic family: lambda_max of sum k e e = (1/d) sum k, so sqrt(d) x Silling-Askari
  EXPECT_NEAR(t.dt_bond, std::sqrt(2.0 * 2.0 * in.rho / (in.c * 2.0 * M_PI * in.horizon)), 1e-20);
  EXPECT_DOUBLE_EQ(t.dt_critical, t.dt_bond); // no contact
  in.micromodulus = Micromodulus::Conic;
  EXPECT_NEAR(stable_time_step(in).dt_bond, t.dt_bond * std::sqrt(2.0), 1e-20);
  in.dimension = 3;
  in.micromodulus = Micromodulus::Constant;
  EXPECT_NEAR(stable_time_step(in).dt_bond,
              std::sqrt(3.0 * 2.0 * in.rho / (in.c * 2.0 * M_PI * in.horizon * in.horizon)), 1e-20);
  // explicit bond bound omega_b^2 (what the pair style computes from the bonds) wins
  in.bond_omega2 = 4.0e14;
  EXPECT_DOUBLE_EQ(stable_time_step(in).dt_bond, 1.0e-7);
  in.bond_omega2 = 0.0;

  // contact only: dt_c = sqrt(2 m/(n K_n V^2))
  TimeStepInput c = contact_only_input(0.95e-4);
  t = stable_time_step(c);
  // R_c < h: the ball holds ceil(pi Rc^2/V) = ceil(2.835) = 3 partners, isotropic: 2 x 3/2 =
  // 3 k/m, below the shallow bound 2 x 2 k/m; the wall (no shallow limit for R_c < h: on its
  // plane) 2 Rc^2/V = 1.805 k/m is smaller: n = 3/2 pair springs, with or without walls
  EXPECT_DOUBLE_EQ(t.n_contacts, 1.5);
  EXPECT_DOUBLE_EQ(t.shallow_depth, c.Rc);
  EXPECT_NEAR(t.dt_contact, std::sqrt(2.0 * 1.2e-5 / (1.5 * 1e20 * 1e-16)), 1e-20);
  c.walls = false;
  EXPECT_DOUBLE_EQ(stable_time_step(c).n_contacts, 1.5);
  // Bhattacharya & Lipton's (2023) R_c = 1.6 h: ball 2 ceil(8.04)/2 = 9 k/m, shallow 4 k/m (2 nodes
  // of a surface row until delta_s = (1.6 - sqrt(1.56)) h = 0.351 h), the wall at that depth
  // 2 sqrt(Rc^2 - d^2)(Rc - d)/h^2 = 2 x 1 x 0.351 = 0.70 k/m: n = 2
  c.Rc = 1.6e-4;
  c.walls = true;
  TimeStepEstimate gs = stable_time_step(c);
  EXPECT_NEAR(gs.shallow_depth, (1.6 - std::sqrt(1.56)) * 1e-4, 1e-15);
  EXPECT_DOUBLE_EQ(gs.n_contacts, 2.0);
  // in 3D (V = h^3): ball 2 ceil(17.2)/3 = 12, shallow 2 x 4 = 8 (4 nodes of a surface
  // plane), wall pi (Rc^2 - d^2)(Rc - d)/h^3 = pi x 0.351 = 1.10: n = 4
  c.dimension = 3;
  c.node_volume = 1e-12;
  EXPECT_DOUBLE_EQ(stable_time_step(c).n_contacts, 4.0);
  c.dimension = 2;
  c.node_volume = 1e-8;
  c.Rc = 0.95e-4;
  c.walls = true;
  c.damping_ratio = 0.5;
  EXPECT_LT(stable_time_step(c).dt_contact, t.dt_contact);
  // combined: 1/dt^2 adds up, safety factor applied
  c.c = in.c;
  c.rho = in.rho;
  c.horizon = in.horizon;
  c.damping_ratio = 0.0;
  const TimeStepEstimate both = stable_time_step(c);
  EXPECT_NEAR(1.0 / (both.dt_critical * both.dt_critical),
              1.0 / (both.dt_bond * both.dt_bond) + 1.0 / (both.dt_contact * both.dt_contact),
              1e-9 / (both.dt_critical * both.dt_critical));
  EXPECT_DOUBLE_EQ(both.dt_recommended, 0.8 * both.dt_critical);
}

// A wall with its own contact law (fix peridem/wall Kn ... Rc ...) enters the contact bound with
// its Kn and Rc (issue 27): the pair's law given as the wall's changes nothing (to the bit), a
// wall 100x stiffer sets n from its own wall_contact_stiffness, and the stiffest wall counts.
TEST(ContactLaw, TimeStepSeesTheWallsOwnLaw)
{
  TimeStepInput c = contact_only_input(1.6e-4);
  const TimeStepEstimate pair_only = stable_time_step(c);
  c.wall_laws = {{c.Kn, c.Rc}};
  EXPECT_EQ(stable_time_step(c).dt_contact, pair_only.dt_contact);
  // a wall of 100 Kn at the shallow depth d = (1.6 - sqrt(1.56)) h: 2 x 100 Kn V sqrt(Rc^2 -
  // d^2)(Rc - d) = 100 x 0.70 pair springs k = Kn V^2, above the pair's 4: n = 35.1
  c.wall_laws = {{1e20, 1.6e-4}, {1e22, 1.6e-4}};
  const double d = c.Rc - (1.6 - std::sqrt(1.56)) * 1e-4;
  const double kw = wall_contact_stiffness(2, 1e22, 1e-8, c.Rc, d);
  const TimeStepEstimate stiff = stable_time_step(c);
  EXPECT_NEAR(stiff.n_contacts, 0.5 * kw / (1e20 * 1e-16), 1e-12 * stiff.n_contacts);
  EXPECT_NEAR(stiff.n_contacts, 35.1, 0.1);
  EXPECT_NEAR(stiff.dt_contact, std::sqrt(2.0 * 1.2e-5 / (0.5 * kw)), 1e-12 * stiff.dt_contact);
  // no walls: their laws do not count
  c.walls = false;
  EXPECT_EQ(stable_time_step(c).dt_contact, pair_only.dt_contact);
}

TEST(ContactLaw, SymmetricMaxEigenvalue)
{
  const double a2[3] = {2.0, 1.0, 0.0};
  EXPECT_DOUBLE_EQ(symmetric_max_eigenvalue(a2, 2), 2.0);
  const double b2[3] = {1.0, 1.0, 1.0}; // [[1,1],[1,1]]: 2, 0
  EXPECT_NEAR(symmetric_max_eigenvalue(b2, 2), 2.0, 1e-15);
  const double a3[6] = {1.0, 2.0, 3.0, 0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(symmetric_max_eigenvalue(a3, 3), 3.0);
  const double b3[6] = {2.0, 2.0, 2.0, 1.0, 1.0, 1.0}; // 1 + J(3x3 ones): 4, 1, 1
  EXPECT_NEAR(symmetric_max_eigenvalue(b3, 3), 4.0, 1e-12);
  const double c3[6] = {2.0, 3.0, 5.0, 1.0, 0.0, 0.0}; // blocks [[2,1],[1,3]] and 5
  EXPECT_NEAR(symmetric_max_eigenvalue(c3, 3), 5.0, 1e-12);
  // a square-lattice family (4-fold symmetric) is isotropic: lambda_max = sum k/2
  double A[3] = {0.0, 0.0, 0.0}, sum = 0.0;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) {
      const double r = std::hypot(i, j);
      if (r == 0.0 || r > 3.0) continue;
      const double k = 1.0 / r, ex = i / r, ey = j / r;
      A[0] += k * ex * ex, A[1] += k * ey * ey, A[2] += k * ex * ey, sum += k;
    }
  EXPECT_NEAR(symmetric_max_eigenvalue(A, 2), 0.5 * sum, 1e-12);
}

TEST(ContactLaw, StableTimeStepIsStableForContactSpring)
{
  // A node of mass m between n_c partner springs K_n V^2 (worst case: all on one axis as an
  // alternating chain): explicit integration at 0.99 dt_c stays bounded, 1.2x grows (the bound
  // is a Gershgorin bound, attained by the alternating mode of a periodic chain).
  const double Kn = 1.0, V = 1.0, m = 1.0;
  auto grows = [&](double dt) {
    // periodic chain of N nodes, springs k between neighbours (n_c = 2 per node)
    const int N = 16;
    std::vector<double> x(N), v(N, 0.0), f(N);
    for (int i = 0; i < N; ++i) x[i] = (i % 2 ? 1e-6 : -1e-6);
    auto forces = [&]() {
      for (int i = 0; i < N; ++i) {
        const int l = (i + N - 1) % N, r = (i + 1) % N;
        f[i] = Kn * V * V * (x[l] - 2.0 * x[i] + x[r]);
      }
    };
    forces();
    for (int s = 0; s < 60; ++s) {
      for (int i = 0; i < N; ++i) v[i] += 0.5 * dt * f[i] / m, x[i] += dt * v[i];
      forces();
      for (int i = 0; i < N; ++i) v[i] += 0.5 * dt * f[i] / m;
    }
    double mx = 0.0;
    for (double xi : x) mx = std::max(mx, std::fabs(xi));
    return mx > 1e-3;
  };
  TimeStepInput c;
  c.dimension = 2;
  c.Kn = Kn;
  c.Rc = 0.5;
  c.node_volume = V;
  c.min_node_mass = m;
  c.n_contacts = 2.0;
  const double dtc = stable_time_step(c).dt_contact;
  EXPECT_FALSE(grows(0.99 * dtc));
  EXPECT_TRUE(grows(1.2 * dtc));
}

TEST(ContactLaw, ParameterChecks)
{
  ContactParams p = base_params();
  EXPECT_NO_THROW(check_contact_params(p));
  ContactParams q = p;
  q.Rc = 0.0;
  EXPECT_THROW(check_contact_params(q), ParameterError);
  q = p;
  q.Rc = -1.0;
  EXPECT_THROW(check_contact_params(q), ParameterError);
  q = p;
  q.mu = -0.1;
  EXPECT_THROW(check_contact_params(q), ParameterError);
  q = p;
  q.damping = ContactDamping::Nodal;
  q.r_d = 1.5;
  EXPECT_THROW(check_contact_params(q), ParameterError);
  q = p;
  q.damping = ContactDamping::Restitution;
  q.kappa_eff = 1.0;
  q.eps_n = 0.0;
  EXPECT_THROW(check_contact_params(q), ParameterError);
  q.eps_n = 0.5;
  EXPECT_NO_THROW(check_contact_params(q));
  q.kappa_eff = 0.0;
  EXPECT_THROW(check_contact_params(q), ParameterError);
}
