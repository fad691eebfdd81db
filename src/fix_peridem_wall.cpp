/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: fix peridem/wall, rigid analytic container walls.

   The node-wall force (repulsion by inclusion-exclusion over walls, edges
   and corners, damping and friction wall by wall) is
   peridem::wall_contact_force(); this file only moves the walls, feeds
   the nodes through it and sums the reactions.
------------------------------------------------------------------------- */

#include "fix_peridem_wall.h"
#include "fix_peridem_vhistory.h"
#include "lmp_peridem_citations.h"
#include "lmp_peridem_topology.h"

#include "lmp_peridem_parse.h"
#include "force.h"
#include "lmp_peridem_startup.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "respa.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
const char *const STYLE = "fix peridem/wall";
const char *const FACES[peridem::kMaxWalls] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
enum { ENERGY = 3 * peridem::kMaxWalls, NLOST, DISSIPATED };

// +1 for a hi wall (its outward normal is +axis), -1 for a lo wall
inline double outward(int w)
{
  return (w % 2 == 0) ? -1.0 : 1.0;
}
} // namespace

/* ----------------------------------------------------------------------
   fix ID group peridem/wall face pos [face pos ...] keyword values ...
     face = xlo xhi ylo yhi zlo zhi;  pos = number | EDGE | v_name
     velocity face v | servo face P gain vmax | shear face vx vy vz |
     lost error|warn|delete | near_list yes|no | contact keywords (lmp_peridem_contact.h)
------------------------------------------------------------------------- */

FixPeridemWall::FixPeridemWall(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), nwalls(2 * domain->dimension), lost_error(1), lost_delete(0),
      deleted_total(0), servo_any(0), var_any(0), in_setup(0), reduced(0), dissipated_local(0.0),
      lost_local(0)
{
  PERIDEM_NS::cite_grain_shape(lmp);
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = PER_WALL * nwalls + 3;
  global_freq = 1;
  extscalar = 1;
  extvector = -1;
  extlist = new int[size_vector];
  for (int w = 0; w < nwalls; w++) {
    const int e[PER_WALL] = {0, 0, 1, 1, 1, 1}; // position, velocity intensive
    for (int j = 0; j < PER_WALL; j++) extlist[PER_WALL * w + j] = e[j];
  }
  extlist[PER_WALL * nwalls] = 0;
  extlist[PER_WALL * nwalls + 1] = 1;
  extlist[PER_WALL * nwalls + 2] = 1;
  energy_global_flag = 1;
  virial_global_flag = virial_peratom_flag = 1;
  restart_global = 1;
  dynamic_group_allow = 1;
  for (double &v : local) v = 0.0;
  for (double &v : total) v = 0.0;

  if (!atom->vfrac_flag || !atom->rmass_flag)
    error->all(FLERR, "{} needs per-atom volumes and masses (atom_style peridem)", STYLE);

  PERIDEM_NS::ContactParser parser(lmp, STYLE);
  int iarg = 3;
  auto need = [&](int n, const char *what) {
    if (iarg + n >= narg) error->all(FLERR, "{}: {} needs {} value(s)", STYLE, what, n);
  };
  while (iarg < narg) {
    const std::string key = arg[iarg];
    const int face = face_index(key);
    if (face >= 0) {
      need(1, arg[iarg]);
      if (face >= nwalls)
        error->all(FLERR, "{}: wall {} needs a 3D simulation (dimension 3)", STYLE, key);
      Wall &wall = walls[face];
      if (wall.active) error->all(FLERR, "{}: wall {} is given twice", STYLE, key);
      wall.active = true;
      const char *value = arg[iarg + 1];
      if (strcmp(value, "EDGE") == 0) {
        wall.pos = (face % 2 == 0) ? domain->boxlo[face / 2] : domain->boxhi[face / 2];
      } else if (utils::strmatch(value, "^v_")) {
        wall.var = value + 2;
        wall.motion = Motion::Variable;
        var_any = 1;
      } else {
        wall.pos = PERIDEM_NS::number(lmp, STYLE, "wall " + key, value);
      }
      iarg += 2;
    } else if (key == "velocity") {
      need(2, "velocity");
      const int w = parse_face(arg[iarg + 1]);
      walls[w].vel = PERIDEM_NS::number(lmp, STYLE, "velocity", arg[iarg + 2]);
      if (walls[w].motion != Motion::Fixed)
        error->all(FLERR, "{}: wall {} has a variable position or a servo and a velocity", STYLE,
                   FACES[w]);
      walls[w].motion = Motion::Velocity;
      iarg += 3;
    } else if (key == "servo") {
      need(4, "servo");
      const int w = parse_face(arg[iarg + 1]);
      Wall &wall = walls[w];
      if (wall.motion != Motion::Fixed)
        error->all(FLERR, "{}: wall {} has a variable position or a velocity and a servo", STYLE,
                   FACES[w]);
      wall.motion = Motion::Servo;
      wall.pressure = PERIDEM_NS::number(lmp, STYLE, "servo pressure", arg[iarg + 2]);
      wall.gain = PERIDEM_NS::number(lmp, STYLE, "servo gain", arg[iarg + 3]);
      wall.vmax = PERIDEM_NS::number(lmp, STYLE, "servo vmax", arg[iarg + 4]);
      if (!(wall.pressure >= 0.0))
        error->all(FLERR, "{}: servo pressure must be >= 0, not {}", STYLE, arg[iarg + 2]);
      if (!(wall.gain > 0.0))
        error->all(FLERR, "{}: servo gain must be > 0, not {}", STYLE, arg[iarg + 3]);
      if (!(wall.vmax > 0.0))
        error->all(FLERR, "{}: servo vmax must be > 0, not {}", STYLE, arg[iarg + 4]);
      servo_any = 1;
      iarg += 5;
    } else if (key == "shear") {
      need(4, "shear");
      const int w = parse_face(arg[iarg + 1]);
      for (int k = 0; k < 3; k++)
        walls[w].shear[k] = PERIDEM_NS::number(lmp, STYLE, "shear", arg[iarg + 2 + k]);
      if (walls[w].shear[w / 2] != 0.0)
        error->all(FLERR,
                   "{}: shear velocity of wall {} must lie in the wall (its {} component must be "
                   "0; use velocity or servo for normal motion)",
                   STYLE, FACES[w], "xyz"[w / 2]);
      if (domain->dimension == 2 && walls[w].shear[2] != 0.0)
        error->all(FLERR, "{}: shear velocity of wall {} has a z component in 2D", STYLE, FACES[w]);
      iarg += 5;
    } else if (key == "contact") {
      need(1, "contact");
      if (strcmp(arg[iarg + 1], "pair") != 0)
        error->all(FLERR, "{}: contact must be followed by pair, not {}", STYLE, arg[iarg + 1]);
      contact_from_pair = true;
      iarg += 2;
    } else if (key == "near_list") {
      need(1, "near_list");
      near_list = PERIDEM_NS::choice(lmp, STYLE, "near_list", arg[iarg + 1], {"no", "yes"}) == 1;
      iarg += 2;
    } else if (key == "lost") {
      need(1, "lost");
      const int mode =
          PERIDEM_NS::choice(lmp, STYLE, "lost", arg[iarg + 1], {"warn", "error", "delete"});
      lost_error = mode == 1;
      lost_delete = mode == 2;
      iarg += 2;
    } else {
      const int used = parser.consume(narg, arg, iarg);
      if (used == 0)
        error->all(FLERR, "{}: unknown wall or keyword {} (walls: xlo xhi ylo yhi{})", STYLE, key,
                   domain->dimension == 3 ? " zlo zhi" : "");
      iarg += used;
    }
  }

  int nactive = 0;
  for (int w = 0; w < nwalls; w++) {
    if (walls[w].active) nactive++;
    if (!walls[w].active && (walls[w].motion != Motion::Fixed || walls[w].shear[0] != 0.0 ||
                             walls[w].shear[1] != 0.0 || walls[w].shear[2] != 0.0))
      error->all(FLERR, "{}: wall {} moves but is not defined (add '{} position')", STYLE, FACES[w],
                 FACES[w]);
  }
  if (nactive == 0) error->all(FLERR, "{}: no wall given (xlo xhi ylo yhi zlo zhi)", STYLE);
  if (contact_from_pair) {
    if (parser.any())
      error->all(FLERR,
                 "{}: contact pair takes the contact law from pair_style peridem/contact: "
                 "give no contact keywords",
                 STYLE);
  } else {
    contact = parser.finish(domain->dimension);
    if (comm->me == 0)
      utils::logmesg(lmp, "{} {}: {}\n", STYLE, id, PERIDEM_NS::describe_contact(contact));
  }
  check_order("as given");
  check_periodic();
}

FixPeridemWall::~FixPeridemWall()
{
  delete[] extlist;
}

int FixPeridemWall::setmask()
{
  return POST_INTEGRATE | POST_FORCE | POST_FORCE_RESPA | END_OF_STEP | POST_RUN | MIN_POST_FORCE |
         (lost_delete ? PRE_EXCHANGE : 0);
}

/* ---------------------------------------------------------------------- */

int FixPeridemWall::face_index(const std::string &name)
{
  for (int w = 0; w < peridem::kMaxWalls; w++)
    if (name == FACES[w]) return w;
  return -1;
}

int FixPeridemWall::parse_face(const char *word) const
{
  const int w = face_index(word);
  if (w < 0 || w >= nwalls)
    error->all(FLERR, "{}: unknown wall {} (walls: xlo xhi ylo yhi{})", STYLE, word,
               domain->dimension == 3 ? " zlo zhi" : "");
  return w;
}

/* ----------------------------------------------------------------------
   'contact pair': each node meets the walls with the law of pair_coeff I I
   of its type I (repulsion, nodal or restitution damping, friction);
   with damping centroid the grain's centre is damped against each wall it
   touches (Jha et al. 2021, §3.2; lmp_peridem_wall_damping.h)
------------------------------------------------------------------------- */

void FixPeridemWall::take_contact_from_pair()
{
  // through Pair::extract, as LAMMPS styles share data: no dependence on the pair class
  Pair *pair = force->pair_match("peridem/contact", 1);
  if (!pair) error->all(FLERR, "{}: contact pair needs pair_style peridem/contact", STYLE);
  int dim = 0;
  const auto *params =
      static_cast<const peridem::ContactParams *>(pair->extract("peridem_contact_params", dim));
  if (!params || dim != 1)
    error->all(FLERR, "{}: pair_style peridem/contact gave no contact parameters", STYLE);
  type_params.assign(atom->ntypes + 1, peridem::ContactParams());
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!(params[t].Kn > 0.0)) // Kn > 0 for every pair_coeff (check_contact_params)
      error->all(FLERR, "{}: contact pair needs pair_coeff {} {} of pair_style peridem/contact",
                 STYLE, t, t);
    type_params[t] = params[t];
  }
  const auto *reach = static_cast<const double *>(pair->extract("peridem_centroid_reach", dim));
  if (!reach || dim != 1)
    error->all(FLERR, "{}: pair_style peridem/contact gave no centroid damping reach", STYLE);
  centroid_damping.set_types(type_params, std::vector<double>(reach, reach + atom->ntypes + 1));
  // (grain IDs: pair_style peridem/contact needs atom_style peridem)
}

/* ----------------------------------------------------------------------
   a wall must stay below (lo) or above (hi) its opposite wall
------------------------------------------------------------------------- */

void FixPeridemWall::check_order(const char *when) const
{
  for (int k = 0; k < nwalls / 2; k++) {
    const Wall &lo = walls[2 * k], &hi = walls[2 * k + 1];
    if (!lo.active || !hi.active) continue;
    if (lo.motion == Motion::Variable && lo.var_step < 0) continue; // not evaluated yet
    if (hi.motion == Motion::Variable && hi.var_step < 0) continue;
    if (!(lo.pos < hi.pos))
      error->all(FLERR, "{}: wall {} at {} is not below wall {} at {} ({})", STYLE, FACES[2 * k],
                 lo.pos, FACES[2 * k + 1], hi.pos, when);
  }
}

/* ----------------------------------------------------------------------
   a wall on a periodic dimension would push nodes near its periodic image
   across the seam; LAMMPS's fix wall refuses it the same way.
   Checked when defined and at each run (change_box may change boundaries).
------------------------------------------------------------------------- */

void FixPeridemWall::check_periodic() const
{
  for (int w = 0; w < nwalls; w++)
    if (walls[w].active && domain->periodicity[w / 2])
      error->all(FLERR,
                 "{}: wall {} is on a periodic dimension ({}); use boundary f, s or m in {} "
                 "for walls",
                 STYLE, FACES[w], "xyz"[w / 2], "xyz"[w / 2]);
}

// damping and friction take v: a run's setup must see the v(n - 1/2) of the step it continues
// (created here, not in the constructor: LAMMPS is still adding this fix there)
void FixPeridemWall::post_constructor()
{
  const peridem::ContactParams &p = contact.params;
  if (!contact_from_pair &&
      (p.damping != peridem::ContactDamping::None || p.friction != peridem::ContactFriction::None))
    FixPeridemVelocityHistory::instance(lmp, STYLE);
}

void FixPeridemWall::init()
{
  check_periodic();
  // made by this fix or by pair_style peridem/contact (its init_style runs before this)
  const int ihistory = modify->find_fix(FixPeridemVelocityHistory::ID);
  history =
      ihistory >= 0 ? dynamic_cast<FixPeridemVelocityHistory *>(modify->fix[ihistory]) : nullptr;
  // under run_style respa the walls act at the outermost level, with the contact pair style
  // (as LAMMPS's fix wall styles); before, they silently did nothing under respa
  if (utils::strmatch(update->integrate_style, "^respa"))
    ilevel_respa = static_cast<Respa *>(update->integrate)->nlevels - 1;
  if (contact_from_pair) take_contact_from_pair();
  for (int w = 0; w < nwalls; w++) {
    Wall &wall = walls[w];
    if (wall.motion != Motion::Variable) continue;
    wall.ivar = input->variable->find(wall.var.c_str());
    if (wall.ivar < 0)
      error->all(FLERR, "{}: variable {} for wall {} does not exist", STYLE, wall.var, FACES[w]);
    if (!input->variable->equalstyle(wall.ivar))
      error->all(FLERR, "{}: variable {} for wall {} is not equal-style", STYLE, wall.var,
                 FACES[w]);
  }
}

void FixPeridemWall::setup(int vflag)
{
  if (!start_checked) check_start();
  lost_local = 0;
  near_ncalls = -1; // Verlet::setup() sorted the atoms and reset neighbor->ncalls
  in_setup = 1;
  if (utils::strmatch(update->integrate_style, "^respa")) {
    auto respa = static_cast<Respa *>(update->integrate);
    respa->copy_flevel_f(ilevel_respa);
    post_force(vflag);
    respa->copy_f_flevel(ilevel_respa);
  } else {
    post_force(vflag);
  }
  in_setup = 0;
}

void FixPeridemWall::post_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel == ilevel_respa) post_force(vflag);
}

/* ----------------------------------------------------------------------
   first run only: nodes already within Rc of a wall (warning), or wholly
   beyond one (an error unless 'lost warn': a wall placed through a grain
   is a placement mistake, not a time-step problem); lmp_peridem_startup.h
------------------------------------------------------------------------- */

void FixPeridemWall::check_start()
{
  start_checked = true;
  update_variable_walls();
  const peridem::WallBox box = make_box();
  PERIDEM_NS::OverlapReport near, beyond;
  double rc_max = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double Rc = (contact_from_pair ? type_params[atom->type[i]] : contact.params).Rc;
    rc_max = std::max(rc_max, Rc);
    int wmin = -1;
    double dmin = Rc;
    for (int w = 0; w < nwalls; w++) {
      if (!box.active[w]) continue;
      const double d = peridem::wall_distance(box, w, atom->x[i]);
      if (d < dmin) {
        dmin = d;
        wmin = w;
      }
    }
    if (wmin < 0) continue;
    const tagint grain = atom->molecule_flag ? atom->molecule[i] : atom->tag[i];
    (dmin <= -Rc ? beyond : near).add(grain, fmt::format("wall {}", FACES[wmin]));
  }
  double rc_all = 0.0;
  MPI_Allreduce(&rc_max, &rc_all, 1, MPI_DOUBLE, MPI_MAX, world);
  const bigint nbeyond = beyond.total(lmp);
  if (nbeyond > 0 && lost_error)
    error->all(FLERR,
               "{} {}: {} nodes lie more than Rc = {} beyond a wall at the first step (e.g. {}): "
               "a wall placed through a grain? Move the wall or the grains (or use 'lost warn' "
               "to let them be)",
               STYLE, id, nbeyond, rc_all, beyond.example_list());
  near.report(lmp, fmt::format("{} {}", STYLE, id), "nodes and walls", rc_all);
  warn_tight_box(rc_all);
}

/* ----------------------------------------------------------------------
   a wall still pushes a node up to Rc beyond its plane; a fixed box face
   closer than that outside the wall (a wall at EDGE) loses such a node
   ("Lost atoms") although the wall would have pushed it back
------------------------------------------------------------------------- */

void FixPeridemWall::warn_tight_box(double Rc) const
{
  std::string tight;
  for (int w = 0; w < nwalls; w++) {
    const int dim = w / 2, side = w % 2;
    // periodic dimensions are refused; a shrink-wrapped face follows the nodes
    if (!walls[w].active || domain->boundary[dim][side] != 1) continue;
    const double room =
        side == 0 ? walls[w].pos - domain->boxlo[dim] : domain->boxhi[dim] - walls[w].pos;
    if (room < Rc * (1.0 - 1e-9)) // a face exactly Rc outside is safe (round-off)
      tight +=
          fmt::format("{}{} ({:.3g} inside the face)", tight.empty() ? "" : ", ", FACES[w], room);
  }
  if (!tight.empty() && comm->me == 0)
    error->warning(FLERR,
                   "{} {}: walls {} lie less than Rc = {} inside a fixed box face: a node the "
                   "wall pushes back from beyond its plane can leave the box and be lost. Put "
                   "the box faces Rc or more outside the walls, or make those boundaries "
                   "shrink-wrapped (boundary m)",
                   STYLE, id, tight, Rc);
}

void FixPeridemWall::min_setup(int vflag)
{
  in_setup = 1;
  post_force(vflag);
  in_setup = 0;
}

void FixPeridemWall::min_post_force(int vflag)
{
  in_setup = 1; // no dissipation bookkeeping, walls do not move
  post_force(vflag);
  in_setup = 0;
}

/* ----------------------------------------------------------------------
   walls with a velocity (given or from the servo) move with the nodes
------------------------------------------------------------------------- */

void FixPeridemWall::post_integrate()
{
  const double dt = update->dt;
  for (int w = 0; w < nwalls; w++) {
    Wall &wall = walls[w];
    if (wall.motion == Motion::Velocity || wall.motion == Motion::Servo) wall.pos += wall.vel * dt;
  }
  check_order("after a step");
}

/* ----------------------------------------------------------------------
   variable walls: position at this step; velocity = backward difference
   over the steps since the last evaluation (0 at the first evaluation)
------------------------------------------------------------------------- */

void FixPeridemWall::update_variable_walls()
{
  if (!var_any) return;
  modify->clearstep_compute();
  const bigint step = update->ntimestep;
  for (int w = 0; w < nwalls; w++) {
    Wall &wall = walls[w];
    if (wall.motion != Motion::Variable || wall.var_step == step) continue;
    const double pos = input->variable->compute_equal(wall.ivar);
    wall.vel = wall.var_step < 0 ? 0.0 : (pos - wall.pos) / ((step - wall.var_step) * update->dt);
    wall.pos = pos;
    wall.var_step = step;
  }
  modify->addstep_compute(step + 1);
  check_order("from its variable");
}

peridem::WallBox FixPeridemWall::make_box() const
{
  peridem::WallBox box;
  box.dimension = domain->dimension;
  for (int w = 0; w < nwalls; w++) {
    box.active[w] = walls[w].active;
    if (w % 2 == 0)
      box.lo[w / 2] = walls[w].pos;
    else
      box.hi[w / 2] = walls[w].pos;
  }
  return box;
}

/* ----------------------------------------------------------------------
   length (2D) or area (3D) of wall w: the extent of the container along
   the other axes, between their walls or the simulation box edges
------------------------------------------------------------------------- */

double FixPeridemWall::wall_area(int w) const
{
  double area = 1.0;
  for (int k = 0; k < domain->dimension; k++) {
    if (k == w / 2) continue;
    const double lo = walls[2 * k].active ? walls[2 * k].pos : domain->boxlo[k];
    const double hi = walls[2 * k + 1].active ? walls[2 * k + 1].pos : domain->boxhi[k];
    area *= hi - lo;
  }
  return area;
}

/* ----------------------------------------------------------------------
   node-wall forces on the owned nodes of the group
------------------------------------------------------------------------- */

void FixPeridemWall::post_force(int vflag)
{
  v_init(vflag);
  update_variable_walls();
  const peridem::WallBox box = make_box();
  const int *type = atom->type;

  peridem::WallContactInput in;
  for (int w = 0; w < nwalls; w++) {
    for (int k = 0; k < 3; k++) in.wall_velocity[w][k] = walls[w].shear[k];
    in.wall_velocity[w][w / 2] = walls[w].vel;
  }
  in.dt = update->dt;

  for (int m = 0; m < ENERGY + 2; m++) local[m] = 0.0;
  double **x = atom->x;
  const double *setup_v = history ? history->setup_velocities() : nullptr;
  const double *vel = setup_v ? setup_v : (atom->v ? atom->v[0] : nullptr);
  double **f = atom->f;
  const double *vfrac = atom->vfrac;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  // the damping and friction forces of a run's steps and of its setup, for their work with the
  // full-step velocities (end_of_step); not in a minimisation
  const bool count_work = update->whichflag == 1;
  if (count_work) {
    work_node.clear();
    work_force.clear();
    work_wall = 0.0;
  }

  // in a run, only the nodes within reach of a wall (looping over every node
  // cost 17 % of a 40-grain bed's step); in setup and minimisation, with
  // near_list no, and unless LAMMPS checks the distance every step
  // (neigh_modify every 1 delay 0 check yes: with a delay, nodes may move any
  // distance between two checks), every node
  const bool use_near = near_list && !in_setup && update->whichflag == 1 && neighbor->dist_check &&
                        neighbor->every == 1 && neighbor->delay == 0;
  if (use_near && near_stale()) build_near(box);
  const int ncand = use_near ? (int)near.size() : nlocal;
  const int *cand = near.data();
  const bool damp_centres = contact_from_pair && centroid_damping.any();
  const tagint *molecule = atom->molecule;
  if (damp_centres) centroid_damping.clear();

  for (int ii = 0; ii < ncand; ii++) {
    const int i = use_near ? cand[ii] : ii;
    if (!(mask[i] & groupbit)) continue;
    const peridem::ContactParams &params =
        contact_from_pair ? type_params[type[i]] : contact.params;
    const double Rc = params.Rc;
    const double reach = damp_centres ? centroid_damping.reach(type[i]) : 0.0;
    int wmin = -1;
    double dmin = Rc;
    for (int w = 0; w < nwalls; w++) {
      if (!box.active[w]) continue;
      const double d = peridem::wall_distance(box, w, x[i]);
      if (d < reach && d > -Rc) centroid_damping.touch(molecule[i], w, type[i]);
      if (d < dmin) {
        dmin = d;
        wmin = w;
      }
    }
    if (wmin < 0) continue; // no wall within Rc
    if (dmin <= -Rc) {
      // the whole contact disk/ball lies beyond the wall: no force can bring it back
      if (lost_error)
        error->one(FLERR,
                   "{}: atom {} is {} beyond wall {} (more than Rc = {}): it crossed the wall "
                   "and feels no wall force. Use a smaller time step, a stiffer contact, or "
                   "'lost warn' to count such nodes instead",
                   STYLE, atom->tag[i], -dmin, FACES[wmin], Rc);
      local[NLOST] += 1.0;
      lost_local++;
      continue;
    }
    for (int k = 0; k < 3; k++) {
      in.x[k] = x[i][k];
      in.v[k] = vel[3 * i + k];
    }
    in.vol = vfrac[i];
    in.mass = rmass[i];
    const peridem::WallContactResult res = peridem::wall_contact_force(box, in, params);
    for (int k = 0; k < 3; k++) f[i][k] += res.f[k];
    local[ENERGY] += res.energy;
    if (count_work && (res.f_dis[0] != 0.0 || res.f_dis[1] != 0.0 || res.f_dis[2] != 0.0))
      keep_work(i, res.f_dis, res.wall_power);
    for (int w = 0; w < nwalls; w++)
      for (int k = 0; k < 3; k++) local[3 * w + k] += res.f_wall[w][k];

    // not vflag_either: Fix::v_setup() of this LAMMPS (29 Sep 2021) leaves it unset, so the
    // virial was tallied only on steps after a step without virial (and from garbage at setup)
    if (vflag_global || vflag_atom) {
      double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      for (int w = 0; w < nwalls; w++) add_wall_virial(w, x[i], res.f_wall[w], vir);
      v_tally(i, vir);
    }
  }
  if (damp_centres) apply_centroid_damping(vel, count_work);
  // a setup has v(n) already: the power of the step it continues, or of the state it starts from
  if (count_work && in_setup) power_prev = dissipative_power();
  if (count_work && !in_setup) work_step = update->ntimestep;
  local[DISSIPATED] = dissipated_local;
  reduced = 0;
  if (servo_any) servo_control();
}

/* ----------------------------------------------------------------------
   the work of the damping and friction forces with the full-step
   velocities v(n) of velocity Verlet, by the trapezoidal rule of
     P(n) = sum_i (F_i(n) . v_i(n) - sum_w F_iw(n) . v_w),
   F_iw the force of wall w on node i and v_w the wall's velocity
   (peridem::dissipated_in_step at the end of each step, P of the setup
   opening a run). pair_style peridem/contact explains the choice
   (count_work there): stuck contacts are counted with the kinetic energy
   they take, not with each flip of their force. Atoms do not change ranks
   or places between post_force and end_of_step.
------------------------------------------------------------------------- */

void FixPeridemWall::keep_work(int i, const double *f, double wall_rate)
{
  work_node.push_back(i);
  work_force.insert(work_force.end(), f, f + 3);
  work_wall += wall_rate;
}

double FixPeridemWall::dissipative_power() const
{
  double **v = atom->v;
  double power = -work_wall;
  for (std::size_t n = 0; n < work_node.size(); n++) {
    const double *fi = &work_force[3 * n];
    const double *vi = v[work_node[n]];
    power += fi[0] * vi[0] + fi[1] * vi[1] + fi[2] * vi[2];
  }
  return power;
}

void FixPeridemWall::end_of_step()
{
  if (work_step != update->ntimestep) return;
  work_step = -1;
  dissipated_local += peridem::dissipated_in_step(power_prev, dissipative_power(), update->dt);
  local[DISSIPATED] = dissipated_local;
  reduced = 0;
}

/* ----------------------------------------------------------------------
   each wall acts as a partner on its plane: virial del (x) f, del from the
   plane to the node along the wall's axis, f the force of wall w on the
   node (-reaction), added to vir
------------------------------------------------------------------------- */

void FixPeridemWall::add_wall_virial(int w, const double *xi, const double *fw, double *vir) const
{
  if (fw[0] == 0.0 && fw[1] == 0.0 && fw[2] == 0.0) return;
  const int k = w / 2;
  const double del = xi[k] - walls[w].pos;
  vir[k] -= del * fw[k];
  if (k == 0) {
    vir[3] -= del * fw[1];
    vir[4] -= del * fw[2];
  } else if (k == 1) {
    vir[3] -= del * fw[0];
    vir[5] -= del * fw[2];
  } else {
    vir[4] -= del * fw[0];
    vir[5] -= del * fw[1];
  }
}

/* ----------------------------------------------------------------------
   contact pair with damping centroid: the dashpot between the centre of
   each grain and each wall it touches (the touches were collected in
   post_force), its forces on the nodes, the wall reactions and the
   virial, and the forces kept for their work (lmp_peridem_wall_damping.h)
------------------------------------------------------------------------- */

void FixPeridemWall::apply_centroid_damping(const double *vel, bool count_work)
{
  double outward_normal[peridem::kMaxWalls][3] = {}, velocity[peridem::kMaxWalls][3] = {};
  for (int w = 0; w < nwalls; w++) {
    outward_normal[w][w / 2] = outward(w);
    for (int k = 0; k < 3; k++) velocity[w][k] = walls[w].shear[k];
    velocity[w][w / 2] = walls[w].vel;
  }
  double **x = atom->x;
  double **f = atom->f;
  const bool tally = vflag_global || vflag_atom;
  centroid_damping.apply(lmp, vel, outward_normal, velocity, [&](int i, int w, const double *fi) {
    for (int k = 0; k < 3; k++) {
      f[i][k] += fi[k];
      local[3 * w + k] -= fi[k];
    }
    if (count_work)
      keep_work(i, fi, fi[0] * velocity[w][0] + fi[1] * velocity[w][1] + fi[2] * velocity[w][2]);
    if (tally) {
      double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      add_wall_virial(w, x[i], fi, vir);
      v_tally(i, vir);
    }
  });
}

/* ----------------------------------------------------------------------
   the list of nodes near a wall is rebuilt when LAMMPS reneighbours (atoms
   may have moved to other ranks or been sorted) or when a wall has moved
   by more than half the skin since the list was built. LAMMPS's distance
   check keeps every node within half the skin of where it was at the last
   reneighbouring, so between two reneighbourings a node moves by at most
   one skin: a node further than Rc + 1.5 skin from every wall stays beyond
   Rc of it until the list is rebuilt. Verlet::setup() of every run sorts
   the atoms and then resets neighbor->ncalls to 0: a list built at ncalls 0
   in the previous run (a run without reneighbouring) would look fresh while
   its indices name other atoms, so setup() marks the list stale
------------------------------------------------------------------------- */

bool FixPeridemWall::near_stale() const
{
  if (neighbor->ncalls != near_ncalls || atom->nlocal != near_nlocal) return true;
  for (int w = 0; w < nwalls; w++)
    if (walls[w].active && std::fabs(walls[w].pos - near_pos[w]) > near_slack) return true;
  return false;
}

void FixPeridemWall::build_near(const peridem::WallBox &box)
{
  double rc_max = contact.params.Rc;
  if (contact_from_pair)
    for (std::size_t t = 1; t < type_params.size(); t++)
      rc_max = std::max(rc_max, type_params[t].Rc);
  rc_max = std::max(rc_max, centroid_damping.max_reach());
  const double reach = rc_max + 1.5 * neighbor->skin;
  double **x = atom->x;
  const int nlocal = atom->nlocal;
  near.clear();
  for (int i = 0; i < nlocal; i++) {
    for (int w = 0; w < nwalls; w++) {
      if (box.active[w] && peridem::wall_distance(box, w, x[i]) < reach) {
        near.push_back(i);
        break;
      }
    }
  }
  near_ncalls = neighbor->ncalls;
  near_nlocal = nlocal;
  for (int w = 0; w < nwalls; w++) near_pos[w] = walls[w].pos;
  near_slack = 0.5 * neighbor->skin;
}

void FixPeridemWall::reduce()
{
  if (reduced) return;
  MPI_Allreduce(local, total, NSUM, MPI_DOUBLE, MPI_SUM, world);
  reduced = 1;
}

/* ----------------------------------------------------------------------
   servo: the wall moves outward at
     v_out = clamp(gain (N/A - P), -vmax, vmax)
   N the normal load the nodes put on the wall (this step), A its length
   (2D) or area (3D), P the target pressure. Against a bed of stiffness
   k_eff (force per displacement) the load relaxes as exp(-t/tau) with
   tau = A/(gain k_eff): stable for any gain with dt < 2 tau, without
   overshoot while tau is long against the bed's own response time.
------------------------------------------------------------------------- */

void FixPeridemWall::servo_control()
{
  reduce();
  for (int w = 0; w < nwalls; w++) {
    Wall &wall = walls[w];
    if (wall.motion != Motion::Servo) continue;
    const double load = outward(w) * total[3 * w + w / 2];
    const double v_out = std::max(
        -wall.vmax, std::min(wall.vmax, wall.gain * (load / wall_area(w) - wall.pressure)));
    wall.vel = outward(w) * v_out;
  }
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   'lost delete': fragments may leave a container through an open
   side in impacts. At each reneighbouring, before LAMMPS would lose them,
   nodes whose whole contact disk lies beyond a wall (d <= -Rc) or that lie
   beyond a fixed box boundary are deleted together with their bonds; the
   partners count those bonds as broken (compute peridem/damage).
------------------------------------------------------------------------- */

void FixPeridemWall::setup_pre_exchange()
{
  pre_exchange();
}

void FixPeridemWall::pre_exchange()
{
  if (!lost_delete) return;
  update_variable_walls();
  const peridem::WallBox box = make_box();
  const int *type = atom->type;
  const int *mask = atom->mask;
  double **x = atom->x;
  std::vector<int> doomed;
  for (int i = 0; i < atom->nlocal; i++) {
    bool gone = PERIDEM_NS::outside_fixed_boundary(domain, x[i]) >= 0;
    if (!gone && (mask[i] & groupbit)) {
      const double Rc = contact_from_pair ? type_params[type[i]].Rc : contact.params.Rc;
      for (int w = 0; w < nwalls && !gone; w++)
        gone = box.active[w] && peridem::wall_distance(box, w, x[i]) <= -Rc;
    }
    if (gone) doomed.push_back(i);
  }
  deleted_total += PERIDEM_NS::delete_nodes_breaking_bonds(lmp, doomed);
}

void FixPeridemWall::post_run()
{
  if (lost_delete && comm->me == 0)
    utils::logmesg(lmp, "{} {}: {} nodes deleted so far (lost delete)\n", STYLE, id, deleted_total);
  if (lost_error || lost_delete) return;
  bigint all = 0;
  MPI_Allreduce(&lost_local, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all > 0 && comm->me == 0)
    error->warning(FLERR,
                   "{} {}: {} node-steps with a node completely beyond a wall in the last run "
                   "(those nodes felt no wall force)",
                   STYLE, id, all);
  lost_local = 0;
}

double FixPeridemWall::compute_scalar()
{
  reduce();
  return total[ENERGY];
}

void *FixPeridemWall::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "peridem_wall_contact") != 0 || contact_from_pair) return nullptr;
  return &contact.params;
}

double FixPeridemWall::compute_vector(int n)
{
  if (n < PER_WALL * nwalls) {
    const int w = n / PER_WALL, j = n % PER_WALL;
    if (j == 0) return walls[w].pos;
    if (j == 1) return walls[w].vel;
    reduce();
    if (j == 2) return outward(w) * total[3 * w + w / 2];
    return total[3 * w + (j - 3)];
  }
  reduce();
  if (n == PER_WALL * nwalls + 2) return static_cast<double>(deleted_total);
  return n == PER_WALL * nwalls ? total[NLOST] : total[DISSIPATED];
}

/* ----------------------------------------------------------------------
   restart: wall positions and velocities (moving and servo walls), the
   dissipated energy
------------------------------------------------------------------------- */

void FixPeridemWall::write_restart(FILE *fp)
{
  double sum = 0.0;
  MPI_Allreduce(&dissipated_local, &sum, 1, MPI_DOUBLE, MPI_SUM, world);
  if (comm->me != 0) return;
  double list[2 * peridem::kMaxWalls + 2];
  int n = 0;
  list[n++] = nwalls;
  for (int w = 0; w < nwalls; w++) {
    list[n++] = walls[w].pos;
    list[n++] = walls[w].vel;
  }
  list[n++] = sum;
  const int size = n * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), n, fp);
}

void FixPeridemWall::restart(char *buf)
{
  const double *list = reinterpret_cast<const double *>(buf);
  if (static_cast<int>(list[0]) != nwalls) {
    if (comm->me == 0)
      error->warning(FLERR, "{} {}: restart has {} walls, not {}: wall state not restored", STYLE,
                     id, static_cast<int>(list[0]), nwalls);
    return;
  }
  for (int w = 0; w < nwalls; w++) {
    Wall &wall = walls[w];
    if (wall.motion == Motion::Velocity || wall.motion == Motion::Servo) {
      wall.pos = list[1 + 2 * w];
      if (wall.motion == Motion::Servo) wall.vel = list[2 + 2 * w];
    }
  }
  dissipated_local = comm->me == 0 ? list[1 + 2 * nwalls] : 0.0;
  start_checked = true; // a restarted bed rests on its walls
  check_order("from the restart file");
}
