/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// pair_style peridem/contact through LAMMPS: forces are
// minus the gradient of the energy (central finite differences), newton_pair
// off gives the forces of newton_pair on, and two MPI ranks give the forces
// of one after run 0 (run this binary under mpirun -np 2 for that check).
// Two disk grains touch, and one of them is cut in two so that self-contact
// (same grain, no bond) acts too; positions are perturbed at random.

#include "lammps_fixture.h"

#include "atom.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "lammps.h"
#include "pair.h"
#include "register_driver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <mpi.h>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

std::string setup(const std::string &newton, const std::string &self)
{
  return "units lj\ndimension 2\nboundary f f p\nnewton " + newton +
         "\natom_style peridem\natom_modify map array\n"
         "region box block -2 2 -2 2 -0.5 0.5 units box\n"
         "create_box 1 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 60\n"
         "special_bonds lj/coul 0.0 1.0 1.0\ncomm_modify cutoff 0.8\n"
         "create_peridem_grains 1 disk radius 0.5 spacing 0.1 horizon 0.3 density 1 at -0.52 0 0\n"
         "create_peridem_grains 1 disk radius 0.5 spacing 0.1 horizon 0.3 density 1 at 0.51 0.03 "
         "0\n"
         "cut_peridem_bonds all segment -0.47 -0.6 -0.47 0.6\n"
         "bond_style zero\nbond_coeff *\n"
         "displace_atoms all random 0.02 0.02 0 4711 units box\n"
         "pair_style peridem/contact self " +
         self + "\npair_coeff * * Kn 1e4 Rc 0.12\nthermo_style custom step evdwl\nrun 0\n";
}

void run_lines(LAMMPS *lmp, const std::string &text)
{
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string one = text.substr(start, end - start);
    if (!one.empty()) lmp->input->one(one);
    start = end + 1;
  }
}

// forces of the owned atoms by atom ID
std::map<tagint, std::array<double, 2>> forces(LAMMPS *lmp)
{
  std::map<tagint, std::array<double, 2>> out;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    out[lmp->atom->tag[i]] = {lmp->atom->f[i][0], lmp->atom->f[i][1]};
  return out;
}

double max_force(const std::map<tagint, std::array<double, 2>> &f)
{
  double m = 0.0;
  for (const auto &[t, v] : f) m = std::max({m, std::fabs(v[0]), std::fabs(v[1])});
  return m;
}

// A disk grain (73 nodes) cut through its middle by cut_peridem_bonds: two pieces of one grain,
// held together by their own bonds, thrown at each other at relative speed 2
const double kThrownRc = 0.095;
std::string thrown_halves(const std::string &self)
{
  return "units lj\ndimension 2\nboundary f f p\natom_style peridem\natom_modify map array\n"
         "comm_modify vel yes\nregion box block -2 2 -2 2 -0.5 0.5 units box\n"
         "create_box 1 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 60\n"
         "special_bonds lj/coul 0.0 1.0 1.0\n"
         "create_peridem_grains 1 disk radius 0.5 spacing 0.1 horizon 0.3 density 1 at 0 0 0\n"
         "bond_style peridem break off\nbond_coeff 1 E 1000 Gc 1 horizon 0.3\n"
         "cut_peridem_bonds all segment 0.05 -0.6 0.05 0.6\n"
         "region lhalf block INF 0.05 INF INF INF INF units box\ngroup left region lhalf\n"
         "group right subtract all left\npair_style peridem/contact self " +
         self + "\npair_coeff * * Kn $(18*1000/(PI*0.3^5)) Rc " + std::to_string(kThrownRc) +
         "\nvelocity left set 1 0 0 units box\nvelocity right set -1 0 0 units box\n"
         "fix integrate all nve\nfix plane all enforce2d\ntimestep 0.0004\nrun 0\n";
}

// the smallest distance between a node of group a and a node of group b, on all ranks
double min_distance(LAMMPS *lmp, const char *a, const char *b)
{
  const int ma = lmp->group->bitmask[lmp->group->find(a)];
  const int mb = lmp->group->bitmask[lmp->group->find(b)];
  std::vector<double> mine; // x, y, 0 (a) or 1 (b)
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const int m = lmp->atom->mask[i];
    if (m & (ma | mb))
      mine.insert(mine.end(), {lmp->atom->x[i][0], lmp->atom->x[i][1], (m & ma) ? 0.0 : 1.0});
  }
  int nprocs = 1, n = static_cast<int>(mine.size());
  MPI_Comm_size(lmp->world, &nprocs);
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp->world);
  for (int p = 1; p < nprocs; p++) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 lmp->world);
  double best = INFINITY;
  for (size_t i = 0; i < all.size(); i += 3)
    for (size_t j = 0; j < all.size(); j += 3)
      if (all[i + 2] == 0.0 && all[j + 2] == 1.0)
        best = std::min(best, std::hypot(all[i] - all[j], all[i + 1] - all[j + 1]));
  return best;
}

class PairPeridemContactTest : public LammpsTest,
                               public ::testing::WithParamInterface<const char *> {
 protected:
  double energy()
  {
    command("run 0");
    return lmp->force->pair->eng_vdwl;
  }
};

} // namespace

// forces = -dE/dx, with newton_pair on and off
TEST_P(PairPeridemContactTest, ForcesAreMinusEnergyGradient)
{
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  if (nprocs > 1) GTEST_SKIP() << "finite differences on one rank";
  command(setup(GetParam(), "yes"));
  const auto f = forces(lmp);
  const double fmax = max_force(f);
  ASSERT_GT(fmax, 0.0) << "no contact force: the test would check nothing";
  // the atoms with the largest forces, and every tenth atom (zero forces too)
  std::vector<std::pair<double, tagint>> order;
  for (const auto &[t, v] : f) order.push_back({std::hypot(v[0], v[1]), t});
  std::sort(order.rbegin(), order.rend());
  std::vector<tagint> picked;
  for (size_t k = 0; k < order.size(); k++)
    if (k < 12 || k % 10 == 0) picked.push_back(order[k].second);
  const double h = 1e-6;
  int checked_nonzero = 0;
  for (tagint t : picked) {
    for (int d = 0; d < 2; d++) {
      const int i = lmp->atom->map(t);
      const double x0 = lmp->atom->x[i][d];
      lmp->atom->x[lmp->atom->map(t)][d] = x0 + h;
      const double ep = energy();
      lmp->atom->x[lmp->atom->map(t)][d] = x0 - h;
      const double em = energy();
      lmp->atom->x[lmp->atom->map(t)][d] = x0;
      const double fd = -(ep - em) / (2.0 * h);
      EXPECT_NEAR(f.at(t)[d], fd, 1e-6 * fmax) << "atom " << t << " direction " << d;
      if (std::fabs(fd) > 1e-3 * fmax) checked_nonzero++;
    }
  }
  EXPECT_GT(checked_nonzero, 10);
}

INSTANTIATE_TEST_SUITE_P(Newton, PairPeridemContactTest, ::testing::Values("on", "off"));

// self-contact acts in the configuration of the finite differences (it adds energy), and it
// keeps the pieces of a cut grain apart: the thrown halves come no closer than 0.8 R_c with it
// (smallest distance over 500 steps, every 5th step: 0.85 R_c measured) and pass through each
// other without it (nodes of the two lattices meet: 1e-15 measured)
TEST_F(LammpsTest, PairPeridemContactSelfContactActs)
{
  command(setup("on", "yes"));
  const double with_self = lmp->force->pair->eng_vdwl;
  command("pair_style peridem/contact self no\npair_coeff * * Kn 1e4 Rc 0.12\nrun 0");
  const double without = lmp->force->pair->eng_vdwl;
  double all[2], local[2] = {with_self, without};
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(all[0], 1.0001 * all[1]);
  EXPECT_GT(all[1], 0.0);

  std::map<std::string, double> closest;
  for (const char *self : {"yes", "no"}) {
    command("clear");
    command(thrown_halves(self));
    double d = min_distance(lmp, "left", "right");
    for (int k = 0; k < 100; k++) {
      command("run 5 pre no post no");
      d = std::min(d, min_distance(lmp, "left", "right"));
    }
    closest[self] = d / kThrownRc;
  }
  std::printf("smallest distance between the halves / R_c: self yes %.4g, self no %.4g\n",
              closest["yes"], closest["no"]);
  EXPECT_GT(closest["yes"], 0.8);
  EXPECT_LT(closest["no"], 0.1);
}

// newton_pair off: the same forces as newton_pair on
TEST_F(LammpsTest, PairPeridemContactNewtonOffMatchesOn)
{
  command(setup("on", "yes"));
  const auto on = forces(lmp);
  command("clear");
  command(setup("off", "yes"));
  const auto off = forces(lmp);
  ASSERT_EQ(on.size(), off.size());
  const double fmax = max_force(on);
  for (const auto &[t, v] : on)
    for (int d = 0; d < 2; d++) EXPECT_NEAR(off.at(t)[d], v[d], 1e-12 * fmax) << "atom " << t;
}

// all ranks: the forces of a one-rank run (MPI_COMM_SELF) on every rank
TEST_F(LammpsTest, PairPeridemContactRanksMatchOneRank)
{
  for (const char *newton : {"on", "off"}) {
    std::vector<std::string> args = {"ref", "-log", "none", "-echo", "none", "-screen", "none"};
    std::vector<char *> argv;
    for (auto &a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    auto *ref = new LAMMPS(static_cast<int>(args.size()), argv.data(), MPI_COMM_SELF);
    peridem_register(ref);
    run_lines(ref, setup(newton, "yes"));
    const auto f1 = forces(ref);
    delete ref;

    command("clear");
    command(setup(newton, "yes"));
    const auto fn = forces(lmp);
    const double fmax = max_force(f1);
    ASSERT_GT(fmax, 0.0);
    for (const auto &[t, v] : fn)
      for (int d = 0; d < 2; d++)
        EXPECT_NEAR(v[d], f1.at(t)[d], 1e-12 * fmax) << "atom " << t << " newton " << newton;
    long n = static_cast<long>(fn.size()), total = 0;
    MPI_Allreduce(&n, &total, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(total, static_cast<long>(f1.size()));
  }
}

// rerun sets up every snapshot (each one builds the neighbour list anew): the pair style's
// copy of the list (copy_neighbour_pairs) follows it. After a run with the grains apart,
// snapshot 1 has them apart, snapshot 2 touching: its contact forces are those of a plain
// run in that configuration (a copy kept from the run or snapshot 1 misses those pairs).
TEST_F(LammpsTest, PairPeridemContactRerunSeesThePairsOfEverySnapshot)
{
  int nprocs = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &nprocs);
  if (nprocs > 1) GTEST_SKIP() << "forces compared by atom on one rank";
  const std::string apart = scratch() + "apart.dump", touching = scratch() + "touching.dump",
                    fdump = scratch() + "forces.dump";
  command(setup("on", "yes"));
  const auto f_touching = forces(lmp);
  ASSERT_GT(max_force(f_touching), 0.0);
  command("reset_timestep 2\nwrite_dump all custom " + touching +
          " id x y modify format float %.17g\n"
          "group right molecule 2\ndisplace_atoms right move 0.8 0 0 units box\n"
          "reset_timestep 1\nwrite_dump all custom " +
          apart + " id x y modify format float %.17g");
  {
    std::ofstream out(apart, std::ios::app);
    std::ifstream in(touching);
    out << in.rdbuf();
  }
  command("run 0 post no"); // the pair style's last list: the grains apart
  command("dump f all custom 1 " + fdump + " id fx fy\ndump_modify f sort id format float %.17g");
  command("rerun " + apart + " dump x y");
  command("undump f");

  const auto rerun_f = read_dump_pairs(fdump, 2);
  ASSERT_EQ(rerun_f.size(), f_touching.size());
  const double fmax = max_force(f_touching);
  for (const auto &[t, v] : f_touching)
    for (int d = 0; d < 2; d++) EXPECT_NEAR(rerun_f.at(t)[d], v[d], 1e-9 * fmax) << "atom " << t;
}
