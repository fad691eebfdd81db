/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// fix peridem/wall: validation through LAMMPS (drop and rebound, damping,
// corner continuity, settled reaction, servo, moving walls, restart, lost nodes).
// The formulas themselves are tested in unittest/core/test_wall_geometry.cpp.

#include "lammps_fixture.h"

#include "atom.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "variable.h"

#include "peridem_wall_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;

namespace {

const std::string POT = std::string(PERIDEM_SOURCE_DIR) + "/potentials/peridem_M1.peridem";
constexpr double H = 0.15e-3;      // node spacing
constexpr double NODE_VOL = H * H; // 2D nodal area
constexpr double NODE_MASS = 1200.0 * NODE_VOL;
constexpr double RC = 0.95 * H;
// K_n of M1 (18 K/(pi eps^5)) divided by 64: the grain is then stiff against its contact and
// less than 1% of the impact energy goes into elastic vibration of the grain (see DropM1).
constexpr double KN_SOFT = 2.5e22;

// A 2D disk grain (radius 1 mm, material M1 of Jha et al. 2021, spacing 0.15 mm, 137 nodes) in
// a 6 mm x 9 mm box; walls are added by the tests.
std::string grain(double xc, double yc)
{
  char buf[2048];
  std::snprintf(buf, sizeof(buf), R"(
units           si
dimension       2
boundary        f f p
atom_style      peridem
atom_modify     map array
lattice         sq %.17g
region          box block -3e-3 3e-3 -1e-3 8e-3 -1e-4 1e-4 units box
create_box      1 box bond/types 1 extra/bond/per/atom 60 extra/special/per/atom 80
region          grain sphere %.17g %.17g 0 1.0e-3 units box
create_atoms    1 region grain
set             type 1 mol 1
set             type 1 volume %.17g
set             type 1 mass %.17g
pair_style      zero 0.7e-3
pair_coeff      * *
special_bonds   lj/coul 0.0 1.0 1.0
create_bonds    many all all 1 0.0 0.6e-3
bond_style      peridem
bond_coeff      1 material %s M1
comm_modify     cutoff 1.5e-3
fix             integrate all nve
fix             plane all enforce2d
timestep        2.5e-8
thermo_style    custom step etotal
thermo          1000000
)",
                H, xc, yc, NODE_VOL, NODE_MASS, POT.c_str());
  return buf;
}

class FixPeridemWallTest : public LammpsTest {
 protected:
  Fix *wall() { return lmp->modify->fix[lmp->modify->find_fix("wall")]; }
  // global vector entry, 0-based: wall w (xlo xhi ylo yhi zlo zhi) entry j
  // (0 position, 1 velocity, 2 normal load, 3-5 force)
  double wall_entry(int w, int j) { return wall()->compute_vector(6 * w + j); }
  double equal(const std::string &expr) { return lmp->input->variable->compute_equal(expr); }
  double mass() const
  {
    double m = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++) m += lmp->atom->rmass[i];
    return m;
  }
  double com(int k) const
  {
    double s = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++) s += lmp->atom->rmass[i] * lmp->atom->x[i][k];
    return s / mass();
  }

  struct Bounce {
    double y0, ymin, peak, e0, max_drift, dissipated;
  };
  // drop from the current state: run in chunks until the centre of mass, having bounced,
  // turns down again (or stays on the floor); energy = ke + pe (wall, gravity) + ebond
  Bounce bounce(int chunk = 40, int max_chunks = 2000)
  {
    Bounce b{com(1), 1e30, -1e30, equal("etotal"), 0.0, 0.0};
    bool rising = false;
    double prev = b.y0;
    for (int c = 0; c < max_chunks; c++) {
      command("run " + std::to_string(chunk) + " pre no post no");
      const double y = com(1);
      b.max_drift = std::max(b.max_drift, std::fabs(equal("etotal") - b.e0));
      b.ymin = std::min(b.ymin, y);
      if (y > prev && b.ymin < b.y0 - 1e-4) rising = true;
      if (rising) b.peak = std::max(b.peak, y);
      if (rising && y < prev) break;
      prev = y;
    }
    b.dissipated = wall()->compute_vector(6 * 4 + 1);
    return b;
  }
  // nodes (lj units, volume 0.7, mass 1.3) at the positions in `nodes` ("x y z" each), walls
  // and options `walls` with K_n = 2, R_c = 1
  void single_nodes(int dim, const std::vector<std::string> &nodes, const std::string &walls)
  {
    const bool d3 = dim == 3;
    command(std::string("units lj\ndimension ") + (d3 ? "3" : "2") + "\nboundary f f " +
            (d3 ? "f" : "p") + "\natom_style peridem\nregion box block -3 4 -1 4 " +
            (d3 ? "-1 4" : "-0.5 0.5") + " units box\ncreate_box 1 box");
    for (const auto &xyz : nodes) command("create_atoms 1 single " + xyz + " units box");
    command("set type 1 mol 1\nset type 1 volume 0.7\nset type 1 mass 1.3\n"
            "fix wall all peridem/wall " +
            walls + " Kn 2.0 Rc 1.0\nrun 0 post no");
  }
  // the core law for node 0 with the lo walls of the first `dim` axes at 0
  peridem::WallContactResult core_force(int dim)
  {
    peridem::WallBox box;
    box.dimension = dim;
    for (int k = 0; k < dim; k++) box.active[2 * k] = true;
    peridem::ContactParams p;
    p.Kn = 2.0;
    p.Rc = 1.0;
    peridem::WallContactInput in;
    for (int k = 0; k < 3; k++) in.x[k] = lmp->atom->x[0][k];
    in.vol = 0.7;
    in.mass = 1.3;
    return peridem::wall_contact_force(box, in, p);
  }
  void move_node(double x)
  {
    char buf[96];
    std::snprintf(buf, sizeof(buf), "set atom 1 x %.17g\nrun 0 post no", x);
    command(buf);
  }
  void drop_setup(const std::string &contact, double gravity = 1e4)
  {
    command(grain(0.0, 1.8e-3));
    command("fix wall all peridem/wall ylo 0.0 " + contact +
            " Rc_factor 0.95 spacing 0.15e-3\n"
            "fix_modify wall energy yes\n"
            "fix grav all gravity " +
            std::to_string(gravity) +
            " vector 0 -1 0\n"
            "fix_modify grav energy yes\n"
            "run 0 post no");
  }
};

// Undamped drop: total energy conserved through the bounce, the centre of mass back to
// its starting height within 2% of the drop.
TEST_F(FixPeridemWallTest, DropWithoutDampingRebounds)
{
  drop_setup("Kn 2.5e22");
  const Bounce b = bounce();
  const double loss = (b.y0 - b.peak) / (b.y0 - b.ymin);
  std::printf("[ measure  ] undamped drop (Kn = M1/64): rebound loss %.4f%% of the drop, energy "
              "drift %.2e relative\n",
              100 * loss, b.max_drift / b.e0);
  EXPECT_LT(std::fabs(loss), 0.02);
  EXPECT_LT(b.max_drift / b.e0, 1e-5);
  EXPECT_EQ(b.dissipated, 0.0);
}

// The same with M1's own K_n: still conservative, but the stiffer contact shakes the grain
// and part of the energy stays in its vibration, the more the faster the impact (4.5 % of
// the drop at 4 m/s, 2.6 % at 1.3 m/s, 1.6 % at 0.4 m/s): not a wall property. At 0.4 m/s
// (g = 100) the centre of mass comes back within 2 % of its starting height.
TEST_F(FixPeridemWallTest, DropM1ContactConservesEnergy)
{
  for (const double g : {1e4, 1e2}) {
    delete lmp;
    lmp = make_lammps();
    drop_setup("material " + POT + " M1", g);
    const Bounce b = bounce(g > 1e3 ? 40 : 200);
    const double loss = (b.y0 - b.peak) / (b.y0 - b.ymin);
    std::printf("[ measure  ] undamped drop (M1 K_n, g = %g): rebound loss %.3f%% of the drop (to "
                "grain vibration), energy drift %.2e relative\n",
                g, 100 * loss, b.max_drift / b.e0);
    EXPECT_LT(b.max_drift / b.e0, 1e-5);
    EXPECT_LT(loss, g > 1e3 ? 0.1 : 0.02);
    EXPECT_GT(loss, 0.0); // some energy does go into vibration
  }
}

// Energy loss grows with the damping ratio; the fix's dissipated energy closes the balance
// (relative error below 3e-8 for every ratio; 5e-6 to 7.7e-5, growing with the ratio, when it
// was counted with the half-step velocities the forces take).
TEST_F(FixPeridemWallTest, DampingLossMonotone)
{
  std::vector<double> losses;
  for (const char *damping : {"none", "nodal 0.05", "nodal 0.2", "nodal 0.5", "nodal 1.0"}) {
    delete lmp;
    lmp = make_lammps();
    drop_setup(std::string("Kn 2.5e22 damping ") + damping);
    const Bounce b = bounce();
    const double loss = (b.y0 - b.peak) / (b.y0 - b.ymin);
    const double balance = (equal("etotal") + b.dissipated - b.e0) / b.e0;
    std::printf("[ measure  ] damping %-10s rebound loss %.4f, energy balance %.2e\n", damping,
                loss, balance);
    if (!losses.empty()) EXPECT_GT(loss, losses.back()) << damping;
    EXPECT_LT(std::fabs(balance), 1e-6) << damping;
    losses.push_back(loss);
  }
}

// Settled grain: the floor carries its weight.
TEST_F(FixPeridemWallTest, SettledReactionEqualsWeight)
{
  command(grain(0.0, 1.1e-3));
  command("fix wall all peridem/wall ylo 0.0 Kn 2.5e22 Rc_factor 0.95 spacing 0.15e-3 "
          "damping nodal 1.0\n"
          "fix grav all gravity 1e4 vector 0 -1 0\n"
          "fix calm all viscous 0.5\n" // damps the grain's own vibration
          "run 40000 post no\n"
          "unfix calm\n"
          "run 4000 post no");
  const double weight = mass() * 1e4;
  const double load = wall_entry(2, 2);
  std::printf("[ measure  ] settled: floor load %.6g, weight %.6g, ratio - 1 = %.2e\n", load,
              weight, load / weight - 1.0);
  EXPECT_NEAR(load / weight, 1.0, 0.01);
  EXPECT_NEAR(wall_entry(2, 4), -load, 1e-12 * weight); // floor pushed down
  EXPECT_NEAR(wall_entry(2, 3), 0.0, 1e-3 * weight);
}

// A node moving from single-wall to corner contact: LAMMPS force = core law exactly; no jump
// at the switch d_x^2 + d_y^2 = R_c^2; the reactions are the opposite of the node force.
TEST_F(FixPeridemWallTest, CornerForceContinuous2D)
{
  single_nodes(2, {"1.0 0.6 0.0"}, "xlo 0.0 ylo 0.0");
  const double xs = 0.8; // switch: xs^2 + 0.6^2 = R_c^2
  auto force_at = [&](double x, double f[3]) {
    move_node(x);
    const peridem::WallContactResult r = core_force(2);
    for (int k = 0; k < 3; k++) f[k] = lmp->atom->f[0][k];
    for (int k = 0; k < 2; k++) EXPECT_NEAR(f[k], r.f[k], 1e-13) << "x = " << x;
    for (int k = 0; k < 2; k++)
      EXPECT_NEAR(wall_entry(0, 3 + k) + wall_entry(2, 3 + k), -f[k], 1e-13) << "x = " << x;
  };
  double fa[3], fb[3], worst = 0.0;
  for (double x = 1.2; x > 0.3; x -= 0.01) force_at(x, fa);
  // across the switch: the force changes by no more than its slope times the step
  for (double h : {1e-3, 1e-6, 1e-9}) {
    force_at(xs + h, fa);
    force_at(xs - h, fb);
    const double jump = std::hypot(fa[0] - fb[0], fa[1] - fb[1]);
    worst = std::max(worst, jump / (2 * h));
    EXPECT_LT(jump, 10.0 * 2 * h) << "step " << h;
  }
  std::printf("[ measure  ] 2D corner switch: |dF|/dx across the switch <= %.3g\n", worst);
}

// The same in 3D across an edge -> corner switch.
TEST_F(FixPeridemWallTest, CornerForceContinuous3D)
{
  single_nodes(3, {"1.0 0.5 0.6"}, "xlo 0.0 ylo 0.0 zlo 0.0");
  // switch where the x wall starts to matter for the y-z edge: x^2 + 0.5^2 + 0.6^2 = 1
  const double xs = std::sqrt(1.0 - 0.25 - 0.36);
  std::vector<double> fs;
  for (double h : {1e-4, -1e-4, 1e-8, -1e-8}) {
    move_node(xs + h);
    const peridem::WallContactResult r = core_force(3);
    for (int k = 0; k < 3; k++) {
      EXPECT_NEAR(lmp->atom->f[0][k], r.f[k], 1e-13);
      fs.push_back(lmp->atom->f[0][k]);
    }
  }
  for (int k = 0; k < 3; k++) {
    EXPECT_LT(std::fabs(fs[k] - fs[3 + k]), 10 * 2e-4);
    EXPECT_LT(std::fabs(fs[6 + k] - fs[9 + k]), 10 * 2e-8);
  }
}

// Servo: the top wall finds the target pressure; the floor carries the same load.
TEST_F(FixPeridemWallTest, ServoHoldsPressure)
{
  const double P = 2.0e4; // force per length (2D); wall length = box width 6 mm
  command(grain(0.0, 1.1e-3));
  command("fix wall all peridem/wall ylo 0.0 yhi 2.3e-3 servo yhi 2.0e4 2.0e-4 0.5 "
          "Kn 2.5e22 Rc_factor 0.95 spacing 0.15e-3 damping nodal 1.0\n"
          "fix calm all viscous 0.5\n"
          "run 40000 post no");
  const double target = P * 6e-3;
  const double top = wall_entry(3, 2), floor = wall_entry(2, 2);
  std::printf("[ measure  ] servo: top load %.6g, target %.6g, floor %.6g, top at %.6g, "
              "speed %.3g\n",
              top, target, floor, wall_entry(3, 0), wall_entry(3, 1));
  EXPECT_NEAR(top / target, 1.0, 0.01);
  EXPECT_NEAR(floor / target, 1.0, 0.01);
}

// Walls at constant velocity and from an equal-style variable: positions and velocities.
TEST_F(FixPeridemWallTest, MovingWalls)
{
  command(grain(0.0, 1.1e-3));
  command("variable top equal 6e-3-2.0*step*dt\n"
          "fix wall all peridem/wall ylo 0.0 yhi v_top xhi 2.5e-3 velocity xhi -3.0 "
          "Kn 2.5e22 Rc_factor 0.95 spacing 0.15e-3\n"
          "run 100 post no");
  const double t = 100 * 2.5e-8;
  EXPECT_NEAR(wall_entry(3, 0), 6e-3 - 2.0 * t, 1e-15);
  EXPECT_NEAR(wall_entry(3, 1), -2.0, 1e-6);
  EXPECT_NEAR(wall_entry(1, 0), 2.5e-3 - 3.0 * t, 1e-15);
  EXPECT_DOUBLE_EQ(wall_entry(1, 1), -3.0);
  EXPECT_EQ(wall_entry(2, 1), 0.0);
}

// A sheared floor drags a resting grain along through friction.
TEST_F(FixPeridemWallTest, ShearDragsGrain)
{
  command(grain(0.0, 1.1e-3));
  command("fix wall all peridem/wall ylo 0.0 shear ylo 0.5 0 0 Kn 2.5e22 Rc_factor 0.95 "
          "spacing 0.15e-3 damping nodal 1.0 friction regularized 0.5\n"
          "fix grav all gravity 1e4 vector 0 -1 0\n"
          "variable vx equal vcm(all,x)\n"
          "run 8000 post no");
  const double vx = equal("vcm(all,x)");
  std::printf("[ measure  ] sheared floor at 0.5: grain vx = %.4g, floor fx = %.4g\n", vx,
              wall_entry(2, 3));
  EXPECT_GT(vx, 0.05);
  EXPECT_LE(vx, 0.5 + 1e-9);
  EXPECT_LT(wall_entry(2, 3), 0.0); // the grain holds the floor back
}

// The friction of a sheared floor on a sliding block is mu N: a
// square block rests on a floor that slides at 0.5 m/s; while the whole
// contact slips, the tangential wall force is mu times the normal load
// (Bhattacharya & Lipton 2023, eq. 4.3, no damping), for two values of mu, and drags the block
// along.
TEST_F(FixPeridemWallTest, ShearFrictionIsMuTimesLoad)
{
  for (double mu : {0.5, 0.2}) {
    std::string setup = grain(0.0, 0.0);
    const std::string disk = "region          grain sphere 0 0 0 1.0e-3 units box";
    const size_t at = setup.find(disk);
    ASSERT_NE(at, std::string::npos);
    setup.replace(at, disk.size(),
                  "region          grain block -0.5e-3 0.5e-3 0.1e-3 1.1e-3 -1e-4 1e-4 units box");
    command("clear");
    command(setup);
    // bottom nodes at y = 0.15 mm, 0.14 mm from the floor: inside R_c = 0.1425 mm
    command("fix wall all peridem/wall ylo 0.01e-3 shear ylo 0.5 0 0 Kn 2.5e22 Rc_factor 0.95 "
            "spacing 0.15e-3 friction regularized " +
            std::to_string(mu) +
            "\nfix grav all gravity 1e4 vector 0 -1 0\n"
            "run 1000 post no");
    const double load = wall_entry(2, 2), fx = wall_entry(2, 3);
    std::printf("[ measure  ] mu %.2g: floor load %.6g, floor fx %.6g, ratio %.12g\n", mu, load, fx,
                -fx / load);
    ASSERT_GT(load, 0.0);
    EXPECT_NEAR(-fx / load, mu, 1e-9 * mu);
    EXPECT_GT(equal("vcm(all,x)"), 0.0);
  }
}

// Servo and moving wall state goes through write_restart/read_restart.
TEST_F(FixPeridemWallTest, RestartKeepsWallState)
{
  const std::string walls = "fix wall all peridem/wall ylo 0.0 yhi 2.3e-3 servo yhi 2.0e4 "
                            "2.0e-4 0.5 xhi 2.8e-3 velocity xhi -1.0 Kn 2.5e22 Rc_factor 0.95 "
                            "spacing 0.15e-3 damping nodal 1.0";
  command(grain(0.0, 1.1e-3));
  command(walls + "\nrun 14000 post no"); // the servo wall is in contact by now
  ASSERT_GT(wall_entry(3, 2), 1.0);
  const std::string file = scratch() + "wall.restart";
  command("write_restart " + file + "\nrun 2000 post no");
  const double top = wall_entry(3, 0), vtop = wall_entry(3, 1), side = wall_entry(1, 0);

  delete lmp;
  lmp = make_lammps();
  command("read_restart " + file + "\nbond_style peridem\nbond_coeff 1 material " + POT +
          " M1\nspecial_bonds lj/coul 0.0 1.0 1.0\npair_style zero 0.7e-3\npair_coeff * *\n"
          "comm_modify cutoff 1.5e-3\nfix integrate all nve\nfix plane all enforce2d\n"
          "timestep 2.5e-8\n" +
          walls + "\nrun 2000 post no");
  EXPECT_NEAR(wall_entry(3, 0), top, 1e-12 * std::fabs(top));
  EXPECT_NEAR(wall_entry(3, 1), vtop, 1e-6 * std::fabs(vtop) + 1e-12);
  EXPECT_NEAR(wall_entry(1, 0), side, 1e-15);
}

// lost warn: a node past a wall by more than R_c is counted, not silently dropped.
TEST_F(FixPeridemWallTest, LostNodeCounted)
{
  single_nodes(2, {"1.0 1.0 0.0", "-1.5 1.0 0.0"}, "xlo 0.0 lost warn");
  EXPECT_EQ(wall()->compute_vector(6 * 4), 1.0);
}

// In a run the walls act only on the nodes within R_c + 1.5 skin of a wall, listed at
// reneighbouring, at every run's setup and whenever a wall has moved by half the skin. A grain
// squeezed by two moving walls (each travels ~7 skins) against the floor, with a small skin,
// in runs of 20 and 300 steps with LAMMPS's atom sorting on (every 50 steps and at setup):
// the trajectory is the same, to the bit, as with near_list no (every node every step). A
// list that missed a node entering the walls' reach, or kept the indices of the previous run
// after setup sorted the atoms and reset neighbor->ncalls to 0, would change it.
TEST_F(FixPeridemWallTest, NearWallListChangesNothing)
{
  auto squeeze = [&](const std::string &near) {
    command("clear");
    command(grain(0.0, 1.1e-3));
    command("atom_modify sort 50 0.0\nneighbor 0.02e-3 bin\nneigh_modify every 1 delay 0 check "
            "yes\nfix wall all peridem/wall ylo 0.0 yhi 2.2e-3 xhi 1.15e-3 velocity yhi -2.0 "
            "velocity xhi -1.0 Kn 2.5e22 Rc_factor 0.95 spacing 0.15e-3 damping nodal 0.5 "
            "friction regularized 0.5 near_list " +
            near + "\nfix grav all gravity 1e4 vector 0 -1 0");
    // short runs first, the grain moved towards the right wall before each: setup sorts the
    // atoms (new indices) and resets neighbor->ncalls to 0 (no reneighbouring in a run)
    for (int run = 0; run < 4; run++)
      command("displace_atoms all move 0.03e-3 0 0\nrun 20 post no");
    for (int run = 0; run < 10; run++) command("run 300 post no");
    std::vector<double> xs(2 * lmp->atom->natoms, 0.0);
    for (int i = 0; i < lmp->atom->nlocal; i++)
      for (int k = 0; k < 2; k++) xs[2 * (lmp->atom->tag[i] - 1) + k] = lmp->atom->x[i][k];
    return std::make_pair(xs, wall_entry(3, 2)); // positions by tag, top wall load
  };
  const auto listed = squeeze("yes");
  const auto every = squeeze("no");
  double dmax = 0.0;
  for (std::size_t n = 0; n < listed.first.size(); n++)
    dmax = std::max(dmax, std::fabs(listed.first[n] - every.first[n]));
  std::printf("[ measure  ] near-wall list: top load %.6g vs %.6g, largest position "
              "difference %.3g m\n",
              listed.second, every.second, dmax);
  EXPECT_GT(listed.second, 0.0); // the walls do press the grain
  EXPECT_EQ(dmax, 0.0);
  EXPECT_EQ(listed.second, every.second);
}

} // namespace
