/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/wall, rigid analytic container walls.

   An axis-aligned rectangle (2D) or box (3D) of flat walls that push the
   peridynamic nodes of the group through Bhattacharya & Lipton's (2023) wall
   contact (§4.5, eq. 4.7-4.8; formulas in peridem_wall_geometry.h, which
   this fix calls). Walls may be fixed, move at a constant velocity, follow
   an equal-style variable, or hold a pressure (servo); they may slide
   along themselves (shear). See doc/fix_peridem_wall.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(peridem/wall,FixPeridemWall);
// clang-format on
#else

#ifndef LMP_FIX_PERIDEM_WALL_H
#define LMP_FIX_PERIDEM_WALL_H

#include "fix.h"
#include "lmp_peridem_contact.h"
#include "lmp_peridem_wall_damping.h"

#include <vector>
#include "peridem_wall_geometry.h"

#include <string>

namespace LAMMPS_NS {

class FixPeridemWall : public Fix {
 public:
  FixPeridemWall(class LAMMPS *, int, char **);
  ~FixPeridemWall() override;
  void post_constructor() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void min_setup(int) override;
  void post_integrate() override;
  void post_force(int) override;
  void post_force_respa(int, int, int) override;
  void end_of_step() override;
  void min_post_force(int) override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  // "peridem_wall_contact": the walls' own contact law (peridem::ContactParams, dim 0), or
  // nullptr with 'contact pair' (then the walls use the pair's); for the pair's time step
  void *extract(const char *, int &) override;

  // 'lost delete': nodes beyond a wall or a fixed box boundary are deleted
  int deletes_lost() const { return lost_delete; }

  // entries of the global vector per wall, then the totals (0-based)
  static constexpr int PER_WALL = 6; // position, velocity, normal load, fx, fy, fz

 private:
  enum class Motion { Fixed, Velocity, Variable, Servo };
  struct Wall {
    bool active = false;
    Motion motion = Motion::Fixed;
    double pos = 0.0;            // coordinate of the wall plane
    double vel = 0.0;            // velocity along the axis (+x, +y or +z)
    double shear[3] = {0, 0, 0}; // tangential velocity (enters friction, damping)
    std::string var;             // equal-style variable of the position
    int ivar = -1;
    bigint var_step = -1;                          // step of the last variable evaluation
    double pressure = 0.0, gain = 0.0, vmax = 0.0; // servo
  };
  Wall walls[peridem::kMaxWalls];
  int nwalls; // 2 * dimension
  PERIDEM_NS::ContactSpec contact;
  // 'contact pair': the law of pair_style peridem/contact for the node's
  // type (pair_coeff I I), per atom type; empty otherwise
  bool contact_from_pair = false;
  // v(n - 1/2) in a run's setup (fix peridem/vhistory), where the wall or the pair dissipates
  class FixPeridemVelocityHistory *history = nullptr;
  std::vector<peridem::ContactParams> type_params;
  // contact pair: pair_coeff I I with damping centroid also damps grain centres at the walls
  PERIDEM_NS::WallCentroidDamping centroid_damping;
  void apply_centroid_damping(const double *vel, bool count_work);
  void add_wall_virial(int w, const double *xi, const double *fw, double *vir) const;
  int lost_error;       // 1: a node beyond a wall ends the run, 0: counted and warned
  int lost_delete;      // 1: nodes beyond a wall or the box are deleted with their bonds
  bigint deleted_total; // nodes deleted so far (lost delete), all ranks
  int servo_any, var_any;
  int in_setup;
  int ilevel_respa = 0;       // run_style respa: the level of the wall forces (outermost)
  bool start_checked = false; // nodes within Rc of a wall at the first step reported
  void check_start();

  // this rank's sums of the latest force evaluation, then the totals
  enum { NSUM = 3 * peridem::kMaxWalls + 3 }; // reactions, energy, nodes lost, dissipated
  double local[NSUM], total[NSUM];
  int reduced;
  double dissipated_local; // energy dissipated by this rank's nodes since the start
  bigint lost_local;       // node-steps beyond a wall on this rank during this run
  // the damping and friction forces of the last step on this rank's nodes, for their work with
  // the full-step velocities at the end of the step (end_of_step)
  std::vector<int> work_node;     // the nodes
  std::vector<double> work_force; // their dissipative forces (3 each)
  double work_wall = 0.0;         // sum of those forces . the velocity of their wall
  bigint work_step = -1;          // the step of those forces (-1: none to count)
  double power_prev = 0.0;        // this rank's power of those forces in the step before
  void keep_work(int i, const double *f, double wall_rate);
  double dissipative_power() const; // this rank's power of the kept forces at v now

  static int face_index(const std::string &name);
  int parse_face(const char *word) const;
  peridem::WallBox make_box() const;
  double wall_area(int w) const;
  void check_periodic() const;
  void warn_tight_box(double Rc) const;
  void check_order(const char *when) const;
  void take_contact_from_pair();
  void update_variable_walls();
  void reduce();
  void servo_control();

  // nodes within reach of a wall (Rc + skin), found at reneighbouring as
  // LAMMPS finds pair neighbours: the step loops over these only
  std::vector<int> near;
  bool near_list = true;   // keyword near_list (no: every node, to check the list against)
  bigint near_ncalls = -1; // neighbor->ncalls of the list
  int near_nlocal = -1;    // atom->nlocal of the list
  double near_pos[peridem::kMaxWalls] = {}; // wall positions of the list
  double near_slack = 0.0;                  // how far a wall may move before a rebuild
  bool near_stale() const;
  void build_near(const peridem::WallBox &box);
};

} // namespace LAMMPS_NS

#endif
#endif
