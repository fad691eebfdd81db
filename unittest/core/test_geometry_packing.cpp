/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// Jammed disk/sphere packings (Bhattacharya & Lipton 2023, §7-7.1): exact
// no-overlap and no-wall-crossing checks, the local jamming criterion of the
// Bhattacharya & Lipton's (2023) Definition 7.1, packing fractions against known values, radius
// distributions and input errors.
#include "peridem_geometry_packing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace peridem;

namespace {
const double tau = 1e-3; // contact tolerance of PackingOptions (default)

Packing pack2d(std::size_t n, double width, double height, std::uint64_t seed = 3,
               RadiusDistribution dist = RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1))
{
  PackingOptions o;
  o.dimension = 2;
  o.hi[0] = width;
  o.hi[1] = height;
  o.seed = seed;
  return pack_spheres(draw_radii(dist, n, seed), o);
}

std::vector<std::array<double, 3>> dirs(std::initializer_list<double> degrees)
{
  std::vector<std::array<double, 3>> out;
  for (double a : degrees) out.push_back({std::cos(a * M_PI / 180), std::sin(a * M_PI / 180), 0.0});
  return out;
}

// Definition 7.1 directly: displacing a backbone disk by s in any of 72
// directions makes it overlap a disk or cross a wall (brute force, no cell grid).
std::size_t movableBackboneDisks(const Packing &p, const JammingReport &rep, double s)
{
  std::vector<bool> rattler(p.centre.size(), false);
  for (auto i : rep.rattler_index) rattler[i] = true;
  std::size_t movable = 0;
  for (std::size_t i = 0; i < p.centre.size(); i++) {
    if (rattler[i]) continue;
    bool any_free = false;
    for (int k = 0; k < 72 && !any_free; k++) {
      const double x = p.centre[i][0] + s * p.radius[i] * std::cos(k * M_PI / 36);
      const double y = p.centre[i][1] + s * p.radius[i] * std::sin(k * M_PI / 36);
      bool blocked = x - p.radius[i] < p.lo[0] || x + p.radius[i] > p.hi[0] ||
                     y - p.radius[i] < p.lo[1] || y + p.radius[i] > p.hi[1];
      for (std::size_t j = 0; j < p.centre.size() && !blocked; j++)
        if (j != i &&
            std::hypot(x - p.centre[j][0], y - p.centre[j][1]) < p.radius[i] + p.radius[j])
          blocked = true;
      any_free = !blocked;
    }
    movable += any_free;
  }
  return movable;
}
} // namespace

TEST(GeometryPacking, DistributionsDrawWhatTheySay)
{
  const auto u = draw_radii(RadiusDistribution::uniform(0.3, 1.1), 20000, 5);
  const auto n = draw_radii(RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1), 20000, 5);
  const auto l = draw_radii(RadiusDistribution::list({0.5, 0.7}), 20000, 5);
  auto mean = [](const std::vector<double> &v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / v.size();
  };
  auto sd = [&](const std::vector<double> &v) {
    const double m = mean(v);
    double s = 0.0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / (v.size() - 1));
  };
  for (double r : u) EXPECT_TRUE(r >= 0.3 && r < 1.1);
  for (double r : n) EXPECT_TRUE(r >= 0.4 && r <= 1.1);
  for (double r : l) EXPECT_TRUE(r == 0.5 || r == 0.7);
  // uniform: mean 0.7, sd 0.8 / sqrt(12); normal: truncation at 4.4 and 3.3 sd
  // changes the moments by < 1e-3; 5 standard errors of the sample mean
  EXPECT_NEAR(mean(u), 0.7, 5 * 0.231 / std::sqrt(20000.0));
  EXPECT_NEAR(sd(u), 0.8 / std::sqrt(12.0), 3e-3);
  EXPECT_NEAR(mean(n), 0.8, 5 * 0.09 / std::sqrt(20000.0));
  EXPECT_NEAR(sd(n), 0.09, 2e-3);
  EXPECT_NEAR(mean(l), 0.6, 5 * 0.1 / std::sqrt(20000.0));
  // the same seed, the same radii; another seed, others
  EXPECT_EQ(n, draw_radii(RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1), 20000, 5));
  EXPECT_NE(n, draw_radii(RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1), 20000, 6));
}

TEST(GeometryPacking, BadDistributionsAreRefused)
{
  EXPECT_THROW(RadiusDistribution::uniform(0.0, 1.0).validate(), GeometryError);
  EXPECT_THROW(RadiusDistribution::uniform(-1.0, 1.0).validate(), GeometryError);
  EXPECT_THROW(RadiusDistribution::uniform(1.0, 0.5).validate(), GeometryError);
  EXPECT_THROW(RadiusDistribution::normal(0.8, -0.1, 0.4, 1.1).validate(), GeometryError);
  EXPECT_THROW(RadiusDistribution::normal(5.0, 0.1, 0.4, 1.1).validate(), GeometryError);
  EXPECT_THROW(RadiusDistribution::list({}).validate(), GeometryError);
  EXPECT_THROW(RadiusDistribution::list({0.5, 0.0}).validate(), GeometryError);
  EXPECT_NO_THROW(RadiusDistribution::normal(0.8, 0.0, 0.4, 1.1).validate());
}

TEST(GeometryPacking, JammingCriterionOnHandMadeContacts)
{
  // 2D: immobile iff the contact directions leave no angular gap >= pi
  EXPECT_TRUE(directions_block_every_move(dirs({90, 210, 330}), 2));
  EXPECT_FALSE(directions_block_every_move(dirs({0, 180}), 2));     // slides along y
  EXPECT_FALSE(directions_block_every_move(dirs({0, 90, 180}), 2)); // free to go down
  EXPECT_FALSE(directions_block_every_move(dirs({10, 60, 120, 170}), 2));
  EXPECT_TRUE(directions_block_every_move(dirs({0, 90, 180, 271}), 2));
  EXPECT_TRUE(directions_block_every_move(dirs({0, 90, 180, 270}), 2)); // a square cage
  // 3D: a tetrahedron's vertex directions block, any three of them do not
  const double s = 1.0 / std::sqrt(3.0);
  std::vector<std::array<double, 3>> tet = {{s, s, s}, {s, -s, -s}, {-s, s, -s}, {-s, -s, s}};
  EXPECT_TRUE(directions_block_every_move(tet, 3));
  tet.pop_back();
  EXPECT_FALSE(directions_block_every_move(tet, 3));
  // the six faces of a cube block; five of them (or four in a plane) do not
  std::vector<std::array<double, 3>> cube = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                             {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  EXPECT_TRUE(directions_block_every_move(cube, 3));
  EXPECT_FALSE(directions_block_every_move({cube.begin(), cube.begin() + 4}, 3));
  cube.pop_back();
  EXPECT_FALSE(directions_block_every_move(cube, 3));
  // collinear opposite contacts leave the perpendicular plane free
  EXPECT_FALSE(directions_block_every_move({{1, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {-1, 0, 0}}, 3));
}

TEST(GeometryPacking, DisksNeverOverlapOrCrossAWallAndAreJammed)
{
  // (disks, container width): the paper's aspect of ~0.6 bed width per disk row
  const std::pair<std::size_t, double> cases[] = {{100, 10.0}, {500, 25.0}, {1500, 40.0}};
  for (const auto &c : cases) {
    const Packing p = pack2d(c.first, c.second, 200.0);
    ASSERT_EQ(p.centre.size(), c.first);
    const GapReport g = smallest_gaps(p);
    // exact: distances minus radii, every pair in reach, every wall incl. the lid
    EXPECT_GE(g.pair, 0.0) << c.first << " disks " << g.pair_i << " " << g.pair_j;
    EXPECT_GE(g.wall, 0.0) << c.first << " disks, disk " << g.wall_i;
    // and the smallest gaps are contacts (within tau r), not loose spacing
    EXPECT_LT(g.pair, tau * 0.8);
    EXPECT_LT(g.wall, tau * 0.8);
    double area = 0.0;
    for (double r : p.radius) area += M_PI * r * r;
    EXPECT_NEAR(p.fraction, area / ((p.hi[0] - p.lo[0]) * (p.hi[1] - p.lo[1])), 1e-12);
    const JammingReport j = jamming_report(p, tau);
    // rattlers: caged disks of no load, a few to ~15 % in jammed polydisperse
    // packings (O'Hern et al. 2003); measured 7-16 % here
    EXPECT_LE(j.rattlers, c.first / 5) << c.first << " disks";
    // isostatic frictionless backbone: 2d = 4 contacts per disk (walls count)
    EXPECT_GT(j.mean_contacts, 3.5);
    // Definition 7.1 checked by brute force: a step of r / 10 in any direction
    // is blocked for (almost) every backbone disk. Not all: with gaps up to
    // tau r, a disk whose contacts leave an angular gap just below pi can slide
    // a little (measured: 0-2 of ~1300 at r / 10, ~7 % at r / 100).
    EXPECT_LE(movableBackboneDisks(p, j, 0.1), c.first / 100) << c.first << " disks";
    // jammed polydisperse disks: the issue asks for >= 0.80, RCP is ~0.84
    if (c.first >= 500)
      EXPECT_GE(p.fraction, 0.80) << c.first << " disks";
    else
      EXPECT_GE(p.fraction, 0.76) << "narrow container: wall layers";

    // rattler growth (Bhattacharya & Lipton 2023, §7.1 step 4): every disk jammed, still no overlap
    Packing q = p;
    const RattlerGrowth G = grow_rattlers(q, 1.1, tau);
    EXPECT_EQ(G.before, j.rattlers);
    const JammingReport jq = jamming_report(q, tau);
    EXPECT_EQ(jq.rattlers, 0u) << c.first << " disks";
    EXPECT_EQ(G.after, 0u);
    const GapReport gq = smallest_gaps(q);
    EXPECT_GE(gq.pair, 0.0) << c.first << " disks " << gq.pair_i << " " << gq.pair_j;
    EXPECT_GE(gq.wall, 0.0) << c.first << " disks, disk " << gq.wall_i;
    // only rattlers changed, and only grew, within the distribution's range
    std::size_t changed = 0;
    for (std::size_t i = 0; i < q.radius.size(); i++) {
      EXPECT_GE(q.radius[i], p.radius[i]);
      EXPECT_LE(q.radius[i], 1.1);
      changed += q.radius[i] != p.radius[i] || q.centre[i] != p.centre[i];
    }
    // (a disk can grow in two passes; a rattler can be jammed by a grown neighbour)
    EXPECT_LE(changed, G.grown);
    EXPECT_GT(changed, 0u);
    EXPECT_GT(q.fraction, p.fraction);
    // Definition 7.1 by brute force on every disk now
    EXPECT_LE(movableBackboneDisks(q, jq, 0.1), c.first / 100) << c.first << " disks";
  }
}

TEST(GeometryPacking, RattlerGrowsToTheInscribedCircle)
{
  // three unit disks touching pairwise leave a hole whose inscribed circle
  // has radius 2 / sqrt(3) - 1 (Descartes), centred at the triangle's centroid
  Packing p;
  p.dimension = 2;
  p.lo[0] = p.lo[1] = -10.0;
  p.hi[0] = p.hi[1] = 10.0;
  const double h = std::sqrt(3.0);
  p.centre = {{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, h, 0.0}, {0.02, 0.5, 0.0}};
  p.radius = {1.0, 1.0, 1.0, 0.05};
  // cap 1: the unit disks (rattlers too, nothing holds them) cannot grow
  RattlerGrowth G = grow_rattlers(p, 1.0, tau);
  EXPECT_EQ(G.grown, 1u);
  EXPECT_NEAR(p.centre[3][0], 0.0, 1e-8);
  EXPECT_NEAR(p.centre[3][1], h / 3.0, 1e-8);
  EXPECT_NEAR(p.radius[3], 2.0 / h - 1.0, 1e-9);
  for (int j = 0; j < 3; j++) // (the unit disks touch each other: gaps 0 +- rounding)
    EXPECT_GE(std::hypot(p.centre[3][0] - p.centre[j][0], p.centre[3][1] - p.centre[j][1]) -
                  p.radius[3] - p.radius[j],
              0.0);
  EXPECT_EQ(G.after, 3u); // the unit disks
  EXPECT_EQ(G.remaining, (std::vector<std::size_t>{0, 1, 2}));
  // a disk alone in a 2 x 2 box: its cage holds radius 1; capped at 0.5 it
  // stays a rattler (no disk smaller than its cage is jammed) and says why
  Packing b;
  b.dimension = 2;
  b.hi[0] = b.hi[1] = 2.0;
  b.centre = {{0.3, 0.4, 0.0}};
  b.radius = {0.2};
  G = grow_rattlers(b, 0.5, tau);
  EXPECT_EQ(G.after, 1u);
  EXPECT_EQ(G.capped, 1u);
  EXPECT_NEAR(b.radius[0], 0.5, 1e-9);
  // uncapped it fills the box, touching all four walls: jammed
  G = grow_rattlers(b, 5.0, tau);
  EXPECT_EQ(G.after, 0u);
  EXPECT_NEAR(b.radius[0], 1.0, 1e-9);
  EXPECT_NEAR(b.centre[0][0], 1.0, 1e-9);
  EXPECT_NEAR(b.centre[0][1], 1.0, 1e-9);
  // 3D: a sphere in a 2 x 2 x 2 box grows to radius 1 at the centre
  Packing s3;
  s3.dimension = 3;
  s3.hi[0] = s3.hi[1] = s3.hi[2] = 2.0;
  s3.centre = {{0.5, 1.3, 0.6}};
  s3.radius = {0.1};
  G = grow_rattlers(s3, 5.0, tau);
  EXPECT_EQ(G.after, 0u);
  EXPECT_NEAR(s3.radius[0], 1.0, 1e-9);
}

TEST(GeometryPacking, RattlersAreFoundAndBlockingIsNotTrivial)
{
  // a disk alone in a box is not jammed; one disk that fills the width
  // between two walls is still free to move up and down
  Packing p;
  p.dimension = 2;
  p.hi[0] = 2.0;
  p.hi[1] = 5.0;
  p.centre = {{1.0, 2.5, 0.0}};
  p.radius = {1.0};
  JammingReport j = jamming_report(p, tau);
  EXPECT_EQ(j.rattlers, 1u);
  p.hi[1] = 2.0;
  p.centre = {{1.0, 1.0, 0.0}};
  j = jamming_report(p, tau); // now touches all four walls
  EXPECT_EQ(j.jammed, 1u);
}

TEST(GeometryPacking, SpheresNeverOverlapAndAreDense)
{
  PackingOptions o;
  o.dimension = 3;
  o.hi[0] = o.hi[1] = 10.0;
  o.hi[2] = 100.0;
  const Packing p =
      pack_spheres(draw_radii(RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1), 500, 9), o);
  const GapReport g = smallest_gaps(p);
  EXPECT_GE(g.pair, 0.0);
  EXPECT_GE(g.wall, 0.0);
  EXPECT_LT(g.pair, tau * 0.8);
  const JammingReport j = jamming_report(p, tau);
  EXPECT_LE(j.rattlers, 500u / 8);
  EXPECT_GT(j.mean_contacts, 5.0);
  // rattler growth jams every sphere (contact directions in no closed half-space)
  Packing q = p;
  const RattlerGrowth G = grow_rattlers(q, 1.1, tau);
  EXPECT_EQ(G.before, j.rattlers);
  EXPECT_EQ(jamming_report(q, tau).rattlers, 0u);
  EXPECT_GE(smallest_gaps(q).pair, 0.0);
  EXPECT_GE(smallest_gaps(q).wall, 0.0);
  // whole box: the wall layers of a 6-diameter-wide box lower it (~0.57);
  // away from the walls (one mean diameter) random close packing: >= 0.60
  EXPECT_GE(p.fraction, 0.55);
  const double lo[3] = {1.6, 1.6, 1.6}, hi[3] = {8.4, 8.4, p.hi[2] - 1.6};
  EXPECT_GE(fraction_inside(p, lo, hi, 60), 0.60);
}

TEST(GeometryPacking, PaperBedsReachThePaperFraction)
{
  // Bhattacharya & Lipton 2023, §7.3: 1490 disks of radius 0.4-1.1 mm (mean 0.8, sd 0.09)
  // in a 50 mm wide container (100 mm high); Bhattacharya & Lipton's (2023) mesh method reaches
  // 0.80
  const Packing p = pack2d(1490, 50.0, 100.0, 12);
  EXPECT_GE(p.fraction, 0.80);
  EXPECT_LE(p.hi[1], 100.0);
  EXPECT_GE(smallest_gaps(p).pair, 0.0);
  // no size segregation: neither the radius nor its squared deviation from
  // the mean correlates with x or height (radii and start positions come from
  // one seed; a shared stream once put the extreme sizes at one side)
  auto correlation = [](const std::vector<double> &a, const std::vector<double> &b) {
    const double n = a.size();
    double ma = 0, mb = 0, sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); i++) {
      ma += a[i] / n;
      mb += b[i] / n;
    }
    for (std::size_t i = 0; i < a.size(); i++) {
      sab += (a[i] - ma) * (b[i] - mb);
      saa += (a[i] - ma) * (a[i] - ma);
      sbb += (b[i] - mb) * (b[i] - mb);
    }
    return sab / std::sqrt(saa * sbb);
  };
  const double mean = std::accumulate(p.radius.begin(), p.radius.end(), 0.0) / p.radius.size();
  std::vector<double> dev2, pos[2];
  for (std::size_t i = 0; i < p.radius.size(); i++) {
    dev2.push_back((p.radius[i] - mean) * (p.radius[i] - mean));
    for (int d = 0; d < 2; d++) pos[d].push_back(p.centre[i][d]);
  }
  for (int d = 0; d < 2; d++) { // 0.1 = 3.9 standard errors at n = 1490
    EXPECT_LT(std::fabs(correlation(p.radius, pos[d])), 0.1) << "axis " << d;
    EXPECT_LT(std::fabs(correlation(dev2, pos[d])), 0.1) << "axis " << d;
  }
  // and the same seed gives the same bed, number for number
  const Packing q = pack2d(1490, 50.0, 100.0, 12);
  EXPECT_EQ(p.centre, q.centre);
  EXPECT_EQ(p.hi[1], q.hi[1]);
}

TEST(GeometryPacking, PerturbedRowsOfThePeriDemPaper)
{
  // Jha et al. (2021) §4.4 (Fig. 22): radii 1 mm +- 0.1 mm, rows in the authors'
  // 68.5 mm x 41 mm container, clearance 0.2 mm, x shifts up to 0.1 r
  RowOptions o;
  o.hi[0] = 68.5;
  o.hi[1] = 41.0;
  o.gap = 0.2;
  o.perturb = 0.1;
  o.seed = 1;
  const Packing p = row_packing(RadiusDistribution::uniform(0.9, 1.1), o);
  // the paper's 502 grains: 16 rows of ~31 disks
  EXPECT_GT(p.radius.size(), 480u);
  EXPECT_LT(p.radius.size(), 520u);
  // exact: nothing closer than the gap, to another disk or a wall
  const GapReport g = smallest_gaps(p);
  EXPECT_GE(g.pair, o.gap * (1 - 1e-12));
  EXPECT_GE(g.wall, o.gap * (1 - 1e-12));
  // centres not aligned vertically: neighbours in a row are apart by more than
  // their radii and the gap, by a random extra of up to 2 perturb r
  double spread = 0.0;
  for (std::size_t i = 1; i < p.centre.size(); i++)
    if (std::fabs(p.centre[i][1] - p.centre[i - 1][1]) < 0.25) // same row
      spread = std::max(spread, std::fabs(std::fabs(p.centre[i][0] - p.centre[i - 1][0]) -
                                          (p.radius[i] + p.radius[i - 1] + o.gap)));
  EXPECT_GT(spread, 0.05); // random extra spacing up to 2 perturb r = 0.2
  EXPECT_LE(spread, 2 * 0.1 * 1.1 + 1e-12);
  // a count limit and the same seed give the first disks of the same bed
  o.max_count = 100;
  const Packing q = row_packing(RadiusDistribution::uniform(0.9, 1.1), o);
  ASSERT_EQ(q.radius.size(), 100u);
  for (std::size_t i = 0; i < 100; i++) EXPECT_EQ(q.centre[i], p.centre[i]);
  // errors
  o.hi[0] = 2.0;
  EXPECT_THROW(row_packing(RadiusDistribution::uniform(0.9, 1.1), o), GeometryError);
  o.hi[0] = 68.5;
  o.gap = -0.1;
  EXPECT_THROW(row_packing(RadiusDistribution::uniform(0.9, 1.1), o), GeometryError);
}

TEST(GeometryPacking, ContainerErrors)
{
  PackingOptions o;
  o.hi[0] = 1.5;
  o.hi[1] = 10.0;
  // a disk wider than the container
  EXPECT_THROW(pack_spheres({1.0}, o), GeometryError);
  // more disk area than the densest packing of the container can hold
  o.hi[0] = 10.0;
  EXPECT_THROW(pack_spheres(std::vector<double>(40, 1.0), o), GeometryError);
  // fits by area (fraction 0.86 < 0.907) but the jammed bed (0.79) is higher than the container
  try {
    pack_spheres(draw_radii(RadiusDistribution::uniform(0.45, 0.55), 110, 1), o);
    ADD_FAILURE() << "expected an error";
  } catch (GeometryError &e) {
    EXPECT_NE(std::string(e.what()).find("high"), std::string::npos) << e.what();
  }
  EXPECT_THROW(pack_spheres({}, o), GeometryError);
  EXPECT_THROW(pack_spheres({0.5, -0.1}, o), GeometryError);
}

// Before any radius is drawn (issue 27: count 4294967306 aborted with std::bad_alloc, 1e8 drew
// 1e8 radii first): a lower bound of the disks' area from the smallest radius, and the smallest
// disk against each extent; a count that may fit passes.
TEST(GeometryPacking, CountIsCheckedBeforeDrawing)
{
  PackingOptions o;
  o.hi[0] = 5.0;
  o.hi[1] = 10.0;
  const auto dist = RadiusDistribution::uniform(0.4, 0.6);
  EXPECT_NO_THROW(check_count_fits(dist, 10, o));
  // 90 disks of radius >= 0.4 cover >= 0.905 of 50: below the densest 0.9069, may fit
  EXPECT_NO_THROW(check_count_fits(dist, 90, o));
  try {
    check_count_fits(dist, 91, o); // >= 0.9148
    ADD_FAILURE() << "expected an error";
  } catch (GeometryError &e) {
    EXPECT_NE(std::string(e.what()).find("at least 0.914832 (91 disks of radius >= 0.4)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(check_count_fits(dist, std::size_t(1) << 62, o), GeometryError);
  o.hi[0] = 0.79; // narrower than the smallest disk
  EXPECT_THROW(check_count_fits(dist, 1, o), GeometryError);
  EXPECT_THROW(check_count_fits(RadiusDistribution::uniform(0.0, 0.6), 1, o), GeometryError);
}

TEST(GeometryPacking, SmallestEnclosingCircle)
{
  // square of side 2: centre, radius sqrt 2
  EnclosingCircle c = smallest_enclosing_circle({{1, 1}, {-1, 1}, {-1, -1}, {1, -1}, {0.2, 0.3}});
  EXPECT_NEAR(c.x, 0.0, 1e-12);
  EXPECT_NEAR(c.y, 0.0, 1e-12);
  EXPECT_NEAR(c.r, std::sqrt(2.0), 1e-12);
  // obtuse triangle: the longest side is the diameter
  c = smallest_enclosing_circle({{0, 0}, {4, 0}, {2, 0.5}});
  EXPECT_NEAR(c.x, 2.0, 1e-12);
  EXPECT_NEAR(c.y, 0.0, 1e-12);
  EXPECT_NEAR(c.r, 2.0, 1e-12);
  // equilateral triangle: circumcircle
  c = smallest_enclosing_circle({{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}});
  EXPECT_NEAR(c.r, 1.0 / std::sqrt(3.0), 1e-12);
  // random cloud: all inside, and no smaller circle about the found centre
  PackingRandom rng(4);
  std::vector<std::array<double, 2>> pts(300);
  for (auto &q : pts) q = {rng.uniform() * 3, rng.uniform()};
  c = smallest_enclosing_circle(pts);
  double far = 0.0;
  for (const auto &q : pts) far = std::max(far, std::hypot(q[0] - c.x, q[1] - c.y));
  EXPECT_NEAR(far, c.r, 1e-9);
}

TEST(GeometryPacking, TiledBedsNeverOverlapAndAreJammed)
{
  // beds of more than 3 tiles are packed tile by tile (pack_spheres); small
  // tiles here so that a quick test has 3 x 4 tiles and the top strip
  PackingOptions o;
  o.dimension = 2;
  o.hi[0] = 60.0;
  o.hi[1] = 400.0;
  o.seed = 4;
  o.tile = 250;
  const auto radii = draw_radii(RadiusDistribution::normal(0.8, 0.09, 0.4, 1.1), 3000, 4);
  const Packing p = pack_spheres(radii, o);
  ASSERT_EQ(p.centre.size(), 3000u);
  const GapReport g = smallest_gaps(p);
  EXPECT_GE(g.pair, 0.0) << g.pair_i << " " << g.pair_j;
  EXPECT_GE(g.wall, 0.0) << g.wall_i;
  EXPECT_LT(g.pair, tau * 0.8);
  EXPECT_LT(g.wall, tau * 0.8);
  // the seams between tiles are real contacts: jammed polydisperse packings
  // have a few to ~15 % rattlers (O'Hern et al. 2003), as the untiled test
  // above; measured here 10-11 % (one minimisation of this bed: 5-7 %)
  const JammingReport j = jamming_report(p, tau);
  EXPECT_LE(j.rattlers, 3000u / 5);
  EXPECT_GT(j.mean_contacts, 3.5);
  EXPECT_GE(p.fraction, 0.80);
  Packing q = p;
  const RattlerGrowth G = grow_rattlers(q, 1.1, tau);
  EXPECT_EQ(G.before, j.rattlers);
  // every disk jammed but for a few whose cage holds more than the largest
  // radius (capped, as one disk of the untiled 100,000-disk bed)
  const JammingReport jq = jamming_report(q, tau);
  EXPECT_EQ(jq.rattlers, G.capped);
  EXPECT_LE(jq.rattlers, 3u);
  EXPECT_GE(smallest_gaps(q).pair, 0.0);
  EXPECT_GE(smallest_gaps(q).wall, 0.0);
  EXPECT_LE(movableBackboneDisks(q, jq, 0.1), 3000u / 100);
  // reproducible; a different tile size is a different bed of the same radii
  EXPECT_EQ(pack_spheres(radii, o).centre, p.centre);
  o.tile = 0;
  const Packing whole = pack_spheres(radii, o);
  EXPECT_NE(whole.centre, p.centre);
  EXPECT_NEAR(whole.fraction, p.fraction, 0.02);
}
