/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the base of the peridynamic bond styles (peridem, peridem/lps),
   as LAMMPS's BPM package has BondBPM. It owns what every model shares:
   the bond_style keywords, the shared bond_coeff keywords, the bond list
   by pieces, the breakage decision and the one break path, the ghost
   cutoff, validation and the link to fix peridem/bonds. A model supplies
   its constants (coeff_keyword, coeff), its per-entry cache (fill_cache)
   and its force kernels run by for_each_intact_bond().
------------------------------------------------------------------------- */

#ifndef LMP_BOND_PERIDEM_BASE_H
#define LMP_BOND_PERIDEM_BASE_H

#include "bond.h"
#include "peridem_bond_law.h"
#include "peridem_material.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class BondPeridemBase : public Bond {
 public:
  BondPeridemBase(class LAMMPS *);
  ~BondPeridemBase() override;

  void settings(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

  // Time-step estimate (pair_style peridem/contact): for each entry n of LAMMPS's bond list a
  // spring constant k[n] (0 for a broken entry) such that the bonds' linearised energy is at
  // most 1/2 sum_n k[n] (e_n . (u_j - u_i))^2 (e_n the reference bond direction).
  // Reference geometry, intact bonds.
  virtual void stability_springs(std::vector<double> &k) = 0;
  // per atom type, the largest 2 lambda_max(A_i)/m_i of the nodes (A_i = sum of k e e over
  // the node's bonds): the bonds' squared frequency bound (peridem_contact_law.h); collective
  std::vector<double> stability_omega2_of_types();

 protected:
  // per bond type, index 1..nbondtypes (flat arrays for the force loops)
  double *s0, *horizon, *spacing;
  int *breakable; // 0: bonds of this type never break (bond_coeff ... break no)
  // the stretch at which a bond of the type breaks: s0, or infinity for break no (set in
  // init_style), so the loops have no extra per-bond test (measured: a breakable[type] test
  // cost 5 % of the loop)
  double *s0_break;
  void allocate();
  // the model's per-type arrays, np1 = nbondtypes + 1 entries (called by allocate())
  virtual void allocate_model(int np1) = 0;
  void set_shared_type(int type, double s0type, double horizon_type, double spacing_type,
                       int breakable_type);

  // the shared keywords of one bond_coeff command, as given; the model's own keywords go to
  // coeff_keyword()
  struct CoeffArgs {
    int ilo = 0, ihi = 0;
    double Gc = 0.0, s0 = 0.0, eps = 0.0, h = 0.0;
    bool haveGc = false, haveS0 = false, haveMaterial = false;
    peridem::Material material;
    std::string origin;
    int breakable = 1;
  };
  CoeffArgs parse_coeff(int narg, char **arg, const char *style);
  // a keyword of bond_coeff that is not a shared one, with its value: false if the model does
  // not know it
  virtual bool coeff_keyword(const std::string &key, const char *value, const char *style) = 0;
  // a keyword's value, which must be > 0 for style
  double coeff_positive(const char *what, const char *value, const char *style);
  // a keyword of bond_style the model reads before the shared ones (at arg[iarg], its value
  // next): false if it is not the model's
  virtual bool settings_keyword(int iarg, int narg, char **arg);

  peridem::BreakageMode breakage;
  int break_flag;                 // 0: bonds never break
  double stretch_allowance = 0.5; // largest stretch of an intact bond, for the ghost cutoff
  int break_after_force;          // 1: a breaking bond still acts in its last step (LAMMPS peri)
  int volume_correction;          // 0: none, 1: linear ramp near the horizon
  int cohesive;                   // 1: bonds between different grains allowed
  int validate_next;              // check the bond list in the next compute()
  class FixPeridemBonds *bonds_fix;

  // the restart fields of a model, per bond type
  void write_types(FILE *fp, const double *a) const;
  void write_types(FILE *fp, const int *a) const;
  void read_types(FILE *fp, double *a);
  void read_types(FILE *fp, int *a);
  // the end of a Bond Coeffs line that every model shares (spacing, break no)
  std::string data_tail(int type) const;

  // The bond list as the piece loops read it: LAMMPS lists the bonds of one atom i1 one after
  // the other, so the loops stream only i2 per entry (partner) and take i1 once per piece of
  // consecutive entries with the same i1 (a piece holds at most CHUNK entries). Pieces are
  // grouped into chunks of at most CHUNK entries (chunk_piece: first piece of each chunk, and
  // the number of pieces at the end). A broken entry has partner i1 (no force).
  struct BondPieces {
    std::vector<int> partner;     // i2 of each entry, i1 once broken
    std::vector<int> piece_atom;  // i1 of each piece
    std::vector<int> piece_start; // first entry of each piece, then the number of entries
    std::vector<int> chunk_piece; // first piece of each chunk, then the number of pieces
    int type_all = 0;             // the type of every intact entry, or 0 when they differ
    std::vector<int> type;        // the type of each entry, when they differ (else empty)
  };
  BondPieces bond_pieces;
  static constexpr int CHUNK = 64; // entries per piece and per chunk
  // atom->userbinsize while the nodes are ordered grain by grain (init_style)
  static constexpr double NO_SPATIAL_SORT = 1e300;
  // the pieces as the loops read them, taken once per pass
  struct PieceView {
    const int *partner;      // BondPieces::partner
    const int *atom, *start; // BondPieces::piece_atom, piece_start
    const int *chunk;        // BondPieces::chunk_piece
    const int *type;         // BondPieces::type (empty when type_all > 0)
    int npieces, nchunks, type_all;
    // the type of intact entry n: ONE_TYPE when type_all > 0
    template <bool ONE_TYPE> int type_of(int n) const { return ONE_TYPE ? type_all : type[n]; }
  };
  PieceView pieces() const
  {
    return {bond_pieces.partner.data(),
            bond_pieces.piece_atom.data(),
            bond_pieces.piece_start.data(),
            bond_pieces.chunk_piece.data(),
            bond_pieces.type.data(),
            int(bond_pieces.piece_atom.size()),
            int(bond_pieces.chunk_piece.size()) - 1,
            bond_pieces.type_all};
  }
  double pieces_memory() const;

  // ev_init, the check of the bond list once per run, and the caches when LAMMPS has rebuilt
  // the bond list: the model's (fill_cache) and the pieces
  void begin_compute(int eflag, int vflag);
  // the model's per-entry data for a new bond list
  virtual void fill_cache() = 0;
  // |x0_i - x0_j| (minimum image) of every intact entry of the bond list into r0, and its
  // inverse into inv_r0 (if not null); the entries of broken bonds keep what they held
  void fill_reference_lengths(std::vector<double> &r0, std::vector<double> *inv_r0) const;
  double reference_length(int i1, int i2) const;

  // The breakage criterion, the only one: a bond breaks once its stretch exceeds the critical
  // stretch of its type (in tension, or either way with break absolute). Whether bonds break at
  // all (break off) and in which order is for_each_intact_bond()'s.
  bool breaks_now(double stretch, int type) const
  {
    return peridem::bond_breaks(stretch, s0_break[type], breakage);
  }
  // the only break path: bond n of the list is broken for good, here and in the bond arrays
  void break_bond(int n, int i1, int i2, double r0, int type);

  // Where a pass stands in a step's order: BREAK_BEFORE_FORCE passes break the bonds that
  // break now when the order is before_force (the default: a breaking bond carries no force in
  // its last step) and skip them; BREAK_AFTER_FORCE passes break them after the kernel when
  // the order is after_force (LAMMPS's peri styles); BREAK_EITHER does both; NO_BREAK passes
  // read the bonds the pass before has left intact.
  enum BreakStage { NO_BREAK = 0, BREAK_BEFORE_FORCE = 1, BREAK_AFTER_FORCE = 2, BREAK_EITHER = 3 };

  // The one traversal of the intact bonds, over pieces p0..p1-1 of pc, in list order. The
  // kernel has
  //   piece(i1)             at the start of each piece
  //   measure(n, i1, i2)    the entry's geometry (before any test)
  //   stretch(n)            its stretch, for the breakage decision (called only if needed)
  //   r0(n)                 its reference length, for the break path
  //   bond(n, i1, i2, type) its contribution (forces, sums)
  // Each is inlined: the kernel's state (sums on i1, lengths) stays in registers.
  template <int STAGE, bool ONE_TYPE, class Kernel>
  inline __attribute__((always_inline)) void for_each_intact_bond(const PieceView &pc, int p0,
                                                                  int p1, Kernel &kernel)
  {
    const bool before = (STAGE & BREAK_BEFORE_FORCE) && break_flag && !break_after_force;
    const bool after = (STAGE & BREAK_AFTER_FORCE) && break_flag && break_after_force;
    for (int p = p0; p < p1; p++) {
      const int i1 = pc.atom[p];
      kernel.piece(i1);
      for (int n = pc.start[p], e = pc.start[p + 1]; n < e; n++) {
        const int i2 = pc.partner[n];
        if (i2 == i1) continue; // broken
        const int type = pc.type_of<ONE_TYPE>(n);
        kernel.measure(n, i1, i2);
        if constexpr ((STAGE & BREAK_BEFORE_FORCE) != 0) {
          if (before && breaks_now(kernel.stretch(n), type)) {
            break_bond(n, i1, i2, kernel.r0(n), type);
            continue;
          }
        }
        kernel.bond(n, i1, i2, type);
        if constexpr ((STAGE & BREAK_AFTER_FORCE) != 0) {
          if (after && breaks_now(kernel.stretch(n), type))
            break_bond(n, i1, i2, kernel.r0(n), type);
        }
      }
    }
  }

  void validate_bonds();
  void report_time_step();
  std::string last_time_step_report; // printed again only when it changes

 private:
  // the bond list the caches were filled for (bond_list_is_new())
  bigint cache_ncalls, cache_generation;
  int **cache_bondlist;
  int cache_nbondlist;
  bool bond_list_is_new() const;
  void remember_bond_list();
  void fill_pieces();
};

} // namespace LAMMPS_NS

#endif
