/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// bond_style peridem/lps through LAMMPS: forces are minus the gradient of the
// energy (central finite differences), and the patch test: an affine
// deformation of a lattice block leaves the nodes two horizons inside
// force-free, and their virial stress is linear elasticity's for K and G
// (3D, 2D plane strain and plane stress; Poisson ratios 0.1 and 0.35).

#include "lammps_fixture.h"

#include "atom.h"
#include "bond.h"
#include "force.h"
#include "peridem_bond_law.h"
#include "bond_loop_check.h"
#include "lammps.h"
#include "library.h"
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

namespace {

constexpr double H = 1.0e-3; // lattice spacing

// a block of n^dim nodes with bonds to every node within nh spacings
std::string block(int dim, int n, double nh, const std::string &style, const std::string &coeff,
                  int bond_types = 1)
{
  const double eps = nh * H * (1.0 + 1e-6);
  const double vol = dim == 3 ? H * H * H : H * H;
  std::string s = fmt::format("units si\ndimension {}\nboundary s s {}\natom_style peridem\n"
                              "atom_modify map array\nlattice {} {}\n",
                              dim, dim == 3 ? "s" : "p", dim == 3 ? "sc" : "sq", H);
  s += fmt::format("region b block 0 {} 0 {} {}\n", n - 1e-3, n - 1e-3,
                   dim == 3 ? fmt::format("0 {}", n - 1e-3) : std::string("-0.5 0.5"));
  s += fmt::format("create_box 1 b bond/types {} extra/bond/per/atom 300 "
                   "extra/special/per/atom 300\ncreate_atoms 1 region b\n"
                   "set type 1 mol 1\nset group all volume {}\nset group all mass {}\n"
                   "pair_style zero {}\npair_coeff * *\nspecial_bonds lj/coul 0.0 1.0 1.0\n"
                   "bond_style {}\nbond_coeff * {} horizon {}\n"
                   "create_bonds many all all 1 0.0 {}\npair_style none\n"
                   "thermo_style custom step pe\nthermo_modify norm no\n",
                   bond_types, vol, 1000.0 * vol, eps * 1.01, style, coeff, eps, eps);
  return s;
}

double energy(LAMMPS *lmp)
{
  lammps_command(lmp, "run 0 post no");
  return lammps_get_thermo(lmp, "pe");
}

} // namespace

class BondPeridemLPS : public LammpsTest {
 protected:
  // largest relative difference between the forces of a few nodes and
  // -dE/dx by central differences
  double finite_difference_error(int dim)
  {
    lammps_command(lmp, "displace_atoms all random 3e-6 3e-6 3e-6 4711 units box");
    if (dim == 2) lammps_command(lmp, "set group all z 0.0");
    energy(lmp);
    double worst = 0.0, fmax = 0.0;
    const double delta = 1e-9;
    for (tagint tag : {1, 17, 40, 77}) {
      for (int d = 0; d < dim; d++) {
        const int i = lmp->atom->map(tag);
        const double f = lmp->atom->f[i][d];
        double *x = lmp->atom->x[lmp->atom->map(tag)];
        const double x0 = x[d];
        x[d] = x0 + delta;
        const double ep = energy(lmp);
        x = lmp->atom->x[lmp->atom->map(tag)];
        x[d] = x0 - delta;
        const double em = energy(lmp);
        x = lmp->atom->x[lmp->atom->map(tag)];
        x[d] = x0;
        energy(lmp);
        const double fd = -(ep - em) / (2.0 * delta);
        fmax = std::max(fmax, std::fabs(f));
        worst = std::max(worst, std::fabs(f - fd));
      }
    }
    std::printf("  finite differences: largest |F + dE/dx| %.3e of max |F| %.3e\n", worst, fmax);
    EXPECT_GT(fmax, 1e-3);
    return worst / fmax;
  }

  struct Patch {
    double force_ratio;  // largest interior |f| over largest |f| of any node
    double stress_error; // largest |sigma - sigma_elastic| over |sigma_elastic|
  };

  // affine u = E x of a block of n^dim nodes; interior: nodes 2 horizons
  // (plus a spacing) inside
  Patch patch(int dim, int n, double nh, double lambda, double G)
  {
    const double E[3][3] = {
        {1.0e-6, 0.4e-6, -0.2e-6}, {0.4e-6, -0.5e-6, 0.3e-6}, {-0.2e-6, 0.3e-6, 0.7e-6}};
    auto comp = [&](int a) {
      std::string s;
      for (int b = 0; b < dim; b++)
        s += fmt::format("{}{:.17g}*{}", b ? "+" : "", E[a][b], "xyz"[b]);
      return s;
    };
    command(fmt::format("variable ux atom {}\nvariable uy atom {}\nvariable uz atom {}", comp(0),
                        comp(1), dim == 3 ? comp(2) : std::string("0.0")));
    command("displace_atoms all move v_ux v_uy v_uz units box");
    command("compute s all stress/atom NULL bond");
    command("run 0 post no");
    double *const *stress = static_cast<double **>(lammps_extract_compute(lmp, "s", 1, 2));
    const double lo = (2.0 * nh + 1.0) * H, hi = (n - 1) * H - lo;
    double fint = 0.0, fall = 0.0, sum[6] = {0, 0, 0, 0, 0, 0};
    int count = 0;
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      const double *x0 = lmp->atom->x0[i];
      const double *f = lmp->atom->f[i];
      const double fn = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
      fall = std::max(fall, fn);
      bool inside = true;
      for (int d = 0; d < dim; d++) inside = inside && x0[d] >= lo - 1e-9 && x0[d] <= hi + 1e-9;
      if (!inside) continue;
      fint = std::max(fint, fn);
      for (int k = 0; k < 6; k++) sum[k] += stress[i][k];
      count++;
    }
    EXPECT_GT(count, 0);
    const double vol = dim == 3 ? H * H * H : H * H;
    double tr = 0.0;
    for (int a = 0; a < dim; a++) tr += E[a][a];
    // LAMMPS's per-atom order xx yy zz xy xz yz
    const int ab[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
    double err = 0.0, norm = 0.0;
    for (int k = 0; k < 6; k++) {
      const int a = ab[k][0], b = ab[k][1];
      if (a >= dim || b >= dim) continue;
      const double ref = (a == b ? lambda * tr : 0.0) + 2.0 * G * E[a][b];
      const double got = sum[k] / (count * vol);
      err = std::max(err, std::fabs(got - ref));
      norm = std::max(norm, std::fabs(ref));
    }
    std::printf("  %dd, horizon %g h, %d interior nodes: interior |f| / max |f| %.2e, "
                "stress error %.4f\n",
                dim, nh, count, fint / fall, err / norm);
    return {fint / fall, err / norm};
  }
};

TEST_F(BondPeridemLPS, ForcesAreMinusTheEnergyGradient3D)
{
  command(block(3, 6, 2.0, "peridem/lps volume_correction linear",
                "K 2e9 G 1.1e9 s0 1.0 influence conic"));
  EXPECT_LT(finite_difference_error(3), 1e-6);
}

TEST_F(BondPeridemLPS, ForcesAreMinusTheEnergyGradient2DPlaneStress)
{
  command(block(2, 10, 3.0, "peridem/lps plane stress", "K 2e9 G 0.5e9 Gc 1e9 influence constant"));
  EXPECT_LT(finite_difference_error(2), 1e-6);
}

TEST_F(BondPeridemLPS, ForcesAreMinusTheEnergyGradient2DThreeDConstants)
{
  command(block(2, 10, 3.0, "peridem/lps plane 3d volume_correction linear",
                "K 2e9 G 0.5e9 s0 1.0 influence inverse"));
  EXPECT_LT(finite_difference_error(2), 1e-6);
}

// the patch test: discretisation error of the stress falls with the horizon
// in lattice spacings (measured values in doc/bond_peridem_lps.rst)
TEST_F(BondPeridemLPS, PatchTest3D)
{
  const double K = 2.0e9;
  for (double nu : {0.1, 0.35}) {
    const double G = 3.0 * K * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
    const double lambda = K - 2.0 * G / 3.0;
    double previous = 1.0;
    for (double nh : {2.0, 3.0}) {
      TearDown();
      SetUp();
      command(block(3, int(4 * nh) + 4, nh, "peridem/lps",
                    fmt::format("K {} G {} s0 1.0 influence conic", K, G)));
      const Patch p = patch(3, int(4 * nh) + 4, nh, lambda, G);
      // round-off: the extension r - r0 of a 1e-6 strain keeps ~10 digits
      EXPECT_LT(p.force_ratio, 1e-9);
      EXPECT_LT(p.stress_error, previous);
      previous = p.stress_error;
    }
    EXPECT_LT(previous, 0.01); // measured 0.0024 (nu 0.1), 0.0011 (nu 0.35)
  }
}

TEST_F(BondPeridemLPS, PatchTest2D)
{
  const double K = 2.0e9;
  for (int stress : {0, 1}) {
    for (double nu : {0.1, 0.35}) {
      const double G = 3.0 * K * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
      const double lambda = K - 2.0 * G / 3.0;
      const double lam = stress ? 2.0 * lambda * G / (lambda + 2.0 * G) : lambda;
      double previous = 1.0;
      for (double nh : {2.0, 4.0, 6.0}) {
        TearDown();
        SetUp();
        command(block(2, int(4 * nh) + 4, nh,
                      fmt::format("peridem/lps plane {}", stress ? "stress" : "strain"),
                      fmt::format("K {} G {} s0 1.0 influence conic", K, G)));
        const Patch p = patch(2, int(4 * nh) + 4, nh, lam, G);
        EXPECT_LT(p.force_ratio, 1e-9);
        EXPECT_LT(p.stress_error, previous);
        previous = p.stress_error;
      }
      EXPECT_LT(previous, 0.01); // measured 0.0047-0.0071
    }
  }
}

// bond_coeff N material FILE NAME with Gc or s0: the command's value overrides the file's Gc
// (s0: a critical stretch from a strength, examples/sheared-fault), in both bond styles
TEST_F(BondPeridemLPS, MaterialCriticalStretchOverride)
{
  const std::string file =
      std::string(PERIDEM_SOURCE_DIR) + "/potentials/granite_kiiskinen2017.peridem";
  const double K = 50e9 / (3.0 * (1.0 - 2.0 * 0.22)), G = 50e9 / (2.0 * 1.22),
               eps = 3.0e-3 * (1.0 + 1e-6);
  struct Case {
    const char *style, *extra;
    double s0;
  };
  const Case cases[] = {
      {"peridem/lps", "", peridem::lps_critical_stretch(K, G, 43.0, eps)},
      {"peridem/lps", " Gc 500", peridem::lps_critical_stretch(K, G, 500.0, eps)},
      {"peridem/lps", " s0 0.0056", 0.0056},
      {"peridem", " s0 0.0056", 0.0056},
  };
  for (const Case &c : cases) {
    TearDown();
    SetUp();
    command(block(2, 4, 3.0, c.style, std::string("material ") + file + " granite" + c.extra));
    int dim = 0;
    const double *s0 = static_cast<double *>(lmp->force->bond->extract("s0", dim));
    ASSERT_NE(s0, nullptr);
    std::printf("  %s%s: s0 = %.10g\n", c.style, c.extra, s0[1]);
    EXPECT_NEAR(s0[1], c.s0, 1e-12 * c.s0);
  }
}

// bond_coeff ... break no: a stretch far beyond s0 breaks no bond of that
// type (both bond styles), and write_data keeps the setting
TEST_F(BondPeridemLPS, UnbreakableBondTypes)
{
  for (const char *style : {"peridem", "peridem/lps"}) {
    const std::string coeff =
        std::string(style) == "peridem" ? "c 1e20 s0 1e-4" : "K 2e9 G 1e9 s0 1e-4";
    for (int breakable : {1, 0}) {
      TearDown();
      SetUp();
      command(block(3, 5, 1.5, style, coeff + (breakable ? "" : " break no")));
      command("compute dmg all peridem/damage\nthermo_style custom step c_dmg[2]\n"
              "displace_atoms all ramp x -1e-5 1e-5 x 0 0.004 units box\nrun 0 post no");
      const double broken = static_cast<double *>(lammps_extract_compute(lmp, "dmg", 0, 1))[1];
      std::printf("  %s, break %s: %g bonds broken\n", style, breakable ? "yes" : "no", broken);
      if (breakable)
        EXPECT_GT(broken, 100.0);
      else
        EXPECT_EQ(broken, 0.0);
      if (!breakable) {
        command("write_data " + scratch() + "unbreakable.data");
        std::FILE *fp = std::fopen((scratch() + "unbreakable.data").c_str(), "r");
        ASSERT_NE(fp, nullptr);
        char line[512];
        bool found = false;
        while (std::fgets(line, sizeof(line), fp))
          if (std::strstr(line, "break no")) found = true;
        std::fclose(fp);
        EXPECT_TRUE(found);
      }
    }
  }
}

// The force pass of ordinary steps (no energy or virial; in 2d without z) gives the
// same forces, to the bit, as the pass of energy steps, which takes one bond at a time with z
// in every bond. Jittered and sheared 2d and 3d blocks with some bonds stretched past s0, one
// bond type or two (another K, G and s0 on the bonds between nodes with x below the middle),
// and with horizon 4.5 h atoms with more bonds than bond_style peridem's chunk (64), which the
// shared list of pieces splits; the forces come from calling the bond style directly.
TEST_F(BondPeridemLPS, PlainForcePassEqualsOneByOne)
{
  for (const double nh : {3.0, 4.5})
    for (const int types : {1, 2})
      for (const int dim : {2, 3}) {
        if (nh > 3.0 && types == 2) continue;
        auto forces = [&](int eflag) {
          TearDown();
          SetUp();
          const int n = dim == 2 ? 10 : 6;
          command(block(dim, n, nh, "peridem/lps", "K 2e9 G 1e9 s0 2e-3", types));
          if (types == 2) {
            command(fmt::format("bond_coeff 2 K 3e9 G 1.5e9 s0 3e-3 horizon {}",
                                nh * H * (1.0 + 1e-6)));
            command(fmt::format("region left block INF {} INF INF INF INF units box", n * H / 2));
            command("group left region left\nset group left bond 2");
          }
          command("run 0 post no");
          return bond_loop_check::forces_after_shear(lmp, dim, H, eflag);
        };
        const auto one = forces(1), plain = forces(0);
        bond_loop_check::expect_same_bits(one, plain, dim,
                                          nh > 3.0     ? "lps, long runs"
                                          : types == 1 ? "lps"
                                                       : "lps, two types");
        if (nh > 3.0 && dim == 3) EXPECT_GT(bond_loop_check::longest_run(lmp), 64);
      }
}
