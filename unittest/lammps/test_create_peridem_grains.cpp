/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// create_peridem_grains and cut_peridem_bonds: node counts and
// volumes, the same bonds as the core geometry library, no bond across a
// notch or crack, grain IDs, 3D and Gmsh grains. Ranks: 1 here; 1 vs 2 ranks
// is checked by the example tests (unittest/lammps/inputs/grains.cmake).

#include "lammps_fixture.h"

#include "atom.h"
#include "lammps.h"

#include "peridem_geometry_grain.h"
#include "peridem_geometry_shapes.h"
#include "peridem_geometry_visibility.h"

#include <cmath>
#include <map>
#include <array>
#include <set>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

using TagBond = std::pair<tagint, tagint>;

// a box for grains: units, dimension, region bounds, bond capacity
std::string grain_box(const std::string &units, int dimension, const std::string &bounds,
                      int bonds_per_atom)
{
  return "units " + units + "\ndimension " + std::to_string(dimension) +
         "\nboundary p p p\natom_style peridem\natom_modify map array\nregion box block " + bounds +
         "\ncreate_box 2 box bond/types 1 extra/bond/per/atom " + std::to_string(bonds_per_atom) +
         " extra/special/per/atom 0\nspecial_bonds lj/coul 0.0 1.0 1.0";
}

const std::string box2d = grain_box("lj", 2, "-4 4 -4 4 -0.5 0.5", 40);

// every bond once, as (smaller tag, larger tag)
std::set<TagBond> bond_set(LAMMPS *lmp)
{
  std::set<TagBond> out;
  Atom *atom = lmp->atom;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const tagint a = atom->tag[i], b = atom->bond_atom[i][m];
      out.emplace(std::min(a, b), std::max(a, b));
    }
  return out;
}

std::set<TagBond> core_bonds(const std::vector<peridem::Bond> &bonds, tagint tag0)
{
  std::set<TagBond> out;
  for (const auto &b : bonds) out.emplace(tag0 + b.first, tag0 + b.second);
  return out;
}

double sum_volume(LAMMPS *lmp)
{
  double v = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++) v += lmp->atom->vfrac[i];
  return v;
}

peridem::Vec2 x0_of(LAMMPS *lmp, tagint tag)
{
  const int i = lmp->atom->map(tag);
  return {lmp->atom->x0[i][0], lmp->atom->x0[i][1]};
}

} // namespace

class CreatePeridemGrainsTest : public LammpsTest {};

TEST_F(CreatePeridemGrainsTest, CellVolumesAreSpacingSquared)
{
  command(box2d);
  command("create_peridem_grains 1 disk radius 1 spacing 0.1 horizon 0.3 density 2.5 at 0 0 0");
  const auto nodes = peridem::lattice_nodes(peridem::make_shape("disk", {}), 0.1);
  ASSERT_EQ(lmp->atom->natoms, static_cast<bigint>(nodes.size()));
  EXPECT_NEAR(sum_volume(lmp), nodes.size() * 0.01, 1e-12);
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    EXPECT_DOUBLE_EQ(lmp->atom->rmass[i], 2.5 * lmp->atom->vfrac[i]);
    EXPECT_EQ(lmp->atom->molecule[i], 1);
    EXPECT_EQ(lmp->atom->type[i], 1);
  }
}

TEST_F(CreatePeridemGrainsTest, ExactVolumesSumToShapeArea)
{
  command(box2d);
  command("create_peridem_grains 2 plus radius 1 arm_width 0.4 spacing 0.07 horizon 0.21 "
          "density 1 at 0.5 -0.25 0 rotate 33 volume exact");
  const double area = peridem::make_shape("plus", {{"radius", 1}, {"arm_width", 0.4}}).area();
  EXPECT_NEAR(sum_volume(lmp), area, 1e-12 * area);
}

TEST_F(CreatePeridemGrainsTest, BondsEqualCoreLibraryAndNodesArePlaced)
{
  command(box2d);
  command("create_peridem_grains 1 notched_plate spacing 0.05 horizon 0.15 density 1 "
          "at 1 -0.5 0 rotate 30");
  peridem::Polygon shape = peridem::make_shape("notched_plate", {});
  const peridem::Grain2D g = peridem::discretize_grain(shape, 0.05, 0.15);
  ASSERT_EQ(lmp->atom->natoms, static_cast<bigint>(g.nodes.size()));
  EXPECT_EQ(bond_set(lmp), core_bonds(g.bonds, 1));
  EXPECT_EQ(lmp->atom->nbonds, static_cast<bigint>(g.bonds.size()));

  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (std::size_t k = 0; k < g.nodes.size(); k++) {
    const peridem::Vec2 p = g.nodes.x[k], x = x0_of(lmp, 1 + k);
    EXPECT_NEAR(x.x, 1 + c * p.x - s * p.y, 1e-12);
    EXPECT_NEAR(x.y, -0.5 + s * p.x + c * p.y, 1e-12);
  }
}

TEST_F(CreatePeridemGrainsTest, NoBondLeavesNonconvexShapes)
{
  command(box2d);
  const std::map<std::string, std::string> shapes = {{"notched_plate", "at -2 -2 0"},
                                                     {"v_notched_plate", "at 2 -2 0"},
                                                     {"ring", "at -2 2 0"},
                                                     {"plus", "at 2 2 0"},
                                                     {"neck", "at 0 0 0"}};
  tagint tag0 = 1;
  for (const auto &sh : shapes) {
    command("create_peridem_grains 1 " + sh.first + " spacing 0.06 horizon 0.18 density 1 " +
            sh.second);
    // in the grain frame (node k has atom ID tag0 + k), where the nodes on the
    // boundary lie exactly on it
    const peridem::Polygon shape = peridem::make_shape(sh.first, {});
    const auto nodes = peridem::lattice_nodes(shape, 0.06);
    int checked = 0;
    for (const auto &b : bond_set(lmp)) {
      if (b.first < tag0 || b.first >= tag0 + static_cast<tagint>(nodes.size())) continue;
      EXPECT_TRUE(
          peridem::segment_inside_exact(shape, nodes.x[b.first - tag0], nodes.x[b.second - tag0]))
          << sh.first << " bond " << b.first << "-" << b.second;
      checked++;
    }
    EXPECT_GT(checked, 0) << sh.first;
    tag0 += nodes.size();
  }
}

// pruning extended (the default), its first name seed, exact and off on the same plus grain:
// the first four give the bonds of the exact segment-in-shape test, off keeps bonds that leave
// the grain (across the gap between two arms)
TEST_F(CreatePeridemGrainsTest, PruningKeywordNamesAndAlias)
{
  command(box2d);
  const std::string plus = "create_peridem_grains 1 plus radius 1 arm_width 0.5 spacing 0.08 "
                           "horizon 0.24 density 1 at ";
  const std::vector<std::string> modes = {"", "pruning extended", "pruning seed", "pruning exact",
                                          "pruning off"};
  const peridem::Polygon shape = peridem::make_shape("plus", {{"radius", 1}, {"arm_width", 0.5}});
  const auto nodes = peridem::lattice_nodes(shape, 0.08);
  std::vector<std::set<TagBond>> bonds; // per mode, in node indices of the grain
  for (std::size_t m = 0; m < modes.size(); m++) {
    const tagint tag0 = 1 + static_cast<tagint>(m * nodes.size());
    command(plus + std::to_string(-3.0 + 1.5 * m) + " 0 0 " + modes[m]);
    ASSERT_EQ(lmp->atom->natoms, static_cast<bigint>((m + 1) * nodes.size())) << modes[m];
    std::set<TagBond> mine;
    for (const auto &b : bond_set(lmp))
      if (b.first >= tag0) mine.emplace(b.first - tag0, b.second - tag0);
    bonds.push_back(mine);
  }
  std::size_t outside = 0;
  for (const auto &b : bonds[4]) {
    const bool inside = peridem::segment_inside_exact(shape, nodes.x[b.first], nodes.x[b.second]);
    EXPECT_EQ(bonds[3].count(b) == 1, inside) << b.first << "-" << b.second;
    if (!inside) outside++;
  }
  EXPECT_GT(outside, 0u); // the plus is nonconvex at this horizon
  for (int m = 0; m < 3; m++) EXPECT_EQ(bonds[m], bonds[3]) << modes[m];
}

TEST_F(CreatePeridemGrainsTest, NotchKeywordAndCutCommandRemoveCrossingBonds)
{
  command(box2d);
  // crack at creation (grain frame), and the same crack cut later on a copy
  command("create_peridem_grains 1 disk radius 1 spacing 0.1 horizon 0.3 density 1 at -2 0 0 "
          "notch -0.63 -0.21 0.52 0.33");
  command("create_peridem_grains 1 disk radius 1 spacing 0.1 horizon 0.3 density 1 at 2 0 0");
  const tagint n = lmp->atom->natoms / 2;
  const bigint uncut = static_cast<bigint>(bond_set(lmp).size());
  command("write_data " + scratch() + "grains.data");
  command("clear");
  command("units lj\ndimension 2\nboundary p p p\natom_style peridem\natom_modify map array");
  command("read_data " + scratch() + "grains.data");
  command("special_bonds lj/coul 0.0 1.0 1.0\npair_style zero 0.5\npair_coeff * *");
  command("comm_modify cutoff 1.0");
  command("cut_peridem_bonds all segment 1.37 -0.21 2.52 0.33");

  const peridem::CutSegment left{{-2.63, -0.21}, {-1.48, 0.33}}, right{{1.37, -0.21}, {2.52, 0.33}};
  std::set<TagBond> first, second;
  for (const auto &b : bond_set(lmp)) {
    const auto &cut = b.first <= n ? left : right;
    EXPECT_FALSE(peridem::bond_crosses_cut(x0_of(lmp, b.first), x0_of(lmp, b.second), cut));
    if (b.first <= n)
      first.emplace(b);
    else
      second.emplace(b.first - n, b.second - n);
  }
  EXPECT_EQ(first, second); // the same crack, at creation or later
  EXPECT_LT(static_cast<bigint>(bond_set(lmp).size()), uncut);
  EXPECT_EQ(lmp->atom->nbonds, static_cast<bigint>(bond_set(lmp).size()));
}

TEST_F(CreatePeridemGrainsTest, GrainIdsAreNewAndUnique)
{
  command(box2d);
  command("create_peridem_grains 1 disk radius 0.5 spacing 0.1 horizon 0.3 density 1 "
          "at -2 -2 0 at 0 -2 0 at 2 -2 0");
  command("create_peridem_grains 2 hexagon radius 0.5 spacing 0.1 horizon 0.3 density 1 "
          "at -2 2 0 at 2 2 0 rotate random 42 overlap 0.05");
  std::map<tagint, std::set<tagint>> ids; // grain ID -> atom IDs
  for (int i = 0; i < lmp->atom->nlocal; i++) ids[lmp->atom->molecule[i]].insert(lmp->atom->tag[i]);
  ASSERT_EQ(ids.size(), 5u);
  tagint expect = 1;
  for (const auto &g : ids) {
    EXPECT_EQ(g.first, expect++);
    // contiguous atom IDs per grain
    EXPECT_EQ(*g.second.rbegin() - *g.second.begin() + 1, static_cast<tagint>(g.second.size()));
  }
  // no bond joins two grains
  for (const auto &b : bond_set(lmp))
    EXPECT_EQ(lmp->atom->molecule[lmp->atom->map(b.first)],
              lmp->atom->molecule[lmp->atom->map(b.second)]);
}

TEST_F(CreatePeridemGrainsTest, MaterialGivesDensityAndHorizon)
{
  command(grain_box("si", 2, "-0.01 0.01 -0.01 0.01 -0.001 0.001", 60));
  command("create_peridem_grains 1 disk radius 0.002 spacing 0.0002 at 0 0 0 material " +
          std::string(PERIDEM_SOURCE_DIR) + "/potentials/peridem_M1.peridem M1");
  const peridem::Grain2D g = peridem::discretize_shape("disk", {{"radius", 0.002}}, 0.0002, 0.6e-3);
  EXPECT_EQ(bond_set(lmp), core_bonds(g.bonds, 1));
  EXPECT_DOUBLE_EQ(lmp->atom->rmass[0], 1200 * lmp->atom->vfrac[0]);
}

TEST_F(CreatePeridemGrainsTest, SolidAndExtrudedGrainsEqualCoreLibrary)
{
  command(grain_box("lj", 3, "-3 3 -3 3 -3 3", 40));
  command("create_peridem_grains 1 sphere radius 1 spacing 0.2 horizon 0.4 density 1 at -1.5 0 0");
  const auto sphere = peridem::discretize_grain_3d(peridem::Shape3D::sphere(1.0), 0.2, 0.4,
                                                   peridem::Pruning::ExtendedBoundary);
  ASSERT_EQ(lmp->atom->natoms, static_cast<bigint>(sphere.nodes.size()));
  EXPECT_EQ(bond_set(lmp), core_bonds(sphere.bonds, 1));
  EXPECT_NEAR(sum_volume(lmp), sphere.nodes.size() * 0.008, 1e-12);

  command("create_peridem_grains 1 plus extrude 0.6 spacing 0.1 horizon 0.2 density 1 at 1.5 0 0");
  const auto plus = peridem::discretize_grain_3d(
      peridem::Shape3D::extrusion(peridem::make_shape("plus", {}), 0.6), 0.1, 0.2,
      peridem::Pruning::ExtendedBoundary);
  std::set<TagBond> mine;
  const tagint tag0 = sphere.nodes.size() + 1;
  for (const auto &b : bond_set(lmp))
    if (b.first >= tag0) mine.insert(b);
  EXPECT_EQ(mine, core_bonds(plus.bonds, tag0));
}

// rotate A axis X Y Z: an extruded plus (arms along x and y, thickness 0.6 along z) turned
// 90 degrees about x lies with its thickness along y; node positions are R (x0 - c) + c
// with Rodrigues' rotation, bonds unchanged.
TEST_F(CreatePeridemGrainsTest, RotationAboutAnAxis3D)
{
  command(grain_box("lj", 3, "-3 3 -3 3 -3 3", 40));
  command("create_peridem_grains 1 plus extrude 0.6 spacing 0.1 horizon 0.2 density 1 at 0 0 0");
  const auto plain = bond_set(lmp);
  std::vector<std::array<double, 3>> before(lmp->atom->natoms + 1);
  for (int i = 0; i < lmp->atom->nlocal; i++)
    for (int d = 0; d < 3; d++) before[lmp->atom->tag[i]][d] = lmp->atom->x[i][d];
  command("delete_atoms group all bond yes");
  command("reset_atom_ids");
  command("create_peridem_grains 1 plus extrude 0.6 spacing 0.1 horizon 0.2 density 1 at 0 0 0 "
          "rotate 90 axis 2 0 0");
  ASSERT_EQ(lmp->atom->natoms + 1, static_cast<bigint>(before.size()));
  EXPECT_EQ(bond_set(lmp), plain);
  double zmax = 0.0, ymax = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const auto &p = before[lmp->atom->tag[i]];
    // about x by 90 degrees: (x, y, z) -> (x, -z, y)
    EXPECT_NEAR(lmp->atom->x[i][0], p[0], 1e-14);
    EXPECT_NEAR(lmp->atom->x[i][1], -p[2], 1e-14);
    EXPECT_NEAR(lmp->atom->x[i][2], p[1], 1e-14);
    for (int d = 0; d < 3; d++) EXPECT_EQ(lmp->atom->x0[i][d], lmp->atom->x[i][d]);
    ymax = std::max(ymax, std::fabs(lmp->atom->x[i][1]));
    zmax = std::max(zmax, std::fabs(lmp->atom->x[i][2]));
  }
  EXPECT_LT(ymax, 0.31); // the thickness (0.6) now along y
  EXPECT_GT(zmax, 0.9);  // an arm (radius 1) now along z
}

TEST_F(CreatePeridemGrainsTest, GmshGrainVolumesSumToMeshArea)
{
  command(box2d);
  const std::string mesh =
      std::string(PERIDEM_SOURCE_DIR) + "/unittest/core/data/square_hole_v41.msh";
  command("create_peridem_grains 1 gmsh " + mesh + " horizon 0.5 density 1 at 0 0 0");
  const peridem::Mesh2D m = peridem::read_gmsh_mesh(mesh);
  const peridem::Grain2D g = peridem::mesh_grain(m, 0.5);
  EXPECT_EQ(lmp->atom->natoms, static_cast<bigint>(g.nodes.size()));
  EXPECT_NEAR(sum_volume(lmp), m.area(), 1e-12 * m.area());
  EXPECT_EQ(bond_set(lmp), core_bonds(g.bonds, 1));
}

// nodes outline: the nodes and volumes of the core library's outline lattice, its bonds, the
// boundary nodes on the disk's circle and on both circles of the ring; nodes lattice is the
// default
TEST_F(CreatePeridemGrainsTest, NodesOutlineOnDiskAndRing)
{
  command(box2d);
  const double h = 0.08, eps = 0.24;
  const std::map<std::string, std::string> shapes = {{"disk", "at -2 0 0"}, {"ring", "at 2 0 0"}};
  tagint tag0 = 1;
  for (const auto &sh : shapes) {
    command("create_peridem_grains 1 " + sh.first + " spacing 0.08 horizon 0.24 density 1 " +
            sh.second + " nodes outline");
    const peridem::Polygon shape = peridem::make_shape(sh.first, {});
    peridem::GrainOptions opt;
    opt.lattice.volume = peridem::NodalVolume::ExactClip;
    opt.lattice.placement = peridem::NodePlacement::Outline;
    const peridem::Grain2D g = peridem::discretize_grain(shape, h, eps, opt);
    const double cx = sh.first == "disk" ? -2.0 : 2.0;
    double volume = 0.0;
    int on_outer = 0, on_inner = 0;
    for (std::size_t k = 0; k < g.nodes.size(); k++) {
      const int i = lmp->atom->map(tag0 + static_cast<tagint>(k));
      ASSERT_GE(i, 0);
      const peridem::Vec2 p(lmp->atom->x0[i][0] - cx, lmp->atom->x0[i][1]);
      EXPECT_NEAR((p - g.nodes.x[k]).norm(), 0.0, 1e-14);
      EXPECT_DOUBLE_EQ(lmp->atom->vfrac[i], g.nodes.volume[k]);
      volume += lmp->atom->vfrac[i];
      // the 64-gon's boundary points lie between r cos(pi/64) and r
      const double r = p.norm(), lo = std::cos(M_PI / 64) * (1 - 1e-12);
      if (r >= lo && r <= 1 + 1e-12) on_outer++;
      if (sh.first == "ring" && r >= 0.6 * lo && r <= 0.6 * (1 + 1e-12)) on_inner++;
      if (shape.boundary_distance(p) > 1e-12)
        EXPECT_GE(shape.boundary_distance(p), 0.5 * h - 1e-12);
    }
    EXPECT_NEAR(volume, shape.area(), 1e-12 * shape.area()) << sh.first;
    EXPECT_GT(on_outer, 0.8 * 2 * M_PI / h) << sh.first;
    if (sh.first == "ring") EXPECT_GT(on_inner, 0.8 * 2 * M_PI * 0.6 / h);
    std::set<TagBond> mine;
    for (const auto &b : bond_set(lmp))
      if (b.first >= tag0 && b.first < tag0 + static_cast<tagint>(g.nodes.size())) mine.insert(b);
    EXPECT_EQ(mine, core_bonds(g.bonds, tag0)) << sh.first;
    tag0 += g.nodes.size();
  }

  // nodes lattice: the default lattice nodes
  command(
      "create_peridem_grains 1 ring spacing 0.08 horizon 0.24 density 1 at 0 2 0 nodes lattice");
  const peridem::Grain2D lat = peridem::discretize_grain(peridem::make_shape("ring", {}), h, eps);
  for (std::size_t k = 0; k < lat.nodes.size(); k++) {
    const peridem::Vec2 p = x0_of(lmp, tag0 + static_cast<tagint>(k));
    EXPECT_NEAR(p.x, lat.nodes.x[k].x, 1e-15);
    EXPECT_NEAR(p.y - 2.0, lat.nodes.x[k].y, 1e-15);
    EXPECT_EQ(lmp->atom->vfrac[lmp->atom->map(tag0 + static_cast<tagint>(k))], h * h);
  }
  EXPECT_EQ(lmp->atom->natoms, static_cast<bigint>(tag0 - 1 + lat.nodes.size()));
}
