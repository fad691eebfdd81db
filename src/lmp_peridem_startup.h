/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: start-up checks shared by pair_style peridem/contact and
   fix peridem/wall.

   - overlaps at the first step: nodes of different grains, or nodes and a
     wall, already closer than the contact radius R_c feel a contact force
     at once (a wall placed through a grain, grains created overlapping);
     one warning with the count and a few grain IDs, on rank 0.
   - neighbour skin: LAMMPS's neighbour list holds at most
     `neigh_modify one` (default 2000) partners per node; with sub-mm node
     spacings the SI default skin (1 mm) puts far more nodes than that in
     the list's reach, and the run stops with "Neighbor list overflow".
     Warn before, with the estimate and a skin that fits.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_STARTUP_H
#define LMP_PERIDEM_STARTUP_H

#include "lmptype.h"

#include <array>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// Collects the overlapping pairs seen on one rank (a grain ID and a partner: another grain's
// ID or a wall name) and reports them on all ranks together.
class OverlapReport {
 public:
  // what: "nodes of different grains" or "nodes and walls"
  void add(LAMMPS_NS::tagint grain, const std::string &partner);
  // One collective call: sums the counts over ranks; rank 0 warns if any, naming up to
  // five pairs (those of rank 0). Returns the total count.
  LAMMPS_NS::bigint report(LAMMPS_NS::LAMMPS *lmp, const std::string &style,
                           const std::string &what, double Rc);
  // The total over ranks (collective) and the examples of this rank, "grain 3 / wall ylo, ..."
  LAMMPS_NS::bigint total(LAMMPS_NS::LAMMPS *lmp) const;
  std::string example_list() const;
  void clear()
  {
    count = 0;
    examples.clear();
  }

 private:
  LAMMPS_NS::bigint count = 0;
  std::vector<std::string> examples;
};

// Number of partners a node has in a half neighbour list of reach `reach` (cutoff + skin) in a
// lattice of nodes of volume `volume` (area in 2D): half the nodes in the disk/ball.
double half_list_partners(int dimension, double reach, double volume);

// Warns (rank 0) when the neighbour list of cutoff `cutoff` plus LAMMPS's skin is likely to hold
// more than `neigh_modify one` partners for a node of the smallest nodal volume.  Collective.
void check_neighbor_skin(LAMMPS_NS::LAMMPS *lmp, const std::string &style, double cutoff);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
