/* SPDX-License-Identifier: MIT */
/* An MPI sweep's finished runs, each sent to rank 0 as it ends (app/sweep_mpi.c). Built into
 * cablesim-mpi only. */
#ifndef CS_SWEEP_MPI_H
#define CS_SWEEP_MPI_H

#include <pthread.h>

#include "study/sweepstudy.h"

typedef struct cs_sweep_receiver {
    pthread_t thread;
    int size; /* the ranks */
    cs_sweep_take *take;
    void *ctx;
} cs_sweep_receiver;

/* Rank 0: a thread that receives the runs the other ranks send and calls take with each at once, until
 * every other rank has sent that it is done. The caller serializes take with its own calls of it. 0, or
 * -1 if the thread cannot start. Requires MPI_THREAD_SERIALIZED: rank 0 makes no other MPI call until
 * cs_sweep_receive_end. */
int cs_sweep_receive_start(cs_sweep_receiver *rx, int size, cs_sweep_take *take, void *ctx);
/* Rank 0: wait for the receiver to have every other rank's runs. */
void cs_sweep_receive_end(cs_sweep_receiver *rx);
/* A rank other than 0: send run i's result to rank 0 (from one thread at a time). */
void cs_sweep_send_run(long i, const cs_sweep_result *r);
/* A rank other than 0, after its last run: tell rank 0 that it is done. */
void cs_sweep_send_done(void);

#endif
