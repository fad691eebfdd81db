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

#include "bond_peridem.h"
#include "peridem_lps_law.h"

#include <string>

namespace LAMMPS_NS {

class BondPeridemLPS : public BondPeridem {
 public:
  BondPeridemLPS(class LAMMPS *);
  ~BondPeridemLPS() override;

  void compute(int, int) override;
  void settings(int, char **) override;
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
  // per bond type, 1..nbondtypes (s0, horizon, spacing, breakable: the base class's arrays)
  double *bulk, *shear;
  int *influence;
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
    std::size_t size() const { return r0.size(); }
  };
  LpsCache lcache;
  std::vector<double> current_length; // |y| of each bond, from the dilation pass
  void fill_lps_cache();

  // per atom (nmax): sum of the dilation pass, theta/m, 1/m, theta
  double *sum, *theta_over_m, *inv_m, *theta;
  int nmax_lps;
  int check_wvolume; // see whether some node still needs its weighted volume
  void grow_lps();
  void compute_weighted_volume();

  void allocate_lps();

  // the passes of compute(): (1) the dilation sums, for 2d and 3d; (3) the forces, for 2d
  // and 3d on most steps, one bond at a time with energy, virial or break_order after_force
  template <int DIM, bool ONE_TYPE> void dilation_pass();
  template <int DIM, bool ONE_TYPE> void force_pass();
  void force_pass_one_by_one(int eflag);
};

} // namespace LAMMPS_NS

#endif
#endif
