/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// create_peridem_bed: grains placed from a jammed bed file are at
// least R_c apart from each other and from the walls at step 0
// (Bhattacharya & Lipton 2023, §7.1 step 5), each fills its security disk (diameter matched), the
// labels pick the lines of each create_peridem_grains, and the bed file
// reads back the disks it wrote. 1 vs 2 ranks: unittest/lammps/inputs/bed.cmake.

#include "lammps_fixture.h"

#include "atom.h"
#include "lammps.h"

#include "peridem_geometry_packing.h"

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;

namespace {

struct Line {
  double x, y, z, r, angle;
  std::string label;
};

std::vector<Line> read_bed(const std::string &file)
{
  std::ifstream in(file);
  std::vector<Line> out;
  std::string s;
  while (std::getline(in, s)) {
    if (s.empty() || s[0] == '#') continue;
    std::istringstream l(s);
    Line b;
    l >> b.x >> b.y >> b.z >> b.r >> b.angle >> b.label;
    out.push_back(b);
  }
  return out;
}

const double Rc = 0.1, W = 10.0, H = 30.0;

// a peridem box of 2 types; block = the region's six bounds
std::string box_setup(int dim, const std::string &block)
{
  return std::string("units lj\ndimension ") +
         (dim == 2 ? "2\nboundary f f p" : "3\nboundary f f f") +
         "\natom_style peridem\natom_modify map array\nregion box block " + block +
         "\ncreate_box 2 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 0\n"
         "special_bonds lj/coul 0.0 1.0 1.0\n";
}

std::string bed_setup(const std::string &dir, const std::string &shapes)
{
  return box_setup(2, "-0.5 10.5 -0.5 30.5 -0.1 0.1") + "create_peridem_bed " + dir +
         "bed.txt count 80 radius normal 0.8 0.09 0.4 1.1 seed 7 box 0 10 0 30 " +
         "contact_radius 0.1 labels " + shapes;
}

} // namespace

class CreatePeridemBed : public LammpsTest {};

TEST_F(CreatePeridemBed, GrainsAreRcApartAtStepZero)
{
  const std::string dir = scratch();
  command(bed_setup(dir, "disk 1 square 1 plus 1"));
  const auto bed = read_bed(dir + "bed.txt");
  ASSERT_EQ(bed.size(), 80u);
  std::map<std::string, int> count;
  for (const auto &b : bed) count[b.label]++;
  EXPECT_EQ(count.size(), 3u);
  for (const char *shape : {"disk", "square", "plus"})
    command(std::string("create_peridem_grains 1 ") + shape +
            " spacing 0.1 horizon 0.3 density 1 positions " + dir + "bed.txt");

  Atom *atom = lmp->atom;
  ASSERT_GT(atom->nlocal, 0);
  // grain IDs follow the commands: disks, then squares, then pluses
  EXPECT_EQ(atom->natoms, atom->nlocal);
  // nearest node of another grain: cell grid of side R_c
  std::unordered_map<long long, std::vector<int>> cells;
  auto key = [](long long i, long long j) { return i * 100000 + j; };
  for (int i = 0; i < atom->nlocal; i++)
    cells[key(std::floor(atom->x[i][0] / Rc), std::floor(atom->x[i][1] / Rc))].push_back(i);
  double closest = 1e30, wall = 1e30;
  for (int i = 0; i < atom->nlocal; i++) {
    const long long ci = std::floor(atom->x[i][0] / Rc), cj = std::floor(atom->x[i][1] / Rc);
    for (int di = -1; di <= 1; di++)
      for (int dj = -1; dj <= 1; dj++) {
        auto it = cells.find(key(ci + di, cj + dj));
        if (it == cells.end()) continue;
        for (int j : it->second)
          if (atom->molecule[j] != atom->molecule[i])
            closest = std::min(
                closest, std::hypot(atom->x[i][0] - atom->x[j][0], atom->x[i][1] - atom->x[j][1]));
      }
    wall = std::min({wall, atom->x[i][0], W - atom->x[i][0], atom->x[i][1], H - atom->x[i][1]});
  }
  // nodes of different grains: no pair inside R_c (checked within one cell)
  EXPECT_GE(closest, Rc);
  EXPECT_GE(wall, Rc);

  // each grain fills its security disk: a node of each grain reaches within a
  // node spacing of the disk's circle (disk and square vertices touch it), none outside
  std::map<tagint, double> reach;
  const int ngrains = static_cast<int>(bed.size());
  std::vector<Line> by_grain;
  for (const char *shape : {"disk", "square", "plus"})
    for (const auto &b : bed)
      if (b.label == shape) by_grain.push_back(b);
  ASSERT_EQ(static_cast<int>(by_grain.size()), ngrains);
  for (int i = 0; i < atom->nlocal; i++) {
    const Line &b = by_grain[atom->molecule[i] - 1];
    const double d = std::hypot(atom->x[i][0] - b.x, atom->x[i][1] - b.y);
    EXPECT_LE(d, b.r * (1 + 1e-12)) << "grain " << atom->molecule[i];
    reach[atom->molecule[i]] = std::max(reach[atom->molecule[i]], d);
  }
  for (const auto &kv : reach) {
    const Line &b = by_grain[kv.first - 1];
    // lattice nodes lie within sqrt(2) h / 2 of the boundary; plus arm tips too
    EXPECT_GT(kv.second, b.r - 0.1 * std::sqrt(2.0)) << "grain " << kv.first << " " << b.label;
  }
}

TEST_F(CreatePeridemBed, BedFileLinesAreTheJammedDisksShrunkByHalfRc)
{
  const std::string dir = scratch();
  command(bed_setup(dir, "a 1"));
  const auto bed = read_bed(dir + "bed.txt");
  // exact: security disks (radius + R_c/2) never overlap, nor cross the inset walls
  for (std::size_t i = 0; i < bed.size(); i++) {
    EXPECT_GE(bed[i].x - bed[i].r, Rc - 1e-12);
    EXPECT_GE(W - bed[i].x - bed[i].r, Rc - 1e-12);
    EXPECT_GE(bed[i].y - bed[i].r, Rc - 1e-12);
    EXPECT_GE(bed[i].r, 0.4 - Rc / 2);
    EXPECT_LE(bed[i].r, 1.1 - Rc / 2);
    EXPECT_TRUE(bed[i].angle >= 0 && bed[i].angle < 360);
    for (std::size_t j = i + 1; j < bed.size(); j++)
      EXPECT_GE(std::hypot(bed[i].x - bed[j].x, bed[i].y - bed[j].y), bed[i].r + bed[j].r + Rc);
  }
  // every disk jammed (rattlers grown, the default): the file's disks, grown
  // back by R_c/2 in the container inset by R_c/2 up to the bed's lid, pass
  // the criterion of jamming_report with the packing tolerance
  peridem::Packing p;
  p.dimension = 2;
  std::ifstream in(dir + "bed.txt");
  std::string s, header;
  while (std::getline(in, s))
    if (s.rfind("# bed ", 0) == 0) {
      std::istringstream l(s.substr(6));
      l >> p.lo[0] >> p.hi[0] >> p.lo[1] >> p.hi[1];
    } else if (s.rfind("# rattlers grown", 0) == 0)
      header = s;
  for (int d = 0; d < 2; d++) {
    p.lo[d] += Rc / 2;
    p.hi[d] -= Rc / 2;
  }
  for (const auto &b : bed) {
    p.centre.push_back({b.x, b.y, 0.0});
    p.radius.push_back(b.r + Rc / 2);
  }
  EXPECT_EQ(peridem::jamming_report(p, 1e-3).rattlers, 0u);
  EXPECT_NE(header.find(" after (0 capped"), std::string::npos) << header;
  // the same seed writes the same file; placing it uses the file's angles
  command("create_peridem_bed " + dir + "again.txt count 80 radius normal 0.8 0.09 0.4 1.1 " +
          "seed 7 box 0 10 0 30 contact_radius 0.1 labels a 1");
  std::ifstream f1(dir + "bed.txt"), f2(dir + "again.txt");
  std::stringstream s1, s2;
  s1 << f1.rdbuf();
  s2 << f2.rdbuf();
  EXPECT_EQ(s1.str(), s2.str());
}

TEST_F(CreatePeridemBed, PerturbedRowsOfThePeriDemPaper)
{
  // Jha et al. (2021) §4.4: radii 1 +- 0.1, circles and hexagons mixed 7 : 3 (the
  // authors' setup script), perturbed rows filling the container
  const std::string dir = scratch();
  command(box_setup(2, "-0.5 20.5 -0.5 15.5 -0.1 0.1") + "create_peridem_bed " + dir +
          "rows.txt radius uniform 0.9 1.1 seed 3 layout rows gap 0.2 perturb 0.1 "
          "box 0 20 0 15 contact_radius 0.1 labels disk 0.7 hexagon 0.3");
  const auto bed = read_bed(dir + "rows.txt");
  ASSERT_GT(bed.size(), 40u);
  std::map<std::string, int> count;
  for (std::size_t i = 0; i < bed.size(); i++) {
    count[bed[i].label]++;
    // shrunk by R_c/2: R_c + gap from walls and from each other
    EXPECT_GE(bed[i].x - bed[i].r, Rc + 0.2 - 1e-12);
    EXPECT_GE(20.0 - bed[i].x - bed[i].r, Rc + 0.2 - 1e-12);
    EXPECT_GE(bed[i].y - bed[i].r, Rc + 0.2 - 1e-12);
    EXPECT_GE(15.0 - bed[i].y - bed[i].r, Rc + 0.2 - 1e-12);
    EXPECT_GE(bed[i].r + Rc / 2, 0.9);
    EXPECT_LE(bed[i].r + Rc / 2, 1.1);
    for (std::size_t j = i + 1; j < bed.size(); j++)
      EXPECT_GE(std::hypot(bed[i].x - bed[j].x, bed[i].y - bed[j].y),
                bed[i].r + bed[j].r + Rc + 0.2 - 1e-12);
  }
  EXPECT_EQ(count.size(), 2u);
  // 7 : 3 within 4 standard deviations of a binomial
  const double n = bed.size(), sd = std::sqrt(n * 0.7 * 0.3);
  EXPECT_NEAR(count["disk"], 0.7 * n, 4 * sd);
  command("create_peridem_grains 1 disk spacing 0.2 horizon 0.6 density 1 positions " + dir +
          "rows.txt");
  command("create_peridem_grains 2 hexagon spacing 0.2 horizon 0.6 density 1 positions " + dir +
          "rows.txt");
  EXPECT_GT(lmp->atom->natoms, 0);
}

TEST_F(CreatePeridemBed, MeshGrainsFillTheirSecurityDisks)
{
  // a Gmsh grain (unit square with a hole): its corners are on the smallest
  // enclosing circle, so each grain reaches its disk's radius exactly
  const std::string dir = scratch();
  command(bed_setup(dir, "mesh 1"));
  const auto bed = read_bed(dir + "bed.txt");
  const std::string mesh =
      std::string(PERIDEM_SOURCE_DIR) + "/unittest/core/data/square_hole_v22.msh";
  command("create_peridem_grains 1 gmsh " + mesh + " horizon 0.5 density 1 label mesh positions " +
          dir + "bed.txt");
  Atom *atom = lmp->atom;
  std::map<tagint, double> reach;
  for (int i = 0; i < atom->nlocal; i++) {
    const Line &b = bed[atom->molecule[i] - 1];
    const double d = std::hypot(atom->x[i][0] - b.x, atom->x[i][1] - b.y);
    reach[atom->molecule[i]] = std::max(reach[atom->molecule[i]], d);
  }
  ASSERT_EQ(reach.size(), bed.size());
  for (const auto &kv : reach) EXPECT_NEAR(kv.second, bed[kv.first - 1].r, 1e-12);
}

TEST_F(CreatePeridemBed, FitRadiusPutsTheShapesRadiusOnTheSecurityDisk)
{
  // fit radius (the authors' perigrain scaling): a perturbed disk's radius parameter R is the
  // security disk's radius r and the outline is centred on the disk; its vertices lie at
  // R (1 - X_i) <= R, so every node is within r of the bed point, and no grain is larger than
  // the same outline scaled by its smallest enclosing circle (fit enclosing, the default,
  // which scales by r / max_i r_i >= 1). A ring's radius is its enclosing circle's: both fits
  // place the same nodes.
  const std::string dir = scratch();
  command(bed_setup(dir, "grain 1"));
  const auto bed = read_bed(dir + "bed.txt");
  Atom *atom = lmp->atom;
  auto grains = [&](const std::string &shape, const std::string &fit) {
    command("delete_atoms group all");
    command("create_peridem_grains 1 " + shape + " spacing 0.1 horizon 0.3 density 1 label grain " +
            fit + " positions " + dir + "bed.txt");
    std::map<tagint, int> nodes;
    std::map<tagint, double> reach;
    std::map<tagint, std::vector<double>> xy;
    for (int i = 0; i < atom->nlocal; i++) {
      const Line &b = bed[atom->molecule[i] - 1];
      const double d = std::hypot(atom->x[i][0] - b.x, atom->x[i][1] - b.y);
      nodes[atom->molecule[i]]++;
      reach[atom->molecule[i]] = std::max(reach[atom->molecule[i]], d);
      xy[atom->tag[i]] = {atom->x[i][0], atom->x[i][1]};
    }
    return std::make_tuple(nodes, reach, xy);
  };
  const auto [n_radius, reach_radius, xy_radius] = grains("perturbed_disk", "fit radius");
  const auto [n_enclosing, reach_enclosing, xy_enclosing] = grains("perturbed_disk", "");
  ASSERT_EQ(n_radius.size(), bed.size());
  int smaller = 0;
  for (const auto &kv : n_radius) {
    const double r = bed[kv.first - 1].r;
    EXPECT_LE(reach_radius.at(kv.first), r * (1 + 1e-12)) << "grain " << kv.first;
    EXPECT_LE(kv.second, n_enclosing.at(kv.first)) << "grain " << kv.first;
    if (kv.second < n_enclosing.at(kv.first)) smaller++;
  }
  EXPECT_GT(smaller, static_cast<int>(bed.size()) / 2); // most outlines stay inside R
  const auto ring_radius = std::get<2>(grains("ring", "fit radius"));
  const auto ring_enclosing = std::get<2>(grains("ring", "fit enclosing"));
  ASSERT_EQ(ring_radius.size(), ring_enclosing.size());
  for (const auto &kv : ring_radius) {
    EXPECT_NEAR(kv.second[0], ring_enclosing.at(kv.first)[0], 1e-12);
    EXPECT_NEAR(kv.second[1], ring_enclosing.at(kv.first)[1], 1e-12);
  }
}

TEST_F(CreatePeridemBed, SpheresAndBoxesIn3d)
{
  // a 3d bed: spheres and boxes inscribed in their security spheres, R_c apart
  const std::string dir = scratch();
  command(box_setup(3, "-0.5 6.5 -0.5 6.5 -0.5 20.5") + "create_peridem_bed " + dir +
          "bed.txt count 40 radius uniform 0.8 1.1 seed 3 box 0 6 0 6 0 20 contact_radius 0.1 "
          "labels sphere 1 box 1");
  const auto bed = read_bed(dir + "bed.txt");
  ASSERT_EQ(bed.size(), 40u);
  command("create_peridem_grains 1 sphere spacing 0.25 horizon 0.6 density 1 positions " + dir +
          "bed.txt");
  command("create_peridem_grains 2 box spacing 0.25 horizon 0.6 density 1 positions " + dir +
          "bed.txt");
  std::vector<Line> by_grain;
  for (const char *shape : {"sphere", "box"})
    for (const auto &b : bed)
      if (b.label == shape) by_grain.push_back(b);
  Atom *atom = lmp->atom;
  ASSERT_GT(atom->nlocal, 0);
  double closest = 1e30, wall = 1e30;
  for (int i = 0; i < atom->nlocal; i++) {
    const Line &b = by_grain[atom->molecule[i] - 1];
    EXPECT_LE(std::sqrt(std::pow(atom->x[i][0] - b.x, 2) + std::pow(atom->x[i][1] - b.y, 2) +
                        std::pow(atom->x[i][2] - b.z, 2)),
              b.r * (1 + 1e-12));
    wall = std::min(
        {wall, atom->x[i][0], 6 - atom->x[i][0], atom->x[i][1], 6 - atom->x[i][1], atom->x[i][2]});
    for (int j = 0; j < i; j++)
      if (atom->molecule[j] != atom->molecule[i])
        closest = std::min(closest, std::sqrt(std::pow(atom->x[i][0] - atom->x[j][0], 2) +
                                              std::pow(atom->x[i][1] - atom->x[j][1], 2) +
                                              std::pow(atom->x[i][2] - atom->x[j][2], 2)));
  }
  EXPECT_GE(closest, Rc);
  EXPECT_GE(wall, Rc);
}
