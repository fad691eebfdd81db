/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM: registration of all PERIDEM styles into a LAMMPS instance.

   LAMMPS as packaged by Debian has no PLUGIN package. The style maps of
   Force, Modify, Atom and Input are public, so the styles are inserted
   there directly, as the PLUGIN package would do.
------------------------------------------------------------------------- */

#ifndef LMP_REGISTER_PERIDEM_H
#define LMP_REGISTER_PERIDEM_H

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
class AtomVec;
class Bond;
class Pair;
class Fix;
class Compute;
class Command;
} // namespace LAMMPS_NS

extern "C" {
/* Register every PERIDEM style into the LAMMPS instance `lmp` (a
   LAMMPS_NS::LAMMPS *, e.g. from lammps_open() or the Python module's
   lmp.lmp pointer). Safe to call more than once. Returns 0 on success; a
   LAMMPS version other than the one PERIDEM was compiled against is a
   LAMMPS error (the process ends). */
int peridem_register(void *lmp);

/* The LAMMPS version string PERIDEM was compiled against. */
const char *peridem_lammps_version();
}

namespace PERIDEM {

/* The message for a version mismatch, empty when the versions agree. */
std::string version_mismatch_message(const std::string &compiled, const std::string &running);

/* A LAMMPS error (the process ends) unless `lmp` is LAMMPS version
   `expected_version`. */
void check_lammps_version(LAMMPS_NS::LAMMPS *lmp, const std::string &expected_version);

/* Register the styles after checking that `lmp` is the LAMMPS version
   `expected_version`; peridem_register() passes the compiled-in version. */
void register_styles(LAMMPS_NS::LAMMPS *lmp, const std::string &expected_version);

/* The creators LAMMPS's style maps hold (Atom::AtomVecCreator, Force::BondCreator, ...). */
using AtomVecCreator = LAMMPS_NS::AtomVec *(*)(LAMMPS_NS::LAMMPS *);
using BondCreator = LAMMPS_NS::Bond *(*)(LAMMPS_NS::LAMMPS *);
using PairCreator = LAMMPS_NS::Pair *(*)(LAMMPS_NS::LAMMPS *);
using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using ComputeCreator = LAMMPS_NS::Compute *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using CommandCreator = LAMMPS_NS::Command *(*)(LAMMPS_NS::LAMMPS *);

/* Receives every PERIDEM style with its creator, one call per style. */
class StyleSink {
 public:
  virtual ~StyleSink() = default;
  virtual void atom(const char *name, AtomVecCreator creator) = 0;
  virtual void bond(const char *name, BondCreator creator) = 0;
  virtual void pair(const char *name, PairCreator creator) = 0;
  virtual void fix(const char *name, FixCreator creator) = 0;
  virtual void compute(const char *name, ComputeCreator creator) = 0;
  virtual void command(const char *name, CommandCreator creator) = 0;
};

/* The list of PERIDEM styles, shared by register_styles() and the plugin. */
void for_each_style(StyleSink &sink);

} // namespace PERIDEM

#endif
