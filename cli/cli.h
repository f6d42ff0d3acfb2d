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
/* host/cosim_main.c: the co-simulation program's own entry (pree-cosim-*). */
int pree_cmd_cosim(int argc, char **argv);

#endif
