// SPDX-License-Identifier: Apache-2.0
/* mem_check.c: the memory estimate's check against the limits (mem_check.h). */
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>
#include "mem_check.h"

/* Field k (0: size, 1: resident) of /proc/self/statm, in bytes; 0 when unreadable. */
static uint64_t statm(int k)
{
    unsigned long long v[2] = {0, 0};
    FILE *f = fopen("/proc/self/statm", "r");
    if (!f) return 0;
    if (fscanf(f, "%llu %llu", &v[0], &v[1]) != 2) v[0] = v[1] = 0;
    fclose(f);
    long page = sysconf(_SC_PAGESIZE);
    return (uint64_t)v[k] * (uint64_t)(page > 0 ? page : 4096);
}

uint64_t mem_resident_bytes(void) { return statm(1); }

/* MemAvailable from /proc/meminfo in bytes; 0 when unknown. */
static uint64_t mem_available(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    if (!f) return 0;
    char line[256];
    unsigned long long kb = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %llu kB", &kb) == 1) break;
    fclose(f);
    return (uint64_t)kb * 1024;
}

static double gib(uint64_t b) { return (double)b / (1024.0 * 1024.0 * 1024.0); }

int mem_check(uint64_t need, uint64_t max_memory, const char *what, char *err, size_t errlen)
{
    uint64_t held = statm(1), vsize = statm(0), avail = mem_available();
    struct rlimit rl;
    const char *limit = NULL;
    uint64_t have = 0, total = need;
    if (max_memory) {
        total = held + need;
        if (total > max_memory) { limit = "--max-memory"; have = max_memory; }
    } else if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && vsize + need > rl.rlim_cur) {
        limit = "the address-space limit (ulimit -v)"; have = (uint64_t)rl.rlim_cur; total = vsize + need;
    } else if (avail && need > avail) {
        limit = "the available memory (MemAvailable)"; have = avail;
    }
    if (!limit) return 0;
    snprintf(err, errlen, "the render would need about %.2f GiB (%s%s) but %s is %.2f GiB: use a smaller image or "
             "scene%s", gib(total), what, max_memory ? ", with what is held" : "", limit, gib(have),
             max_memory ? ", or raise --max-memory" : ", or set the limit with --max-memory");
    return -1;
}
