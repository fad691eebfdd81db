/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bond_style peridem, bond-based peridynamics with breakage.
   See doc/bond_peridem.rst.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(peridem,BondPeridem);
// clang-format on
#else

#ifndef LMP_BOND_PERIDEM_H
#define LMP_BOND_PERIDEM_H

#include "bond.h"
#include "peridem_bond_law.h"
#include "peridem_material.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class BondPeridem : public Bond {
 public:
  BondPeridem(class LAMMPS *);
  ~BondPeridem() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double equilibrium_distance(int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

  // Time-step estimate (pair_style peridem/contact): for each entry n of LAMMPS's bond list a
  // spring constant k[n] (0 for a broken entry) such that the bonds' linearised energy is at
  // most 1/2 sum_n k[n] (e_n . (u_j - u_i))^2 (e_n the reference bond direction).
  // Reference geometry, intact bonds; bond_peridem_stability.cpp.
  virtual void stability_springs(std::vector<double> &k);
  // per atom type, the largest 2 lambda_max(A_i)/m_i of the nodes (A_i = sum of k e e over
  // the node's bonds): the bonds' squared frequency bound (peridem_contact_law.h); collective
  std::vector<double> stability_omega2_of_types();

 protected:
  // the coefficients of one bond type, as bond_coeff derives them
  struct TypeParams {
    double c = 0.0;       // spring constant c_w (Bhattacharya & Lipton 2023, eq. 3.2, Table 1)
    double s0 = 0.0;      // critical stretch
    double horizon = 0.0; // eps: bonds are no longer than this
    double spacing = 0.0; // node spacing h for the volume correction (0: not given)
    peridem::Micromodulus micromodulus = peridem::Micromodulus::Constant;
    int breakable = 1; // 0: bonds of this type never break (bond_coeff ... break no)
  };
  // per bond type, index 1..nbondtypes (flat arrays for the force loop)
  double *c, *s0, *horizon, *spacing;
  int *conic, *breakable;
  // the stretch at which a bond of the type breaks: s0, or infinity for
  // break no (set in init_style), so the force loop has no extra per-bond
  // test (measured: a breakable[type] test cost 5 % of the loop)
  double *s0_break;

  // the keywords of one bond_coeff command, as given, for this style and peridem/lps
  struct CoeffArgs {
    int ilo = 0, ihi = 0;
    double E = 0.0, K = 0.0, G = 0.0, Gc = 0.0, cval = 0.0, s0 = 0.0, eps = 0.0, h = 0.0;
    bool haveE = false, haveK = false, haveG = false, haveGc = false, haveC = false, haveS0 = false,
         haveMaterial = false, haveMicro = false, haveInfluence = false;
    peridem::Micromodulus micro = peridem::Micromodulus::Constant;
    std::string influence;
    peridem::Material material;
    std::string origin;
    int breakable = 1;
  };
  CoeffArgs parse_coeff(int narg, char **arg, const char *style);

  peridem::BreakageMode breakage;
  int break_flag;                 // 0: bonds never break
  double stretch_allowance = 0.5; // largest stretch of an intact bond, for the ghost cutoff
  int break_after_force;          // 1: a breaking bond still acts in its last step (LAMMPS peri)
  int volume_correction;          // 0: none, 1: linear ramp near the horizon
  int cohesive;                   // 1: bonds between different grains allowed
  int validate_next;              // check the bond list in the next compute()
  class FixPeridemBonds *bonds_fix;

  // per entry of LAMMPS's bond list, valid until it is rebuilt
  // per entry of the bond list, as separate arrays (the force loop streams
  // inv_r0 and k only; r0 serves breakage and energy)
  struct BondCache {
    std::vector<double> r0;     // reference length |xi|
    std::vector<double> inv_r0; // 1/|xi|
    std::vector<double> k;      // c w(|xi|) V_i V_j, times the volume factor (if not uniform)
    bool k_uniform = false;     // every intact bond of the list has k = k_value (k empty)
    double k_value = 0.0;
    // The list as the chunked loop reads it: LAMMPS lists the bonds of one atom i1 one after
    // the other, so the loop streams only i2 per entry (partner) and takes i1 once per piece
    // of consecutive entries with the same i1 (a piece holds at most CHUNK entries). Pieces
    // are grouped into chunks of at most CHUNK entries (chunk_piece: first piece of each
    // chunk, and the number of pieces at the end). A broken entry has partner i1 (no force).
    std::vector<int> partner;     // i2 of each entry, i1 once broken
    std::vector<int> piece_atom;  // i1 of each piece
    std::vector<int> piece_start; // first entry of each piece, then the number of entries
    std::vector<int> chunk_piece; // first piece of each chunk, then the number of pieces
    int type_all = 0;             // the type of every intact entry, or 0 when they differ
    std::vector<int> type;        // the type of each entry, when they differ (else empty)
    std::size_t size() const { return r0.size(); }
  };
  BondCache cache;
  static constexpr int CHUNK = 64; // entries per chunk of the chunked loop
  // atom->userbinsize while the nodes are ordered grain by grain (init_style)
  static constexpr double NO_SPATIAL_SORT = 1e300;
  // the pieces of the bond list as the piece loops read them, taken once per pass
  struct PieceView {
    const int *partner;      // BondCache::partner
    const int *atom, *start; // BondCache::piece_atom, piece_start
    const int *chunk;        // BondCache::chunk_piece
    const int *type;         // BondCache::type (empty when type_all > 0)
    int npieces, nchunks, type_all;
    // the type of intact entry n: ONE_TYPE when type_all > 0
    template <bool ONE_TYPE> int type_of(int n) const { return ONE_TYPE ? type_all : type[n]; }
  };
  PieceView pieces() const
  {
    return {cache.partner.data(),
            cache.piece_atom.data(),
            cache.piece_start.data(),
            cache.chunk_piece.data(),
            cache.type.data(),
            int(cache.piece_atom.size()),
            int(cache.chunk_piece.size()) - 1,
            cache.type_all};
  }
  // the bond list the caches were filled for (bond_list_is_new())
  bigint cache_ncalls, cache_generation;
  int **cache_bondlist;
  bool bond_list_is_new(std::size_t cached_entries) const;
  void remember_bond_list();
  void fill_cache();
  void compute_one_by_one(int eflag);
  void compute_chunked();
  template <int DIM, bool UNIFORM_K, bool ONE_TYPE> void chunked_pass();
  void fill_pieces();
  double pieces_memory() const;
  double bond_stiffness(int type, double r0, int i1, int i2) const;
  double stiffness(int type, double r0, double vol1, double vol2) const;

  void allocate();
  void set_type(int type, const TypeParams &p);
  void validate_bonds();
  void report_time_step();
  std::string last_time_step_report; // printed again only when it changes
  void break_bond(int n, int i1, int i2, double r0, double s0type);
  double reference_length(int i1, int i2) const;
  double reference_length_flat(const double *x0, int i1, int i2) const;
};

} // namespace LAMMPS_NS

#endif
#endif
