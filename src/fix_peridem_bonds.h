/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/bonds, the bookkeeping of broken bonds.

   Created by bond_style peridem (ID PERIDEM_BONDS); not meant to be
   defined in an input script. A broken bond is removed from the bond
   arrays at once (so its nodes may drift apart without LAMMPS losing a
   bond partner); this fix remembers, per node and across migration and
   restarts, how many of its bonds broke and the damage measure Z they had
   when they broke, for compute peridem/damage.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(peridem/bonds,FixPeridemBonds);
// clang-format on
#else

#ifndef LMP_FIX_PERIDEM_BONDS_H
#define LMP_FIX_PERIDEM_BONDS_H

#include "fix.h"

#include <functional>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {
namespace PERIDEM_NS {
class DamageSectionColumn;
}

class FixPeridemBonds : public Fix {
 public:
  static constexpr const char *ID = "PERIDEM_BONDS";

  FixPeridemBonds(class LAMMPS *, int, char **);
  ~FixPeridemBonds() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void min_setup(int) override;
  void pre_force(int) override;
  void post_force(int) override;
  void min_pre_force(int) override;
  void min_post_force(int) override;
  // LAMMPS rebuilt its neighbour and bond lists: at every setup (also of each snapshot of
  // rerun, which resets neighbor->ncalls to 0 each time), every reneighbouring of a run and
  // of a minimisation. The bond styles refill their per-entry caches when this changes.
  void setup_post_neighbor() override { list_generation++; }
  void post_neighbor() override { list_generation++; }
  void min_post_neighbor() override { list_generation++; }
  bigint bond_list_generation() const { return list_generation; }

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_reverse_comm_size(int, int) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

  // write_data: a PeridemDamage section (ID, broken count, Z, then the column of each fix
  // that adds one, lmp_peridem_damage_column.h) when any node has broken bonds; read back
  // through fix property/atom (see doc)
  void write_data_section_size(int, int &, int &) override;
  void write_data_section_pack(int, double **) override;
  void write_data_section_keyword(int, FILE *) override;
  void write_data_section(int, FILE *, int, double **, int) override;
  static constexpr const char *DATA_SECTION = "PeridemDamage";

  // the bond between local or ghost atoms i1, i2 broke with damage term z;
  // removes it from the bond arrays of the local atoms that store it
  void bond_broken(int i1, int i2, double z);
  // changes at every run's (or minimisation's) setup and at every broken bond or deleted
  // partner on this rank: computes that read the bonds evaluate them once per timestep and
  // value of this stamp (agreeing across ranks: a break changes one rank's stamp only)
  bigint change_stamp() const { return stamp; }

  // per atom: number of broken bonds, largest Z term of a broken bond
  const double *broken_count() const { return nbroken; }
  const double *broken_z() const { return zbroken; }

  // owned atom i lost an intact bond partner that was deleted (escaped node: fix
  // peridem/escapes, fix peridem/wall lost delete): the bond counts as broken
  void partner_deleted(int i)
  {
    nbroken[i] += 1.0;
    stamp++;
  }
  // restart files written before fix peridem/lps existed end this fix's per-atom record
  // with that fix's weighted volume m: kept here per local atom, for fix peridem/lps to take
  // when its bond style creates it just after this one (empty with files of today's layout)
  std::vector<double> take_old_restart_m();

 private:
  double *nbroken, *zbroken;
  bigint broken_here; // bonds broken on this rank since the last post_force
  // newton_bond on: partners (by tag) that atoms at these local or ghost
  // indices lost this step; they travel home by reverse communication and
  // leave the special lists there
  std::unordered_map<int, std::vector<tagint>> lost_partners;
  int comm_mode; // which reverse communication is under way: COUNTS or PARTNERS
  // pair_style peridem/contact's intake of the nodes of broken bonds (init()), or nullptr
  std::function<void(int, int)> *broken_pair_sink = nullptr;
  // the columns other fixes add to the damage section, as write_data writes it (init())
  std::vector<PERIDEM_NS::DamageSectionColumn *> wd_columns;
  std::vector<double> old_restart_m; // take_old_restart_m()

  void forget_partner(int i, tagint partner);
  void adopt_data_file_damage();
  void refuse_misnamed_damage();
  void check_damage_per_grain(const double *nb);

  void clear_ghosts();
  void collect();
  static void remove_bond(class Atom *atom, int i, tagint partner);
  bigint stamp = 0;
  bigint list_generation = 0; // bond_list_generation()
};

} // namespace LAMMPS_NS

#endif
#endif
