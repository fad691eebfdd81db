/* ----------------------------------------------------------------------
   lmp_peridem: the LAMMPS executable with the PERIDEM styles registered.

   Same command line as `lmp` (-in, -var, -log, -screen, stdin, mpirun -np N):
   it is LAMMPS's own main program, linked with libperidem, whose
   LAMMPS::post_create hook registers the styles when LAMMPS is created and
   again after every `clear` (see post_create_hook.cpp).
------------------------------------------------------------------------- */

#include "accelerator_kokkos.h"
#include "input.h"
#include "lammps.h"
#include "lmppython.h"
#include "register_peridem.h"

#include <cstdio>
#include <cstdlib>
#include <mpi.h>

using namespace LAMMPS_NS;

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  MPI_Comm lammps_comm = MPI_COMM_WORLD;

  try {
    auto *lammps = new LAMMPS(argc, argv, lammps_comm);
    // The hook has registered the styles already; registering is idempotent
    // and keeps the styles available even if the hook were bypassed.
    peridem_register(lammps);
    lammps->input->file();
    delete lammps;
  } catch (fmt::format_error &fe) {
    fprintf(stderr, "fmt::format_error: %s\n", fe.what());
    KokkosLMP::finalize();
    Python::finalize();
    MPI_Abort(MPI_COMM_WORLD, 1);
    exit(1);
  }

  KokkosLMP::finalize();
  Python::finalize();
  MPI_Barrier(lammps_comm);
  MPI_Finalize();
  return 0;
}
