/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// PERIDEM: analytic rigid walls of an axis-aligned container (no LAMMPS dependency).
//
// Reference: Bhattacharya & Lipton 2023, "Simulating grain shape effects and damage in granular
// media using PeriDEM", SIAM J. Sci. Comput., Sec. 4.5, eq. (4.7)-(4.8), Fig. 2.
//
// ---- doc block (reusable by doc/fix_peridem_wall.rst) -------------------------------------
// A node at p with contact radius R_c interacts with the wall material inside its contact
// disk (2D) or ball (3D) B = B_{R_c}(p).  For a wall plane at signed distance d from p
// (d > 0: p inside the container) the wall region is S = B n {outside of the plane}:
//   2D circular segment:  |S| = R^2 acos(d/R) - d sqrt(R^2 - d^2)
//                              = pi R^2/2 - R^2 asin(d/R) - d sqrt(R^2 - d^2)        Bhattacharya &
//                              Lipton 2023, §4.5
//                         first moment about p along the outward normal n:
//                         M = 2/3 (R^2 - d^2)^{3/2},  |c - p| = M/|S|              Bhattacharya &
//                         Lipton 2023, §4.5
//   3D spherical cap:     |S| = pi (R - d)^2 (2R + d)/3,  M = pi/4 (R^2 - d^2)^2,
//                         |c - p| = 3 (R + d)^2/(4 (2R + d)).
// Limits: d = 0 gives the half disk pi R^2/2 (half ball 2 pi R^3/3) with |c - p| = 4R/(3 pi)
// (3R/8); d -> R gives |S| -> 0 continuously; d <= -R (node a full radius beyond the wall)
// gives the whole disk with centroid p, where no direction exists (the node is lost).
//
// Near an edge or corner several walls are within R_c.  Region of B outside the container
// (inclusion-exclusion, Bhattacharya & Lipton 2023, below eq. 4.7):  |U| = sum_i |S_i| - sum_{i<j}
// |S_i n S_j|
// + sum_{i<j<k} |S_i n S_j n S_k|, and the same for the first moments (moments are additive).
// Two walls on the same axis have disjoint regions, so only walls on different axes combine.
//   2D corner: S_i n S_j = B n {x > a, y > b} in the walls' local frame, closed form (exact):
//     |S_ij| = G(x_b) - G(lo) - b (x_b - lo)  (b >= 0),  G(x) = 1/2 (x s + R^2 asin(x/R)),
//     s = sqrt(R^2 - x^2), x_b = sqrt(R^2 - b^2), lo = max(a, -x_b); moments
//     M_x = [-s^3/3]_lo^x_b - b (x_b^2 - lo^2)/2,  M_y = 1/2 [(R^2 - b^2) x - x^3/3]_lo^x_b.
//     For a, b >= 0 these are exactly Bhattacharya & Lipton's (2023) |S_li n S_lj|, I_y and I_x
//     (Bhattacharya & Lipton's (2023) I_x is the moment along the normal of l_i when a = d_lj, b =
//     d_li).  At a = b = 0 the quarter disk pi R^2/4.  The formulas also hold for a, b < 0 (node
//     past a wall) via the complement of the part below y = b.
//   3D edge and corner: the cross-section of B at height x is a disk of radius
//     rho(x) = sqrt(R^2 - x^2), and the edge/corner region's cross-section is the exact 2D
//     segment/quadrant above; its area and moments are integrated over x in [a, R] by
//     tanh-sinh quadrature split at the kinks rho = |b|, |c|, sqrt(b^2 + c^2).  Accuracy:
//     relative error < 1e-13 against nested adaptive quadrature of the chord length (tests).
//   Continuity: the intersection regions shrink to zero area and zero moment as the node
//     leaves the edge/corner zone (d_i^2 + d_j^2 -> R_c^2), so the area and centroid of U are
//     continuous when a node moves from single-wall to corner contact; the code evaluates
//     every intersection whose walls are all within R_c (an empty one gives exactly 0).
//
// Force (Bhattacharya & Lipton 2023, eq. 4.7): every region S acts as ONE contact partner located
// at its centroid c_S with volume |S|: F_S = -K_n (R_c - |c_S - p|) V_x |S| e_S, e_S = (c_S -
// p)/|c_S - p|, i.e. proportional to the area (volume) and directed from the centroid toward the
// node. Repulsion: Bhattacharya & Lipton 2023, eq. (4.8) superposes the FORCES of the regions with
// the inclusion-exclusion signs (F = sum F_Si - sum F_{Si n Sj} (+ triple terms in 3D));
// wall_contact_force() does that with the one contact law of peridem_contact_law.h.  This is not
// the same as one partner at the centroid of the union U (the force is not linear in the region);
// the union is available from wall_union_region().  The magnitude K_n V (R|S| - |M_S|) grows with
// the region (S in T implies R|S| - |M_S| <= R|T| - |M_T|), so an intersection term never exceeds
// the single-wall terms.  Each region force lies in the span of its walls' normals; its component
// along wall w's normal is wall w's share, giving the wall's normal load N_w and reaction.
// Damping and friction (Bhattacharya & Lipton 2023, below eq. 4.8: eq. 4.3, 4.5 with the wall
// segment as partner) are applied wall by wall: partner = the single-wall segment S_w at its
// centroid, velocity of wall w, friction bound mu N_w.  (Superposing damping/friction of the
// intersection regions with negative signs, read literally, can produce energy in 3D corners and in
// mixed stick/slip states; per-wall terms each dissipate, so the total does.)  With one wall in
// range all of this is exactly eq. (4.7) with eq. (4.3), (4.5). Energy: for a single wall the force
// is exactly -dU/dp of
//   U(d) = K_n V int_d^R (R |S(s)| - M(s)) ds   (closed form, wall_potential());
// the edge/corner correction terms of eq. (4.8) are not exactly conservative; their energy is
// reported as the pair energy 1/2 K_n (R - |c - p|)^2 V |S| (approximation).
// -------------------------------------------------------------------------------------------
#ifndef PERIDEM_WALL_GEOMETRY_H
#define PERIDEM_WALL_GEOMETRY_H

#include "peridem_contact_law.h"

namespace peridem {

// Area (2D) or volume (3D) of a wall region and its first moment about the node position
// (centroid offset c - p = moment/area).
struct WallRegion {
  double area = 0.0;
  double moment[3] = {0.0, 0.0, 0.0};
};

// Local frames: the region lies on the positive side of each cut, x > a (and y > b, z > c);
// a, b, c are the signed distances from the node to the walls (positive inside the box).
WallRegion disk_segment(double R, double d);                    // 2D, moment along x
WallRegion disk_quadrant(double R, double a, double b);         // 2D corner, moments x, y
WallRegion ball_cap(double R, double d);                        // 3D, moment along x
WallRegion ball_edge(double R, double a, double b);             // 3D, quadrature
WallRegion ball_corner(double R, double a, double b, double c); // 3D, quadrature

// Wall potential of one plane at signed distance d: U(d) = K_n V int_d^R (R|S| - M) ds,
// 2D or 3D; 0 for d >= R.  (Force on the node along the outward normal: -K_n V (R|S| - M).)
double wall_potential(int dimension, double Kn, double R, double vol, double d);

// Axis-aligned container.  Wall 2k is the plane x_k = lo[k] (container side x_k > lo[k]),
// wall 2k+1 the plane x_k = hi[k] (container side x_k < hi[k]).
constexpr int kMaxWalls = 6;
constexpr int kMaxWallPartners = 26; // 3D: 6 walls + 12 edges + 8 corners
struct WallBox {
  int dimension = 2;
  double lo[3] = {0.0, 0.0, 0.0};
  double hi[3] = {0.0, 0.0, 0.0};
  bool active[kMaxWalls] = {false, false, false, false, false, false};
};

// Signed distance from p to wall w, positive on the container side.
inline double wall_distance(const WallBox &box, int w, const double p[3])
{
  const int k = w / 2;
  return (w % 2 == 0) ? p[k] - box.lo[k] : box.hi[k] - p[k];
}

// One term of Bhattacharya & Lipton 2023, eq. (4.8): the region shared by the walls in the bit mask
// `walls`, with the inclusion-exclusion sign (+1 single wall, -1 two walls, +1 three walls); moment
// in the global frame.
struct WallPartner {
  int sign = 0;
  unsigned walls = 0;
  WallRegion region;
};

// Lists the nonempty terms for a node at p (active walls with distance < R only).  Returns the
// number written to out (at most kMaxWallPartners).
int wall_partners(const WallBox &box, const double p[3], double R, WallPartner *out);

// Area/volume and moment of the union of the wall regions (signed sum of the partners).
WallRegion wall_union_region(const WallPartner *partners, int n);

// Node-wall interaction through the contact law, Bhattacharya & Lipton 2023, eq. (4.7)-(4.8).
struct WallContactInput {
  double x[3] = {0.0, 0.0, 0.0};
  double v[3] = {0.0, 0.0, 0.0};
  double vol = 0.0, mass = 0.0, dt = 0.0;
  double wall_velocity[kMaxWalls][3] = {}; // velocity of each wall (damping, friction)
};
// f_dis and wall_power split the power, so that a caller can count the work of the damping and
// friction forces F_w with another node velocity v' (fix peridem/wall: v(n) of velocity Verlet):
// f_dis . v' - wall_power.
struct WallContactResult {
  double f[3] = {0.0, 0.0, 0.0};     // total force on the node
  double energy = 0.0;               // repulsion energy (see doc block)
  double power = 0.0;                // dissipation rate, sum over walls of F_w . (v - v_w) <= 0
  double f_dis[3] = {0.0, 0.0, 0.0}; // damping + friction of all walls, sum_w F_w
  double wall_power = 0.0;           // sum_w F_w . v_w: power = f_dis . v - wall_power
  double f_wall[kMaxWalls][3] = {};  // reaction: force exerted BY the node ON each wall
  double min_distance = 0.0;         // smallest signed distance to an active wall
  int n_partners = 0;
};
WallContactResult wall_contact_force(const WallBox &box, const WallContactInput &in,
                                     const ContactParams &params);

} // namespace peridem

#endif
