/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/vhistory, the velocities the dissipative forces of
   the last step used, so that a run boundary or a restart continues a
   damped or frictional run as one uninterrupted run.

   Velocity Verlet computes the forces of step n with v(n - 1/2); the setup
   of a run computes them again, at the same positions, but LAMMPS has
   v(n) by then. Damping and friction depend on v, so the first half-kick
   of the next run differed (kinetic energy 1.2e-2 apart in a crushing
   bed). This fix keeps v(n - 1/2) per node (migration, restarts) and hands
   it to pair_style peridem/contact and fix peridem/wall in a run's setup.
   A node whose velocity changed since that step (velocity, set, a data
   file) is taken at its velocity, as before.

   At the end of each step of a run it also calls pair_style
   peridem/contact back (extract "peridem_step_end"), which counts the
   work of its dissipative forces with the full-step velocities v(n) then.
   A pair style has no end-of-step stage of its own; this fix exists
   exactly when the pair's forces depend on v, so a second internal fix
   made under the same condition would only add an ID and its checks.
   fix peridem/wall, a fix, counts its own work in its own end_of_step.

   Created by pair_style peridem/contact and fix peridem/wall when they
   dissipate (ID PERIDEM_VHISTORY); not meant to be defined in an input.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(peridem/vhistory,FixPeridemVelocityHistory);
// clang-format on
#else

#ifndef LMP_FIX_PERIDEM_VHISTORY_H
#define LMP_FIX_PERIDEM_VHISTORY_H

#include "fix.h"

#include <functional>

namespace LAMMPS_NS {

class FixPeridemVelocityHistory : public Fix {
 public:
  static constexpr const char *ID = "PERIDEM_VHISTORY";
  // the one instance, created on first use; call from a style's init_style() or a fix's
  // post_constructor() (never from a constructor or init(): LAMMPS is adding fixes then)
  static FixPeridemVelocityHistory *instance(class LAMMPS *lmp, const char *caller);

  FixPeridemVelocityHistory(class LAMMPS *, int, char **);
  ~FixPeridemVelocityHistory() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void end_of_step() override;
  void post_run() override;

  // In the setup of a run: per owned and ghost atom, flat, the velocity its dissipative
  // forces take (v(n - 1/2) of the last step, or v where it changed since); nullptr
  // elsewhere (take atom->v).
  const double *setup_velocities() const;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  static constexpr int NVALUES = 7; // vhalf (3), vend (3), known
  double **vhalf;        // v(n - 1/2) of the last step's forces; in setup, the velocity to use
  double **vend;         // v at the end of that step's run: a node whose v differs was changed
  double *known;         // the step whose v(n - 1/2) vhalf holds (0: none)
  bool in_run = false;   // between a run's setup and its end (restarts written in a run)
  bool prepared = false; // setup_velocities() valid in this setup
  // what pair_style peridem/contact does at the end of each step and of each run (found at
  // each init; nullptr: nothing)
  const std::function<void()> *step_end = nullptr, *run_end = nullptr;
};

} // namespace LAMMPS_NS

#endif
#endif
