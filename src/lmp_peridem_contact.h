/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: contact keywords seen from LAMMPS commands.

   The keywords below set one peridem::ContactParams (peridem_contact_law.h).
   They are shared by `pair_coeff` of pair_style peridem/contact and by
   `fix peridem/wall`, so both read the same words the same way:

     material FILE NAME      K_n = 18 k/(pi eps^p) from the material's bulk
                             modulus k and horizon eps (contact_stiffness)
     Kn value                K_n given directly (force/(length volume^2))
     horizon eps             horizon (overrides the material's; with Kn it
                             gives k = pi eps^p K_n/18 for restitution)
     Kn_form eps4 | eps5     p: default eps4 in 2D (force per unit thickness),
                             eps5 in 3D; eps5 in 2D for Jha et al.'s (2021)
                             tests; eps4 in 3D is an error
     Rc value                contact radius R_c
     Rc_factor f             R_c = f h with the node spacing h of
     spacing h               (the papers use f = 0.95; R_c = eps/5 is Rc)
     damping none | nodal r_d | restitution eps_n C | centroid eps_n C
                             (centroid: dashpot between grain centres, PeriDEM
                             Jha et al. 2021, eq. 26-30; pair_style peridem/contact only)
     centroid_range D        damping centroid acts while two nodes of the
                             grains are closer than D >= R_c (default R_c)
     centroid_bounding F     damping centroid acts while the grains' centres
                             are closer than b + b' + F R_c (bounding radii;
                             Jha et al.'s code, F = 1.01)
     kappa k                 the dashpot's kappa (eq. 23, 28) given directly,
                             instead of the bulk modulus behind K_n
     friction none | regularized mu | coulomb mu

   Exactly one of material / Kn, and one of Rc / Rc_factor are required.
   Rc larger than the horizon is allowed with a warning (see parse notes in
   the .cpp). Errors name the command and the bad value; no physics here.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_CONTACT_H
#define LMP_PERIDEM_CONTACT_H

#include "peridem_contact_law.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace LAMMPS_NS {
namespace PERIDEM_NS {

// The parsed result: the law's parameters and what they were derived from.
struct ContactSpec {
  peridem::ContactParams params;
  double bulk_modulus = 0.0; // k behind K_n (0: Kn given without a horizon)
  double horizon = 0.0;      // eps (0: not known)
  double density = 0.0;      // from the material (0: not known)
  // K_n = 18 k/(pi eps^p): p = 4 (2D default) or 5 (3D, or Kn_form eps5)
  peridem::KnForm kn_form = peridem::KnForm::Eps5;
  std::string origin; // for the log, e.g. "material M1 of file"
  // where the restitution/centroid dashpot's kappa (params.kappa_eff) came from, for the log
  std::string kappa_origin;
  // damping centroid eps_n C: a dashpot between the centres of two grains in
  // contact (Jha et al. 2021, eq. 26-30), applied by pair_style peridem/contact.
  // params.damping is then None (no nodal dashpot) and params.eps_n, C and
  // kappa_eff hold eps_bar, C_bar and kappa_eff of eq. 28.
  bool centroid = false;
  // centroid_range D: the dashpot acts while two nodes of the grains are
  // closer than D (0: R_c, eq. 27 as written; D >= R_c)
  double centroid_range = 0.0;
  // centroid_bounding F: instead, the dashpot acts while the grains' centres are closer than
  // b + b' + F R_c, b the bounding radius of each grain (the largest distance of its nodes
  // from its centre in the reference configuration); Jha et al.'s (2021) code does this
  // with F = 1.01 (0: off)
  double centroid_bounding = 0.0;
  // distance below which two grains count as touching for the dashpot
  double centroid_reach() const { return centroid_range > 0.0 ? centroid_range : params.Rc; }
};

// Collects contact keywords among other keywords of a command (layered
// parsing: the owner tries consume() first and handles what it returns 0 for).
class ContactParser {
 public:
  ContactParser(LAMMPS_NS::LAMMPS *lmp, std::string command);

  // If arg[iarg] is a contact keyword, reads it with its values and returns
  // the number of words used; returns 0 for any other word.
  int consume(int narg, char **arg, int iarg);

  // Completes and checks the parameters for a simulation of this dimension;
  // ends the run with a LAMMPS error naming the command if they are invalid.
  ContactSpec finish(int dimension) const;

  // Accept 'damping centroid' (grain-level damping needs the pair style's
  // per-grain centres; a wall fix leaves it off and gets an error).
  void allow_centroid(bool yes) { centroid_allowed = yes; }

  // whether consume() has read any contact keyword
  bool any() const { return consumed > 0; }

 private:
  LAMMPS_NS::LAMMPS *lmp;
  std::string command;
  ContactSpec spec;
  bool have_material = false, have_kn = false, have_rc = false, have_factor = false;
  bool have_form = false, have_kappa = false;
  bool centroid_allowed = false;
  int consumed = 0;
  double material_k = 0.0, material_horizon = 0.0, material_E = 0.0;
  double horizon = 0.0, rc_factor = 0.0, spacing = 0.0, kappa = 0.0;

  int consume_one(int narg, char **arg, int iarg);
  // arg[iarg] as a number (error if missing), and as a number > 0
  double number(int narg, char **arg, int iarg, const char *what) const;
  double positive(int narg, char **arg, int iarg, const char *what) const;
  // kappa of the restitution/centroid dashpot, and where it came from
  void set_kappa(ContactSpec &out, int dimension) const;
  void warn_kappa_from_kn(const ContactSpec &out) const;
};

// All of arg[0..narg-1] must be contact keywords (pair_coeff after the types).
ContactSpec parse_contact(LAMMPS_NS::LAMMPS *lmp, const std::string &command, int narg, char **arg,
                          int dimension, bool allow_centroid = false);

// "Kn_form eps4: 18 k/(pi eps^4), 2d per unit thickness" (or eps5), for the log
std::string describe_kn_form(peridem::KnForm form);

// One line for the log: "Kn = ..., Rc = ..., damping ..., friction ..."; with restitution or
// centroid damping also kappa and beta (per square root of m_eq) and where they came from.
std::string describe_contact(const ContactSpec &spec);

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
