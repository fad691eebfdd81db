/* ----------------------------------------------------------------------
   PERIDEM: format tags at the start of the restart sections of PERIDEM
   styles.
------------------------------------------------------------------------- */

#include "lmp_peridem_restart.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <mpi.h>

using namespace LAMMPS_NS;

namespace PERIDEM {

void write_restart_tag(FILE *fp, RestartTag tag)
{
  const int value = tag;
  fwrite(&value, sizeof(int), 1, fp);
}

void check_restart_tag(LAMMPS *lmp, FILE *fp, RestartTag tag, const char *style)
{
  int value = 0;
  // a file without a tag holds other data at this place: read its bytes
  // without sfread's end-of-file error so that the message below is the one
  // the user sees
  if (lmp->comm->me == 0 && fread(&value, sizeof(int), 1, fp) != 1) value = 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, lmp->world);
  if (value != tag)
    lmp->error->all(FLERR,
                    "{}: the restart file was written by an older PERIDEM (its {} settings are in "
                    "another format, tag {:#x}, expected {:#x}); restart it with the version "
                    "that wrote it, or go through write_data in that version and read_data in "
                    "this one",
                    style, style, (unsigned)value, (unsigned)tag);
}

} // namespace PERIDEM
