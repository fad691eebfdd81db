/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: pure node-to-node contact law (repulsion, damping, friction) shared by
// `pair_style peridem/contact` and `fix peridem/wall` (no LAMMPS dependency).
//
// References:
//  Bhattacharya & Lipton 2023, "Simulating grain shape effects ... using PeriDEM", SIAM J. Sci.
//  Comput.: eq. (4.1) repulsion and K_n,
//         eq. (4.3) regularized nonlocal friction, eq. (4.5) nodal damping, Sec. 4.4 self
//         contact, Sec. 4.5 walls (the wall fills in the partner, see peridem_wall_geometry.h).
//  Jha, Desai, Bhattacharya & Lipton 2021 (Jha et al. 2021), "PeriDEM", J. Mech. Phys. Solids 151:
//  eq. (16)-(18) normal force, eq. (19)-(20)
//         Coulomb friction, eq. (21)-(25) restitution damping, eq. (26)-(30) centroid damping,
//         eq. (36) K_n.
//
// Conventions (the same for every function here):
//   sep  = x_j - x_i      current vector from node i to its partner j; r = |sep|; e = sep/r
//   vrel = v_i - v_j      velocity of i relative to j (Bhattacharya & Lipton 2023 v(x,y), Jha et
//   al. 2021 -(v'-v)) vn   = vrel . e       > 0 while the nodes approach (= -delta_dot of Jha et
//   al. 2021, eq. 21) Forces are the force ON i; the partner receives the opposite force (Newton's
//   third law). The force is a force (not a density): Bhattacharya & Lipton 2023, eq. (4.1) F_r
//   already carries V_i V_j and the Jha et al. 2021 densities are multiplied by V (their eq. 17, 22
//   are per volume of x). A rigid partner (wall) has mass_j = +infinity.
//
// Choices where the papers are ambiguous (each is noted again where it is used):
//  * K_n for unlike materials: both papers take the harmonic mean of the BULK MODULI
//    (Bhattacharya & Lipton 2023, below eq. 4.1, Jha et al. 2021, eq. 25 and Sec. 3.2) and then K_n
//    = 18 k_eff/(pi eps^p).  For equal horizons that equals the harmonic mean of the two K_n; with
//    unlike horizons (not covered by the papers) contact_stiffness_mixed() takes the harmonic mean
//    of the two K_n.
//  * Sign of friction and damping: Bhattacharya & Lipton 2023, eq. (4.3) writes -mu|F_r|
//  e_perp(y,x) and Jha et al. 2021
//    eq. (19)-(20) -mu|F_n| (I - e e)(v' - v)/|v' - v|; read literally the latter pushes i
//    ALONG its tangential velocity relative to j (the sign error of one public code).  Here
//    friction always opposes the tangential part of vrel and damping opposes vn, so the power
//    F . vrel of both is <= 0.
//  * Bhattacharya & Lipton 2023, eq. (4.5) prints v/|v| (a unit vector) in the damping force, which
//  contradicts its
//    own Kelvin-Voigt derivation (c = beta_d V_x V_y, dissipation -c |v_n|^2); we use the
//    derivation: F_d = -c vn e.
//  * Masses: Bhattacharya & Lipton 2023 uses the mass rho V_x of the receiving node alone (partner
//  held fixed) in
//    beta_d and in v_thr / eps_f of eq. (4.3).  That breaks Newton's third law when V_i != V_j
//    and, for two equal free nodes, makes the "stick" force reverse the relative velocity.  We
//    use the reduced mass m_red = m_i m_j/(m_i + m_j), which equals Bhattacharya & Lipton's (2023)
//    rho V_x for a rigid partner (walls) and is symmetric.  The restitution formula Jha et al.
//    2021, eq. (23) keeps its own m_eq = harmonic mean = 2 m_red (eq. 24).
//  * The stick branch of eq. (4.3) cancels the tangential relative velocity of ONE pair in one
//    step; a node sticking to several partners at once overshoots (inherent to a pairwise law;
//    the wall applies one friction term per wall): against k rigid partners its tangential
//    velocity goes from v_t to -(k - 1) v_t, reversed for k = 2, grown (energy fed in, until
//    the pairs slip) for k >= 3. The styles count that work as negative dissipation.
//  * Damping acts only while the nodes approach (vn > 0) as Jha et al. 2021, eq. (22), (27) state;
//    Bhattacharya & Lipton 2023, eq. (4.5) (Kelvin-Voigt) damps both ways:
//    ContactParams::damp_approach_only.
#ifndef PERIDEM_CONTACT_LAW_H
#define PERIDEM_CONTACT_LAW_H

#include "peridem_bond_law.h" // Micromodulus, ParameterError
#include "peridem_math.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace peridem {

// ---------------------------------------------------------------------------------------
// Parameters
// ---------------------------------------------------------------------------------------

// Normal contact stiffness K_n = 18 k/(pi eps^p), k the bulk modulus, eps the horizon.
//  p = 5 (Bhattacharya & Lipton 2023, eq. 4.1 as printed, Jha et al. 2021, eq. 36), the 3D form:
//  volumes in m^3, so
//    K_n (R_c - r) V_i V_j needs K_n in N/m^7 = Pa/m^5 to be a force (N); 18 k/(pi eps^5) is.
//  p = 4, the 2D form: nodal "volumes" are areas (m^2) and forces are per unit thickness
//    (N/m), so K_n needs N/m^6 = Pa/m^4, which 18 k/(pi eps^4) has; eps^5 in 2D gives a
//    "force" in N/m^2, numerically 1/eps times too stiff (2000x in SI for eps = 0.5 mm).
//    Bhattacharya & Lipton's public code (perigrain, exp_dict.py and the 2D setup.py
//    scripts) uses delta^4 in every 2D setup and delta^5 only in 3D; the bond constant drops
//    the same power from 3D to 2D (18 K/(pi eps^4) in 3D, 9 E/(pi eps^3) in 2D,
//    peridem_bond_law.cpp).  Jha et al.'s PeriDEM code uses eps^5 in 2D (with a soft
//    material, K = 0.0216 GPa), so their Table 2 needs p = 5 (KnForm::Eps5).
enum class KnForm { Eps4, Eps5 };
inline int kn_exponent(KnForm form)
{
  return form == KnForm::Eps4 ? 4 : 5;
}
inline const char *kn_form_name(KnForm form)
{
  return form == KnForm::Eps4 ? "eps4" : "eps5";
}
// The default of a dimension: 2D per unit thickness (eps^4), 3D eps^5.
inline KnForm default_kn_form(int dimension)
{
  return dimension == 2 ? KnForm::Eps4 : KnForm::Eps5;
}
inline double contact_stiffness(double bulk_modulus, double horizon, KnForm form)
{
  return 18.0 * bulk_modulus / (kPi * std::pow(horizon, kn_exponent(form)));
}
// The inverse: the bulk modulus k behind a given K_n.
inline double bulk_modulus_from_stiffness(double Kn, double horizon, KnForm form)
{
  return Kn * kPi * std::pow(horizon, kn_exponent(form)) / 18.0;
}

// Harmonic mean 2ab/(a+b) (Bhattacharya & Lipton 2023, below eq. 4.1, Jha et al. 2021, eq. 24, 25);
// written as 2/(1/a + 1/b) so that b = +infinity (a rigid partner) gives 2a.
inline double harmonic_mean(double a, double b)
{
  return 2.0 / (1.0 / a + 1.0 / b);
}

// Reduced mass m_i m_j/(m_i + m_j) = harmonic_mean/2; m_j = +infinity gives m_i.
inline double reduced_mass(double m_i, double m_j)
{
  return 1.0 / (1.0 / m_i + 1.0 / m_j);
}

// K_n for two materials with bulk moduli k1, k2 and a common horizon: k_eff = harmonic mean
// (Jha et al. 2021, eq. 25) inserted in eq. 36.
inline double contact_stiffness(double k1, double k2, double horizon, KnForm form)
{
  return contact_stiffness(harmonic_mean(k1, k2), horizon, form);
}

// Unlike horizons (not in the papers): harmonic mean of the two K_n; equals the above when
// eps1 == eps2.
inline double contact_stiffness_mixed(double k1, double eps1, double k2, double eps2, KnForm form)
{
  return harmonic_mean(contact_stiffness(k1, eps1, form), contact_stiffness(k2, eps2, form));
}

// Damping ratio zeta that gives restitution eps_n for a linear spring-dashpot damped during
// the whole contact: eps_n = exp(-pi zeta/sqrt(1 - zeta^2))  <=>
// zeta = -ln(eps_n)/sqrt(pi^2 + ln(eps_n)^2), the factor inside Jha et al. 2021, eq. (23).
inline double damping_ratio_from_restitution(double eps_n)
{
  const double l = std::log(eps_n);
  return -l / std::sqrt(kPi * kPi + l * l);
}

// Restitution-based dashpot viscosity (Jha et al. 2021, eq. 23 nodal, eq. 28 centroid):
//   beta_n = -2 C ln(eps_n) sqrt(kappa_eff R_c m_eq/(pi^2 + ln(eps_n)^2))
// m_eq = harmonic mean of the two masses (eq. 24 nodes, eq. 29 grains), kappa_eff eq. 25.
// It is 2 zeta sqrt(k m) with zeta from damping_ratio_from_restitution, k = kappa_eff R_c and
// m = m_eq; it yields restitution eps_n exactly only if C^2 kappa_eff R_c m_eq equals the
// actual contact spring times the reduced mass AND the dashpot acts during the whole contact
// (unittest/core/contact_reference.h); otherwise C is a calibration constant (Jha et al. 2021
// uses C-bar = 100).  Units: force/velocity.
inline double restitution_damping_coefficient(double eps_n, double C, double kappa_eff, double R_c,
                                              double m_eq)
{
  if (eps_n >= 1.0) return 0.0;
  return 2.0 * C * damping_ratio_from_restitution(eps_n) * std::sqrt(kappa_eff * R_c * m_eq);
}

enum class ContactDamping {
  None,
  Nodal,       // Bhattacharya & Lipton 2023, eq. (4.5): c = 2 r_d sqrt(k m_red), k = K_n V_i V_j
  Restitution, // Jha et al. 2021, eq. (22)-(25): c = beta_n(eps_n, C, kappa_eff, R_c, m_eq)
};
// Centroid damping (Jha et al. 2021, eq. 26-30) acts between grain centres, not node pairs:
// see centroid_damping_force() below; the nodal call then uses ContactDamping::None.

enum class ContactFriction {
  None,
  Regularized, // Bhattacharya & Lipton 2023, eq. (4.3): stick/slip with v_thr = mu|F_r| dt/m, eps_f
               // = dt/m
  Coulomb,     // Jha et al. 2021, eq. (19)-(20): magnitude mu|F_n| opposing the tangential velocity
};

struct ContactParams {
  double Kn = 0.0; // normal stiffness (Bhattacharya & Lipton 2023, eq. 4.1)
  double Rc = 0.0; // contact radius
  ContactDamping damping = ContactDamping::None;
  double r_d = 0.0;       // Nodal: damping ratio in [0, 1]
  double eps_n = 1.0;     // Restitution: damping parameter (<= 1)
  double C = 1.0;         // Restitution: constant C > 0
  double kappa_eff = 0.0; // Restitution: effective bulk modulus (Jha et al. 2021, eq. 25)
  bool damp_approach_only = true;
  ContactFriction friction = ContactFriction::None;
  double mu = 0.0; // friction coefficient
};

// Validates ranges (Kn > 0, Rc > 0, r_d in [0,1], 0 < eps_n <= 1, C > 0, kappa_eff > 0 when
// Restitution, mu >= 0); throws ParameterError with a message naming the bad value.
void check_contact_params(const ContactParams &p);

// ---------------------------------------------------------------------------------------
// Per-pair law
// ---------------------------------------------------------------------------------------

struct ContactInput {
  double sep[3] = {0.0, 0.0, 0.0};  // x_j - x_i (z = 0 in 2D)
  double vrel[3] = {0.0, 0.0, 0.0}; // v_i - v_j
  double vol_i = 0.0, vol_j = 0.0;  // nodal volumes (wall: vol_j = segment area |S_l|)
  double mass_i = 0.0;              // rho_i V_i
  double mass_j = std::numeric_limits<double>::infinity(); // +inf: rigid partner
  double dt = 0.0;                                         // time step (Regularized friction only)
  // Self contact (Bhattacharya & Lipton 2023, Sec. 4.4): reference distance |xi| of two nodes of
  // the same grain with no intact bond; < 0 (default) for nodes of different grains.
  double ref_dist = -1.0;
  // Normal force magnitude for the friction bound mu|F_r|; < 0 (default): this pair's own
  // repulsion.  The wall uses it to apply the net wall repulsion of eq. (4.8) to each wall.
  double friction_normal_force = -1.0;
};

struct ContactResult {
  double f[3] = {0.0, 0.0, 0.0};      // total force on i
  double f_rep[3] = {0.0, 0.0, 0.0};  // repulsion part
  double f_damp[3] = {0.0, 0.0, 0.0}; // damping part
  double f_fric[3] = {0.0, 0.0, 0.0}; // friction part
  double fpair = 0.0;   // signed normal force magnitude on i along e (<= 0 repulsive):
                        // f_rep + f_damp = fpair * e (LAMMPS virial convention)
  double energy = 0.0;  // repulsion energy; f_rep = -dE/dx_i exactly
  double power = 0.0;   // (f_damp + f_fric) . vrel  (<= 0, rate of dissipation)
  bool contact = false; // r < effective contact radius
  bool stick = false;   // Regularized friction in the stick branch
};

// Effective contact radius and stiffness multiplier for a pair (Bhattacharya & Lipton 2023,
// Sec. 4.4):
//   different grains (ref_dist < 0) or |xi| >= R_c:  radius R_c, multiplier 1 (eq. 4.1);
//   same grain with |xi| < R_c:  radius |xi|, multiplier R_c/|xi|.
// Sec. 4.4 gives the force density c_w (r - R)/R e for r < R, R = min(|xi|, R_c); with the
// Bhattacharya & Lipton's (2023) own identification c_w = K_n R_c (it matches eq. 4.1 for |xi| >
// R_c) this is F = -K_n (R_c/R) (R - r) V_i V_j e.  Continuous in |xi| at |xi| = R_c.
struct EffectiveRadius {
  double radius;
  double stiffness_factor;
};
inline EffectiveRadius effective_contact_radius(double Rc, double ref_dist)
{
  if (ref_dist < 0.0 || ref_dist >= Rc) return {Rc, 1.0};
  return {ref_dist, Rc / ref_dist};
}

// Repulsion magnitude and energy for distance r (scalar kernel of eq. 4.1 / Sec. 4.4):
//   F(r) = -K (R - r) V_i V_j  (force on i along e; negative = pushes i away from j)
//   E(r) = 1/2 K (R - r)^2 V_i V_j,  so  F = dE/dr ... and force on i = -dE/dx_i = F e.
// Zero for r >= R.  K = K_n * stiffness_factor.
inline double repulsion_force(double K, double R, double r, double vol_i, double vol_j)
{
  return r < R ? -K * (R - r) * vol_i * vol_j : 0.0;
}
inline double repulsion_energy(double K, double R, double r, double vol_i, double vol_j)
{
  return r < R ? 0.5 * K * (R - r) * (R - r) * vol_i * vol_j : 0.0;
}

// The single entry point: repulsion + damping + friction between node i and partner j.
// A wall calls it with sep = centroid of the wall segment minus x_i, vol_j = |S_l|,
// vrel = v_i - v_wall, mass_j = +inf (Bhattacharya & Lipton 2023, Sec. 4.5 below eq. 4.8).
ContactResult contact_force(const ContactInput &in, const ContactParams &p);

// ---------------------------------------------------------------------------------------
// Centroid (grain-level) damping, Jha et al. 2021, eq. (26)-(30)
// ---------------------------------------------------------------------------------------
// Force on the centre of grain p due to grain p' (both given by centre position z_c and velocity
// v_c), acting only while the centres approach and while dist(grains) < R_c (the caller checks
// the distance condition; pass in_contact):
//   delta_dot_c = (v_c' - v_c) . e_c,   e_c = (z_c' - z_c)/|z_c' - z_c|        (eq. 26)
//   F = beta_bar delta_dot_c e_c   if delta_dot_c < 0                         (eq. 27 x |Omega_p|)
// with beta_bar from restitution_damping_coefficient(eps_bar, C_bar, kappa_eff, R_c, M_eq),
// M_eq = harmonic_mean(M_p, M_p') (eq. 28-29).  Eq. (30): each node x of grain p receives the
// share F V_x/|Omega_p|.  Returns the power F . (v_c - v_c') (<= 0).
double centroid_damping_force(const double sep_c[3], const double vrel_c[3], double beta_bar,
                              bool in_contact, double f[3]);

// ---------------------------------------------------------------------------------------
// Dissipated energy
// ---------------------------------------------------------------------------------------
// The energy that forces dissipate in step n of velocity Verlet, from their power at the
// full-step velocities, P(n) = sum_i F_i(n) . v_i(n) (v after the second half-kick):
// -(P(n - 1) + P(n)) dt/2, the trapezoidal rule, which is how the integrator changes the
// kinetic energy: m/2 (|v(n)|^2 - |v(n - 1)|^2) = (F(n - 1) . v(n - 1) + F(n) . v(n)) dt/2 -
// dt^2/(8m) (|F(n)|^2 - |F(n - 1)|^2) for the total force, the last term telescoping over a
// run (Swope et al. 1982 for the velocity form of Verlet's scheme). `previous` holds P(n - 1)
// and becomes P(n). pair_style peridem/contact and fix peridem/wall count their damping and
// friction this way (the power at v(n - 1/2), which those forces take, counts a force that
// only reverses a velocity as a loss).
inline double dissipated_in_step(double &previous, double power, double dt)
{
  const double dissipated = -0.5 * (previous + power) * dt;
  previous = power;
  return dissipated;
}

// ---------------------------------------------------------------------------------------
// Stable time step
// ---------------------------------------------------------------------------------------
// Bound on the largest frequency of the linearised system (velocity Verlet / central
// difference is stable for dt < 2/omega_max, and (2/omega)(sqrt(1+zeta^2) - zeta) with damping
// ratio zeta).  For springs k_b along unit vectors e_b between free nodes (bonds:
// k_b = c w V_i V_j/|xi|, contact: K_n V_i V_j) and springs k_w along the normal n to rigid
// partners (walls) the Rayleigh quotient gives
//   u.K u = sum_b k_b (e_b.(u_i - u_j))^2 + sum_w k_w (n.u_i)^2 <= sum_i u_i.(2 A_i + W_i) u_i,
//   A_i = sum_{b at i} k_b e_b e_b,  W_i = sum_{w at i} k_w n n,
// so omega^2 <= max_i lambda_max(2 A_i + W_i)/m_i: a spring to a rigid partner counts once,
// a spring between two free nodes twice (Silling & Askari 2005 take the row sum, which
// assumes all bonds along one line; a family symmetric under the lattice's 90-degree rotations
// has an isotropic A_i = (sum k_b/d) 1, d times less).
//  bonds:    given explicitly (bond_omega2 = max_i 2 lambda_max(A_i)/m_i over the actual bonds,
//            what pair_style peridem/contact passes), or from the full-horizon integral
//            (isotropic): omega_b^2 = (2/d) c I/rho with I = int_H w(r)/r dV:
//            2D  constant 2 pi eps, conic pi eps;  3D  constant 2 pi eps^2, conic (2/3) pi eps^2.
//  contact:  the springs a node meets at the penetrations a stable run reaches.
//            k = K_n V^2 (V the largest nodal volume, h = V^(1/d) the spacing), on the smallest
//            nodal mass m, omega_c^2 = n_eff k/m with n_eff the largest of
//            * partners of another grain: at most min(ball, shallow), where
//              ball    = 2 ceil(|B_Rc|/V)/d   (the contact ball full of partners, isotropic), and
//              shallow = 2 x 2^(d-1)          (the surface row (2D) or plane (3D) of a lattice
//                        grain offers at most 2^(d-1) nodes within R_c while the penetration
//                        delta = R_c - gap stays below delta_s = R_c - sqrt(R_c^2 - h^2): a third
//                        node of the row, lateral distance h, needs gap^2 + h^2 < R_c^2; the
//                        second row, gap + h < R_c, needs a deeper one; for R_c <= h never)
//            * a wall at the same depth: the tangent stiffness of Bhattacharya & Lipton 2023, eq.
//            (4.7) at distance
//              d = R_c - delta_s (wall_contact_stiffness), counted once (rigid partner).
//            One body at a time: a node pressed into one body has its own grain on the other
//            side.  The penetrations of the papers' runs are far below delta_s (the bed of
//            Bhattacharya & Lipton 2023: delta_s = 0.35 h = 22 um, reached with eps^5 only by ~1
//            J/m per node against ~1e-4 J/m of kinetic energy a node has after falling the box
//            height); runs that press nodes deeper (crushing, compaction to overlap) need a smaller
//            step than this estimate: n_contacts overrides n_eff/2 (effective pair springs). dt_c =
//            (2/omega_c) (sqrt(1+zeta^2) - zeta), zeta the damping ratio of one pair.
//  combined: omega^2 <= omega_b^2 + omega_c^2  =>  dt = 1/sqrt(1/dt_b^2 + 1/dt_c^2);
//            recommended = safety * dt.
// Measured thresholds against this estimate: doc/pair_peridem_contact.rst.

// Normal tangent stiffness -dF/dd of the wall force of Bhattacharya & Lipton 2023, eq. (4.7) on a
// node at distance d in [0, R_c] from one wall plane (F = K_n V (R_c |S| - M),
// peridem_wall_geometry.h):
//   2D  2 K_n V sqrt(R_c^2 - d^2) (R_c - d)      3D  pi K_n V (R_c^2 - d^2) (R_c - d)
// (2 K_n V R_c^2 and pi K_n V R_c^3 on the wall plane, 0 at d = R_c).
double wall_contact_stiffness(int dimension, double Kn, double V, double Rc, double d);

struct TimeStepInput {
  int dimension = 3;
  double rho = 0.0; // density
  double c = 0.0;   // bond constant c (peridem_bond_law.h); 0: no bonds
  Micromodulus micromodulus = Micromodulus::Constant;
  double horizon = 0.0;
  double bond_omega2 = 0.0;   // > 0: explicit max_i 2 lambda_max(A_i)/m_i of the bonds
  double node_volume = 0.0;   // largest nodal volume
  double min_node_mass = 0.0; // smallest nodal mass
  double Kn = 0.0;            // 0: no contact
  double Rc = 0.0;
  double damping_ratio = 0.0; // contact damping ratio (r_d, or zeta of eq. 23)
  double n_contacts = 0.0;    // > 0: effective pair springs n (omega_c^2 = 2 n k/m); 0: above
  bool walls = true;          // a fix peridem/wall exists: the wall term takes part
  // walls with a contact law of their own (fix peridem/wall Kn ... Rc ...): the stiffest sets
  // the wall term; empty: the walls use Kn and Rc above ('contact pair')
  std::vector<std::array<double, 2>> wall_laws; // {Kn, Rc} each
  double safety = 0.8;
};
struct TimeStepEstimate {
  double dt_bond = std::numeric_limits<double>::infinity();
  double dt_contact = std::numeric_limits<double>::infinity();
  double dt_critical = std::numeric_limits<double>::infinity();    // combined
  double dt_recommended = std::numeric_limits<double>::infinity(); // safety * dt_critical
  double n_contacts = 0.0;    // effective pair springs omega_c^2 m/(2 k) used
  double shallow_depth = 0.0; // delta_s (R_c when R_c <= h)
};
TimeStepEstimate stable_time_step(const TimeStepInput &in);

// Largest eigenvalue of a symmetric 2x2 (dimension 2: a = xx, yy, xy) or 3x3 (a = xx, yy, zz,
// xy, xz, yz) matrix, closed form.
double symmetric_max_eigenvalue(const double *a, int dimension);

// Silling-Askari bond bound from an explicit sum S = sum_j c w(|xi_j|) V_j/|xi_j| over the
// bonds of the stiffest node: dt_b = sqrt(2 rho/S).
inline double bond_critical_time_step(double rho, double sum_c_w_vol_over_xi)
{
  return std::sqrt(2.0 * rho / sum_c_w_vol_over_xi);
}

} // namespace peridem

#endif
