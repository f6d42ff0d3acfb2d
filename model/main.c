/* main.c: the `pree` program: git-style subcommands over the PREE reference engine. */
#include <stdio.h>
#include <string.h>
#include "cli.h"

typedef struct { const char *name; int (*run)(int, char **); const char *summary; } command_t;

/* pree_cmd_cosim is optional: the co-simulation host links it in when it is built. */
__attribute__((weak)) int pree_cmd_cosim(int argc, char **argv);

static const command_t commands[] = {
    {"render",  pree_cmd_render,  "render a scene with progressive photon mapping"},
    {"compare", pree_cmd_compare, "compare two images: SSIM, SNR, PSNR, RMSE, max difference"},
    {"cosim",   pree_cmd_cosim,   "render with the Verilated PREE RTL doing the radiance estimation"},
};

static void usage(FILE *f)
{
    fprintf(f, "usage: pree <command> [options]\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (commands[i].run)
            fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].summary);
    fprintf(f, "\n'pree <command> --help' describes a command's options.\n");
}

int main(int argc, char **argv)
{
    if (argc < 2) { usage(stderr); return 2; }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) { usage(stdout); return 0; }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (commands[i].run && !strcmp(argv[1], commands[i].name))
            return commands[i].run(argc - 1, argv + 1);
    fprintf(stderr, "pree: unknown command '%s' (try 'pree --help')\n", argv[1]);
    return 2;
}
