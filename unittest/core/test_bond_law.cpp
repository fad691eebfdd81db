/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Tests of the pure bond law (src/peridem_bond_law.h): conservative forces, c and s0 against
// numerical integration of the strain energy density and of the fracture energy, Bhattacharya &
// Lipton 2023, Table 1, volume-correction ramps, breakage and damage measures.
#include "peridem_bond_law.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace peridem;

namespace {

constexpr double kPi = 3.14159265358979323846;
using Vec = std::array<double, 3>;

double norm(const Vec &a)
{
  return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// Gauss-Legendre rule on [a, b] (Newton iteration on P_n).
struct Rule {
  std::vector<double> x, w;
};
Rule gauss_legendre(int n, double a, double b)
{
  Rule r;
  for (int i = 1; i <= n; ++i) {
    double t = std::cos(kPi * (i - 0.25) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double dt = p1 / dp;
      t -= dt;
      if (std::fabs(dt) < 1e-16) break;
    }
    r.x.push_back(0.5 * (a + b) + 0.5 * (b - a) * t);
    r.w.push_back((b - a) / ((1.0 - t * t) * dp * dp));
  }
  return r;
}

// Energy of one bond (unit nodal volumes) from x = 0 to x' = xi under the affine map y = F x,
// evaluated through the public per-bond functions.
double affine_bond_energy(const BondConstants &bc, Micromodulus m, double eps, const Vec &xi,
                          const double F[3][3])
{
  Vec y{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) y[a] += F[a][b] * xi[b];
  const double r = norm(xi);
  return bond_energy(bc.c, micromodulus_value(m, r, eps), stretch(norm(y), r), r, 1.0, 1.0);
}

// Strain energy density W = 1/2 int_{H_eps} e dV' by quadrature (Bhattacharya & Lipton 2023,
// eq. 3.1 energy form).
double strain_energy_density(int dim, const BondConstants &bc, Micromodulus m, double eps,
                             const double F[3][3])
{
  const int n = 24;
  const Rule R = gauss_legendre(n, 0.0, eps);
  double W = 0.0;
  if (dim == 2) {
    const Rule T = gauss_legendre(n, 0.0, 2.0 * kPi);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec xi{R.x[i] * std::cos(T.x[j]), R.x[i] * std::sin(T.x[j]), 0.0};
        W += R.w[i] * T.w[j] * R.x[i] * affine_bond_energy(bc, m, eps, xi, F);
      }
  } else {
    const Rule C = gauss_legendre(n, -1.0, 1.0); // cos(polar angle)
    const Rule P = gauss_legendre(n, 0.0, 2.0 * kPi);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const double st = std::sqrt(1.0 - C.x[j] * C.x[j]);
          const Vec xi{R.x[i] * st * std::cos(P.x[k]), R.x[i] * st * std::sin(P.x[k]),
                       R.x[i] * C.x[j]};
          W += R.w[i] * C.w[j] * P.w[k] * R.x[i] * R.x[i] * affine_bond_energy(bc, m, eps, xi, F);
        }
  }
  return 0.5 * W;
}

// Fracture energy (Silling-Askari 2005): energy of all bonds, each at stretch s0, that cross a
// unit area of the plane z = 0.  A bond of length r at angle phi from the normal, starting at
// depth z below the plane, crosses it iff z < r cos(phi):
//   2D: int_0^eps dr int_{-pi/2}^{pi/2} dphi int_0^{r cos phi} dz  e(r) r
//   3D: int_0^eps dr int_0^{pi/2} dphi int_0^{r cos phi} dz  e(r) 2 pi r^2 sin(phi)
double fracture_energy(int dim, const BondConstants &bc, Micromodulus m, double eps)
{
  const int n = 24;
  const Rule R = gauss_legendre(n, 0.0, eps);
  const Rule P = gauss_legendre(n, dim == 2 ? -0.5 * kPi : 0.0, 0.5 * kPi);
  double G = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double r = R.x[i], zmax = r * std::cos(P.x[j]);
      const Rule Z = gauss_legendre(8, 0.0, zmax);
      const double e = bond_energy(bc.c, micromodulus_value(m, r, eps), bc.s0, r, 1.0, 1.0);
      const double jac = dim == 2 ? r : 2.0 * kPi * r * r * std::sin(P.x[j]);
      for (int k = 0; k < 8; ++k) G += R.w[i] * P.w[j] * Z.w[k] * e * jac;
    }
  return G;
}

const Micromodulus kBoth[] = {Micromodulus::Constant, Micromodulus::Conic};
const char *name(Micromodulus m)
{
  return m == Micromodulus::Constant ? "constant" : "conic";
}

} // namespace

// Bhattacharya & Lipton 2023, Table 1 (2D, nu = 1/3) with sample numbers: steel-like M_1 of
// Bhattacharya & Lipton 2023, Table 2, G_c = 135 J/m^2 (Bhattacharya & Lipton 2023, Sec. 6.4), eps
// = 0.133 mm.
TEST(BondLaw, Table1TwoDimensional)
{
  const double E = 191e9, Gc = 135.0, eps = 0.133e-3, nu = 1.0 / 3.0;
  const auto cst =
      derive_bond_constants(2, Micromodulus::Constant, ElasticInput::YoungsModulus, E, Gc, eps);
  EXPECT_NEAR(cst.c / (6 * E / (kPi * std::pow(eps, 3) * (1 - nu))), 1.0, 1e-13);
  EXPECT_NEAR(cst.s0 / std::sqrt(4 * kPi * Gc / (9 * E * eps)), 1.0, 1e-13);
  const auto con =
      derive_bond_constants(2, Micromodulus::Conic, ElasticInput::YoungsModulus, E, Gc, eps);
  EXPECT_NEAR(con.c / (24 * E / (kPi * std::pow(eps, 3) * (1 - nu))), 1.0, 1e-13);
  EXPECT_NEAR(con.s0 / std::sqrt(5 * kPi * Gc / (9 * E * eps)), 1.0, 1e-13);
  // Absolute sample values (hand-computed): c = 9E/(pi eps^3), 36E/(pi eps^3).
  EXPECT_NEAR(cst.c, 9 * 191e9 / (kPi * 2.352637e-12), 1e-6 * cst.c);
  EXPECT_NEAR(bond_based_poisson_ratio(2), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(bond_based_poisson_ratio(3), 0.25, 1e-15);
}

// 3D: Silling-Askari PMB constants and the conic analogue derived in peridem_bond_law.cpp.
TEST(BondLaw, ClosedFormsThreeDimensional)
{
  const double K = 14.9e9, Gc = 10.0, eps = 1.5e-3;
  const auto cst =
      derive_bond_constants(3, Micromodulus::Constant, ElasticInput::BulkModulus, K, Gc, eps);
  EXPECT_NEAR(cst.c / (18 * K / (kPi * std::pow(eps, 4))), 1.0, 1e-13);
  EXPECT_NEAR(cst.s0 / std::sqrt(5 * Gc / (9 * K * eps)), 1.0, 1e-13);
  const auto con =
      derive_bond_constants(3, Micromodulus::Conic, ElasticInput::BulkModulus, K, Gc, eps);
  EXPECT_NEAR(con.c / (90 * K / (kPi * std::pow(eps, 4))), 1.0, 1e-13);
  EXPECT_NEAR(con.s0 / std::sqrt(2 * Gc / (3 * K * eps)), 1.0, 1e-13);
  // E input: K = E/(3(1-2nu)) with nu = 1/4, i.e. K = 2E/3.
  const auto viaE = derive_bond_constants(3, Micromodulus::Constant, ElasticInput::YoungsModulus,
                                          1.5 * K, Gc, eps);
  EXPECT_NEAR(viaE.c / cst.c, 1.0, 1e-13);
  EXPECT_NEAR(viaE.s0 / cst.s0, 1.0, 1e-13);
  // 2D K input: E = 3K(1-2nu) = K for nu = 1/3.
  const auto k2 =
      derive_bond_constants(2, Micromodulus::Conic, ElasticInput::BulkModulus, K, Gc, eps);
  const auto e2 =
      derive_bond_constants(2, Micromodulus::Conic, ElasticInput::YoungsModulus, K, Gc, eps);
  EXPECT_NEAR(k2.c / e2.c, 1.0, 1e-13);
  // LAMMPS examples/peri/in.peri.pmb uses c = 1.6863e22 (cutoff 0.0015001 = 3 lattice
  // spacings + 1e-7): that is 18K/(pi eps^4) for K = 14.9 GPa and eps = 0.0015 m.
  const auto lmp = derive_bond_constants(3, Micromodulus::Constant, ElasticInput::BulkModulus,
                                         14.9e9, 1.0, 0.0015);
  EXPECT_NEAR(lmp.c / 1.6863e22, 1.0, 1e-4);
}

// The strain energy density of a uniform isotropic stretch equals linear elasticity's:
// 2D plane stress W = E s^2/(1-nu), 3D W = 9/2 K s^2, by quadrature of the bond energies.
TEST(BondLaw, StrainEnergyDensityMatchesElasticity)
{
  const double E = 70e9, Gc = 50.0, eps = 2e-3, s = 1e-3;
  for (int dim : {2, 3})
    for (Micromodulus m : kBoth) {
      const auto bc = derive_bond_constants(dim, m, ElasticInput::YoungsModulus, E, Gc, eps);
      const double F[3][3] = {{1 + s, 0, 0}, {0, 1 + s, 0}, {0, 0, dim == 3 ? 1 + s : 1.0}};
      const double W = strain_energy_density(dim, bc, m, eps, F);
      const double nu = bond_based_poisson_ratio(dim);
      const double K = E / (3 * (1 - 2 * nu));
      const double expected = dim == 2 ? E * s * s / (1 - nu) : 4.5 * K * s * s;
      EXPECT_NEAR(W / expected, 1.0, 1e-10) << dim << "D " << name(m);
    }
}

// Uniaxial strain probes the Poisson ratio (Cauchy relation of bond-based models):
// 2D plane stress W = E/(1-nu^2) s^2/2 with nu = 1/3; 3D W = (lambda+2mu) s^2/2 with
// lambda = mu, nu = 1/4.  Only to O(s) because the bond stretch is nonlinear in s.
TEST(BondLaw, UniaxialStrainEnergyFixesPoissonRatio)
{
  const double E = 70e9, Gc = 50.0, eps = 2e-3, s = 1e-7;
  const double F[3][3] = {{1 + s, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int dim : {2, 3})
    for (Micromodulus m : kBoth) {
      const auto bc = derive_bond_constants(dim, m, ElasticInput::YoungsModulus, E, Gc, eps);
      const double nu = bond_based_poisson_ratio(dim);
      const double W = strain_energy_density(dim, bc, m, eps, F);
      const double expected = dim == 2 ? 0.5 * E / (1 - nu * nu) * s * s
                                       : 0.5 * E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * s * s;
      EXPECT_NEAR(W / expected, 1.0, 1e-6) << dim << "D " << name(m);
    }
}

// s0 reproduces G_c through the Silling-Askari crack-surface integral (both micromoduli,
// 2D and 3D, E and K input).
TEST(BondLaw, CriticalStretchReproducesFractureEnergy)
{
  const double Gc = 135.0, eps = 0.6e-3;
  for (int dim : {2, 3})
    for (Micromodulus m : kBoth)
      for (ElasticInput in : {ElasticInput::YoungsModulus, ElasticInput::BulkModulus}) {
        const auto bc = derive_bond_constants(dim, m, in, 3e9, Gc, eps);
        EXPECT_NEAR(fracture_energy(dim, bc, m, eps) / Gc, 1.0, 1e-10) << dim << "D " << name(m);
      }
}

// F = dE/d|y| (finite differences, both signs of stretch, with micromodulus and volumes).
TEST(BondLaw, ForceIsDerivativeOfEnergyAlongBond)
{
  const double c = 3.7e20, eps = 1e-3, vi = 2.1e-10, vj = 1.3e-10;
  for (Micromodulus m : kBoth)
    for (double r : {0.2e-3, 0.7e-3, 0.999e-3})
      for (double s : {-0.03, -1e-4, 2e-4, 0.05}) {
        const double w = micromodulus_value(m, r, eps);
        const double l = r * (1 + s), h = 1e-6 * l;
        auto energy = [&](double len) { return bond_energy(c, w, stretch(len, r), r, vi, vj); };
        const double fd = (energy(l + h) - energy(l - h)) / (2 * h);
        const double F = bond_force(c, w, stretch(l, r), vi, vj);
        EXPECT_NEAR(F / fd, 1.0, 1e-6) << name(m) << " r=" << r << " s=" << s;
        EXPECT_EQ(F > 0, s > 0); // tension pulls i toward j
      }
}

// The bond loop's form (one division per bond) is the same law up to rounding.
TEST(BondLaw, LoopFormMatchesLaw)
{
  const double k = 3.7e20 * 2.1e-10 * 1.3e-10;
  for (double r0 : {0.2e-3, 0.7e-3, 1.5e-3})
    for (double s : {-0.03, -1e-4, 0.0, 2e-4, 0.05}) {
      const double r = r0 * (1 + s);
      const double s_loop = stretch_from_inverse(r, 1.0 / r0);
      EXPECT_NEAR(s_loop, stretch(r, r0), 1e-15) << "r0=" << r0 << " s=" << s;
      const double f_law = bond_force(k, 1.0, stretch(r, r0), 1.0, 1.0) / r;
      const double f_loop = bond_force_per_length(k, 1.0 / r0, 1.0 / r);
      EXPECT_NEAR(f_loop, f_law, 1e-12 * k / r0 * (std::fabs(s) + 1e-3)) << r0 << " " << s;
    }
}

// Force on node i is F e = -grad_{y_i} E and on node j -F e (finite differences of E with
// respect to the vector positions).
TEST(BondLaw, ForceIsMinusGradientOfEnergyWrtPositions)
{
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double c = 5e19, eps = 1.0;
  for (Micromodulus m : kBoth)
    for (int trial = 0; trial < 20; ++trial) {
      Vec x0i{U(gen), U(gen), U(gen)}, x0j{}, yi{}, yj{};
      Vec dir{U(gen), U(gen), U(gen)};
      const double r = 0.3 + 0.6 * std::fabs(U(gen));
      for (int a = 0; a < 3; ++a) {
        x0j[a] = x0i[a] + r * dir[a] / norm(dir);
        yi[a] = x0i[a] + 0.02 * U(gen);
        yj[a] = x0j[a] + 0.02 * U(gen);
      }
      const double rref = norm({x0j[0] - x0i[0], x0j[1] - x0i[1], x0j[2] - x0i[2]});
      const double w = micromodulus_value(m, rref, eps);
      auto energy = [&](const Vec &pi, const Vec &pj) {
        const double l = norm({pj[0] - pi[0], pj[1] - pi[1], pj[2] - pi[2]});
        return bond_energy(c, w, stretch(l, rref), rref, 1.0, 1.0);
      };
      const Vec d{yj[0] - yi[0], yj[1] - yi[1], yj[2] - yi[2]};
      const double l = norm(d), F = bond_force(c, w, stretch(l, rref), 1.0, 1.0);
      for (int a = 0; a < 3; ++a) {
        const double h = 1e-6;
        Vec ip = yi, im = yi, jp = yj, jm = yj;
        ip[a] += h;
        im[a] -= h;
        jp[a] += h;
        jm[a] -= h;
        const double fi = -(energy(ip, yj) - energy(im, yj)) / (2 * h);
        const double fj = -(energy(yi, jp) - energy(yi, jm)) / (2 * h);
        const double scale = std::fabs(F) + 1e-300;
        EXPECT_NEAR(fi, F * d[a] / l, 1e-6 * scale);
        EXPECT_NEAR(fj, -F * d[a] / l, 1e-6 * scale);
      }
    }
}

TEST(BondLaw, MicromodulusValues)
{
  EXPECT_DOUBLE_EQ(micromodulus_value(Micromodulus::Constant, 0.9, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(micromodulus_value(Micromodulus::Conic, 0.25, 1.0), 0.75);
  EXPECT_DOUBLE_EQ(micromodulus_value(Micromodulus::Conic, 1.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(micromodulus_value(Micromodulus::Conic, 1.2, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(stretch(1.1, 1.0), 0.10000000000000009);
}

TEST(BondLaw, Breakage)
{
  const double s0 = 0.01;
  EXPECT_FALSE(bond_breaks(0.0099, s0));
  EXPECT_FALSE(bond_breaks(0.01, s0)); // strictly greater, as LAMMPS peri/pmb
  EXPECT_TRUE(bond_breaks(0.0101, s0));
  EXPECT_FALSE(bond_breaks(-0.02, s0)); // tension only by default
  EXPECT_TRUE(bond_breaks(-0.02, s0, BreakageMode::Absolute));
  EXPECT_TRUE(bond_breaks(0.02, s0, BreakageMode::Absolute));
  EXPECT_FALSE(bond_breaks(-0.005, s0, BreakageMode::Absolute));
}

// Both ramps: 1 up to eps - h/2, continuous, linear and decreasing to 1/2 at eps; the
// LammpsPeri variant is literally pair_peri_pmb.cpp's expression.
TEST(BondLaw, VolumeFactorRamps)
{
  const double eps = 3.0015, h = 1.0, half = 0.5 * h;
  for (VolumeCorrection vc : {VolumeCorrection::LammpsPeri, VolumeCorrection::PeriDEM}) {
    EXPECT_DOUBLE_EQ(volume_factor(vc, 0.5, eps, h), 1.0);
    EXPECT_DOUBLE_EQ(volume_factor(vc, eps - half - 1e-9, eps, h), 1.0);
    EXPECT_NEAR(volume_factor(vc, eps - half, eps, h), 1.0, 1e-12);
    EXPECT_NEAR(volume_factor(vc, eps - half + 1e-9, eps, h), 1.0, 1e-8);
    EXPECT_NEAR(volume_factor(vc, eps, eps, h), 0.5, 1e-12);
    double prev = 1.0;
    for (int k = 1; k <= 100; ++k) {
      const double r = eps - half + k * half / 100.0;
      const double f = volume_factor(vc, r, eps, h);
      EXPECT_LT(f, prev);
      EXPECT_NEAR(f, (eps + half - r) / h, 1e-12);
      const double lmp = (-1.0 / (2 * half)) * r + (1.0 + ((eps - half) / (2 * half)));
      EXPECT_NEAR(f, lmp, 1e-12);
      prev = f;
    }
  }
  EXPECT_DOUBLE_EQ(volume_factor(VolumeCorrection::None, eps, eps, h), 1.0);
}

TEST(BondLaw, DamageMeasures)
{
  EXPECT_DOUBLE_EQ(bond_fraction_damage(3, 12), 0.25);
  EXPECT_DOUBLE_EQ(bond_fraction_damage(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(bond_fraction_damage(7, 7), 1.0);
  // Jha et al. 2021, eq. 14 as printed: |u_j - u_i| / |xi| / s0.
  EXPECT_NEAR(z_displacement_term(0.002, 0.1, 0.01), 2.0, 1e-14);
  EXPECT_NEAR(z_displacement_term(0.05 * 2.0, 2.0, 0.01), 5.0, 1e-13);
  // the stretch measure of the authors' code: |s| / s0, compression counted too
  EXPECT_NEAR(z_stretch_term(0.02, 0.01), 2.0, 1e-15);
  EXPECT_NEAR(z_stretch_term(-0.005, 0.01), 0.5, 1e-15);
  // displacement measure >= stretch measure (triangle inequality), equal for a pure stretch
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int t = 0; t < 100; ++t) {
    const Vec xi{U(gen), U(gen), U(gen)}, du{0.1 * U(gen), 0.1 * U(gen), 0.1 * U(gen)};
    const double r = norm(xi);
    const double s = stretch(norm({xi[0] + du[0], xi[1] + du[1], xi[2] + du[2]}), r);
    EXPECT_GE(z_displacement_term(norm(du), r, 0.01) + 1e-12, z_stretch_term(s, 0.01));
    const Vec along{0.05 * xi[0], 0.05 * xi[1], 0.05 * xi[2]}; // pure stretch by 5 %
    const double s_along = stretch(norm({xi[0] + along[0], xi[1] + along[1], xi[2] + along[2]}), r);
    EXPECT_NEAR(z_displacement_term(norm(along), r, 0.01), z_stretch_term(s_along, 0.01), 1e-11);
  }
  // a rigid rotation by theta about z: the stretch measure is zero, the displacement measure
  // 2 sin(theta/2) / s0 on every bond (so eq. 14 as printed reads Z >= 1 from theta = s0 on)
  const double theta = 0.02, c = std::cos(theta), sn = std::sin(theta);
  for (int t = 0; t < 20; ++t) {
    const Vec xi{U(gen), U(gen), U(gen)};
    const Vec y{c * xi[0] - sn * xi[1], sn * xi[0] + c * xi[1], xi[2]};
    const Vec du{y[0] - xi[0], y[1] - xi[1], 0.0};
    const double r = norm(xi), rxy = std::hypot(xi[0], xi[1]);
    EXPECT_NEAR(z_stretch_term(stretch(norm(y), r), 0.01), 0.0, 1e-12);
    EXPECT_NEAR(z_displacement_term(norm(du), r, 0.01), 2.0 * std::sin(theta / 2) * rxy / r / 0.01,
                1e-11);
  }
}

// Jha et al. 2021, eq. (10) for material M1 (K = 5G/3, so the bracket vanishes).
TEST(BondLaw, LpsCriticalStretch)
{
  const double K = 0.0216e9, G = 0.01296e9, Gc = 50.0, eps = 0.6e-3;
  EXPECT_NEAR(lps_critical_stretch(K, G, Gc, eps), std::sqrt(Gc / (3 * G * eps)), 1e-15);
  EXPECT_NEAR(lps_critical_stretch(2e9, 0.6e9, 500, 1e-3),
              std::sqrt(500 / ((1.8e9 + 0.31640625 * (2e9 - 1e9)) * 1e-3)), 1e-15);
  EXPECT_THROW(lps_critical_stretch(K, -G, Gc, eps), ParameterError);
}

namespace {
std::string error_of(int dim, double mod, double Gc, double eps)
{
  try {
    derive_bond_constants(dim, Micromodulus::Constant, ElasticInput::YoungsModulus, mod, Gc, eps);
  } catch (const ParameterError &e) {
    return e.what();
  }
  return "";
}
} // namespace

TEST(BondLaw, InvalidParametersAreRejected)
{
  EXPECT_NE(error_of(1, 1e9, 1, 1).find("dimension must be 2 or 3"), std::string::npos);
  EXPECT_NE(error_of(3, 0.0, 1, 1).find("Young's modulus E must be a positive"), std::string::npos);
  EXPECT_NE(error_of(3, 1e9, -1, 1).find("fracture energy G_c must be a positive"),
            std::string::npos);
  EXPECT_NE(error_of(2, 1e9, 1, 0).find("horizon must be a positive"), std::string::npos);
  EXPECT_NE(error_of(2, 1e9, 1, std::nan("")).find("horizon"), std::string::npos);
  EXPECT_NE(error_of(2, INFINITY, 1, 1).find("Young's modulus"), std::string::npos);
  EXPECT_EQ(error_of(2, 1e9, 1, 1), "");
  try {
    derive_bond_constants(3, Micromodulus::Conic, ElasticInput::BulkModulus, -5, 1, 1);
    FAIL() << "no exception";
  } catch (const ParameterError &e) {
    EXPECT_NE(std::string(e.what()).find("bulk modulus K"), std::string::npos);
  }
  EXPECT_THROW(direct_bond_constants(0.0, 0.1), ParameterError);
  EXPECT_THROW(direct_bond_constants(1.0, -0.1), ParameterError);
  const auto d = direct_bond_constants(1.6863e22, 0.0005);
  EXPECT_EQ(d.c, 1.6863e22);
  EXPECT_EQ(d.s0, 0.0005);
  EXPECT_THROW(bond_based_poisson_ratio(4), ParameterError);
}
