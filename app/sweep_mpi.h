/* SPDX-License-Identifier: MIT */
/* An MPI sweep: the ranks share its runs, and each finished run is sent to rank 0 as it ends
 * (app/sweep_mpi.c). Built into cablesim-mpi only. */
#ifndef CS_SWEEP_MPI_H
#define CS_SWEEP_MPI_H

#include "cablesim/sweep.h"

/* The hooks of a sweep's study (cablesim/sweep.h's cs_sweep_ranks_def) that share it among the ranks of
 * MPI_COMM_WORLD, rank 0's receiver thread among them. Requires MPI_THREAD_SERIALIZED: rank 0 makes no other
 * MPI call while the receiver runs. */
void cs_sweep_mpi_hooks(cs_sweep_ranks_def *ranks);

#endif
