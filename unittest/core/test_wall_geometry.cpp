/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Tests of the analytic wall regions and wall forces (src/peridem_wall_geometry.h) against
// independent adaptive quadrature of chord lengths, Bhattacharya & Lipton's (2023) printed formulas
// and limits.
#include "peridem_wall_geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

using namespace peridem;

namespace {

// ---- independent reference: adaptive Gauss-Kronrod (7-15) -----------------------------------
const double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                        0.207784955007898467600689403773245, 0.0};
const double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
const double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

double gk_rule(const std::function<double(double)> &f, double a, double b, double &err)
{
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double k = kWgk[7] * f(c), g = kWg[3] * f(c);
  for (int j = 0; j < 7; ++j) {
    const double s = f(c - h * kXgk[j]) + f(c + h * kXgk[j]);
    k += kWgk[j] * s;
    if (j % 2 == 1) g += kWg[j / 2] * s;
  }
  err = std::fabs(k - g) * h;
  return k * h;
}

double gk_adapt(const std::function<double(double)> &f, double a, double b, double tol,
                int depth = 0)
{
  if (!(b > a)) return 0.0;
  double err;
  const double k = gk_rule(f, a, b, err);
  // at least 3 levels of splitting, so that no feature is missed by the first rule
  // (err also accepted at the round-off level of the interval's value)
  // (the tolerance of a half interval stops halving at 1e-17, the round-off of one GK rule
  // on O(1) values: below that the recursion only multiplies work)
  if ((depth >= 3 && (err < tol || err < 1e-15 * std::fabs(k))) || depth > 30) return k;
  const double c = 0.5 * (a + b);
  const double t = std::max(0.5 * tol, 1e-17);
  return gk_adapt(f, a, c, t, depth + 1) + gk_adapt(f, c, b, t, depth + 1);
}

// Adaptive quadrature over [a, b] split at the given breakpoints (kinks of the integrand).
double gk_breaks(const std::function<double(double)> &f, double a, double b,
                 std::vector<double> breaks, double tol)
{
  breaks.push_back(a);
  breaks.push_back(b);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double lo = std::max(a, breaks[i]), hi = std::min(b, breaks[i + 1]);
    if (hi > lo) sum += gk_adapt(f, lo, hi, tol);
  }
  return sum;
}

// x where sqrt(R^2 - x^2) = t (both signs), if any
std::vector<double> kinks(double R, std::initializer_list<double> ts)
{
  std::vector<double> out;
  for (double t : ts)
    if (t * t < R * R) {
      out.push_back(std::sqrt(R * R - t * t));
      out.push_back(-std::sqrt(R * R - t * t));
    }
  return out;
}

// 2D: region {x > a, y > b} of the disk radius R (b = -R: single wall).
WallRegion ref_quadrant(double R, double a, double b, double tol = 1e-15)
{
  auto lowtop = [=](double x, double &lo, double &top) {
    top = std::sqrt(std::max(0.0, R * R - x * x));
    lo = std::max(b, -top);
    return top > lo;
  };
  WallRegion r;
  const double x0 = std::max(a, -R);
  const std::vector<double> br = kinks(R, {b});
  r.area = gk_breaks(
      [&](double x) {
        double lo, t;
        return lowtop(x, lo, t) ? t - lo : 0.0;
      },
      x0, R, br, tol);
  r.moment[0] = gk_breaks(
      [&](double x) {
        double lo, t;
        return lowtop(x, lo, t) ? x * (t - lo) : 0.0;
      },
      x0, R, br, tol);
  r.moment[1] = gk_breaks(
      [&](double x) {
        double lo, t;
        return lowtop(x, lo, t) ? 0.5 * (t * t - lo * lo) : 0.0;
      },
      x0, R, br, tol);
  return r;
}

// 3D: region {x > a, y > b, z > c} of the ball radius R, nested adaptive quadrature of the
// z-chord.  which = 0 volume, 1..3 moments.
double ref_corner(double R, double a, double b, double c, int which)
{
  auto inner = [=](double x) {
    const double rho2 = R * R - x * x;
    if (rho2 <= 0.0) return 0.0;
    const double rho = std::sqrt(rho2);
    auto fy = [=](double y) {
      const double zt = std::sqrt(std::max(0.0, rho2 - y * y));
      const double zl = std::max(c, -zt);
      if (!(zt > zl)) return 0.0;
      switch (which) {
      case 0:
        return zt - zl;
      case 1:
        return x * (zt - zl);
      case 2:
        return y * (zt - zl);
      default:
        return 0.5 * (zt * zt - zl * zl);
      }
    };
    return gk_breaks(fy, std::max(b, -rho), rho, kinks(rho, {c}), 1e-15);
  };
  return gk_breaks(inner, std::max(a, -R), R, kinks(R, {b, c, std::sqrt(b * b + c * c)}), 1e-13);
}

void expect_region_near(const WallRegion &got, const WallRegion &ref, double scale_area,
                        double scale_moment, double tol, const char *what)
{
  EXPECT_NEAR(got.area, ref.area, tol * scale_area) << what;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.moment[k], ref.moment[k], tol * scale_moment) << what;
}

} // namespace

// ---------------------------------------------------------------------------------------------
// 2D
// ---------------------------------------------------------------------------------------------

TEST(WallGeometry2D, SegmentMatchesQuadratureAndSeed)
{
  const double R = 0.7;
  for (double t : {-0.99, -0.7, -0.3, 0.0, 0.2, 0.5, 0.9, 0.999, 0.999999}) {
    const double d = t * R;
    const WallRegion s = disk_segment(R, d);
    const WallRegion ref = ref_quadrant(R, d, -R);
    expect_region_near(s, ref, R * R, R * R * R, 1e-10, "segment");
    // Bhattacharya & Lipton 2023, Sec. 4.5: |S| = pi R^2/2 - R^2 asin(d/R) - sqrt(R^2 - d^2) d,
    //                     |c - p| = 2/3 (R^2 - d^2)^{3/2}/|S|
    const double seed_area =
        0.5 * M_PI * R * R - R * R * std::asin(d / R) - std::sqrt(R * R - d * d) * d;
    EXPECT_NEAR(s.area, seed_area, 1e-14 * R * R);
    if (d >= 0.0 && d < 0.99 * R) {
      EXPECT_NEAR(s.moment[0] / s.area, 2.0 / 3.0 * std::pow(R * R - d * d, 1.5) / seed_area,
                  1e-13 * R);
    }
  }
}

TEST(WallGeometry2D, SegmentLimits)
{
  const double R = 1.3;
  const WallRegion half = disk_segment(R, 0.0); // at contact: half disk
  EXPECT_NEAR(half.area, 0.5 * M_PI * R * R, 1e-15);
  EXPECT_NEAR(half.moment[0] / half.area, 4.0 * R / (3.0 * M_PI), 1e-15);
  EXPECT_EQ(disk_segment(R, R).area, 0.0); // d = R_c: nothing
  EXPECT_LT(disk_segment(R, R * (1.0 - 1e-12)).area, 1e-17);
  EXPECT_GT(disk_segment(R, R * (1.0 - 1e-6)).area, 0.0);
  EXPECT_NEAR(disk_segment(R, -R).area, M_PI * R * R, 1e-15); // fully across the wall
}

TEST(WallGeometry2D, CornerMatchesQuadratureAndSeed)
{
  const double R = 1.0;
  const double vals[] = {-0.95, -0.6, -0.2, 0.0, 0.1, 0.3, 0.5, 0.7, 0.9};
  for (double a : vals)
    for (double b : vals) {
      const WallRegion q = disk_quadrant(R, a, b);
      const WallRegion ref = ref_quadrant(R, a, b);
      expect_region_near(q, ref, 1.0, 1.0, 1e-10,
                         (std::to_string(a) + " " + std::to_string(b)).c_str());
      // symmetry: swapping the walls swaps the moments
      const WallRegion qs = disk_quadrant(R, b, a);
      EXPECT_NEAR(qs.area, q.area, 1e-14);
      EXPECT_NEAR(qs.moment[0], q.moment[1], 1e-14);
      if (a >= 0.0 && b >= 0.0 && a * a + b * b < R * R) {
        // Bhattacharya & Lipton's (2023) printed expressions with d_li = b (wall l_i: y = b), d_lj
        // = a
        const double di = b, dj = a;
        const double area = -0.5 * R * R * std::asin(di / R) +
                            0.5 * R * R * std::asin(std::sqrt(R * R - dj * dj) / R) + di * dj -
                            0.5 * std::sqrt(R * R - di * di) * di -
                            0.5 * std::sqrt(R * R - dj * dj) * dj;
        const double Ix = dj * dj * dj / 6.0 - 0.5 * (R * R - di * di) * dj +
                          std::pow(R * R - di * di, 1.5) / 3.0;
        const double Iy = -0.5 * R * R * di + di * di * di / 6.0 + 0.5 * di * dj * dj +
                          std::pow(R * R - dj * dj, 1.5) / 3.0;
        // With these roles Bhattacharya & Lipton's (2023) area expression matches; its I_x is the
        // moment along x (normal of the wall at distance d_lj) and I_y along y.
        EXPECT_NEAR(q.area, area, 1e-13) << a << " " << b;
        EXPECT_NEAR(q.moment[0], Iy, 1e-13) << a << " " << b;
        EXPECT_NEAR(q.moment[1], Ix, 1e-13) << a << " " << b;
      }
    }
  // quarter disk at the corner, centroid 4R/(3 pi) along both axes
  const WallRegion quarter = disk_quadrant(2.0, 0.0, 0.0);
  EXPECT_NEAR(quarter.area, M_PI, 1e-14);
  EXPECT_NEAR(quarter.moment[0] / quarter.area, 8.0 / (3.0 * M_PI), 1e-14);
  EXPECT_NEAR(quarter.moment[1] / quarter.area, 8.0 / (3.0 * M_PI), 1e-14);
  EXPECT_EQ(disk_quadrant(1.0, 0.6, 0.8).area, 0.0); // corner exactly on the circle
}

TEST(WallGeometry2D, BoxUnionMatchesQuadrature)
{
  // Region of the contact disk outside the box [0,1]x[0,1] for nodes near the lower-left
  // corner, against direct quadrature of the outside chord.
  WallBox box;
  box.dimension = 2;
  box.hi[0] = box.hi[1] = 1.0;
  for (bool &a : box.active) a = true;
  const double R = 0.1;
  for (double px : {0.02, 0.05, 0.08, 0.12})
    for (double py : {0.0, 0.03, 0.07, 0.099}) {
      const double p[3] = {px, py, 0.0};
      WallPartner parts[kMaxWallPartners];
      const int n = wall_partners(box, p, R, parts);
      const WallRegion u = wall_union_region(parts, n);
      // outside = x < 0 or y < 0 (relative coordinates X = x - px): integrate over X the part
      // of the chord with y < 0, plus for X < -px the whole chord.
      auto chord = [&](double X, int which) {
        const double s = std::sqrt(std::max(0.0, R * R - X * X));
        const double lo = -s;
        const double hi = (X < -px) ? s : std::min(s, -py);
        if (!(hi > lo)) return 0.0;
        return which == 0 ? hi - lo : which == 1 ? X * (hi - lo) : 0.5 * (hi * hi - lo * lo);
      };
      for (int w = 0; w < 3; ++w) {
        const double ref =
            gk_breaks([&](double X) { return chord(X, w); }, -R, R,
                      {-px, std::sqrt(R * R - py * py), -std::sqrt(R * R - py * py)}, 1e-16);
        const double got = w == 0 ? u.area : u.moment[w - 1];
        EXPECT_NEAR(got, ref, 1e-10 * (w == 0 ? R * R : R * R * R)) << px << " " << py << " " << w;
      }
    }
}

TEST(WallGeometry2D, ContinuousAcrossCornerSwitch)
{
  // Move a node along the circle d_x^2 + d_y^2 = R^2 where the corner term switches on.
  WallBox box;
  box.dimension = 2;
  box.hi[0] = box.hi[1] = 10.0;
  for (bool &a : box.active) a = true;
  ContactParams cp;
  cp.Kn = 1e4;
  cp.Rc = 0.1;
  cp.friction = ContactFriction::Coulomb;
  cp.mu = 0.3;
  cp.damping = ContactDamping::Nodal;
  cp.r_d = 0.4;
  double worst = 0.0;
  for (double ang : {0.3, 0.7, 1.1}) {
    const double dx = cp.Rc * std::cos(ang), dy = cp.Rc * std::sin(ang);
    WallContactInput in;
    in.vol = 0.01;
    in.mass = 0.02;
    in.v[0] = -0.3;
    in.v[1] = 0.2;
    double f[2][2];
    WallRegion u[2];
    for (int side = 0; side < 2; ++side) {
      const double scale = side == 0 ? 1.0 + 1e-13 : 1.0 - 1e-13; // just outside / inside
      in.x[0] = dx * scale;
      in.x[1] = dy * scale;
      WallPartner parts[kMaxWallPartners];
      const int n = wall_partners(box, in.x, cp.Rc, parts);
      u[side] = wall_union_region(parts, n);
      const double q[3] = {dx * (side == 0 ? 1.0 + 1e-6 : 1.0 - 1e-6),
                           dy * (side == 0 ? 1.0 + 1e-6 : 1.0 - 1e-6), 0.0};
      EXPECT_EQ(wall_partners(box, q, cp.Rc, parts), side == 0 ? 2 : 3);
      const WallContactResult r = wall_contact_force(box, in, cp);
      f[side][0] = r.f[0];
      f[side][1] = r.f[1];
    }
    const double fscale = cp.Kn * in.vol * cp.Rc * cp.Rc * cp.Rc;
    worst = std::max(
        {worst, std::fabs(f[0][0] - f[1][0]) / fscale, std::fabs(f[0][1] - f[1][1]) / fscale});
    EXPECT_NEAR(u[0].area, u[1].area, 1e-12 * cp.Rc * cp.Rc);
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(u[0].moment[k], u[1].moment[k], 1e-12 * std::pow(cp.Rc, 3));
  }
  EXPECT_LT(worst, 1e-12);
  std::printf("  largest force jump at the corner switch / (K_n V R_c^3): %.3g\n", worst);
}

TEST(WallGeometry2D, SingleWallForceIsMinusGradientOfPotential)
{
  const double Kn = 2e4, R = 0.1, V = 0.003;
  for (int dim : {2, 3})
    for (double t : {-0.5, 0.0, 0.3, 0.8, 0.97}) {
      const double d = t * R, h = 1e-5 * R;
      const WallRegion s = dim == 2 ? disk_segment(R, d) : ball_cap(R, d);
      // force along the outward normal: -K_n V (R|S| - M), Bhattacharya & Lipton 2023, eq. (4.7)
      const double fn = -Kn * V * (R * s.area - s.moment[0]);
      // moving outward by h decreases d: F_n = -dU/dp_n = dU/dd
      const double fd =
          (wall_potential(dim, Kn, R, V, d + h) - wall_potential(dim, Kn, R, V, d - h)) / (2.0 * h);
      EXPECT_NEAR(fn, fd, 1e-6 * std::fabs(fn)) << dim << " " << t;
    }
}

// The single-wall potential against a quadrature of its definition (away from the edge),
// and near d = R against the leading terms of its expansion (the closed form gave
// -5e-10 per node there); it is continuous where the 2D evaluation switches to the series.
TEST(WallGeometry2D, SingleWallPotentialAccurateUpToTheEdge)
{
  const double Kn = 2e4, R = 0.1, V = 0.003;
  for (int dim : {2, 3})
    for (double t : {-1.0, -0.5, 0.0, 0.5, 0.9}) {
      // composite Simpson of int_d^R (R|S(s)| - M(s)) ds
      const double d = t * R;
      const int n = 20000;
      const double step = (R - d) / n;
      double sum = 0.0;
      for (int k = 0; k <= n; ++k) {
        const double s = d + k * step;
        const WallRegion r = dim == 2 ? disk_segment(R, s) : ball_cap(R, s);
        const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        sum += w * (R * r.area - r.moment[0]);
      }
      const double quad = Kn * V * sum * step / 3.0;
      EXPECT_NEAR(wall_potential(dim, Kn, R, V, d), quad, 1e-9 * quad) << dim << " " << t;
    }
  for (double eta : {1e-3, 1e-6, 1e-9, 1e-12}) { // eta = (R - d)/R
    const double d = R * (1.0 - eta);
    const double th = 2.0 * std::asin(std::sqrt(0.5 * (R - d) / R)); // d as represented
    const double u2 =
        Kn * V * std::pow(R, 4) * (std::pow(th, 7) / 35.0 - 13.0 * std::pow(th, 9) / 1260.0);
    EXPECT_GT(wall_potential(2, Kn, R, V, d), 0.0) << eta;
    EXPECT_NEAR(wall_potential(2, Kn, R, V, d), u2, 1e-6 * u2) << eta;
    const double h = R - d, u3 = Kn * V * 3.14159265358979323846 * std::pow(h, 4) * R / 6.0;
    EXPECT_GT(wall_potential(3, Kn, R, V, d), 0.0) << eta;
    // leading term pi R h^4/6; the next, -pi h^5/20, is 0.3 eta of it
    EXPECT_NEAR(wall_potential(3, Kn, R, V, d), u3, 0.31 * eta * u3 + 1e-14 * u3) << eta;
  }
  const double d1 = R * std::cos(1.0);
  const double below = wall_potential(2, Kn, R, V, d1 * (1.0 + 1e-12));
  const double above = wall_potential(2, Kn, R, V, d1 * (1.0 - 1e-12));
  EXPECT_NEAR(below, above, 1e-11 * above);
}

TEST(WallGeometry2D, WallForceUsesContactLawAndReaction)
{
  WallBox box;
  box.dimension = 2;
  box.hi[0] = box.hi[1] = 1.0;
  box.active[2] = true; // floor only
  ContactParams cp;
  cp.Kn = 1e4;
  cp.Rc = 0.1;
  WallContactInput in;
  in.x[0] = 0.5;
  in.x[1] = 0.04;
  in.vol = 0.01;
  in.mass = 0.02;
  const WallContactResult r = wall_contact_force(box, in, cp);
  const WallRegion s = disk_segment(cp.Rc, 0.04);
  const double dist = s.moment[0] / s.area;
  EXPECT_NEAR(r.f[1], cp.Kn * (cp.Rc - dist) * in.vol * s.area, 1e-15); // up, eq. (4.7)
  EXPECT_NEAR(r.f[0], 0.0, 1e-18);
  EXPECT_NEAR(r.f_wall[2][1], -r.f[1], 1e-18);
  EXPECT_NEAR(r.energy, wall_potential(2, cp.Kn, cp.Rc, in.vol, 0.04), 1e-18);
  EXPECT_NEAR(r.min_distance, 0.04, 1e-15);
}

// Moving walls: the damping and friction of each wall act on v - v_w, so their power is
// f_dis . v - sum_w F_w . v_w (wall_power); fix peridem/wall counts the work with v(n) through
// this split.
TEST(WallGeometry2D, DissipativeForceAndWallPowerSplitThePower)
{
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(0.0, 1.0), sv(-1.0, 1.0);
  int tested = 0;
  for (int dim : {2, 3})
    for (int trial = 0; trial < 100; ++trial) {
      WallBox box;
      box.dimension = dim;
      for (int k = 0; k < dim; ++k) box.hi[k] = 1.0;
      for (int w = 0; w < 2 * dim; ++w) box.active[w] = true;
      ContactParams cp;
      cp.Kn = 1e4;
      cp.Rc = 0.1;
      cp.friction = trial % 2 ? ContactFriction::Coulomb : ContactFriction::Regularized;
      cp.mu = 0.5;
      cp.damping = ContactDamping::Nodal;
      cp.r_d = 0.5;
      cp.damp_approach_only = false;
      WallContactInput in;
      for (int k = 0; k < dim; ++k) {
        in.x[k] = 0.1 * u(gen);
        in.v[k] = sv(gen);
      }
      for (int w = 0; w < 2 * dim; ++w)
        for (int k = 0; k < dim; ++k) in.wall_velocity[w][k] = 0.5 * sv(gen);
      in.vol = 1e-3;
      in.mass = 2e-3;
      in.dt = 1e-3;
      const WallContactResult r = wall_contact_force(box, in, cp);
      double f2 = 0.0, fv = 0.0;
      for (int k = 0; k < 3; ++k) {
        f2 += r.f_dis[k] * r.f_dis[k];
        fv += r.f_dis[k] * in.v[k];
      }
      if (f2 == 0.0) continue; // beyond R_c of every wall
      EXPECT_NEAR(fv - r.wall_power, r.power, 1e-12 * std::sqrt(f2)) << dim << " trial " << trial;
      EXPECT_LE(r.power, 1e-12 * std::sqrt(f2)) << dim << " trial " << trial;
      tested++;
    }
  EXPECT_GT(tested, 100);
}

TEST(WallGeometry2D, WallFrictionAndDampingDissipateNearCorners)
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), sv(-1.0, 1.0);
  for (int dim : {2, 3}) {
    WallBox box;
    box.dimension = dim;
    for (int k = 0; k < dim; ++k) box.hi[k] = 1.0;
    for (int w = 0; w < 2 * dim; ++w) box.active[w] = true;
    for (auto fr : {ContactFriction::Coulomb, ContactFriction::Regularized})
      for (int trial = 0; trial < 300; ++trial) {
        ContactParams cp;
        cp.Kn = 1e4;
        cp.Rc = 0.1;
        cp.friction = fr;
        cp.mu = 0.5;
        cp.damping = ContactDamping::Nodal;
        cp.r_d = 0.5;
        WallContactInput in;
        for (int k = 0; k < dim; ++k) {
          in.x[k] = 0.12 * u(gen) - 0.01; // near the lower corner, sometimes just across
          in.v[k] = sv(gen) * (trial % 2 ? 1.0 : 1e-6);
        }
        in.vol = 1e-3;
        in.mass = 2e-3;
        in.dt = 1e-3;
        const WallContactResult r = wall_contact_force(box, in, cp);
        double f2 = 0.0, v2 = 0.0;
        for (int k = 0; k < 3; ++k) f2 += r.f[k] * r.f[k], v2 += in.v[k] * in.v[k];
        // each wall's damping + friction dissipates (eq. 4.3, 4.5 per wall)
        EXPECT_LE(r.power, 1e-12 * std::sqrt(f2 * v2)) << dim << " trial " << trial;
        // f_dis and wall_power split the power: power = f_dis . v - wall_power (walls at rest)
        const double split = r.f_dis[0] * in.v[0] + r.f_dis[1] * in.v[1] + r.f_dis[2] * in.v[2];
        EXPECT_NEAR(split - r.wall_power, r.power, 1e-12 * std::sqrt(f2 * v2) + 1e-300);
        EXPECT_EQ(r.wall_power, 0.0);
        // static walls: the reactions balance the force on the node
        for (int k = 0; k < 3; ++k) {
          double sum = r.f[k];
          for (int w = 0; w < kMaxWalls; ++w) sum += r.f_wall[w][k];
          EXPECT_NEAR(sum, 0.0, 1e-12 * std::sqrt(f2) + 1e-300);
        }
      }
  }
}

// ---------------------------------------------------------------------------------------------
// 3D
// ---------------------------------------------------------------------------------------------

TEST(WallGeometry3D, CapMatchesQuadratureAndLimits)
{
  const double R = 0.8;
  for (double t : {-0.9, -0.4, 0.0, 0.3, 0.8, 0.999}) {
    const double d = t * R;
    const WallRegion s = ball_cap(R, d);
    WallRegion ref;
    ref.area = gk_adapt([&](double x) { return M_PI * (R * R - x * x); }, d, R, 1e-15);
    ref.moment[0] = gk_adapt([&](double x) { return M_PI * x * (R * R - x * x); }, d, R, 1e-15);
    expect_region_near(s, ref, R * R * R, R * R * R * R, 1e-12, "cap");
    EXPECT_NEAR(s.moment[0] / s.area, 3.0 * (R + d) * (R + d) / (4.0 * (2.0 * R + d)), 1e-13);
  }
  const WallRegion half = ball_cap(R, 0.0);
  EXPECT_NEAR(half.area, 2.0 / 3.0 * M_PI * R * R * R, 1e-15);
  EXPECT_NEAR(half.moment[0] / half.area, 3.0 * R / 8.0, 1e-15);
  EXPECT_EQ(ball_cap(R, R).area, 0.0);
}

TEST(WallGeometry3D, EdgeAndCornerMatchNestedQuadrature)
{
  const double R = 1.0;
  const double cases[][3] = {{0.0, 0.0, 0.0},  {0.2, 0.3, 0.1},   {0.5, 0.1, -1.0},
                             {-0.3, 0.4, 0.2}, {0.6, 0.6, -1.0},  {-0.5, -0.4, -0.6},
                             {0.1, -0.7, 0.5}, {0.55, 0.5, 0.45}, {0.9, 0.0, 0.0}};
  double worst = 0.0;
  for (const auto &cs : cases) {
    const double a = cs[0], b = cs[1], c = cs[2];
    const WallRegion g = (c <= -R) ? ball_edge(R, a, b) : ball_corner(R, a, b, c);
    WallRegion ref;
    ref.area = ref_corner(R, a, b, c, 0);
    for (int k = 0; k < 3; ++k) ref.moment[k] = ref_corner(R, a, b, c, k + 1);
    expect_region_near(g, ref, 1.0, 1.0, 1e-10, "edge/corner");
    worst = std::max(worst, std::fabs(g.area - ref.area));
    for (int k = 0; k < 3; ++k) worst = std::max(worst, std::fabs(g.moment[k] - ref.moment[k]));
  }
  std::printf("  3D edge/corner quadrature: largest abs. error vs nested GK (R = 1): %.3g\n",
              worst);
  // limits: quarter ball at an edge, eighth ball at a corner; centroid 3R/8 per axis (corner)
  const WallRegion edge = ball_edge(2.0, 0.0, 0.0);
  EXPECT_NEAR(edge.area, M_PI * 8.0 / 3.0, 1e-13);
  const WallRegion corner = ball_corner(2.0, 0.0, 0.0, 0.0);
  EXPECT_NEAR(corner.area, M_PI * 8.0 / 6.0, 1e-13);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(corner.moment[k] / corner.area, 0.75, 1e-13);
  // consistency: edge with a far third wall equals the corner routine with c = -R
  const WallRegion e2 = ball_edge(1.0, 0.3, 0.2), c2 = ball_corner(1.0, 0.3, 0.2, -1.0);
  EXPECT_DOUBLE_EQ(e2.area, c2.area);
}

TEST(WallGeometry3D, CornerPartnersAndContinuity)
{
  WallBox box;
  box.dimension = 3;
  for (int k = 0; k < 3; ++k) box.hi[k] = 5.0;
  for (bool &a : box.active) a = true;
  const double R = 0.1;
  const double p[3] = {0.03, 0.04, 0.05}; // within R of three walls, all pairs, the corner
  WallPartner parts[kMaxWallPartners];
  EXPECT_EQ(wall_partners(box, p, R, parts), 7);
  // union vs direct nested quadrature of the ball part outside the box (x<0 or y<0 or z<0):
  // ball volume minus the part inside = B n {X > -px, Y > -py, Z > -pz}
  const WallRegion u = wall_union_region(parts, 7);
  const double inside = ref_corner(R, -p[0], -p[1], -p[2], 0);
  EXPECT_NEAR(u.area, 4.0 / 3.0 * M_PI * R * R * R - inside, 1e-10 * R * R * R);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(u.moment[k], -ref_corner(R, -p[0], -p[1], -p[2], k + 1), 1e-10 * std::pow(R, 4));

  // continuity where the corner term switches on: d_x^2 + d_y^2 + d_z^2 = R^2
  const double dir[3] = {0.5, 0.6, std::sqrt(1.0 - 0.25 - 0.36)};
  WallRegion side[2];
  for (int s = 0; s < 2; ++s) {
    const double scale = s == 0 ? 1.0 + 1e-13 : 1.0 - 1e-13;
    const double q[3] = {R * dir[0] * scale, R * dir[1] * scale, R * dir[2] * scale};
    const int n = wall_partners(box, q, R, parts);
    side[s] = wall_union_region(parts, n);
    const double scale6 = s == 0 ? 1.0 + 1e-6 : 1.0 - 1e-6;
    const double q6[3] = {R * dir[0] * scale6, R * dir[1] * scale6, R * dir[2] * scale6};
    EXPECT_EQ(wall_partners(box, q6, R, parts), s == 0 ? 6 : 7);
  }
  EXPECT_NEAR(side[0].area, side[1].area, 1e-12 * R * R * R);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(side[0].moment[k], side[1].moment[k], 1e-12 * std::pow(R, 4));
}

// The wall's normal tangent stiffness used by the time-step estimate (wall_contact_stiffness,
// peridem_contact_law.h) is the second derivative of the wall potential of Bhattacharya & Lipton
// 2023, eq. (4.7): checked by central differences of wall_potential in 2D and 3D over the contact
// range.
TEST(WallGeometry, ContactStiffnessIsPotentialCurvature)
{
  const double Kn = 3.0, V = 0.7, R = 1.3;
  for (int dim : {2, 3})
    for (double frac : {0.0, 0.1, 0.35, 0.6, 0.9, 0.99}) {
      const double d = frac * R, step = 1e-4 * R;
      const double curv =
          (wall_potential(dim, Kn, R, V, d + step) - 2.0 * wall_potential(dim, Kn, R, V, d) +
           wall_potential(dim, Kn, R, V, d - step)) /
          (step * step);
      const double k = wall_contact_stiffness(dim, Kn, V, R, d);
      EXPECT_NEAR(k, curv, 1e-5 * Kn * V * R * R) << "dim " << dim << " d/R " << frac;
    }
  // on the plane: 2 K V R^2 (2D) and pi K V R^3 (3D); nothing at d = R
  EXPECT_DOUBLE_EQ(wall_contact_stiffness(2, Kn, V, R, 0.0), 2.0 * Kn * V * R * R);
  EXPECT_DOUBLE_EQ(wall_contact_stiffness(3, Kn, V, R, 0.0), M_PI * Kn * V * R * R * R);
  EXPECT_EQ(wall_contact_stiffness(2, Kn, V, R, R), 0.0);
}
