/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: pair_style peridem/contact, nonlocal node-to-node contact with
   damping and friction between grains and within a grain (self-contact).
   See doc/pair_peridem_contact.rst.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(peridem/contact,PairPeridemContact);
// clang-format on
#else

#ifndef LMP_PAIR_PERIDEM_CONTACT_H
#define LMP_PAIR_PERIDEM_CONTACT_H

#include "lmp_peridem_contact.h"
#include "pair.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairPeridemContact : public Pair {
 public:
  PairPeridemContact(class LAMMPS *);
  ~PairPeridemContact() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  void setup() override;
  double init_one(int, int) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void *extract(const char *, int &) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  // the contact law of a type pair (after pair_coeff), e.g. for walls
  const PERIDEM_NS::ContactSpec &type_spec(int i, int j) const { return spec[i][j]; }
  bool type_set(int i, int j) const { return allocated && setflag[i][j]; }
  // node pairs i, j of different grains closer than their contact radius R_c, from the
  // neighbour list of the last force computation (i owned, j owned or ghost), for compute
  // peridem/contacts
  void grain_node_contacts(std::vector<std::array<int, 2>> &out) const;
  double memory_usage() override;

 protected:
  // the contact law's input for atoms i, j; false: same grain, self-contact off
  bool pair_input(int i, int j, peridem::ContactInput &in) const;
  // contact law of each type pair, index [i][j] with 1 <= i, j <= ntypes
  std::vector<std::vector<PERIDEM_NS::ContactSpec>> spec;
  double **cut;      // contact radius of each type pair (or centroid_range)
  double **touchsq;  // squared distance below which grains touch (damping centroid)
  int self_contact;  // 1: nodes of one grain without an intact bond touch too
  double dissipated; // this rank's share of the energy dissipated by damping and friction
  // the work of the dissipative forces (damping, friction, centroid dashpot) with the full-step
  // velocities: their sum per node in compute() (owned and, with newton_pair, ghost nodes, whose
  // shares go home by reverse communication), counted at the end of the step (count_work).
  // Few nodes touch in a bed: the slots written are listed, cleared and summed, not all atoms.
  std::vector<double> fdis;    // 3 per atom slot, flat; 0 except in the listed slots
  std::vector<int> fdis_mark;  // per slot: the compute call that last wrote it
  std::vector<int> fdis_slots; // the slots written by the last compute call
  int fdis_call = 0;           // compute calls that kept the forces
  bigint fdis_step = -1;       // the step whose forces fdis holds (-1: none to count)
  double power_prev = 0.0;     // this rank's P(n - 1) = sum F . v(n - 1) of the step before
  void start_fdis();
  void add_fdis(int i, double fx, double fy, double fz)
  {
    if (fdis_mark[i] != fdis_call) {
      fdis_mark[i] = fdis_call;
      fdis_slots.push_back(i);
    }
    double *fd = &fdis[3 * std::size_t(i)];
    fd[0] += fx;
    fd[1] += fy;
    fd[2] += fz;
  }
  double dissipative_power() const; // this rank's sum of fdis . v over its nodes
  // called by fix peridem/vhistory at the end of each step and of each run (extract
  // "peridem_step_end", "peridem_run_end")
  std::function<void()> step_end, run_end;
  void count_work();
  void fold_dissipated(); // the shares of all ranks onto rank 0 (restart files hold rank 0's)
  std::vector<peridem::ContactParams> diag_params; // extract("peridem_contact_params")
  std::vector<double> diag_reach;                  // extract("peridem_centroid_reach")

  void allocate();
  void mix(int i, int j);
  void report_time_step();
  // Kn and Rc of each fix peridem/wall with a contact law of its own
  std::vector<std::array<double, 2>> own_wall_laws() const;
  static std::string wall_law_note(const std::vector<std::array<double, 2>> &laws);
  std::string last_time_step_report; // printed again only when it changes
  bool start_checked = false;        // overlaps at the first step reported (setup())
  void report_start_overlaps();

  // ---- damping centroid (Jha et al. 2021, §2.3.2, eq. 26-30) ----
  // Grains are molecule IDs. The pair loop records the grain pairs with a
  // node pair closer than R_c; they are gathered from all ranks (one
  // MPI_Allgather of a count per step, MPI_Allgatherv when there are any).
  // Only then each rank sums m, m x (unwrapped) and m v of its owned nodes
  // per grain and one MPI_Allreduce gives every rank all centres. Each rank
  // applies the dashpot of every grain pair to its own nodes.
  int centroid_on;                 // some type pair uses damping centroid
  std::vector<tagint> grain_ids;   // sorted IDs of all grains
  std::vector<int> grain_table;    // ID -> index when the IDs are dense
  bool grains_stale;               // rebuild grain_ids before the next use
  std::vector<int> grain_of;       // grain index of each owned node
  std::vector<double> grain_local; // per grain m, m x, m v (7), + unknown IDs
  std::vector<double> grain_sum;   // the same summed over ranks
  std::vector<double> grain_force; // damping force on each grain (3)
  // grain pairs in contact: grain IDs (smaller first) and the node types
  std::vector<std::array<tagint, 4>> touch_local, touch_all;
  // the neighbour pairs, copied at each build of the list (copy_neighbour_pairs)
  struct NodePair {
    int i, j;
  };
  std::vector<NodePair> pairs;
  bool pairs_copied = false; // a list has been copied (it may hold no pairs)
  // the velocities the forces take, flat: atom->v, or in a run's setup those of the step it
  // continues (fix peridem/vhistory, when the contact dissipates)
  class FixPeridemVelocityHistory *history = nullptr;
  const double *vel = nullptr;
  const double *velocities() const;
  // fix peridem/bonds hands over the nodes of each broken bond (extract "peridem_broken_pair"):
  // they join the copy of the neighbour pairs at once, instead of at a rebuild of the lists
  std::function<void(int, int)> broken_pair_sink;
  void copy_neighbour_pairs();
  std::vector<int> counts, displs; // for MPI_Allgatherv

  int gather_counts(int n);         // counts, displs for MPI_Allgatherv; total
  int grain_index(tagint id) const; // -1 if unknown
  void build_grain_index();
  void sum_grain_centres();
  void compute_centroid_damping(bool tally_virial, bool keep_fdis);
  // centroid_bounding: grain pairs by the distance of their centres (Jha et al.'s code)
  int bounding_on = 0;          // some type pair uses centroid_bounding
  bool bounding_stale = true;   // recompute bounding and grain_type before the next use
  std::vector<double> bounding; // bounding radius of each grain (reference configuration)
  std::vector<int> grain_type;  // largest atom type of each grain's nodes
  std::vector<int> order;       // grains sorted by centre x
  void add_bounding_touches();
  void compute_bounding_radii();
};

} // namespace LAMMPS_NS

#endif
#endif
