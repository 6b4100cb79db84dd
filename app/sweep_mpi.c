/* SPDX-License-Identifier: MIT */
/* An MPI sweep's finished runs, each sent to rank 0 as it ends: rank 0 alone writes the study's folder
 * and its journal (the other ranks may run on machines that do not see that folder), so a run another
 * rank finishes reaches the journal, appended and fsync'ed, only through rank 0. A thread of rank 0
 * receives each one at once, beside rank 0's own runs, so a kill -9 of the sweep loses the runs under
 * way on every rank and no run done. */
#define _POSIX_C_SOURCE 200809L
#include <mpi.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sweep_mpi.h"

enum { TAG_RUN = 1, TAG_DONE = 2 };

/* A run's message: its index, then its result's bytes (as cablesim/sweep.h hands them to send_run). */
typedef struct cs_sweep_receiver {
    pthread_t thread;
    int size;               /* the ranks */
    size_t bytes;           /* a result's */
    unsigned char *message; /* sizeof(long) + bytes */
    cs_sweep_take_fn take;
    void *ctx;
} cs_sweep_receiver;

/* Open MPI's blocking receive spins on its core; the receiver polls every millisecond instead, and leaves
 * rank 0's cores to its runs. */
static void *receive(void *arg) {
    cs_sweep_receiver *rx = arg;
    for (int done = 1; done < rx->size;) { /* rank 0 and the ranks that said they are done */
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
            nanosleep(&(struct timespec){0, 1000000}, NULL);
            continue;
        }
        MPI_Recv(rx->message, (int)(sizeof(long) + rx->bytes), MPI_BYTE, st.MPI_SOURCE, st.MPI_TAG,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (st.MPI_TAG == TAG_DONE) {
            done++;
        } else {
            long index;
            memcpy(&index, rx->message, sizeof index);
            rx->take(rx->ctx, index, rx->message + sizeof index);
        }
    }
    return NULL;
}

/* ---- the study's hooks (cablesim/sweep.h's cs_sweep_ranks_def) on MPI_COMM_WORLD ---- */

static cs_sweep_receiver receiver;

static void mpi_share(void *ctx, void *data, size_t bytes) {
    (void)ctx;
    MPI_Bcast(data, (int)bytes, MPI_BYTE, 0, MPI_COMM_WORLD);
}

static int mpi_largest(void *ctx, int v) {
    (void)ctx;
    MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return v;
}

/* Rank 0: a thread that receives the runs the other ranks send and calls take with each at once, until
 * every other rank has sent that it is done. 0, or -1 if it cannot start. Requires
 * MPI_THREAD_SERIALIZED: rank 0 makes no other MPI call until mpi_receive_end. */
static int mpi_receive_start(void *ctx, size_t bytes, cs_sweep_take_fn take, void *take_ctx) {
    (void)ctx;
    MPI_Comm_size(MPI_COMM_WORLD, &receiver.size);
    receiver.bytes = bytes;
    receiver.take = take;
    receiver.ctx = take_ctx;
    receiver.message = malloc(sizeof(long) + bytes);
    if (receiver.message && pthread_create(&receiver.thread, NULL, receive, &receiver) == 0) return 0;
    free(receiver.message);
    receiver.message = NULL;
    return -1;
}

/* Rank 0: wait for the receiver to have every other rank's runs. */
static void mpi_receive_end(void *ctx) {
    (void)ctx;
    pthread_join(receiver.thread, NULL);
    free(receiver.message);
    receiver.message = NULL;
}

/* A rank other than 0: send run i's result to rank 0 (from one thread at a time). */
static void mpi_send_run(void *ctx, long i, const void *result, size_t bytes) {
    static unsigned char *message;
    static size_t capacity;
    (void)ctx;
    if (capacity < sizeof i + bytes) {
        unsigned char *m = realloc(message, sizeof i + bytes);
        if (!m) MPI_Abort(MPI_COMM_WORLD, 1); /* the run cannot reach rank 0's journal */
        message = m, capacity = sizeof i + bytes;
    }
    memcpy(message, &i, sizeof i);
    memcpy(message + sizeof i, result, bytes);
    MPI_Send(message, (int)(sizeof i + bytes), MPI_BYTE, 0, TAG_RUN, MPI_COMM_WORLD);
}

/* A rank other than 0, after its last run: tell rank 0 that it is done. */
static void mpi_send_done(void *ctx) {
    (void)ctx;
    MPI_Send(NULL, 0, MPI_BYTE, 0, TAG_DONE, MPI_COMM_WORLD);
}

static void mpi_abort(void *ctx, int status) {
    (void)ctx;
    MPI_Abort(MPI_COMM_WORLD, status);
}

void cs_sweep_mpi_hooks(cs_sweep_ranks_def *ranks) {
    ranks->share = mpi_share, ranks->largest = mpi_largest, ranks->receive_start = mpi_receive_start;
    ranks->receive_end = mpi_receive_end, ranks->send_run = mpi_send_run, ranks->send_done = mpi_send_done;
    ranks->abort = mpi_abort;
}
