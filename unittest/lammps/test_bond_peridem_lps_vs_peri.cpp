/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// bond_style peridem/lps against LAMMPS's own pair_style peri/lps on the same
// nodes with the same constants (K, G, s0 with alpha = 0, horizon, influence
// 1/r, the linear partial-volume ramp). peri/lps works with force, energy
// and mass densities: its force and energy equal ours divided by the node
// volume (all volumes equal here), and the trajectories are the same.

#include "lammps_fixture.h"
#include "peri_compare.h"

#include "atom.h"
#include "bond_peridem_lps.h"
#include "force.h"
#include "lammps.h"
#include "library.h"

#include <array>
#include <cmath>
#include <map>

using namespace LAMMPS_NS;

namespace {

constexpr double VOLUME = 1.25e-10, DENSITY = 2200.0;

// the target of LAMMPS's examples/peri/in.peri.lps (or a cube), either style;
// K and G differ (the example has K = G) so that both terms are checked
std::string setup(bool stock, const std::string &region)
{
  std::string s = fmt::format("units si\nboundary s s s\natom_style {}\natom_modify map array\n"
                              "neighbor 0.0010 bin\nlattice sc 0.0005\n{}\n",
                              stock ? "peri" : "peridem", region);
  if (stock)
    return s + "create_box 1 target\ncreate_atoms 1 region target\n"
               "pair_style peri/lps\npair_coeff * * 14.9e9 8.1e9 0.0015001 0.0005 0.0\n"
               "set group all density 2200\nset group all volume 1.25e-10\n";
  return s + fmt::format("create_box 1 target bond/types 1 extra/bond/per/atom 70 "
                         "extra/special/per/atom 140\ncreate_atoms 1 region target\n"
                         "set type 1 mol 1\nset group all volume {}\nset group all mass {}\n"
                         "pair_style zero 0.0016\npair_coeff * *\n"
                         "special_bonds lj/coul 0.0 1.0 1.0\n"
                         "bond_style peridem/lps volume_correction linear break_order after_force\n"
                         "bond_coeff 1 K 14.9e9 G 8.1e9 s0 0.0005 horizon 0.0015001 "
                         "influence inverse\n"
                         "create_bonds many all all 1 0.0 0.0015001\npair_style none\n",
                         VOLUME, DENSITY * VOLUME);
}

} // namespace

class BondPeridemLPSVsPeriLPS : public ::testing::Test {
 protected:
  void TearDown() override
  {
    delete stock;
    delete ours;
  }
  LAMMPS *stock = nullptr, *ours = nullptr;
};

TEST_F(BondPeridemLPSVsPeriLPS, ForcesAndEnergyOfADeformedBlockAgree)
{
  const std::string cube = "region target block -0.003 0.003 -0.003 0.003 -0.003 0.003 units box";
  // peri/lps takes its reference from the positions at its first run
  const std::string deform = "displace_atoms all random 1e-7 1e-7 1e-7 87287 units box\n"
                             "thermo_style custom step pe\nrun 0";
  stock = make_lammps();
  lammps_commands_string(stock, (setup(true, cube) + "run 0\n" + deform).c_str());
  ours = make_lammps();
  lammps_commands_string(ours, (setup(false, cube) + deform).c_str());

  peri_compare::expect_same_forces(stock, ours, VOLUME, 2197);

  // Energy density: peri/lps tallies K theta^2/2 per node and, per ordered
  // pair, ev_tally(i, i, ..., 0.5 * evdwl) with newton off, i.e. half of
  // 15G/(2m) omega (e^d)^2 V_j: its deviatoric energy is half of W's
  // (Jha et al. 2021, eq. 8; ours is checked against the forces by finite
  // differences in test_bond_peridem_lps). With the volumetric part from
  // our dilations, ours = vol + 2 (stock - vol).
  const double pe_stock = lammps_get_thermo(stock, "pe");
  const double pe_ours = lammps_get_thermo(ours, "pe") / VOLUME;
  const double *theta = dynamic_cast<BondPeridemLPS *>(ours->force->bond)->dilation();
  double vol = 0.0;
  for (int i = 0; i < ours->atom->nlocal; i++) vol += 0.5 * 14.9e9 * theta[i] * theta[i];
  std::printf("  energy density: peri/lps %.12e, ours %.12e, volumetric %.6e\n", pe_stock, pe_ours,
              vol);
  EXPECT_GT(vol, 1e-3 * pe_ours);
  EXPECT_NEAR(pe_ours, vol + 2.0 * (pe_stock - vol), 1e-10 * pe_ours);
}

TEST_F(BondPeridemLPSVsPeriLPS, ImpactBreaksTheSameBonds)
{
  // in.peri.lps with the indenter at 20 m/s instead of 100 m/s: peri/lps's
  // own short-range contact (nodes closer than 0.9 of their reference
  // distance) stays inactive, so both codes solve the same equations. Our
  // indenter stiffness is peri's times the node volume (force, not force
  // density).
  // (target radius 3 mm instead of 5 mm: 1243 nodes, a third of the run time)
  const std::string cyl = "region target cylinder y 0.0 0.0 0.0030 -0.0050 0.0 units box";
  const std::string run = "velocity all set 0.0 0.0 0.0 sum no units box\nfix 1 all nve\n"
                          "variable y equal 0.00155-step*dt*20\n"
                          "fix 2 all indent {} sphere 0.0 v_y 0.0 0.0015 units box\n"
                          "timestep 1.0e-7\nthermo 1000\n{}\nrun 1000\n";
  stock = make_lammps();
  lammps_commands_string(
      stock, (setup(true, cyl) + fmt::format(run, 1e17, "compute dmg all damage/atom")).c_str());
  ours = make_lammps();
  lammps_commands_string(
      ours, (setup(false, cyl) + fmt::format(run, 1e17 * VOLUME, "compute dmg all peridem/damage"))
                .c_str());

  peri_compare::expect_same_impact(stock, ours, 1243, 100.0);
}
