/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: the linear peridynamic solid (state-based, LPS), pure functions (no LAMMPS).
//
// References:
//  Jha, Desai, Bhattacharya & Lipton 2021, "PeriDEM", J. Mech. Phys. Solids 151, 104376: eq.
//  (5)-(9) force state, weighted
//         volume m_x, dilation theta_x, deviatoric extension e^d; eq. (10) critical stretch
//         (lps_critical_stretch in peridem_bond_law.h); eq. (33)-(34) discrete sums.
//  Silling, Epton, Weckner, Xu & Askari, J. Elasticity 88 (2007): the LPS in 3D.
//  Le, Chan & Schwartz, Int. J. Numer. Meth. Eng. 98 (2014) 547: the 2D LPS.
//
// In d dimensions, with influence omega(r), partial-volume factor beta and extension
// e = |y| - r of a bond of reference length r (sums over the intact bonds of node i):
//   m_i     = sum_j omega beta r^2 V_j                       (weighted volume, Jha et al. 2021, eq.
//   8) theta_i = (d/m_i) sum_j omega beta r e V_j               (dilation, Jha et al. 2021, eq. 34)
//   W_i     = a/2 theta_i^2 + b/(2 m_i) sum_j omega beta (e - theta_i r/d)^2 V_j
// Matching W to linear elasticity (isotropic averages <n_a n_b> = delta/d,
// <(n.E n)^2> = 2 E:E/(d(d+2)) for traceless E) gives b = d(d+2) G and a = the d-dimensional
// bulk modulus: 3D a = K, b = 15 G; 2D plane strain a = lambda + G = K + G/3, b = 8 G; 2D
// plane stress a = lambda* + G with lambda* = 2 lambda G/(lambda + 2G). dW/de_j gives the
// scalar force state  t_i(j) = omega beta [(d a - b/d) theta_i r / m_i + b e / m_i]
// (3D: (3K - 5G) theta r/m + 15 G e/m, Jha et al. 2021, eq. 9 and LAMMPS peri/lps), and the force
// of bond ij on node i, along y_j - y_i, is (Jha et al. 2021, eq. 33 times V_i)
//   F_ij = V_i V_j omega beta [c_vol (theta_i/m_i + theta_j/m_j) r + c_dev (1/m_i + 1/m_j) e]
// with c_vol = d a - b/d, c_dev = b.
#ifndef PERIDEM_LPS_LAW_H
#define PERIDEM_LPS_LAW_H

#include "peridem_bond_law.h"

namespace peridem {

// Influence function omega(r) (Jha et al. 2021, eq. 7 names it J(r/eps)).
//  Conic:    1 - r/eps, the paper's.
//  Constant: 1.
//  Inverse:  1/r, LAMMPS peri/lps's (influence_function() in pair_peri_lps.cpp).
enum class Influence { Conic, Constant, Inverse };

inline double influence_value(Influence w, double r, double horizon)
{
  switch (w) {
  case Influence::Conic:
    return std::max(0.0, 1.0 - r / horizon);
  case Influence::Inverse:
    return 1.0 / r;
  case Influence::Constant:
  default:
    return 1.0;
  }
}

// Which constants a 2D model uses (3D ignores it).
//  PlaneStrain (default) and PlaneStress: d = 2 with the 2D bulk modulus above.
//  ThreeD: the 3D constants (d = 3, a = K, b = 15 G) applied to 2D sums, as Jha et al. 2021, eq.
//  (7)-(9)
//          are written and as its reference code (prashjha/PeriDEM) evaluates them in 2D; for
//          comparing with that paper's numbers only: the resulting 2D material is not the one
//          K and G describe.
enum class LpsPlane { PlaneStrain, PlaneStress, ThreeD };

struct LpsConstants {
  double d = 3.0;     // dilation factor: theta = (d/m) sum omega beta r e V
  double a = 0.0;     // bulk modulus of the d-dimensional model
  double b = 0.0;     // deviatoric constant d(d+2) G
  double c_vol = 0.0; // d a - b/d
  double c_dev = 0.0; // b
};

// K: 3D bulk modulus, G: shear modulus (ParameterError unless both > 0 and the plane-stress
// lambda* is defined). dimension 2 or 3.
LpsConstants lps_constants(int dimension, LpsPlane plane, double K, double G);

// Force of one bond ij on node i along the current bond (positive: tension, towards j).
// k = omega beta V_i V_j; theta_over_m = theta/m and inv_m = 1/m of the two nodes.
inline double lps_bond_force(const LpsConstants &c, double k, double r0, double e,
                             double theta_over_m_i, double theta_over_m_j, double inv_m_i,
                             double inv_m_j)
{
  return k * (c.c_vol * (theta_over_m_i + theta_over_m_j) * r0 + c.c_dev * (inv_m_i + inv_m_j) * e);
}

// The share of bond ij in the energy sum_i V_i W_i: node i's deviatoric term of this bond
// and its volumetric energy apportioned by omega beta r^2 V_j / m_i (the weights sum to 1),
// plus the same for node j. Summed over all bonds of one type, the total is sum_i V_i W_i.
inline double lps_bond_energy(const LpsConstants &c, double k, double r0, double e, double theta_i,
                              double theta_j, double inv_m_i, double inv_m_j)
{
  const double di = e - theta_i * r0 / c.d, dj = e - theta_j * r0 / c.d;
  return 0.5 * k *
         (c.c_dev * (di * di * inv_m_i + dj * dj * inv_m_j) +
          c.a * r0 * r0 * (theta_i * theta_i * inv_m_i + theta_j * theta_j * inv_m_j));
}

// Time-step bound (pair_style peridem/contact): the LPS energy is not a sum over
// bonds (theta couples a node's whole family), but it is bounded by one.  For node i with
// S = sum_j omega beta e^2 V_j:
//   theta_i^2 = (d/m)^2 (sum omega beta r e V)^2 <= (d^2/m) S          (Cauchy-Schwarz, m =
//                                                                       sum omega beta r^2 V)
//   sum omega beta (e - theta r/d)^2 V <= S   (theta r/d is the omega beta V-weighted least-
//                                              squares fit of e by a multiple of r)
// so W_i <= (a d^2 + b)/(2 m_i) S and sum_i V_i W_i <= 1/2 sum_bonds k_b e_b^2 with
//   k_b = (a d^2 + b) omega beta V_i V_j (1/m_i + 1/m_j).
// Linearised about the reference state (e_b = e_b.(u_j - u_i)) this is a bond-based spring
// network that is at least as stiff as the LPS, so the Rayleigh bound of the bond-based
// time step (Silling & Askari 2005, stable_time_step in peridem_contact_law.h) holds with
// these springs.  Pure dilation attains the volumetric part (ratio a d^2/(a d^2 + b)), a
// pure deviatoric field with theta = 0 the deviatoric part.
inline double lps_spring_constant(const LpsConstants &c)
{
  return c.a * c.d * c.d + c.b;
}

} // namespace peridem

#endif
