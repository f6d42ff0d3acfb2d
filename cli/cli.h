// SPDX-License-Identifier: Apache-2.0
/* cli.h: the subcommands of the `pree` program, one function each, dispatched by cli/main.c.
 * Each takes the arguments after its own name (argv[0] is the subcommand name) and returns
 * the process exit status: 0 on success, 1 on a runtime failure, 2 on a usage error.
 * Errors are printed as one line on stderr: "pree <cmd>: <what>: <why>". */
#ifndef PREE_CLI_H
#define PREE_CLI_H

int pree_cmd_render(int argc, char **argv);
int pree_cmd_compare(int argc, char **argv);
int pree_cmd_check(int argc, char **argv);
/* cli_version.c: `git describe` of the tree this program was built from ("unknown" outside git). */
const char *pree_version(void);
/* cli_mpi.c: under an MPI launcher (mpirun, srun) initialise MPI; without one, nothing.
 * pree_mpi_begin returns 1 to go on, or -1 (message printed, by rank 0 only) to exit with
 * status 2; pree_mpi_end finalises what begin initialised. pree_mpi_build: the MPI the program
 * was built with ("Open MPI 4.1.4"), or "none". */
int pree_mpi_begin(int *argc, char ***argv);
/* The co-simulation program's (host/cosim_main.c): every rank prints its own messages. */
int pree_mpi_begin_cosim(int *argc, char ***argv);
void pree_mpi_end(void);
const char *pree_mpi_build(void);
/* host/cosim_main.c: the co-simulation program's own entry (pree-cosim-*). */
int pree_cmd_cosim(int argc, char **argv);

#endif
