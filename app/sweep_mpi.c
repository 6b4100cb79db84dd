/* SPDX-License-Identifier: MIT */
/* An MPI sweep's finished runs, each sent to rank 0 as it ends: rank 0 alone writes the study's folder
 * and its journal (the other ranks may run on machines that do not see that folder), so a run another
 * rank finishes reaches the journal, appended and fsync'ed, only through rank 0. A thread of rank 0
 * receives each one at once, beside rank 0's own runs, so a kill -9 of the sweep loses the runs under
 * way on every rank and no run done. */
#define _POSIX_C_SOURCE 200809L
#include <mpi.h>
#include <string.h>
#include <time.h>

#include "sweep_mpi.h"

enum { TAG_RUN = 1, TAG_DONE = 2 };

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

int cs_sweep_receive_start(cs_sweep_receiver *rx, int size, cs_sweep_take *take, void *ctx) {
    rx->size = size;
    rx->take = take;
    rx->ctx = ctx;
    return pthread_create(&rx->thread, NULL, receive, rx) == 0 ? 0 : -1;
}

void cs_sweep_receive_end(cs_sweep_receiver *rx) {
    pthread_join(rx->thread, NULL);
}

void cs_sweep_send_run(long i, const cs_sweep_result *r) {
    run_message m;
    memset(&m, 0, sizeof m); /* the padding too: every byte sent is defined */
    m.index = i;
    m.result = *r;
    MPI_Send(&m, (int)sizeof m, MPI_BYTE, 0, TAG_RUN, MPI_COMM_WORLD);
}

void cs_sweep_send_done(void) {
    MPI_Send(NULL, 0, MPI_BYTE, 0, TAG_DONE, MPI_COMM_WORLD);
}
