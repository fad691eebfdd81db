#!/usr/bin/env bash
# mpirun.sh NP COMMAND...: run COMMAND on NP MPI ranks (as root too).
source "$(dirname "$0")/mpi_env.sh"
np="$1"; shift
exec mpirun -np "$np" "$@"
