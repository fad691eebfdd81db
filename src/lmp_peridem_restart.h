/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM: format tags at the start of the restart sections of PERIDEM
   styles.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_RESTART_H
#define LMP_PERIDEM_RESTART_H

#include <cstdio>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace PERIDEM {

// Restart sections of the PERIDEM force styles start with a tag that names
// the style and the version of its format. A file of another format (an
// older PERIDEM, before a field was added) is refused with a clear message
// instead of being misread; raise the version whenever a field changes.
enum RestartTag : int {
  RESTART_BOND_PERIDEM = 0x50444201,     // bond_style peridem: format 1
  RESTART_BOND_PERIDEM_LPS = 0x50444c01, // bond_style peridem/lps: format 1
  RESTART_PAIR_CONTACT = 0x50445001,     // pair_style peridem/contact: format 1
};

void write_restart_tag(FILE *fp, RestartTag tag);

// reads the tag on rank 0, broadcasts it, and ends the run with an error
// naming the style when it is not `tag`
void check_restart_tag(LAMMPS_NS::LAMMPS *lmp, FILE *fp, RestartTag tag, const char *style);

} // namespace PERIDEM

#endif
