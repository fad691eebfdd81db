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

#include "bond_peridem_base.h"

namespace LAMMPS_NS {

class BondPeridem : public BondPeridemBase {
 public:
  BondPeridem(class LAMMPS *);
  ~BondPeridem() override;

  void compute(int, int) override;
  void coeff(int, char **) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;
  void stability_springs(std::vector<double> &k) override;

 protected:
  // per bond type, 1..nbondtypes: the spring constant c_w (Bhattacharya & Lipton 2023,
  // eq. 3.2, Table 1) and the micromodulus (1: conic); s0, horizon, spacing, breakable: the
  // base's
  double *c;
  int *conic;
  void allocate_model(int np1) override;

  // the model's keywords of one bond_coeff command (coeff_keyword())
  struct ModelArgs {
    double E = 0.0, K = 0.0, cval = 0.0;
    bool haveE = false, haveK = false, haveC = false, haveMicro = false;
    peridem::Micromodulus micro = peridem::Micromodulus::Constant;
    // peridem/lps's keywords, refused with a pointer to that style
    bool haveG = false, haveInfluence = false;
  };
  ModelArgs margs;
  bool coeff_keyword(const std::string &key, const char *value, const char *style) override;

  // per entry of the bond list, as separate arrays (the force loop streams inv_r0 and k only;
  // r0 serves breakage and energy); the base's pieces give i1, i2 and the type
  struct BondCache {
    std::vector<double> r0;     // reference length |xi|
    std::vector<double> inv_r0; // 1/|xi|
    std::vector<double> k;      // c w(|xi|) V_i V_j, times the volume factor (if not uniform)
    bool k_uniform = false;     // every intact bond of the list has k = k_value (k empty)
    double k_value = 0.0;
  };
  BondCache cache;
  void fill_cache() override;
  template <bool ONE_TYPE> void compute_one_by_one(int eflag);
  // the force loop of ordinary steps (no energy, no virial): the chunked passes, defined in
  // bond_peridem_chunked.h; bond_style peridem/opt compiles the same passes with flags of its
  // own and overrides this
  virtual void compute_chunked();
  // VARIANT is a tag type in an unnamed namespace of the file that instantiates the passes:
  // each file's copy then has internal linkage and keeps that file's compiler flags (two
  // copies of one name with external linkage are one to the linker, which keeps either)
  template <class VARIANT> void chunked_passes();
  template <class VARIANT, int DIM, bool UNIFORM_K, bool ONE_TYPE> void chunked_pass();
  double bond_stiffness(int type, double r0, int i1, int i2) const;
  double stiffness(int type, double r0, double vol1, double vol2) const;
};

} // namespace LAMMPS_NS

#endif
#endif
