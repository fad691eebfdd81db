/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// The nodes of a rank stay in memory grain by grain (fix peridem/bonds,
// peridem_atom_order.h) instead of in LAMMPS's spatial order, unless
// atom_modify sort names a bin size; atom_modify sort 0 0 leaves the order
// alone. Three square grains side by side, so that LAMMPS's spatial sort
// (rows of bins) interleaves them. Run on 1 rank here and on 2 ranks by
// ctest (grains crossing the boundary between the ranks).

#include "lammps_fixture.h"

#include "atom.h"
#include "comm.h"
#include "lammps.h"
#include "library.h"

#include <cmath>
#include <mpi.h>
#include <vector>

using namespace LAMMPS_NS;

namespace {

// the local nodes, in memory order, are in ascending (grain, atom ID) order, on every rank
bool grain_major(LAMMPS *lmp)
{
  const Atom *a = lmp->atom;
  int ok = 1;
  for (int i = 1; i < a->nlocal && ok; i++)
    ok = a->molecule[i - 1] < a->molecule[i] ||
         (a->molecule[i - 1] == a->molecule[i] && a->tag[i - 1] < a->tag[i]);
  int all = 0;
  MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

// the atom IDs of the local nodes in memory order
std::vector<tagint> local_order(LAMMPS *lmp)
{
  return std::vector<tagint>(lmp->atom->tag, lmp->atom->tag + lmp->atom->nlocal);
}

// a per-atom vector of 3 doubles (x, f, ...) of all atoms, by atom ID
std::vector<double> by_id(LAMMPS *lmp, const char *name)
{
  std::vector<double> v(3 * lmp->atom->natoms);
  lammps_gather_atoms(lmp, const_cast<char *>(name), 1, 3, v.data());
  return v;
}

double largest_difference(const std::vector<double> &a, const std::vector<double> &b)
{
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); k++) d = std::max(d, std::fabs(a[k] - b[k]));
  return d;
}

double largest(const std::vector<double> &a)
{
  double m = 0.0;
  for (double v : a) m = std::max(m, std::fabs(v));
  return m;
}

} // namespace

class AtomOrder : public LammpsTest {
 protected:
  // three 11 x 11 node squares at x = -3, 0, 3 (the ranks split the box at x = 0),
  // deformed a little so that the bonds pull
  void build(const std::string &sort)
  {
    command(fmt::format(
        "units lj\ndimension 2\nboundary f f p\nprocessors * 1 1\natom_style peridem\n"
        "atom_modify map array\n{}\nregion box block -6 9 -3 3 -0.5 0.5\n"
        "create_box 1 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 0\n"
        "special_bonds lj/coul 0.0 1.0 1.0\n"
        "create_peridem_grains 1 square side 2 spacing 0.2 horizon 0.6 density 1 at -3 0 0\n"
        "create_peridem_grains 1 square side 2 spacing 0.2 horizon 0.6 density 1 at 0 0 0\n"
        "create_peridem_grains 1 square side 2 spacing 0.2 horizon 0.6 density 1 at 3 0 0\n"
        "displace_atoms all random 0.01 0.01 0 7 units box\n"
        "pair_style zero 0.4\npair_coeff * *\nbond_style peridem\n"
        "bond_coeff * c 50 s0 0.05 horizon 0.60001\nneighbor 0.1 bin\ntimestep 0.005\n"
        "thermo_style custom step ke ebond\nthermo_modify norm no",
        sort));
  }
};

TEST_F(AtomOrder, NodesStayGrainByGrainUnlessTheSortHasABinSize)
{
  // a bin size given to atom_modify sort: LAMMPS's spatial sort, rows of bins across the
  // three grains
  build("atom_modify sort 1000 0.2");
  command("run 0 post no");
  EXPECT_FALSE(grain_major(lmp));
  const std::vector<double> f_space = by_id(lmp, "f");
  const std::vector<tagint> space_order = local_order(lmp);

  // atom_modify sort 0 0: the order stays as it is
  command("atom_modify sort 0 0.0\nrun 0 post no");
  EXPECT_EQ(local_order(lmp), space_order);

  // no bin size: grain by grain again, at the setup of the next run, with the same forces
  // up to the order of the sums
  command("atom_modify sort 1000 0.0\nrun 0 post no");
  EXPECT_TRUE(grain_major(lmp));
  const std::vector<double> f_grain = by_id(lmp, "f");
  EXPECT_GT(largest(f_grain), 1e-3);
  EXPECT_LE(largest_difference(f_grain, f_space), 1e-12 * largest(f_grain));
}

TEST_F(AtomOrder, DefaultKeepsTheOrderOfCreation)
{
  build("");
  const std::vector<tagint> created = local_order(lmp);
  EXPECT_TRUE(grain_major(lmp)); // create_peridem_grains numbers grain by grain
  command("run 0 post no");
  EXPECT_TRUE(grain_major(lmp));
  EXPECT_EQ(local_order(lmp), created);
}

TEST_F(AtomOrder, OrderingAtEveryReneighbouringChangesNoTrajectory)
{
  // the grains move +x (by 1) through the boundary between the ranks (2 ranks): nodes migrate,
  // and the nodes are put in grain order again at every reneighbouring (sort 1), with
  // ghosts present (fix peridem/bonds, pre_exchange); some bonds are cut first, so that
  // the per-node broken counts move with their nodes
  auto trajectory = [this](const std::string &sort) {
    command("clear");
    build(sort);
    command("cut_peridem_bonds all segment 0.1 -2 0.1 0.5\n"
            "velocity all set 2 0 0 sum no units box\n"
            "velocity all create 0.05 3 dist gaussian sum yes\n"
            "neigh_modify every 1 delay 0 check no\nfix 1 all nve\n"
            "compute dmg all peridem/damage\nrun 100 post no");
    std::vector<double> x = by_id(lmp, "x");
    std::vector<double> broken(lmp->atom->natoms);
    lammps_gather(lmp, const_cast<char *>("c_dmg[1]"), 1, 1, broken.data());
    x.insert(x.end(), broken.begin(), broken.end());
    return x;
  };
  const std::vector<double> none = trajectory("atom_modify sort 0 0.0");
  const std::vector<double> grains = trajectory("atom_modify sort 1 0.0");
  EXPECT_TRUE(grain_major(lmp) || lmp->comm->nprocs > 1); // exchange appends arrivals
  EXPECT_LE(largest_difference(none, grains), 1e-10 * largest(none));
}
