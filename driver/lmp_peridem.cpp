/* ----------------------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   lmp_peridem: the LAMMPS executable with the PERIDEM styles registered.

   Same command line as `lmp` (-in, -var, -log, -screen, stdin, mpirun -np N):
   it is LAMMPS's own main program, linked with libperidem, whose
   LAMMPS::post_create hook registers the styles when LAMMPS is created and
   again after every `clear` (see post_create_hook.cpp).
------------------------------------------------------------------------- */

#include "exceptions.h"
#include "input.h"
#include "lammps.h"
#include "library.h"
#include "register_driver.h"

#include <cstdio>
#include <cstdlib>
#include <mpi.h>

using namespace LAMMPS_NS;

namespace {
void finalize()
{
  lammps_kokkos_finalize();
  lammps_python_finalize();
}
} // namespace

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
  } catch (LAMMPSAbortException &) {
    // an error on one rank (LAMMPS 2022 and later throw; the message is already printed)
    finalize();
    MPI_Abort(MPI_COMM_WORLD, 1);
  } catch (LAMMPSException &) {
    // an error on every rank (LAMMPS 2022 and later; 29 Sep 2021 exits inside Error::all)
    finalize();
    MPI_Barrier(lammps_comm);
    MPI_Finalize();
    exit(1);
  } catch (fmt::format_error &fe) {
    fprintf(stderr, "fmt::format_error: %s\n", fe.what());
    finalize();
    MPI_Abort(MPI_COMM_WORLD, 1);
    exit(1);
  }

  finalize();
  MPI_Barrier(lammps_comm);
  MPI_Finalize();
  return 0;
}
