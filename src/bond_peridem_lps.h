/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: bond_style peridem/lps, state-based peridynamics (the linear
   peridynamic solid) with breakage. See doc/bond_peridem_lps.rst.
------------------------------------------------------------------------- */

#ifdef BOND_CLASS
// clang-format off
BondStyle(peridem/lps,BondPeridemLPS);
// clang-format on
#else

#ifndef LMP_BOND_PERIDEM_LPS_H
#define LMP_BOND_PERIDEM_LPS_H

#include "bond_peridem_base.h"

namespace peridem {
struct LpsConstants;
enum class LpsPlane;
} // namespace peridem

namespace LAMMPS_NS {

class BondPeridemLPS : public BondPeridemBase {
 public:
  BondPeridemLPS(class LAMMPS *);
  ~BondPeridemLPS() override;

  void compute(int, int) override;
  void coeff(int, char **) override;
  void init_style() override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  double single(int, double, int, int, double &) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;
  void stability_springs(std::vector<double> &k) override;

  // dilation theta of local atoms after the last force computation (0 without bonds)
  const double *dilation() const { return theta; }

 protected:
  // per bond type, 1..nbondtypes (s0, horizon, spacing, breakable: the base's)
  double *bulk, *shear;
  int *influence;
  void allocate_model(int np1) override;

  // the model's keywords of one bond_coeff command (coeff_keyword())
  struct ModelArgs {
    double K = 0.0, G = 0.0;
    bool haveK = false, haveG = false, haveInfluence = false;
    std::string influence;
    // bond_style peridem's keywords, refused with a pointer to that style
    bool haveC = false, haveE = false, haveMicro = false;
  };
  ModelArgs margs;
  bool coeff_keyword(const std::string &key, const char *value, const char *style) override;
  bool settings_keyword(int iarg, int narg, char **arg) override;
  std::vector<peridem::LpsConstants> constants;
  peridem::LpsPlane plane;
  bool plane_given = false; // plane strain|stress given (a 3d simulation refuses them)
  // for the log: "plane strain", "plane stress", "plane 3d" (2d), "3d" (3d)
  std::string plane_description() const;
  double dfac; // d of theta = (d/m) sum omega beta r e V

  // per entry of the bond list, one array per quantity: the dilation pass streams r0, wi and
  // wj, the force pass k and r0 (an array of 32-byte structs made both passes read all four:
  // 64 bytes per bond per step against 40)
  struct LpsCache {
    std::vector<double> r0; // reference length
    std::vector<double> k;  // omega beta V_i V_j
    std::vector<double> wi; // omega beta r0 V_j: weight of the extension in theta_i
    std::vector<double> wj; // omega beta r0 V_i
  };
  LpsCache lcache;
  std::vector<double> current_length; // |y| of each bond, from the dilation pass
  void fill_cache() override;

  // per atom (nmax): sum of the dilation pass, theta/m, 1/m, theta
  double *sum, *theta_over_m, *inv_m, *theta;
  int nmax_lps;
  int check_wvolume;            // see whether some node still needs its weighted volume
  class FixPeridemLPS *lps_fix; // m and the communication of the passes (init_style())
  void grow_lps();
  void compute_weighted_volume();

  // the passes of compute(), each on the base's traversal of the intact bonds: (1) the
  // dilation sums, for 2d and 3d; (3) the forces, for 2d and 3d on most steps, one bond at a
  // time with energy, virial or break_order after_force
  template <int DIM, bool ONE_TYPE> void dilation_pass();
  template <int DIM, bool ONE_TYPE> void force_pass();
  template <bool ONE_TYPE> void force_pass_one_by_one(int eflag);
};

} // namespace LAMMPS_NS

#endif
#endif
