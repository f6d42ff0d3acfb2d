// SPDX-License-Identifier: Apache-2.0
/* fail_trace.h: a failing bench or co-simulation leaves an FST trace of the cycles around its
 * first mismatch and names it in its message. Runs are deterministic, so the program runs itself
 * again (/proc/self/exe, the same arguments) with extra arguments that open a trace and limit it
 * to a window of cycles (vharness.h: +trace=FILE +trace_window=A:B for the benches; --trace FILE
 * --trace-window A:B for pree cosim and top_bench); the rerun's output is discarded.
 * Header-only, valid C and C++, for the C++ benches and the C hosts alike.
 *
 *   fail_trace_path(buf, len, tag, cycle)  the trace's name: FAIL_TRACE_DIR (environment) or the
 *                              program's folder, "<program>[-<tag>]-fail-c<cycle>.fst"
 *   fail_trace_window(first, before, after, &from, &to)  cycles [first - before, first + after]
 *   fail_trace_bench(argc, argv, name, tag, first, before, after)  all of it for a bench (below)
 *   fail_trace_rerun(argc, argv, extra, nextra, path)  0 when the rerun wrote the trace path
 *                              (the rerun gets FAIL_TRACE_RERUN=1 in its environment and must not
 *                              rerun itself: fail_trace_wanted() is 0 there) */
#ifndef PREE_FAIL_TRACE_H
#define PREE_FAIL_TRACE_H

#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

/* 1 unless this run is itself a trace rerun. */
static inline int fail_trace_wanted(void) { return getenv("FAIL_TRACE_RERUN") == NULL; }

static inline void fail_trace_window(uint64_t first, uint64_t before, uint64_t after, uint64_t *from, uint64_t *to)
{
    *from = first > before ? first - before : 0;
    *to = first + after;
}

static inline void fail_trace_path(char *buf, size_t len, const char *tag, uint64_t cycle)
{
    char exe[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    exe[n > 0 ? n : 0] = '\0';
    const char *dir = getenv("FAIL_TRACE_DIR");
    const char *slash = strrchr(exe, '/');
    const char *prog = slash ? slash + 1 : "bench";
    int dlen = dir ? (int)strlen(dir) : slash ? (int)(slash - exe) : 1;
    if (!dir) dir = slash ? exe : ".";
    snprintf(buf, len, "%.*s/%s%s%s-fail-c%llu.fst", dlen, dir, prog, tag && tag[0] ? "-" : "", tag ? tag : "",
             (unsigned long long)cycle);
}

static inline int fail_trace_rerun(int argc, char **argv, const char *const *extra, int nextra, const char *path)
{
    char **args = (char **)calloc((size_t)(argc + nextra + 1), sizeof *args);
    if (!args) return -1;
    for (int i = 0; i < argc; i++) args[i] = argv[i];
    for (int i = 0; i < nextra; i++) args[argc + i] = (char *)extra[i];
    unlink(path);
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0) { dup2(null, 1); dup2(null, 2); }
        setenv("FAIL_TRACE_RERUN", "1", 1);
        execv("/proc/self/exe", args);
        _exit(127);
    }
    free(args);
    int st = 0;
    if (pid < 0 || waitpid(pid, &st, 0) < 0) return -1;
    struct stat sb;
    return stat(path, &sb) == 0 && sb.st_size > 0 ? 0 : -1;
}

/* A bench's failure (plusargs, vharness.h): unless +trace was given or this is itself a rerun,
 * rerun with a trace of cycles [first - before, first + after] and print
 * "<name>: first mismatch at cycle C; cycles A..B traced in PATH" on stdout. */
static inline void fail_trace_bench(int argc, char **argv, const char *name, const char *tag, uint64_t first,
                                    uint64_t before, uint64_t after)
{
    for (int i = 1; i < argc; i++)
        if (!strncmp(argv[i], "+trace=", 7)) return;
    if (!fail_trace_wanted()) return;
    uint64_t from, to;
    fail_trace_window(first, before, after, &from, &to);
    char path[4096], tr[4200], win[64];
    fail_trace_path(path, sizeof path, tag, first);
    snprintf(tr, sizeof tr, "+trace=%s", path);
    snprintf(win, sizeof win, "+trace_window=%llu:%llu", (unsigned long long)from, (unsigned long long)to);
    const char *extra[] = {tr, win};
    if (fail_trace_rerun(argc, argv, extra, 2, path) == 0)
        printf("%s: first mismatch at cycle %llu; cycles %llu..%llu traced in %s\n", name, (unsigned long long)first,
               (unsigned long long)from, (unsigned long long)to, path);
    else
        printf("%s: first mismatch at cycle %llu; the traced rerun wrote no %s\n", name, (unsigned long long)first, path);
}

#endif
