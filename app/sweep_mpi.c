/* SPDX-License-Identifier: MIT */
/* An MPI sweep's finished runs, each sent to rank 0 as it ends: rank 0 alone writes the study's folder
 * and its journal (the other ranks may run on machines that do not see that folder), so a run another
 * rank finishes reaches the journal, appended and fsync'ed, only through rank 0. A thread of rank 0
 * receives each one at once, beside rank 0's own runs, so a kill -9 of the sweep loses the runs under
 * way on every rank and no run done. */
#define _POSIX_C_SOURCE 200809L
#include <mpi.h>
#include <pthread.h>
#include <string.h>
#include <time.h>

#include "sweep_mpi.h"

enum { TAG_RUN = 1, TAG_DONE = 2 };

typedef struct cs_sweep_receiver {
    pthread_t thread;
    int size; /* the ranks */
    cs_sweep_take *take;
    void *ctx;
} cs_sweep_receiver;

typedef struct run_message {
    long index;
    cs_sweep_result result;
} run_message;

/* Open MPI's blocking receive spins on its core; the receiver polls every millisecond instead, and leaves
 * rank 0's cores to its runs. */
static void *receive(void *arg) {
    cs_sweep_receiver *rx = arg;
    run_message m;
    for (int done = 1; done < rx->size;) { /* rank 0 and the ranks that said they are done */
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
            nanosleep(&(struct timespec){0, 1000000}, NULL);
            continue;
        }
        MPI_Recv(&m, (int)sizeof m, MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (st.MPI_TAG == TAG_DONE)
            done++;
        else
            rx->take(rx->ctx, m.index, &m.result);
    }
    return NULL;
}

/* Rank 0: a thread that receives the runs the other ranks send and calls take with each at once, until
 * every other rank has sent that it is done. The caller serializes take with its own calls of it. 0, or
 * -1 if the thread cannot start. Requires MPI_THREAD_SERIALIZED: rank 0 makes no other MPI call until
 * cs_sweep_receive_end. */
static int cs_sweep_receive_start(cs_sweep_receiver *rx, int size, cs_sweep_take *take, void *ctx) {
    rx->size = size;
    rx->take = take;
    rx->ctx = ctx;
    return pthread_create(&rx->thread, NULL, receive, rx) == 0 ? 0 : -1;
}

/* Rank 0: wait for the receiver to have every other rank's runs. */
static void cs_sweep_receive_end(cs_sweep_receiver *rx) {
    pthread_join(rx->thread, NULL);
}

/* A rank other than 0: send run i's result to rank 0 (from one thread at a time). */
static void cs_sweep_send_run(long i, const cs_sweep_result *r) {
    run_message m;
    memset(&m, 0, sizeof m); /* the padding too: every byte sent is defined */
    m.index = i;
    m.result = *r;
    MPI_Send(&m, (int)sizeof m, MPI_BYTE, 0, TAG_RUN, MPI_COMM_WORLD);
}

/* A rank other than 0, after its last run: tell rank 0 that it is done. */
static void cs_sweep_send_done(void) {
    MPI_Send(NULL, 0, MPI_BYTE, 0, TAG_DONE, MPI_COMM_WORLD);
}

/* ---- the study's hooks (study/sweepstudy.h) on MPI_COMM_WORLD ---- */

static cs_sweep_receiver receiver;

static void mpi_share(void *ctx, void *data, long bytes) {
    (void)ctx;
    MPI_Bcast(data, (int)bytes, MPI_BYTE, 0, MPI_COMM_WORLD);
}

static int mpi_largest(void *ctx, int v) {
    (void)ctx;
    MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return v;
}

static int mpi_receive_start(void *ctx, cs_sweep_take *take, void *take_ctx) {
    int size;
    (void)ctx;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return cs_sweep_receive_start(&receiver, size, take, take_ctx);
}

static void mpi_receive_end(void *ctx) {
    (void)ctx;
    cs_sweep_receive_end(&receiver);
}

static void mpi_send_run(void *ctx, long i, const cs_sweep_result *r) {
    (void)ctx;
    cs_sweep_send_run(i, r);
}

static void mpi_send_done(void *ctx) {
    (void)ctx;
    cs_sweep_send_done();
}

static void mpi_abort(void *ctx, int status) {
    (void)ctx;
    MPI_Abort(MPI_COMM_WORLD, status);
}

void cs_sweep_mpi_hooks(cs_sweep_ranks *ranks) {
    ranks->share = mpi_share, ranks->largest = mpi_largest, ranks->receive_start = mpi_receive_start;
    ranks->receive_end = mpi_receive_end, ranks->send_run = mpi_send_run, ranks->send_done = mpi_send_done;
    ranks->abort = mpi_abort;
}
