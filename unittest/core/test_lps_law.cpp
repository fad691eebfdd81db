/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// The linear peridynamic solid's constants (peridem_lps_law.h): the strain energy density
// of a homogeneous small strain, integrated over the horizon by quadrature, equals linear
// elasticity's for the given K and G (3D; 2D plane strain and plane stress), for every
// influence function; and the 3D constants are LAMMPS peri/lps's.

#include "peridem_lps_law.h"

#include "gtest/gtest.h"

#include <array>
#include <cmath>
#include <vector>

using namespace peridem;

namespace {

using Strain = std::array<std::array<double, 3>, 3>;

// W of Jha et al. 2021, eq. 8 for the affine small strain eps (e = r n.eps.n), by quadrature over
// the ball (d = 3) or disk (d = 2) of radius 1 (the horizon), linearised in eps
double lps_energy_density(const LpsConstants &c, int dim, Influence w, const Strain &eps)
{
  const int nr = 200, nphi = 16, nt = dim == 3 ? 128 : 1;
  const double pi = std::acos(-1.0);
  double m = 0.0, s1 = 0.0;
  // first pass: m and the dilation; second: deviatoric sum
  auto each = [&](auto &&fn) {
    for (int ir = 0; ir < nr; ir++) {
      const double r = (ir + 0.5) / nr, dr = 1.0 / nr;
      for (int it = 0; it < nt; it++) {
        // Gauss-free midpoint rule in cos(theta) for 3D
        const double ct = dim == 3 ? -1.0 + (it + 0.5) * 2.0 / nt : 0.0;
        const double st = dim == 3 ? std::sqrt(1.0 - ct * ct) : 1.0;
        for (int ip = 0; ip < nphi; ip++) {
          const double phi = (ip + 0.5) * 2.0 * pi / nphi;
          const double n[3] = {st * std::cos(phi), st * std::sin(phi), ct};
          const double dA =
              dim == 3 ? r * r * dr * (2.0 / nt) * (2.0 * pi / nphi) : r * dr * (2.0 * pi / nphi);
          double nen = 0.0;
          for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) nen += n[a] * eps[a][b] * n[b];
          fn(r, r * nen, influence_value(w, r, 1.0) * dA);
        }
      }
    }
  };
  each([&](double r, double e, double wdA) {
    m += wdA * r * r;
    s1 += wdA * r * e;
  });
  const double theta = c.d / m * s1;
  double dev = 0.0;
  each([&](double r, double e, double wdA) {
    const double ed = e - theta * r / c.d;
    dev += wdA * ed * ed;
  });
  return 0.5 * c.a * theta * theta + 0.5 * c.b / m * dev;
}

// lambda/2 (tr eps)^2 + G eps:eps over the first dim components
double elastic_energy_density(double lambda, double G, int dim, const Strain &eps)
{
  double tr = 0.0, ee = 0.0;
  for (int a = 0; a < dim; a++) {
    tr += eps[a][a];
    for (int b = 0; b < dim; b++) ee += eps[a][b] * eps[a][b];
  }
  return 0.5 * lambda * tr * tr + G * ee;
}

const Strain STRAIN = {
    {{1.0e-3, 0.4e-3, -0.2e-3}, {0.4e-3, -0.5e-3, 0.3e-3}, {-0.2e-3, 0.3e-3, 0.7e-3}}};

} // namespace

TEST(LpsLaw, ThreeDConstantsAreLammpsPeriLps)
{
  // pair_peri_lps.cpp: (3K - 5G) theta r0 / m and 15 G dr / m, theta = 3/m sum
  const LpsConstants c = lps_constants(3, LpsPlane::PlaneStrain, 14.9e9, 8.1e9);
  EXPECT_EQ(c.d, 3.0);
  EXPECT_DOUBLE_EQ(c.c_vol, 3.0 * 14.9e9 - 5.0 * 8.1e9);
  EXPECT_DOUBLE_EQ(c.c_dev, 15.0 * 8.1e9);
  EXPECT_DOUBLE_EQ(c.a, 14.9e9);
}

TEST(LpsLaw, EnergyOfAHomogeneousStrainIsLinearElasticity)
{
  const double K = 2.0e9;
  for (double nu : {0.1, 0.35}) {
    const double G = 3.0 * K * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
    const double lambda = K - 2.0 * G / 3.0;
    const double lambda_star = 2.0 * lambda * G / (lambda + 2.0 * G);
    for (Influence w : {Influence::Conic, Influence::Constant, Influence::Inverse}) {
      struct Case {
        int dim;
        LpsPlane plane;
        double lam;
      };
      for (const Case &k :
           {Case{3, LpsPlane::PlaneStrain, lambda}, Case{2, LpsPlane::PlaneStrain, lambda},
            Case{2, LpsPlane::PlaneStress, lambda_star}}) {
        const LpsConstants c = lps_constants(k.dim, k.plane, K, G);
        const double W = lps_energy_density(c, k.dim, w, STRAIN);
        const double ref = elastic_energy_density(k.lam, G, k.dim, STRAIN);
        EXPECT_NEAR(W, ref, 2e-4 * ref) << "dim " << k.dim << " plane " << int(k.plane) << " nu "
                                        << nu << " influence " << int(w);
      }
    }
  }
}

TEST(LpsLaw, ThreeDOptionIn2DIsNotThe2DMaterial)
{
  // the paper's 3D constants applied to 2D sums (theta = 3/m sum, 3K, 15G): an in-plane
  // dilation eps stores 9K eps^2/2, not the plane-strain 2(K + G/3) eps^2
  const double K = 2.0e9, G = 1.0e9;
  const LpsConstants c = lps_constants(2, LpsPlane::ThreeD, K, G);
  EXPECT_EQ(c.d, 3.0);
  Strain dil{};
  dil[0][0] = dil[1][1] = 1e-3;
  const double W = lps_energy_density(c, 2, Influence::Conic, dil);
  const double strain_ref = elastic_energy_density(K - 2.0 * G / 3.0, G, 2, dil);
  EXPECT_GT(std::fabs(W - strain_ref), 0.05 * strain_ref);
}

TEST(LpsLaw, BadConstantsAreRefused)
{
  EXPECT_THROW(lps_constants(3, LpsPlane::PlaneStrain, 0.0, 1.0), ParameterError);
  EXPECT_THROW(lps_constants(3, LpsPlane::PlaneStrain, 1.0, -1.0), ParameterError);
  EXPECT_THROW(lps_constants(1, LpsPlane::PlaneStrain, 1.0, 1.0), ParameterError);
}

TEST(LpsLaw, BondEnergySumsToTheNodeEnergy)
{
  // one node with three bonds (the partners' own terms set to zero by inv_m_j = 0):
  // sum of the bond shares = V_i W_i of Jha et al. 2021, eq. 8
  const LpsConstants c = lps_constants(3, LpsPlane::PlaneStrain, 3.0, 1.0);
  const double Vi = 0.7, r0[3] = {1.0, 1.5, 2.0}, e[3] = {0.01, -0.02, 0.005},
               Vj[3] = {0.5, 0.8, 1.1};
  double m = 0.0, s = 0.0;
  for (int n = 0; n < 3; n++) {
    m += r0[n] * r0[n] * Vj[n];
    s += r0[n] * e[n] * Vj[n];
  }
  const double theta = 3.0 * s / m;
  double dev = 0.0, shares = 0.0;
  for (int n = 0; n < 3; n++) {
    dev += std::pow(e[n] - theta * r0[n] / 3.0, 2) * Vj[n];
    shares += lps_bond_energy(c, Vi * Vj[n], r0[n], e[n], theta, 0.0, 1.0 / m, 0.0);
  }
  const double W = 0.5 * c.a * theta * theta + 0.5 * c.b / m * dev;
  EXPECT_NEAR(shares, Vi * W, 1e-14 * Vi * W);
}

// The time-step bound of the LPS (lps_spring_constant): for any extensions e_j of a node's
// family W_i <= (a d^2 + b)/(2 m_i) sum omega beta e^2 V_j (Cauchy-Schwarz on theta, least
// squares on the deviatoric part), with equality of the volumetric part for pure dilation and
// of the deviatoric part for theta = 0.  A random 2D family (plane strain) and a 3D one.
TEST(LpsLaw, SpringConstantBoundsTheNodeEnergy)
{
  unsigned seed = 12345;
  auto uniform = [&seed]() {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) & 0xffff) / 65536.0;
  };
  for (int dim : {2, 3}) {
    const LpsConstants c = lps_constants(dim, LpsPlane::PlaneStrain, 2.0e9, 0.9e9);
    const int n = 40;
    std::vector<double> r(n), w(n), V(n), e(n);
    for (int j = 0; j < n; j++) {
      r[j] = 0.1 + 0.9 * uniform();
      w[j] = influence_value(Influence::Conic, r[j], 1.05);
      V[j] = 0.5 + uniform();
    }
    auto energy = [&](const std::vector<double> &ext, double &bound) {
      double m = 0.0, s = 0.0, sq = 0.0;
      for (int j = 0; j < n; j++) {
        m += w[j] * r[j] * r[j] * V[j];
        s += w[j] * r[j] * ext[j] * V[j];
        sq += w[j] * ext[j] * ext[j] * V[j];
      }
      const double theta = c.d / m * s;
      double dev = 0.0;
      for (int j = 0; j < n; j++) {
        const double ed = ext[j] - theta * r[j] / c.d;
        dev += w[j] * ed * ed * V[j];
      }
      bound = 0.5 * lps_spring_constant(c) / m * sq;
      return 0.5 * c.a * theta * theta + 0.5 * c.b / m * dev;
    };
    double bound = 0.0;
    for (int trial = 0; trial < 200; trial++) {
      for (int j = 0; j < n; j++) e[j] = uniform() - 0.3;
      const double W = energy(e, bound);
      EXPECT_GT(W, 0.0);
      EXPECT_LE(W, bound * (1.0 + 1e-12)) << "dim " << dim << " trial " << trial;
    }
    // pure dilation e = s r: W = a d^2 s^2/2, bound (a d^2 + b) s^2/2
    for (int j = 0; j < n; j++) e[j] = 1e-3 * r[j];
    const double Wdil = energy(e, bound);
    EXPECT_NEAR(Wdil / bound, c.a * c.d * c.d / lps_spring_constant(c), 1e-12);
  }
}
