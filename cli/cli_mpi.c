// SPDX-License-Identifier: Apache-2.0
/* cli_mpi.c: the program under an MPI launcher (mpirun, srun). Built with Open MPI when make
 * finds mpicc (MPI=1, the default then; MPI=0 builds without). The same binary runs without a
 * launcher: MPI is initialised only when the launcher's environment says the process is one of
 * its ranks, so a plain `pree render` does not start an MPI singleton.
 *
 * With more than one rank only `pree render` (distributed: model/ppm/render_dist.c,
 * docs/scale_out.md) and `pree cosim` (one Verilated PREE a rank: host/cosim_main.c) run; any
 * other command stops with one message from rank 0 and exit status 2. Ranks of a render other
 * than 0 are silent (stdout and stderr on /dev/null): rank 0 prints, for all. */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
#ifdef PREE_MPI
#include <mpi.h>
#endif

/* The launchers' variables that name a process as one of their ranks (Open MPI's mpirun, PMIx
 * as under Slurm's srun --mpi=pmix, PMI-1/2 as under srun --mpi=pmi2). */
static int under_launcher(void)
{
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", NULL};
    for (const char *const *v = vars; *v; v++)
        if (getenv(*v)) return 1;
    return 0;
}

/* MPI_Init_thread under the launcher. cmd: the command, which must be one that runs distributed
 * (render, or cosim in the co-simulation program) when there is more than one rank; silence:
 * ranks other than 0 print nothing. 1, or -1 with rank 0's message. */
static int begin(int *argc, char ***argv, const char *cmd, int silence)
{
    if (!under_launcher()) return 1;
#ifdef PREE_MPI
    /* FUNNELED: the render's OpenMP threads run beside MPI, and only the main thread calls it
     * (the exchange in flight is polled by thread 0 of the tracing loop). */
    int provided = MPI_THREAD_SINGLE;
    if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        fprintf(stderr, "pree: MPI_Init_thread failed under the launcher\n");
        return -1;
    }
    if (provided < MPI_THREAD_FUNNELED) {
        fprintf(stderr, "pree: the MPI library does not support MPI_THREAD_FUNNELED (threads beside MPI)\n");
        MPI_Finalize();
        return -1;
    }
    int size = 1, rank = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (size > 1 && (!cmd || (strcmp(cmd, "render") && strcmp(cmd, "cosim")))) {
        if (rank == 0)
            fprintf(stderr, "pree: %d MPI ranks: only 'pree render' and 'pree cosim' run distributed "
                    "(docs/scale_out.md); run one rank, or without mpirun\n", size);
        MPI_Finalize();
        return -1;
    }
    if (size > 1 && rank > 0 && silence) {   /* rank 0 speaks for all: it reports every rank's failure */
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0) { dup2(null, 1); dup2(null, 2); close(null); }
    }
    return 1;
#else
    (void)argc;
    (void)argv;
    (void)cmd;
    (void)silence;
    const char *n = getenv("OMPI_COMM_WORLD_SIZE");
    if (n && atoi(n) > 1) {
        const char *r = getenv("OMPI_COMM_WORLD_RANK");
        if (!r || atoi(r) == 0)
            fprintf(stderr, "pree: started as one of %s MPI ranks, but built without MPI "
                    "(install libopenmpi-dev: scripts/install-deps.sh, then rebuild)\n", n);
        return -1;
    }
    return 1;
#endif
}

/* `pree cosim` execs its co-simulation program, which initialises MPI itself (no exec after
 * MPI_Init). */
int pree_mpi_begin(int *argc, char ***argv)
{
    const char *cmd = *argc > 1 ? (*argv)[1] : NULL;
    if (cmd && !strcmp(cmd, "cosim")) return 1;
    return begin(argc, argv, cmd, 1);
}

/* Every rank of a co-simulation speaks for itself: its errors are its own. */
int pree_mpi_begin_cosim(int *argc, char ***argv) { return begin(argc, argv, "cosim", 0); }

void pree_mpi_end(void)
{
#ifdef PREE_MPI
    int on = 0, off = 0;
    MPI_Initialized(&on);
    MPI_Finalized(&off);
    if (on && !off) MPI_Finalize();
#endif
}

const char *pree_mpi_build(void)
{
#ifdef PREE_MPI
#ifdef OMPI_MAJOR_VERSION
#define PREE_STR2(x) #x
#define PREE_STR(x) PREE_STR2(x)
    return "Open MPI " PREE_STR(OMPI_MAJOR_VERSION) "." PREE_STR(OMPI_MINOR_VERSION) "." PREE_STR(OMPI_RELEASE_VERSION);
#else
    return "MPI " #MPI_VERSION;
#endif
#else
    return "none";
#endif
}
