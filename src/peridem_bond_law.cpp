/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: derivation of the bond-based constants c and s0 (see peridem_bond_law.h).
//
// Derivation (d = 2 or 3, micromodulus w(r) = W(r/eps), bond energy per unit volume^2
// e(r) = 1/2 c w(r) s^2 r, i.e. bond_energy() without the two nodal volumes).
// Write m_k = int_0^1 W(t) t^k dt, so int_0^eps w(r) r^k dr = m_k eps^(k+1):
//   constant W = 1:     m_k = 1/(k+1)
//   conic    W = 1 - t: m_k = 1/(k+1) - 1/(k+2) = 1/((k+1)(k+2))
//
// (i) Elastic constant: uniform isotropic stretch y = (1+s) x gives every bond stretch s.
// The strain energy density at a point is half the energy of its bonds (Bhattacharya & Lipton 2023,
// eq. 3.1):
//   W_pd = 1/2 int_{H_eps} e(r) dV.
//   2D: W_pd = 1/2 int_0^eps 1/2 c w s^2 r 2 pi r dr   = pi/2 c s^2 m_2 eps^3
//   3D: W_pd = 1/2 int_0^eps 1/2 c w s^2 r 4 pi r^2 dr = pi   c s^2 m_3 eps^4
// Linear elasticity for eps_ab = s delta_ab:
//   2D plane stress: sigma_xx = sigma_yy = E s/(1-nu),  W = E s^2/(1-nu)
//   3D:              W = 1/2 K (3 s)^2 = 9/2 K s^2
// Equating:
//   2D: c = 2E/(pi eps^3 (1-nu) m_2): constant (m_2 = 1/3)  c = 6E/(pi eps^3 (1-nu)),
//                                     conic    (m_2 = 1/12) c = 24E/(pi eps^3 (1-nu)),
//       i.e. Bhattacharya & Lipton 2023, Table 1; with nu = 1/3: 9E/(pi eps^3) and 36E/(pi eps^3).
//   3D: c = 9K/(2 pi eps^4 m_3):      constant (m_3 = 1/4)  c = 18K/(pi eps^4)  [SA05],
//                                     conic    (m_3 = 1/20) c = 90K/(pi eps^4).
//
// (ii) Fracture energy (Silling-Askari 2005): G_c is the energy of all bonds crossing a unit
// crack surface (plane z = 0), each broken at stretch s0 (full bond energy, each bond counted
// once): points at depth z in (0, eps) below, partners above within eps.
//   3D: the partners of a point at depth z at distance r > z lie in a spherical cap, polar
//       angle phi < acos(z/r):  int_0^acos(z/r) 2 pi r^2 sin(phi) dphi = 2 pi r^2 (1 - z/r).
//       G_c = int_0^eps dz int_z^eps e(r; s0) 2 pi r^2 (1 - z/r) dr
//           = pi c s0^2 int_0^eps w r^3 [int_0^r (1 - z/r) dz] dr = pi/2 c s0^2 m_4 eps^5.
//       constant (m_4 = 1/5):  G_c = pi c s0^2 eps^5/10, with c = 18K/(pi eps^4):
//                              s0 = sqrt(5 G_c/(9 K eps))   [SA05]
//       conic    (m_4 = 1/30): G_c = pi c s0^2 eps^5/60, with c = 90K/(pi eps^4):
//                              s0 = sqrt(2 G_c/(3 K eps))
//   2D: partners at distance r > z subtend the arc |theta| < acos(z/r): length 2 r acos(z/r).
//       G_c = int_0^eps dz int_z^eps e(r; s0) 2 r acos(z/r) dr
//           = c s0^2 int_0^eps w r^2 [int_0^r acos(z/r) dz] dr = c s0^2 m_3 eps^4
//       (int_0^r acos(z/r) dz = r int_0^1 acos(t) dt = r).
//       constant (m_3 = 1/4):  with c = 9E/(pi eps^3): s0 = sqrt(4 pi G_c/(9 E eps))  [BL T.1]
//       conic    (m_3 = 1/20): with c = 36E/(pi eps^3): s0 = sqrt(5 pi G_c/(9 E eps)) [BL T.1]
// Note that the Table 1 s0 values hold only for nu = 1/3; in general s0 = sqrt(G_c/(c m_3
// eps^4)) in 2D and sqrt(2 G_c/(pi c m_4 eps^5)) in 3D, which is what is computed below.
#include "peridem_bond_law.h"
#include "peridem_math.h"

#include <cmath>
#include <sstream>

namespace peridem {

namespace {

// m_k = int_0^1 W(t) t^k dt for the micromodulus shape W.
double moment(Micromodulus m, int k)
{
  const double a = k + 1.0;
  return m == Micromodulus::Constant ? 1.0 / a : 1.0 / (a * (a + 1.0));
}

void require_positive(const char *what, double value)
{
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream msg;
    msg << what << " must be a positive finite number (got " << value << ")";
    throw ParameterError(msg.str());
  }
}

void require_dimension(int dimension)
{
  if (dimension != 2 && dimension != 3)
    throw ParameterError("dimension must be 2 or 3 (got " + std::to_string(dimension) + ")");
}

} // namespace

double bond_based_poisson_ratio(int dimension)
{
  require_dimension(dimension);
  return dimension == 2 ? 1.0 / 3.0 : 0.25;
}

BondConstants derive_bond_constants(int dimension, Micromodulus micromodulus, ElasticInput input,
                                    double modulus, double G_c, double horizon)
{
  require_dimension(dimension);
  require_positive(input == ElasticInput::YoungsModulus ? "Young's modulus E" : "bulk modulus K",
                   modulus);
  require_positive("fracture energy G_c", G_c);
  require_positive("horizon", horizon);

  const double nu = bond_based_poisson_ratio(dimension);
  BondConstants bc;
  if (dimension == 2) {
    // E of the plane-stress sheet; from the 3D bulk modulus K = E/(3(1-2nu)) with nu = 1/3.
    const double E =
        input == ElasticInput::YoungsModulus ? modulus : 3.0 * modulus * (1.0 - 2.0 * nu);
    bc.c = 2.0 * E / (kPi * std::pow(horizon, 3) * (1.0 - nu) * moment(micromodulus, 2));
    bc.s0 = std::sqrt(G_c / (bc.c * moment(micromodulus, 3) * std::pow(horizon, 4)));
  } else {
    const double K =
        input == ElasticInput::BulkModulus ? modulus : modulus / (3.0 * (1.0 - 2.0 * nu));
    bc.c = 9.0 * K / (2.0 * kPi * std::pow(horizon, 4) * moment(micromodulus, 3));
    bc.s0 = std::sqrt(2.0 * G_c / (kPi * bc.c * moment(micromodulus, 4) * std::pow(horizon, 5)));
  }
  // finite inputs can still overflow (E = 1e300 gives c = inf): refuse rather than run with inf
  require_positive("spring constant c", bc.c);
  require_positive("critical stretch s0", bc.s0);
  return bc;
}

BondConstants direct_bond_constants(double c, double s0)
{
  require_positive("spring constant c", c);
  require_positive("critical stretch s0", s0);
  return {c, s0};
}

double lps_critical_stretch(double K, double G, double G_c, double horizon)
{
  require_positive("bulk modulus K", K);
  require_positive("shear modulus G", G);
  require_positive("fracture energy G_c", G_c);
  require_positive("horizon", horizon);
  // Jha et al. 2021, eq. (10)
  const double denom = 3.0 * G + std::pow(0.75, 4) * (K - 5.0 * G / 3.0);
  if (!(denom > 0.0))
    throw ParameterError("LPS critical stretch undefined: 3G + (3/4)^4 (K - 5G/3) <= 0");
  return std::sqrt(G_c / (denom * horizon));
}

} // namespace peridem
