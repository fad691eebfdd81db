/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// single() against compute(), on the configuration of the force-style YAML
// tests (unittest/force-styles/tests/data.peridem: two grains, 54 nodes, 370
// bonds, 9 contacts). LAMMPS's drivers check single() on a molecular system
// of their own (atom_style molecular/full), which our styles cannot use
// (they need the volumes, reference positions and grains of atom_style
// peridem), so their `single` tests are skipped and this test does the same
// check on our configuration: for every bond (every pair within the cutoff)
// the energies of single() sum to the style's energy and the forces it
// returns, applied along the pair, add up to the per-atom forces of compute().

#include "lammps_fixture.h"

#include "atom.h"
#include "bond.h"
#include "force.h"
#include "lammps.h"
#include "neigh_list.h"
#include "pair.h"

#include <cmath>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

const std::string kTests = PERIDEM_SOURCE_DIR "/unittest/force-styles/tests";

std::string setup(const std::string &pair_style, const std::string &bond_style)
{
  return "variable input_dir index " + kTests + "\nvariable pair_style index '" + pair_style +
         "'\nvariable bond_style index '" + bond_style + "'\ninclude " + kTests + "/in.peridem\n";
}

double max_abs_force(LAMMPS *lmp)
{
  double m = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    for (int k = 0; k < 3; k++) m = std::max(m, std::fabs(lmp->atom->f[i][k]));
  return m;
}

// adds the energy and central force of single() for the pair i, j: force
// fforce * (x_i - x_j) on i, the opposite on j (LAMMPS's convention)
template <class Single>
double add_single(LAMMPS *lmp, int i, int j, std::vector<double> &f, Single single)
{
  double del[3], rsq = 0.0, fforce = 0.0;
  for (int k = 0; k < 3; k++) {
    del[k] = lmp->atom->x[i][k] - lmp->atom->x[j][k];
    rsq += del[k] * del[k];
  }
  const double e = single(rsq, fforce);
  for (int k = 0; k < 3; k++) {
    f[3 * i + k] += del[k] * fforce;
    f[3 * j + k] -= del[k] * fforce;
  }
  return e;
}

} // namespace

class SingleVsCompute : public LammpsTest,
                        public ::testing::WithParamInterface<std::vector<std::string>> {};

TEST_P(SingleVsCompute, Bond)
{
  const auto &p = GetParam();
  command(setup("none", p[0]));
  command(p[1]);
  command("run 0 post no");
  Bond *bond = lmp->force->bond;
  Atom *atom = lmp->atom;
  const int n = atom->nlocal;
  ASSERT_EQ(n, 54);
  std::vector<double> f(3 * n, 0.0);
  double energy = 0.0;
  int nbonds = 0;
  for (int i = 0; i < n; i++) {
    for (int m = 0; m < atom->num_bond[i]; m++) {
      const int j = atom->map(atom->bond_atom[i][m]);
      const int btype = atom->bond_type[i][m];
      energy += add_single(lmp, i, j, f, [&](double rsq, double &fforce) {
        return bond->single(btype, rsq, i, j, fforce);
      });
      nbonds++;
    }
  }
  ASSERT_EQ(nbonds, 370); // newton_bond on: each bond stored once
  EXPECT_NEAR(energy, bond->energy, 1e-12 * std::fabs(bond->energy));
  const double scale = max_abs_force(lmp);
  ASSERT_GT(scale, 0.0);
  for (int i = 0; i < n; i++)
    for (int k = 0; k < 3; k++)
      EXPECT_NEAR(f[3 * i + k], atom->f[i][k], 1e-12 * scale) << "atom tag " << atom->tag[i];
}

INSTANTIATE_TEST_SUITE_P(
    Styles, SingleVsCompute,
    ::testing::Values(
        std::vector<std::string>{"peridem", "bond_coeff 1 E 1e9 Gc 1000 horizon 2.0001e-3\n"
                                            "bond_coeff 2 E 2e9 Gc 1000 horizon 2.0001e-3 "
                                            "micromodulus conic"},
        std::vector<std::string>{"peridem volume_correction linear",
                                 "bond_coeff 1 c 2.4e20 s0 0.02 horizon 2.0001e-3 spacing 1e-3\n"
                                 "bond_coeff 2 E 2e9 Gc 1000 horizon 2.0001e-3 spacing 1e-3"},
        std::vector<std::string>{"peridem/lps",
                                 "bond_coeff 1 K 1e9 G 6e8 Gc 1000 horizon 2.0001e-3\n"
                                 "bond_coeff 2 K 2e9 G 1e9 Gc 1000 horizon 2.0001e-3 "
                                 "influence inverse"}));

// pair_style peridem/contact without damping and friction: single() gives the
// whole force. (With damping or friction single() returns the normal part of
// the force, damping included; the tangential friction is not a central force
// and has no single() form.)
class PairSingleVsCompute : public LammpsTest {};

TEST_F(PairSingleVsCompute, Repulsion)
{
  command(setup("peridem/contact", "zero"));
  command("bond_coeff *\npair_coeff * * Kn 1.2e23 Rc 0.9e-3\npair_coeff 2 2 Kn 2.4e23 Rc 0.8e-3\n"
          "pair_coeff 1 2 Kn 1.8e23 Rc 0.95e-3\nrun 0 post no");
  Pair *pair = lmp->force->pair;
  Atom *atom = lmp->atom;
  const int n = atom->nlocal;
  std::vector<double> f(3 * n, 0.0);
  double energy = 0.0;
  int contacts = 0;
  NeighList *list = pair->list;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      const double e = add_single(lmp, i, j, f, [&](double rsq, double &fforce) {
        return pair->single(i, j, atom->type[i], atom->type[j], rsq, 1.0, 1.0, fforce);
      });
      if (e != 0.0) contacts++;
      energy += e;
    }
  }
  ASSERT_GT(contacts, 0);
  EXPECT_NEAR(energy, pair->eng_vdwl, 1e-12 * std::fabs(pair->eng_vdwl));
  const double scale = max_abs_force(lmp);
  ASSERT_GT(scale, 0.0);
  for (int i = 0; i < n; i++)
    for (int k = 0; k < 3; k++)
      EXPECT_NEAR(f[3 * i + k], atom->f[i][k], 1e-12 * scale) << "atom tag " << atom->tag[i];
}
