/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: pure bond-based peridynamic bond law (no LAMMPS dependency).
//
// References:
//  Bhattacharya & Lipton 2023, "Simulating grain shape effects and damage in granular media
//       using PeriDEM", SIAM J. Sci. Comput.: eq. (3.1)-(3.2) force density,
//       Table 1 (spring constant c_w and critical stretch s_0 in 2D), Remark 1 (bond-based
//       Poisson ratio 1/3 in 2D, 1/4 in 3D), Sec. 3.1 (breakage, bond-fraction damage).
//  Jha, Desai, Bhattacharya & Lipton 2021 (Jha et al. 2021), "PeriDEM", J. Mech. Phys. Solids 151:
//  eq. (7)-(10) state-based model,
//       eq. (14)-(15) damage Z and fracture zone, eq. (31)-(33) nodal volumes and discrete force.
//  [SA05] Silling & Askari, Comput. Struct. 83 (2005) 1526: PMB constants in 3D.
//
// Sign conventions used throughout:
//   xi  = x0_j - x0_i (reference bond), |xi| = r;  y = y_j - y_i (current bond), |y| = l;
//   stretch s = (l - r)/r;  e = y/l.
//   The pair force on node i is  F e  with  F = c w(r) s V_i V_j  (positive F = attraction
//   of i toward j, i.e. tension); node j gets -F e.  F is exactly dE/dl of the bond energy
//   E = 1/2 c w(r) s^2 r V_i V_j, so forces are conservative.
#ifndef PERIDEM_BOND_LAW_H
#define PERIDEM_BOND_LAW_H

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace peridem {

// Thrown for invalid physical parameters (non-positive modulus, bad dimension, ...).
// The message is meant to be shown to the user verbatim (e.g. via LAMMPS error->all).
class ParameterError : public std::runtime_error {
 public:
  explicit ParameterError(const std::string &msg) : std::runtime_error(msg) {}
};

// Micromodulus (bond-based, Bhattacharya & Lipton 2023, Table 1) and, for the state-based model,
// the influence function J(r/eps) of Jha et al. 2021, eq. (7); "Conic" is 1 - r/eps in both cases.
enum class Micromodulus { Constant, Conic };

// Which elastic constant is handed to derive_bond_constants().
//  YoungsModulus: E.  BulkModulus: the 3D (material) bulk modulus K = E/(3(1-2nu)).
// Bond-based peridynamics fixes the Poisson ratio (Bhattacharya & Lipton 2023, Remark 1): nu = 1/3
// in 2D (plane stress, thin sheet), nu = 1/4 in 3D, so either constant determines the other:
//   3D: K = E/(3(1-2*1/4)) = 2E/3.   2D: K = E/(3(1-2*1/3)) = E.
enum class ElasticInput { YoungsModulus, BulkModulus };

// When a bond breaks (Bhattacharya & Lipton 2023, Sec. 3.1 breaks on |s| > s0; LAMMPS peri/pmb and
// Silling-Askari break in tension only, s > s0).
enum class BreakageMode { Tension, Absolute };

// Partial-volume ("volume correction") of the neighbour volume V_j near the horizon edge.
//  None:       factor 1.
//  LammpsPeri: exactly stock LAMMPS PERI (src/PERI/pair_peri_pmb.cpp, compute():
//              "if (fabs(r0 - delta) <= half_lc) vfrac_scale = (-1/(2 half_lc)) r0
//               + (1 + (delta - half_lc)/(2 half_lc))", the same in fix_peri_neigh.cpp),
//              i.e. factor (eps + h/2 - r)/h when |r - eps| <= h/2, else 1, with h the
//              lattice constant (domain->lattice->xlattice).
//  PeriDEM:    PeriDEM reference code (model/dem/demModel.cpp, computePeridynamicForces):
//              "if (rji > horizon - 0.5 h) volj *= (horizon + 0.5 h - rji)/h", h = mesh size.
// Both are the same linear ramp from 1 at r = eps - h/2 to 1/2 at r = eps; they differ only
// outside the range of existing bonds (r > eps).  The factor multiplies V_j (and, being a
// function of r only, is symmetric in i,j).
enum class VolumeCorrection { None, LammpsPeri, PeriDEM };

// Constants of the bond law: spring constant c (the c_w of Bhattacharya & Lipton 2023, eq. 3.2;
// units [modulus]/[length]^(d+1), so that c w s is a force per volume^2) and critical stretch s0.
struct BondConstants {
  double c = 0.0;
  double s0 = 0.0;
};

// Bond-based Poisson ratio (Bhattacharya & Lipton 2023, Remark 1): 1/3 in 2D (plane stress), 1/4 in
// 3D.
double bond_based_poisson_ratio(int dimension);

// Derive c and s0 from physical constants by matching (i) the strain energy density of a
// uniform isotropic stretch to linear elasticity and (ii) the energy of all bonds crossing a
// unit crack surface to G_c (derivations in peridem_bond_law.cpp).  Results:
//   2D (plane stress, nu = 1/3, Bhattacharya & Lipton 2023, Table 1):
//     constant: c = 6E/(pi eps^3 (1-nu)) = 9E/(pi eps^3),   s0 = sqrt(4 pi G_c/(9 E eps))
//     conic:    c = 24E/(pi eps^3 (1-nu)) = 36E/(pi eps^3), s0 = sqrt(5 pi G_c/(9 E eps))
//   3D (nu = 1/4):
//     constant: c = 18K/(pi eps^4),  s0 = sqrt(5 G_c/(9 K eps))   [SA05]
//     conic:    c = 90K/(pi eps^4),  s0 = sqrt(2 G_c/(3 K eps)) = sqrt(6 G_c/(9 K eps))
// Throws ParameterError for dimension not 2/3 or non-positive modulus, G_c or horizon.
BondConstants derive_bond_constants(int dimension, Micromodulus micromodulus, ElasticInput input,
                                    double modulus, double G_c, double horizon);

// c and s0 given directly (for comparison with other codes); validated > 0.
BondConstants direct_bond_constants(double c, double s0);

// Critical stretch of the linear peridynamic solid (state-based, 3D) used by Jha et al. 2021, eq.
// (10) (from Zhu & Zhao): s0 = sqrt(G_c / ((3 G + (3/4)^4 (K - 5G/3)) eps)).
double lps_critical_stretch(double K, double G, double G_c, double horizon);

// ---------------------------------------------------------------------------------------
// Per-bond pure functions (inline; called once per bond per step).
// ---------------------------------------------------------------------------------------

// Stretch s = (|y| - |xi|)/|xi|  (Bhattacharya & Lipton 2023, Sec. 3, below eq. 3.1).
inline double stretch(double current_length, double reference_length)
{
  return (current_length - reference_length) / reference_length;
}

// Micromodulus value w(r) of Bhattacharya & Lipton 2023, Table 1: 1 (constant) or 1 - r/eps
// (conic), 0 beyond eps.
inline double micromodulus_value(Micromodulus m, double r, double horizon)
{
  if (m == Micromodulus::Constant) return 1.0;
  return std::max(0.0, 1.0 - r / horizon);
}

// Pair force magnitude on node i along e = y/|y| (positive = toward j):
// F = c w s V_i V_j  (Bhattacharya & Lipton 2023, eq. 3.2 times the two nodal volumes, Jha et al.
// 2021, eq. 33).
inline double bond_force(double c, double w, double s, double vol_i, double vol_j)
{
  return c * w * s * vol_i * vol_j;
}

// Bond energy E = 1/2 c w s^2 |xi| V_i V_j, so that dE/d|y| = F above.
inline double bond_energy(double c, double w, double s, double reference_length, double vol_i,
                          double vol_j)
{
  return 0.5 * c * w * s * s * reference_length * vol_i * vol_j;
}

// The same law in the form the bond loop uses, one division per bond: with 1/|xi| cached
// and 1/|y| computed once, s = |y|/|xi| - 1 and F/|y| = k s/|y| = k (1/|xi| - 1/|y|),
// k = c w V_i V_j. Equal to stretch() and bond_force()/|y| up to rounding.
inline double stretch_from_inverse(double current_length, double inv_reference_length)
{
  return current_length * inv_reference_length - 1.0;
}
inline double bond_force_per_length(double k, double inv_reference_length,
                                    double inv_current_length)
{
  return k * (inv_reference_length - inv_current_length);
}

// Breakage test (Bhattacharya & Lipton 2023, Sec. 3.1): Tension: s > s0; Absolute: |s| > s0.
inline bool bond_breaks(double s, double s0, BreakageMode mode = BreakageMode::Tension)
{
  return (mode == BreakageMode::Tension ? s : std::fabs(s)) > s0;
}

// Partial-volume factor multiplying V_j for a bond of reference length r (see enum above).
// h: lattice constant (LammpsPeri) or mesh size (PeriDEM).  Continuous, 1 for
// r <= eps - h/2, decreasing linearly to 1/2 at r = eps.
inline double volume_factor(VolumeCorrection vc, double r, double horizon, double h)
{
  const double half = 0.5 * h;
  switch (vc) {
  case VolumeCorrection::LammpsPeri:
    // pair_peri_pmb.cpp: (-1/(2 half_lc)) r0 + (1 + (delta - half_lc)/(2 half_lc))
    return (std::fabs(r - horizon) <= half) ? (horizon + half - r) / h : 1.0;
  case VolumeCorrection::PeriDEM:
    return (r > horizon - half) ? (horizon + half - r) / h : 1.0;
  case VolumeCorrection::None:
  default:
    return 1.0;
  }
}

// Bond-fraction damage of a node (Bhattacharya & Lipton 2023, Sec. 3.1): broken / reference bonds
// (0 if no bonds).
inline double bond_fraction_damage(long broken, long reference)
{
  return reference > 0 ? static_cast<double>(broken) / static_cast<double>(reference) : 0.0;
}

// The damage Z of Jha et al. 2021, eqs. (14)-(15): Z(x) is the largest bond strain in the
// horizon of x over the critical strain s0, and Z >= 1 marks the fracture zone. Two measures of
// one bond's strain are offered; Z of a node is the max over its reference bonds.
//
// Stretch measure (the default of compute peridem/damage): |s| / s0 with the bond stretch
// s = (|y| - |xi|)/|xi|. This is what the authors' PeriDEM code computes (max |S/Sc| with S the
// material's bond strain), and it is zero under a rigid motion of the grain.
inline double z_stretch_term(double stretch, double s0)
{
  return std::fabs(stretch) / s0;
}

// Displacement measure, eq. (14) as printed: |u_j - u_i| / |xi| / s0. It is never below the
// stretch measure (triangle inequality) but counts rotation as strain: a grain rotated rigidly
// by theta reads 2 sin(theta/2) / s0 on every bond, which exceeds 1 from theta ~ s0 on.
inline double z_displacement_term(double displacement_difference_norm, double reference_length,
                                  double s0)
{
  return displacement_difference_norm / reference_length / s0;
}

} // namespace peridem

#endif
