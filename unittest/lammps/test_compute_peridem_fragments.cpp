/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

// compute peridem/fragments against hand classification: grains cut by
// cut_peridem_bonds along straight lines between node rows fall into pieces
// whose nodes are known from their reference positions alone. Grain 1
// straddles the periodic x boundary and is cut along it (both pieces
// straddle it); grain 2 spans the subdomain boundaries of 2, 3 and 4 ranks
// and is cut into 3; grain 3 stays intact. Run on 1 rank here and on 2, 3
// and 4 ranks by ctest (processors * 1 1: the subdomain boundaries cross
// the grains). Newton on and off.

#include "lammps_fixture.h"

#include "atom.h"
#include "lammps.h"
#include "library.h"

#include <mpi.h>

#include <array>
#include <limits>
#include <map>

using namespace LAMMPS_NS;

namespace {

// expected piece of a node from its reference position (the cut lines)
int piece_of(tagint grain, const double *x0)
{
  if (grain == 1) return x0[1] > 0.05 ? 1 : 2; // cut along y = 0.05
  if (grain == 2) return x0[1] < -0.45 ? 3 : (x0[1] < 1.05 ? 4 : 5);
  return 6; // grain 3: intact
}
constexpr int NPIECES = 6;
constexpr double H = 0.1; // node spacing: volume h^2 per node, density 2

struct Pieces {
  std::array<double, NPIECES + 1> nodes{}, mintag{};
};

Pieces classify(LAMMPS *lmp)
{
  Pieces local, all;
  local.mintag.fill(std::numeric_limits<double>::max());
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const int p = piece_of(lmp->atom->molecule[i], lmp->atom->x0[i]);
    local.nodes[p] += 1.0;
    local.mintag[p] = std::min(local.mintag[p], double(lmp->atom->tag[i]));
  }
  MPI_Allreduce(local.nodes.data(), all.nodes.data(), NPIECES + 1, MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  MPI_Allreduce(local.mintag.data(), all.mintag.data(), NPIECES + 1, MPI_DOUBLE, MPI_MIN,
                MPI_COMM_WORLD);
  return all;
}

} // namespace

class ComputePeridemFragments : public LammpsTest,
                                public ::testing::WithParamInterface<const char *> {
 protected:
  void build()
  {
    command(fmt::format(
        "units lj\ndimension 2\nboundary p p p\nnewton on {}\nprocessors * 1 1\n"
        "atom_style peridem\natom_modify map array\nregion box block -5 5 -5 5 -0.5 0.5\n"
        "create_box 1 box bond/types 1 extra/bond/per/atom 40 extra/special/per/atom 0\n"
        "special_bonds lj/coul 0.0 1.0 1.0\n"
        "create_peridem_grains 1 square side 2 spacing {h} horizon {e} density 2 at 4.5 0 0\n"
        "create_peridem_grains 1 square side 4 spacing {h} horizon {e} density 2 at 0 0 0\n"
        "create_peridem_grains 1 disk radius 0.8 spacing {h} horizon {e} density 2 at -3 3 0\n"
        "pair_style zero 0.5\npair_coeff * *\nbond_style zero\nbond_coeff *\n"
        "comm_modify cutoff 1.0",
        GetParam(), fmt::arg("h", H), fmt::arg("e", 3 * H)));
  }
};

TEST_P(ComputePeridemFragments, IntactGrainsAreOneFragmentEach)
{
  build();
  command("compute frag all peridem/fragments\nthermo_style custom step c_frag\nrun 0 post no");
  auto *v = static_cast<double *>(lammps_extract_compute(lmp, "frag", 0, 1));
  EXPECT_EQ(v[0], 3.0);
  EXPECT_EQ(v[1], 3.0);
  EXPECT_EQ(v[2], 0.0);
  auto **a = static_cast<double **>(lammps_extract_compute(lmp, "frag", 0, 2));
  for (int g = 0; g < 3; g++) EXPECT_EQ(a[g][0], 1.0) << "grain " << g + 1;
}

TEST_P(ComputePeridemFragments, CutPiecesAcrossPeriodicAndSubdomainBoundaries)
{
  build();
  // the cuts run between node rows (a cut through a row leaves the row
  // bonded to both sides: one piece)
  command("cut_peridem_bonds all segment 3 0.05 6 0.05\n"
          "cut_peridem_bonds all segment -3 -0.45 3 -0.45 segment -3 1.05 3 1.05\n"
          "compute frag all peridem/fragments\n"
          "compute big all peridem/fragments min nodes 500\n"
          "compute bigvol all peridem/fragments min volume 5.0\n"
          "thermo_style custom step c_frag c_big[2] c_bigvol[2]\nrun 0 post no");
  const Pieces expect = classify(lmp);
  // the lattice of the squares (nodes on the edges): rows of 21 and 41 nodes
  EXPECT_EQ(expect.nodes[1], 10 * 21);
  EXPECT_EQ(expect.nodes[2], 11 * 21);
  EXPECT_EQ(expect.nodes[3], 16 * 41);
  EXPECT_EQ(expect.nodes[4], 15 * 41);
  EXPECT_EQ(expect.nodes[5], 10 * 41);

  auto *v = static_cast<double *>(lammps_extract_compute(lmp, "frag", 0, 1));
  EXPECT_EQ(v[0], 6.0);
  EXPECT_EQ(v[1], 6.0);
  auto **a = static_cast<double **>(lammps_extract_compute(lmp, "frag", 0, 2));
  EXPECT_EQ(a[0][0], 2.0);
  EXPECT_EQ(a[1][0], 3.0);
  EXPECT_EQ(a[2][0], 1.0);

  // size filter: only the 656- and 615-node pieces reach 500 nodes (volume >= 5)
  int passing = 0;
  double debris_volume = 0.0;
  for (int p = 1; p <= NPIECES; p++) {
    if (expect.nodes[p] >= 500)
      passing++;
    else
      debris_volume += expect.nodes[p] * H * H;
  }
  for (const char *id : {"big", "bigvol"}) {
    auto *vb = static_cast<double *>(lammps_extract_compute(lmp, id, 0, 1));
    EXPECT_EQ(vb[0], 6.0) << id;
    EXPECT_EQ(vb[1], passing) << id;
    EXPECT_EQ(vb[2], 6.0 - passing) << id;
    EXPECT_NEAR(vb[3], debris_volume, 1e-9) << id;
    auto **ab = static_cast<double **>(lammps_extract_compute(lmp, id, 0, 2));
    EXPECT_EQ(ab[0][1], 0.0) << id;
    EXPECT_EQ(ab[1][1], 2.0) << id;
    EXPECT_EQ(ab[2][1], 0.0) << id;
  }

  // per node: the fragment ID is the smallest atom ID of its piece
  command("variable f atom c_frag\nrun 0 post no");
  auto *f = static_cast<double *>(lammps_extract_compute(lmp, "frag", 1, 1));
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const int p = piece_of(lmp->atom->molecule[i], lmp->atom->x0[i]);
    ASSERT_EQ(f[i], expect.mintag[p]) << "atom " << lmp->atom->tag[i];
  }

  // local rows (all on rank 0): ID, grain, nodes, volume, mass of each piece
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0) {
    auto **loc = static_cast<double **>(lammps_extract_compute(lmp, "frag", 2, 2));
    std::map<double, int> piece_of_id;
    for (int p = 1; p <= NPIECES; p++) piece_of_id[expect.mintag[p]] = p;
    for (int r = 0; r < NPIECES; r++) {
      ASSERT_TRUE(piece_of_id.count(loc[r][0])) << "row " << r;
      const int p = piece_of_id[loc[r][0]];
      EXPECT_EQ(loc[r][1], p <= 2 ? 1.0 : (p <= 5 ? 2.0 : 3.0)) << "grain of piece " << p;
      EXPECT_EQ(loc[r][2], expect.nodes[p]) << "nodes of piece " << p;
      EXPECT_NEAR(loc[r][3], expect.nodes[p] * H * H, 1e-9) << "volume of piece " << p;
      EXPECT_NEAR(loc[r][4], 2.0 * expect.nodes[p] * H * H, 1e-9) << "mass of piece " << p;
    }
  }

  // the counts survive migration: every node moves by one unit in x, across
  // the subdomain boundaries and the periodic boundary
  command("velocity all set 10 0 0\nfix nve all nve\nrun 20 post no");
  auto *v2 = static_cast<double *>(lammps_extract_compute(lmp, "frag", 0, 1));
  EXPECT_EQ(v2[0], 6.0);
}

// A chain whose bonds are all stored by the lower atom ID (newton_bond on:
// one copy; node 4 stores none), one node per subdomain on 4 ranks, across
// the periodic boundary: node 4 learns its fragment only if ghosts send
// their labels home (reverse communication), round after round.
TEST_P(ComputePeridemFragments, ChainAcrossAllSubdomains)
{
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  if (me == 0)
    write_text_file(scratch() + "chain.data", R"(chain

4 atoms
1 atom types
3 bonds
1 bond types

-1 1 xlo xhi
-1 1 ylo yhi
-0.5 0.5 zlo zhi

Atoms # peridem

1 1 1 0.25 1.0 0.75 0 0 0.75 0 0
2 1 1 0.25 1.0 -0.75 0 0 1.25 0 0
3 1 1 0.25 1.0 -0.25 0 0 1.75 0 0
4 1 1 0.25 1.0 0.25 0 0 2.25 0 0

Bonds

1 1 1 2
2 1 2 3
3 1 3 4
)");
  MPI_Barrier(MPI_COMM_WORLD);
  command(fmt::format("units lj\ndimension 2\nboundary p p p\nnewton on {}\nprocessors * 1 1\n"
                      "atom_style peridem\natom_modify map array\nread_data {}chain.data\n"
                      "special_bonds lj/coul 0.0 1.0 1.0\nbond_style zero\nbond_coeff *\n"
                      "comm_modify cutoff 0.6\ncompute frag all peridem/fragments\n"
                      "thermo_style custom step c_frag\nrun 0 post no",
                      GetParam(), scratch()));
  auto *v = static_cast<double *>(lammps_extract_compute(lmp, "frag", 0, 1));
  EXPECT_EQ(v[0], 1.0);
  auto *f = static_cast<double *>(lammps_extract_compute(lmp, "frag", 1, 1));
  for (int i = 0; i < lmp->atom->nlocal; i++) EXPECT_EQ(f[i], 1.0) << "atom " << lmp->atom->tag[i];
  // cut the middle bond (reference x = 1.5): two fragments, IDs 1 and 3
  command("cut_peridem_bonds all segment 1.5 -1 1.5 1\nrun 0 post no");
  v = static_cast<double *>(lammps_extract_compute(lmp, "frag", 0, 1));
  EXPECT_EQ(v[0], 2.0);
  f = static_cast<double *>(lammps_extract_compute(lmp, "frag", 1, 1));
  for (int i = 0; i < lmp->atom->nlocal; i++)
    EXPECT_EQ(f[i], lmp->atom->tag[i] <= 2 ? 1.0 : 3.0) << "atom " << lmp->atom->tag[i];
}

INSTANTIATE_TEST_SUITE_P(Newton, ComputePeridemFragments, ::testing::Values("on", "off"));
