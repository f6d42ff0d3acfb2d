// SPDX-License-Identifier: Apache-2.0
/* main.c: the `pree` program: git-style subcommands over the PREE reference engine.
 *
 * `pree cosim` is a program of its own (host/, built with the Verilated RTL only when asked):
 * one per RTL configuration, build/pree-cosim-p1 .. -p16 (paper datapath) and -s1 .. -s16
 * (stable), with an f after the count for PipeFast = 1 (-p4f). `pree cosim ...` runs the one its
 * --preu, --datapath and --pipe-fast name, from the directory this program lives in, with the
 * same arguments. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"

typedef struct { const char *name; int (*run)(int, char **); const char *summary; } command_t;

static int run_cosim(int argc, char **argv);

static const command_t commands[] = {
    {"render",  pree_cmd_render,  "render a scene with progressive photon mapping"},
    {"check",   pree_cmd_check,   "parse and validate a scene; report what a render would need"},
    {"compare", pree_cmd_compare, "compare two images: SSIM, SNR, PSNR, RMSE, max difference"},
    {"cosim",   run_cosim,        "render with the Verilated PREE RTL doing the radiance estimation"},
};

/* The co-simulation program for the configuration the arguments ask for, next to this one.
 * The last --preu and --datapath (either form: --preu 8, --preu=8) win, as in the program's
 * own parsing; a bad value is left for that program to report. With --model-only (no RTL is
 * clocked) any co-simulation program that is built will do when that one is not. */
static int run_cosim(int argc, char **argv)
{
    const char *preu = "4", *dp = "paper", *fast = "";
    int model_only = 0, axi = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--")) break;
        if (!strcmp(argv[i], "--model-only")) model_only = 1;
        if (!strcmp(argv[i], "--axi")) axi = 1;
        else if (!strcmp(argv[i], "--pipe-fast")) fast = "f";
        else if (!strncmp(argv[i], "--preu=", 7)) preu = argv[i] + 7;
        else if (!strncmp(argv[i], "--datapath=", 11)) dp = argv[i] + 11;
        else if (i + 1 < argc && !strcmp(argv[i], "--preu")) preu = argv[++i];
        else if (i + 1 < argc && !strcmp(argv[i], "--datapath")) dp = argv[++i];
    }
    if (strcmp(preu, "1") && strcmp(preu, "2") && strcmp(preu, "4") && strcmp(preu, "8") && strcmp(preu, "16"))
        preu = "4";
    const char d = strcmp(dp, "stable") ? 'p' : 's';
    char self[PATH_MAX], path[PATH_MAX + 32];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n < 0) { fprintf(stderr, "pree cosim: cannot find this program's directory: %s\n", strerror(errno)); return 1; }
    self[n] = '\0';
    char *slash = strrchr(self, '/');
    if (slash) *slash = '\0';
    snprintf(path, sizeof path, "%s/pree-cosim-%s%c%s%s", self, axi ? "axi-" : "", d, preu, fast);
    execv(path, argv);
    for (const char *const *o = (const char *const[]){"p4", "p8", "p16", "s4", NULL}; model_only && *o; o++) {
        char alt[PATH_MAX + 32];
        snprintf(alt, sizeof alt, "%s/pree-cosim-%s", self, *o);
        execv(alt, argv);
    }
    fprintf(stderr, "pree cosim: %s: %s (build it with 'make %s')\n", path, strerror(errno),
            strstr(path, "build/") ? strstr(path, "build/") : path);
    return 1;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: pree <command> [options]\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\n'pree <command> --help' describes a command's options; 'pree --version' the build.\n");
}

/* Descriptors 0, 1 and 2 open (on /dev/null where closed), so that no output file is given
 * one of them and then receives the messages meant for stderr. */
static void std_fds_open(void)
{
    for (int fd = 0; fd < 3; fd++)
        if (fcntl(fd, F_GETFD) < 0 && errno == EBADF) {
            int n = open("/dev/null", fd ? O_WRONLY : O_RDONLY);
            if (n >= 0 && n != fd) { dup2(n, fd); close(n); }
        }
}

int main(int argc, char **argv)
{
    std_fds_open();
    if (argc < 2) { usage(stderr); return 2; }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) { usage(stdout); return 0; }
    if (!strcmp(argv[1], "--version")) { printf("pree %s\nMPI: %s\n", pree_version(), pree_mpi_build()); return 0; }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name)) {
            if (pree_mpi_begin(&argc, &argv) < 0) return 2;
            const int rc = commands[i].run(argc - 1, argv + 1);
            pree_mpi_end();
            return rc;
        }
    fprintf(stderr, "pree: unknown command '%s' (try 'pree --help')\n", argv[1]);
    return 2;
}
