/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: contact keywords seen from LAMMPS commands.

   Choices (documented in doc/fix_peridem_wall.rst, "Contact keywords"):
   - bulk modulus k of a material: its K if the file gives it; a material
     given by E alone takes the bond-based Poisson ratio of the dimension
     (1/4 in 3D, 1/3 in 2D, Bhattacharya & Lipton 2023, Remark 1), k = E/(3(1-2 nu)).
   - Rc larger than the horizon: a warning, not an error. The papers keep
     R_c < eps (R_c = 0.95 h or eps/5), but nothing in the law breaks when
     R_c > eps: the contact zone is just thicker than the bond family (a
     calibrated Kn, or a thick wall layer, may want that). An error would
     forbid those; a warning still flags a typo such as Rc 0.5 for 0.5e-3.
------------------------------------------------------------------------- */

#include "lmp_peridem_contact.h"
#include "lmp_peridem_parse.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include "lmp_peridem_material.h"

#include <cmath>
#include <utility>

using namespace LAMMPS_NS;

namespace LAMMPS_NS {
namespace PERIDEM_NS {

ContactParser::ContactParser(LAMMPS *lmp_in, std::string command_in)
    : lmp(lmp_in), command(std::move(command_in))
{
}

double ContactParser::number(int narg, char **arg, int iarg, const char *what) const
{
  if (iarg >= narg) lmp->error->all(FLERR, "{}: keyword {} needs a value", command, what);
  return PERIDEM_NS::number(lmp, command, what, arg[iarg]);
}

double ContactParser::positive(int narg, char **arg, int iarg, const char *what) const
{
  const double v = number(narg, arg, iarg, what);
  if (!(v > 0.0)) lmp->error->all(FLERR, "{}: {} must be > 0, not {}", command, what, arg[iarg]);
  return v;
}

/* ----------------------------------------------------------------------
   one keyword with its values; 0 if the word is not a contact keyword
------------------------------------------------------------------------- */

int ContactParser::consume(int narg, char **arg, int iarg)
{
  const int used = consume_one(narg, arg, iarg);
  if (used > 0) consumed++;
  return used;
}

int ContactParser::consume_one(int narg, char **arg, int iarg)
{
  const std::string key = arg[iarg];
  peridem::ContactParams &p = spec.params;
  if (key == "material") {
    if (iarg + 2 >= narg)
      lmp->error->all(FLERR, "{}: material needs a file name and a material name", command);
    const peridem::Material m = load_material(lmp, command, arg[iarg + 1], arg[iarg + 2]);
    have_material = true;
    material_k = m.elastic.K;
    material_E = m.elastic.E;
    material_horizon = m.horizon;
    spec.density = m.density;
    spec.origin = fmt::format("material {} of {}", arg[iarg + 2], arg[iarg + 1]);
    return 3;
  }
  if (key == "Kn") {
    p.Kn = positive(narg, arg, iarg + 1, "Kn");
    have_kn = true;
    return 2;
  }
  if (key == "horizon") {
    horizon = positive(narg, arg, iarg + 1, "horizon");
    return 2;
  }
  if (key == "Kn_form") {
    if (iarg + 1 >= narg) lmp->error->all(FLERR, "{}: Kn_form needs eps4 or eps5", command);
    const std::string form = arg[iarg + 1];
    if (form != "eps4" && form != "eps5")
      lmp->error->all(FLERR, "{}: Kn_form must be eps4 or eps5, not {}", command, form);
    spec.kn_form = form == "eps4" ? peridem::KnForm::Eps4 : peridem::KnForm::Eps5;
    have_form = true;
    return 2;
  }
  if (key == "Rc") {
    p.Rc = positive(narg, arg, iarg + 1, "Rc (contact radius)");
    have_rc = true;
    return 2;
  }
  if (key == "Rc_factor") {
    rc_factor = positive(narg, arg, iarg + 1, "Rc_factor (Rc = Rc_factor * spacing)");
    have_factor = true;
    return 2;
  }
  if (key == "spacing") {
    spacing = positive(narg, arg, iarg + 1, "spacing");
    return 2;
  }
  if (key == "damping") {
    if (iarg + 1 >= narg)
      lmp->error->all(FLERR,
                      "{}: damping needs none, nodal r_d, restitution eps_n C or centroid eps_n C",
                      command);
    const std::string mode = arg[iarg + 1];
    spec.centroid = false;
    if (mode == "none") {
      p.damping = peridem::ContactDamping::None;
      return 2;
    }
    if (mode == "nodal") {
      p.damping = peridem::ContactDamping::Nodal;
      p.r_d = number(narg, arg, iarg + 2, "damping nodal");
      if (!(p.r_d >= 0.0 && p.r_d <= 1.0))
        lmp->error->all(FLERR, "{}: damping ratio r_d must lie in [0, 1], not {}", command,
                        arg[iarg + 2]);
      return 3;
    }
    if (mode == "restitution" || mode == "centroid") {
      if (mode == "centroid" && !centroid_allowed)
        lmp->error->all(FLERR,
                        "{}: damping centroid acts between grains and is available in pair_coeff "
                        "of pair_style peridem/contact only",
                        command);
      spec.centroid = mode == "centroid";
      p.damping =
          spec.centroid ? peridem::ContactDamping::None : peridem::ContactDamping::Restitution;
      const std::string what = "damping " + mode;
      p.eps_n = number(narg, arg, iarg + 2, what.c_str());
      p.C = number(narg, arg, iarg + 3, (what + " (C)").c_str());
      if (!(p.eps_n > 0.0 && p.eps_n <= 1.0))
        lmp->error->all(FLERR, "{}: {} eps_n must lie in (0, 1], not {}", command, mode,
                        arg[iarg + 2]);
      if (!(p.C > 0.0))
        lmp->error->all(FLERR, "{}: {} constant C must be > 0, not {}", command, mode,
                        arg[iarg + 3]);
      return 4;
    }
    lmp->error->all(FLERR, "{}: damping must be none, nodal, restitution or centroid, not {}",
                    command, mode);
  }
  if (key == "kappa") {
    kappa = positive(narg, arg, iarg + 1, "kappa");
    have_kappa = true;
    return 2;
  }
  if (key == "centroid_range") {
    if (!centroid_allowed)
      lmp->error->all(FLERR,
                      "{}: centroid_range belongs to damping centroid, which is available in "
                      "pair_coeff of pair_style peridem/contact only",
                      command);
    spec.centroid_range = positive(narg, arg, iarg + 1, "centroid_range");
    return 2;
  }
  if (key == "centroid_bounding") {
    if (!centroid_allowed)
      lmp->error->all(FLERR,
                      "{}: centroid_bounding belongs to damping centroid, which is available in "
                      "pair_coeff of pair_style peridem/contact only",
                      command);
    spec.centroid_bounding = positive(narg, arg, iarg + 1, "centroid_bounding");
    return 2;
  }
  if (key == "friction") {
    if (iarg + 1 >= narg)
      lmp->error->all(FLERR, "{}: friction needs none, regularized mu or coulomb mu", command);
    const std::string mode = arg[iarg + 1];
    if (mode == "none") {
      p.friction = peridem::ContactFriction::None;
      p.mu = 0.0;
      return 2;
    }
    if (mode != "regularized" && mode != "coulomb")
      lmp->error->all(FLERR, "{}: friction must be none, regularized or coulomb, not {}", command,
                      mode);
    p.friction = mode == "coulomb" ? peridem::ContactFriction::Coulomb
                                   : peridem::ContactFriction::Regularized;
    p.mu = number(narg, arg, iarg + 2, "friction");
    if (!(p.mu >= 0.0))
      lmp->error->all(FLERR, "{}: friction coefficient mu must be >= 0, not {}", command,
                      arg[iarg + 2]);
    return 3;
  }
  return 0;
}

/* ----------------------------------------------------------------------
   K_n, R_c and the restitution modulus from what was given; checks
------------------------------------------------------------------------- */

ContactSpec ContactParser::finish(int dimension) const
{
  ContactSpec out = spec;
  peridem::ContactParams &p = out.params;
  Error *error = lmp->error;
  if (have_material == have_kn)
    error->all(FLERR, "{}: give exactly one of 'material FILE NAME' and 'Kn value'", command);
  if (have_rc == have_factor)
    error->all(FLERR, "{}: give exactly one of 'Rc value' and 'Rc_factor f' (with spacing h)",
               command);

  // K_n = 18 k/(pi eps^4) per unit thickness in 2D, eps^5 in 3D (contact_stiffness); eps^4
  // in 3D would give a K_n with the units of no force at all
  if (!have_form)
    out.kn_form = peridem::default_kn_form(dimension);
  else if (out.kn_form == peridem::KnForm::Eps4 && dimension != 2)
    error->all(FLERR,
               "{}: Kn_form eps4 (force per unit thickness) is for 2d simulations only; a {}d "
               "simulation uses eps5",
               command, dimension);

  out.horizon = horizon > 0.0 ? horizon : (have_material ? material_horizon : 0.0);
  if (have_material) {
    if (!(out.horizon > 0.0))
      error->all(FLERR, "{}: {} has no horizon: add horizon to the file or the command", command,
                 out.origin);
    double k = material_k;
    if (std::isnan(k) && !std::isnan(material_E)) {
      const double nu = dimension == 2 ? 1.0 / 3.0 : 0.25; // bond-based Poisson ratio
      k = material_E / (3.0 * (1.0 - 2.0 * nu));
    }
    if (!(k > 0.0))
      error->all(FLERR, "{}: {} gives neither a bulk modulus K nor E", command, out.origin);
    out.bulk_modulus = k;
    p.Kn = peridem::contact_stiffness(k, out.horizon, out.kn_form);
  } else {
    out.origin = "Kn given";
    if (out.horizon > 0.0)
      out.bulk_modulus = peridem::bulk_modulus_from_stiffness(p.Kn, out.horizon, out.kn_form);
  }

  if (have_factor) {
    if (!(spacing > 0.0))
      error->all(FLERR, "{}: Rc_factor needs the node spacing: add 'spacing h'", command);
    p.Rc = rc_factor * spacing;
  }

  set_kappa(out, dimension);

  if (out.centroid_range > 0.0) {
    if (!out.centroid)
      error->all(FLERR, "{}: centroid_range {} needs damping centroid eps_n C", command,
                 out.centroid_range);
    if (out.centroid_range < p.Rc)
      error->all(FLERR, "{}: centroid_range {} must be >= the contact radius Rc = {}", command,
                 out.centroid_range, p.Rc);
  }

  if (out.centroid_bounding > 0.0) {
    if (!out.centroid)
      error->all(FLERR, "{}: centroid_bounding {} needs damping centroid eps_n C", command,
                 out.centroid_bounding);
    if (out.centroid_range > 0.0)
      error->all(FLERR, "{}: centroid_bounding and centroid_range exclude each other", command);
  }

  if (out.horizon > 0.0 && p.Rc > out.horizon && lmp->comm->me == 0)
    error->warning(FLERR, "{}: contact radius Rc = {} is larger than the horizon {}", command, p.Rc,
                   out.horizon);

  try {
    peridem::check_contact_params(p);
  } catch (peridem::ParameterError &e) {
    error->all(FLERR, "{}: {}", command, e.what());
  }
  return out;
}

/* ----------------------------------------------------------------------
   kappa_eff of the restitution and centroid dashpots (Jha et al. 2021,
   eq. 23, 25, 28): the bulk modulus k behind K_n, or kappa given
------------------------------------------------------------------------- */

void ContactParser::set_kappa(ContactSpec &out, int dimension) const
{
  peridem::ContactParams &p = out.params;
  Error *error = lmp->error;
  if (p.damping != peridem::ContactDamping::Restitution && !out.centroid) {
    if (have_kappa)
      error->all(FLERR,
                 "{}: kappa {:g} needs damping restitution or centroid (it sets their dashpot)",
                 command, kappa);
    return;
  }
  if (have_kappa) {
    p.kappa_eff = kappa;
    out.kappa_origin = "kappa given";
    return;
  }
  if (!(out.bulk_modulus > 0.0))
    error->all(FLERR,
               "{}: damping {} needs the bulk modulus: use 'material FILE NAME', or give "
               "'horizon eps' with Kn, or 'kappa k'",
               command, out.centroid ? "centroid" : "restitution");
  p.kappa_eff = out.bulk_modulus;
  if (have_material) {
    out.kappa_origin = "bulk modulus of " + out.origin;
    return;
  }
  out.kappa_origin = fmt::format("pi eps^{} Kn/18 from Kn, horizon {} and Kn_form {}",
                                 peridem::kn_exponent(out.kn_form), out.horizon,
                                 peridem::kn_form_name(out.kn_form));
  if (dimension == 2 && !have_form) warn_kappa_from_kn(out);
}

// Jha et al.'s (2021) inputs give Kn = 18 K/(pi eps^5) (their eq. 36) with kappa = K.
// Under the 2d default eps4 (since Nov 2026) the same Kn gives kappa = pi eps^4 Kn/18 = K/eps:
// a dashpot sqrt(1/eps) times stronger (a drop that bounced then sticks), with no other sign.
void ContactParser::warn_kappa_from_kn(const ContactSpec &out) const
{
  if (lmp->comm->me != 0) return;
  lmp->error->warning(FLERR,
                      "{}: in 2d an explicit Kn under the default Kn_form eps4 gives the {} "
                      "dashpot kappa = pi eps^4 Kn/18 = {:.6g} (horizon {}); if Kn is 18 K/(pi "
                      "eps^5), as in Jha et al.'s (2021) inputs, that is K/eps, not K. Give "
                      "Kn_form eps5 (or kappa K) to get kappa = K",
                      command, out.centroid ? "centroid" : "restitution", out.params.kappa_eff,
                      out.horizon);
}

/* ---------------------------------------------------------------------- */

ContactSpec parse_contact(LAMMPS *lmp, const std::string &command, int narg, char **arg,
                          int dimension, bool allow_centroid)
{
  ContactParser parser(lmp, command);
  parser.allow_centroid(allow_centroid);
  for (int iarg = 0; iarg < narg;) {
    const int used = parser.consume(narg, arg, iarg);
    if (used == 0) lmp->error->all(FLERR, "{}: unknown keyword {}", command, arg[iarg]);
    iarg += used;
  }
  return parser.finish(dimension);
}

std::string describe_kn_form(peridem::KnForm form)
{
  return form == peridem::KnForm::Eps4 ? "Kn_form eps4: 18 k/(pi eps^4), 2d per unit thickness"
                                       : "Kn_form eps5: 18 k/(pi eps^5)";
}

namespace {
// ", kappa = ... (origin), beta = B sqrt(m_eq) (...)": beta of eq. 23 (nodes) or 28 (grain
// centres) per square root of the mass m_eq, which is known only in contact
std::string describe_dashpot(const ContactSpec &spec)
{
  const peridem::ContactParams &p = spec.params;
  const double per_sqrt_mass =
      peridem::restitution_damping_coefficient(p.eps_n, p.C, p.kappa_eff, p.Rc, 1.0);
  return fmt::format(", kappa = {:.6g} ({}), beta = {:.6g} sqrt({}) (2 C zeta sqrt(kappa Rc {}), "
                     "zeta = {:.6g} from eps_n, Jha et al. 2021 eq. {}; {})",
                     p.kappa_eff, spec.kappa_origin, per_sqrt_mass, spec.centroid ? "M_eq" : "m_eq",
                     spec.centroid ? "M_eq" : "m_eq",
                     peridem::damping_ratio_from_restitution(p.eps_n), spec.centroid ? 28 : 23,
                     spec.centroid ? "M_eq = harmonic mean of the two grain masses"
                                   : "m_eq = harmonic mean of the two node masses, 2 m at a wall");
}
} // namespace

std::string describe_contact(const ContactSpec &spec)
{
  const peridem::ContactParams &p = spec.params;
  std::string damping = "none";
  if (p.damping == peridem::ContactDamping::Nodal)
    damping = fmt::format("nodal r_d = {}", p.r_d);
  else if (p.damping == peridem::ContactDamping::Restitution)
    damping = fmt::format("restitution eps_n = {} C = {}", p.eps_n, p.C);
  if (spec.centroid && spec.centroid_bounding > 0.0)
    damping = fmt::format("centroid eps_n = {} C = {} (grains touch while their centres are "
                          "closer than b + b' + {} Rc, b the bounding radii)",
                          p.eps_n, p.C, spec.centroid_bounding);
  else if (spec.centroid)
    damping = fmt::format("centroid eps_n = {} C = {} (grains touch below {})", p.eps_n, p.C,
                          spec.centroid_reach());
  if (spec.centroid || p.damping == peridem::ContactDamping::Restitution)
    damping += describe_dashpot(spec);
  std::string friction = "none";
  if (p.friction == peridem::ContactFriction::Regularized)
    friction = fmt::format("regularized mu = {}", p.mu);
  else if (p.friction == peridem::ContactFriction::Coulomb)
    friction = fmt::format("coulomb mu = {}", p.mu);
  return fmt::format("Kn = {} ({}, {}), Rc = {}, damping {}, friction {}", p.Kn,
                     describe_kn_form(spec.kn_form), spec.origin, p.Rc, damping, friction);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS
