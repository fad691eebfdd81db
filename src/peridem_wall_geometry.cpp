/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: analytic rigid walls (formulas and references in peridem_wall_geometry.h).
#include "peridem_wall_geometry.h"
#include "peridem_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace peridem {

namespace {

// phi - sin(phi), accurate also for small phi (series below 0.1).
double phi_minus_sin(double phi)
{
  if (phi >= 0.1) return phi - std::sin(phi);
  const double p2 = phi * phi;
  return phi * p2 / 6.0 *
         (1.0 - p2 / 20.0 * (1.0 - p2 / 42.0 * (1.0 - p2 / 72.0 * (1.0 - p2 / 110.0))));
}

// Tanh-sinh nodes on [-1, 1], step 1/8, |t| <= 4 (65 nodes; weights below 1e-30 beyond).
constexpr int kTsHalf = 32;
constexpr double kTsStep = 1.0 / 8.0;
struct TanhSinhRule {
  double x[2 * kTsHalf + 1]; // abscissa
  double c[2 * kTsHalf + 1]; // 1 - |x| (complement, exact near the ends)
  double w[2 * kTsHalf + 1];
  TanhSinhRule()
  {
    for (int k = -kTsHalf; k <= kTsHalf; ++k) {
      const double t = k * kTsStep;
      const double u = 0.5 * kPi * std::sinh(t);
      const double ch = std::cosh(u);
      const int i = k + kTsHalf;
      x[i] = std::tanh(u);
      c[i] = std::exp(-std::fabs(u)) / ch;
      w[i] = kTsStep * 0.5 * kPi * std::cosh(t) / (ch * ch);
    }
  }
};
const TanhSinhRule &tanh_sinh()
{
  static const TanhSinhRule rule;
  return rule;
}

// Slice integrand of the 3D edge/corner: the cross-section at height x is the 2D region
// {y > b, z > c} of the disk of radius rho = sqrt(R^2 - x^2).
void add_slice(double R, double x, double b, double c, double w, WallRegion &acc)
{
  const double rho = std::sqrt(std::max(0.0, R * R - x * x));
  if (rho <= 0.0) return;
  const WallRegion q = disk_quadrant(rho, b, c);
  acc.area += w * q.area;
  acc.moment[0] += w * x * q.area;
  acc.moment[1] += w * q.moment[0];
  acc.moment[2] += w * q.moment[1];
}

} // namespace

/* ---------------------------------------------------------------------------------------
   2D: circular segment and corner region
------------------------------------------------------------------------------------------ */

WallRegion disk_segment(double R, double d)
{
  WallRegion s;
  if (d >= R) return s;
  if (d <= -R) {
    s.area = kPi * R * R;
    return s;
  }
  // half angle theta = acos(d/R); area = R^2 (2 theta - sin 2 theta)/2 (no cancellation).
  const double theta = std::acos(d / R);
  const double h = R - d; // R^2 - d^2 = h (2R - h), accurate near d = R
  const double s2 = h * (2.0 * R - h);
  s.area = 0.5 * R * R * phi_minus_sin(2.0 * theta);
  s.moment[0] = 2.0 / 3.0 * s2 * std::sqrt(s2);
  return s;
}

WallRegion disk_quadrant(double R, double a, double b)
{
  WallRegion q;
  if (a >= R || b >= R) return q;
  a = std::max(a, -R);
  b = std::max(b, -R);
  const double D = (R - a) * (R + a) - b * b; // R^2 - a^2 - b^2 > 0: corner C inside
  if (!(D > 0.0)) {
    // C = (a, b) outside the disk: at most one cut is active, or both cut disjoint segments.
    if (a >= 0.0 && b >= 0.0) return q;
    if (a < 0.0 && b >= 0.0) {
      const WallRegion sy = disk_segment(R, b);
      q.area = sy.area;
      q.moment[1] = sy.moment[0];
    } else if (a >= 0.0) {
      q = disk_segment(R, a);
    } else { // disk minus the disjoint segments x < a and y < b
      const WallRegion sx = disk_segment(R, -a), sy = disk_segment(R, -b);
      q.area = kPi * R * R - sx.area - sy.area;
      q.moment[0] = sx.moment[0];
      q.moment[1] = sy.moment[0];
    }
    return q;
  }
  // C inside: region = right triangle C, P2 = (xb, b), P1 = (a, ya) plus the circular segment
  // cut off by the chord P2 P1 (arc angle delta).  The legs are computed without cancellation,
  // so the area vanishes like legs^2 as C reaches the circle (corner switch).
  const double xb = std::sqrt((R - b) * (R + b)), ya = std::sqrt((R - a) * (R + a));
  const double lx = a >= 0.0 ? D / (xb + a) : xb - a; // xb - a
  const double ly = b >= 0.0 ? D / (ya + b) : ya - b; // ya - b
  const double tri = 0.5 * lx * ly;
  const double phi1 = std::atan2(ya, a), phi2 = std::atan2(b, xb);
  const double delta = phi1 - phi2, mid = 0.5 * (phi1 + phi2);
  const double seg = 0.5 * R * R * phi_minus_sin(delta);
  const double sh = std::sin(0.5 * delta);
  const double segm = 2.0 / 3.0 * R * R * R * sh * sh * sh; // segment moment about p
  q.area = tri + seg;
  q.moment[0] = tri * (a + xb + a) / 3.0 + segm * std::cos(mid);
  q.moment[1] = tri * (b + b + ya) / 3.0 + segm * std::sin(mid);
  return q;
}

/* ---------------------------------------------------------------------------------------
   3D: spherical cap (closed form), edge and corner (quadrature of the exact 2D slice)
------------------------------------------------------------------------------------------ */

WallRegion ball_cap(double R, double d)
{
  WallRegion s;
  if (d >= R) return s;
  if (d <= -R) {
    s.area = 4.0 / 3.0 * kPi * R * R * R;
    return s;
  }
  const double h = R - d, s2 = h * (2.0 * R - h);
  s.area = kPi * h * h * (3.0 * R - h) / 3.0;
  s.moment[0] = 0.25 * kPi * s2 * s2;
  return s;
}

WallRegion ball_corner(double R, double a, double b, double c)
{
  WallRegion acc;
  if (a >= R || b >= R || c >= R) return acc;
  a = std::max(a, -R);
  b = std::max(b, -R);
  c = std::max(c, -R);
  // Kinks of the slice as a function of x: rho = |b|, |c|, sqrt(b^2 + c^2).
  double cuts[10];
  int nc = 0;
  cuts[nc++] = a;
  for (double t : {b * b, c * c, b * b + c * c}) {
    if (t >= R * R) continue;
    const double x = std::sqrt(R * R - t);
    if (x > a && x < R) cuts[nc++] = x;
    if (-x > a && -x < R) cuts[nc++] = -x;
  }
  cuts[nc++] = R;
  for (int i = 1; i < nc; ++i) // insertion sort (at most 8 cuts)
    for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
  const TanhSinhRule &ts = tanh_sinh();
  for (int i = 0; i + 1 < nc; ++i) {
    const double x0 = cuts[i], x1 = cuts[i + 1];
    if (!(x1 > x0)) continue;
    const double half = 0.5 * (x1 - x0);
    for (int k = 0; k <= 2 * kTsHalf; ++k) {
      // distance to the nearer end computed from the complement (no rounding to the end)
      const double x = ts.x[k] < 0.0 ? x0 + half * ts.c[k] : x1 - half * ts.c[k];
      add_slice(R, x, b, c, half * ts.w[k], acc);
    }
  }
  return acc;
}

WallRegion ball_edge(double R, double a, double b)
{
  return ball_corner(R, a, b, -R);
}

/* ---------------------------------------------------------------------------------------
   single-wall potential U(d) = K_n V int_d^R (R |S(s)| - M(s)) ds
------------------------------------------------------------------------------------------ */

namespace {

// F(T) = int_0^T f(t) sin t dt with f(t) = t - sin t cos t - 2/3 sin^3 t, so that the 2D
// single-wall potential is U = K_n V R^4 F(theta), theta = acos(d/R) (substitute s = R cos t
// in int_d^R (R|S(s)| - M(s)) ds, |S| = R^2 (t - sin t cos t), M = 2/3 R^3 sin^3 t).
// F(T) = T^7/35 - 13 T^9/1260 + ...: the closed form cancels to nothing near d = R (measured:
// -5e-10 per node where the value is 1e-46), so small T use the power series, whose
// coefficients follow from writing f sin t as a sum of sines and cosines of t, 2t, 3t, 4t:
//   F = sum_k a_k T^(2k+1), a_k = (-1)^k/(2k+1)! [1 - (2k+1) - 1/4 + 3^(2k+1)/12
//                                               + 2^(2k+1)/6 - 4^(2k+1)/48],  k >= 3
// (a_0 = a_1 = a_2 = 0 exactly).
double wall_potential_2d_F(double T)
{
  if (T < 1.0) {
    double sum = 0.0, fact = 5040.0;              // (2k+1)! for k = 3
    double p2 = 128.0, p3 = 2187.0, p4 = 16384.0; // 2^(2k+1), 3^(2k+1), 4^(2k+1)
    double Tp = std::pow(T, 7), sign = -1.0;
    for (int k = 3; k < 40; ++k) {
      const double n = 2.0 * k + 1.0;
      const double a = sign / fact * (1.0 - n - 0.25 + p3 / 12.0 + p2 / 6.0 - p4 / 48.0);
      const double term = a * Tp;
      sum += term;
      if (std::fabs(term) <= 1e-17 * std::fabs(sum)) break;
      fact *= (n + 1.0) * (n + 2.0);
      p2 *= 4.0;
      p3 *= 9.0;
      p4 *= 16.0;
      Tp *= T * T;
      sign = -sign;
    }
    return sum;
  }
  // closed form (loses at most about two digits for T >= 1)
  const double s1 = std::sin(T), s2 = std::sin(2.0 * T), s3 = std::sin(3.0 * T),
               s4 = std::sin(4.0 * T);
  return s1 - T * std::cos(T) - 0.25 * (s1 - s3 / 3.0) - 0.25 * T + s2 / 6.0 - s4 / 48.0;
}

// Portable bit tests on a wall mask (kMaxWalls bits; no compiler builtins).
bool single_wall(unsigned mask)
{
  return mask != 0 && (mask & (mask - 1)) == 0;
}

int lowest_wall(unsigned mask)
{
  int w = 0;
  while (w < kMaxWalls && !(mask & (1u << w))) ++w;
  return w;
}

} // namespace

double wall_potential(int dimension, double Kn, double R, double vol, double d)
{
  if (d >= R) return 0.0;
  d = std::max(d, -R);
  const double h = R - d; // exact near d = R
  if (dimension == 2) {
    // theta = acos(d/R) = 2 asin(sqrt(h/2R)), accurate for small h
    const double theta = 2.0 * std::asin(std::min(1.0, std::sqrt(0.5 * h / R)));
    return Kn * vol * R * R * R * R * wall_potential_2d_F(theta);
  }
  // 3D: R int_d^R |S| ds - int_d^R M ds = pi h^4 (R/6 - h/20) with h = R - d: the
  // polynomial in d of the closed form, rewritten in h without cancellation
  return Kn * vol * kPi * h * h * h * h * (R / 6.0 - h / 20.0);
}

/* ---------------------------------------------------------------------------------------
   container: inclusion-exclusion terms of Bhattacharya & Lipton 2023, eq. (4.8)
------------------------------------------------------------------------------------------ */

int wall_partners(const WallBox &box, const double p[3], double R, WallPartner *out)
{
  const int dim = box.dimension;
  // candidate walls per axis: index into 0..5 or -1; both walls of an axis may be near.
  int cand[3][3];
  int ncand[3] = {1, 1, 1};
  for (int k = 0; k < 3; ++k) {
    cand[k][0] = -1;
    if (k >= dim) continue;
    for (int w = 2 * k; w <= 2 * k + 1; ++w)
      if (box.active[w] && wall_distance(box, w, p) < R) cand[k][ncand[k]++] = w;
  }
  int n = 0;
  for (int i0 = 0; i0 < ncand[0]; ++i0)
    for (int i1 = 0; i1 < ncand[1]; ++i1)
      for (int i2 = 0; i2 < ncand[2]; ++i2) {
        const int ws[3] = {cand[0][i0], cand[1][i1], cand[2][i2]};
        int axes[3], walls[3], m = 0;
        double dist[3];
        for (int k = 0; k < 3; ++k)
          if (ws[k] >= 0) {
            axes[m] = k;
            walls[m] = ws[k];
            dist[m] = wall_distance(box, ws[k], p);
            ++m;
          }
        if (m == 0) continue;
        WallRegion loc;
        if (m == 1)
          loc = dim == 2 ? disk_segment(R, dist[0]) : ball_cap(R, dist[0]);
        else if (m == 2)
          loc = dim == 2 ? disk_quadrant(R, dist[0], dist[1]) : ball_edge(R, dist[0], dist[1]);
        else
          loc = ball_corner(R, dist[0], dist[1], dist[2]);
        if (!(loc.area > 0.0)) continue;
        WallPartner &wp = out[n++];
        wp.sign = (m % 2 == 1) ? 1 : -1;
        wp.walls = 0;
        wp.region.area = loc.area;
        for (int k = 0; k < 3; ++k) wp.region.moment[k] = 0.0;
        for (int j = 0; j < m; ++j) {
          wp.walls |= 1u << walls[j];
          const double outward = (walls[j] % 2 == 0) ? -1.0 : 1.0;
          wp.region.moment[axes[j]] = outward * loc.moment[j];
        }
      }
  return n;
}

WallRegion wall_union_region(const WallPartner *partners, int n)
{
  WallRegion u;
  for (int i = 0; i < n; ++i) {
    u.area += partners[i].sign * partners[i].region.area;
    for (int k = 0; k < 3; ++k) u.moment[k] += partners[i].sign * partners[i].region.moment[k];
  }
  return u;
}

/* ---------------------------------------------------------------------------------------
   node-wall force through the contact law
------------------------------------------------------------------------------------------ */

WallContactResult wall_contact_force(const WallBox &box, const WallContactInput &in,
                                     const ContactParams &params)
{
  WallContactResult res;
  const double R = params.Rc;
  res.min_distance = std::numeric_limits<double>::infinity();
  for (int w = 0; w < 2 * box.dimension; ++w)
    if (box.active[w]) res.min_distance = std::min(res.min_distance, wall_distance(box, w, in.x));

  // 1. Repulsion: signed superposition of the region forces, Bhattacharya & Lipton 2023, eq. (4.8).
  // Each region's
  //    force lies in the span of its walls' normals; its component along a wall's axis is that
  //    wall's share (normal load N_w, used for friction and for the reaction force).
  ContactParams rep = params;
  rep.damping = ContactDamping::None;
  rep.friction = ContactFriction::None;
  WallPartner parts[kMaxWallPartners];
  const int n = wall_partners(box, in.x, R, parts);
  res.n_partners = n;
  double load[kMaxWalls] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}; // N_w >= 0 pushes the node in
  for (int i = 0; i < n; ++i) {
    const WallPartner &wp = parts[i];
    ContactInput ci;
    for (int k = 0; k < 3; ++k) ci.sep[k] = wp.region.moment[k] / wp.region.area;
    ci.vol_i = in.vol;
    ci.vol_j = wp.region.area;
    ci.mass_i = in.mass;
    const ContactResult cr = contact_force(ci, rep);
    const double sg = wp.sign;
    for (int k = 0; k < 3; ++k) res.f[k] += sg * cr.f[k];
    if (single_wall(wp.walls)) {
      const int w = lowest_wall(wp.walls);
      res.energy +=
          wall_potential(box.dimension, params.Kn, R, in.vol, wall_distance(box, w, in.x));
    } else {
      res.energy += sg * cr.energy;
    }
    for (int w = 0; w < kMaxWalls; ++w)
      if (wp.walls & (1u << w)) {
        const double outward = (w % 2 == 0) ? -1.0 : 1.0;
        load[w] -= sg * outward * cr.f[w / 2];
      }
  }
  for (int w = 0; w < kMaxWalls; ++w) {
    const double outward = (w % 2 == 0) ? -1.0 : 1.0;
    res.f_wall[w][w / 2] = outward * load[w];
  }

  // 2. Damping and friction, wall by wall (Bhattacharya & Lipton 2023, below eq. 4.8: eq. 4.3
  // and 4.5 with the wall's
  //    segment S_w as the partner, its velocity, e = its normal), friction bounded by mu N_w.
  //    Each wall's term dissipates on its own, so the sum does too.
  if (params.damping == ContactDamping::None && params.friction == ContactFriction::None)
    return res;
  for (int w = 0; w < 2 * box.dimension; ++w) {
    if (!box.active[w]) continue;
    const double d = wall_distance(box, w, in.x);
    if (!(d < R) || d <= -R) continue;
    const WallRegion seg = box.dimension == 2 ? disk_segment(R, d) : ball_cap(R, d);
    const double outward = (w % 2 == 0) ? -1.0 : 1.0;
    ContactInput ci;
    ci.sep[w / 2] = outward * seg.moment[0] / seg.area;
    for (int k = 0; k < 3; ++k) ci.vrel[k] = in.v[k] - in.wall_velocity[w][k];
    ci.vol_i = in.vol;
    ci.vol_j = seg.area;
    ci.mass_i = in.mass;
    ci.dt = in.dt;
    ci.friction_normal_force = std::max(0.0, load[w]);
    const ContactResult cr = contact_force(ci, params);
    for (int k = 0; k < 3; ++k) {
      const double fdis = cr.f_damp[k] + cr.f_fric[k];
      res.f[k] += fdis;
      res.f_dis[k] += fdis;
      res.f_wall[w][k] -= fdis;
      res.wall_power += fdis * in.wall_velocity[w][k];
    }
    res.power += cr.power;
  }
  return res;
}

} // namespace peridem
