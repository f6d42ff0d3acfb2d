// SPDX-License-Identifier: Apache-2.0
/* fp32_vecgen.c: write a vector file for the Icarus testbenches of the binary32 units.
 *
 * Usage: fp32_vecgen <add|mul|sqr|div|cmp|wacc|u2f> <random_count> <seed> <out_file>
 * Writes the unit's directed list (fp32_gen.c) followed by random_count random cases, one per
 * line as four hex fields "a b sub expected" (expected = result bits, or for cmp the flags
 * {unordered, eq, le, lt} as one hex digit). a and expected have 8 digits, 16 for the 64-bit
 * fields (a of wacc and u2f, expected of wacc). Exit status 0 on success, 1 on an I/O error,
 * 2 on a usage error; a partly written file is removed.
 */
#include "fp32_gen.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

static int write_case(FILE *f, fp32_unit_t unit, const fp32_case_t *c)
{
    const int a_digits = (unit == FP32_WACC || unit == FP32_U2F) ? 16 : 8;
    const int y_digits = unit == FP32_WACC ? 16 : 8;
    return fprintf(f, "%0*" PRIx64 " %08" PRIx32 " %" PRIx32 " %0*" PRIx64 "\n",
                   a_digits, c->a, c->b, c->sub, y_digits, c->y) < 0 ? -1 : 0;
}

int main(int argc, char **argv)
{
    fp32_unit_t unit;
    if (argc != 5 || fp32_unit_parse(argv[1], &unit) != 0) {
        fprintf(stderr, "usage: fp32_vecgen <add|mul|sqr|div|cmp|wacc|u2f> <random_count> <seed> <out_file>\n");
        return 2;
    }
    unsigned long long count = strtoull(argv[2], NULL, 0);
    uint64_t rng = strtoull(argv[3], NULL, 0) * 0x9E3779B97F4A7C15ULL + 1;

    FILE *f = fopen(argv[4], "w");
    if (!f) { perror(argv[4]); return 1; }
    int err = 0;
    size_t nd = fp32_directed_count(unit);
    for (size_t i = 0; i < nd && !err; i++) {
        fp32_case_t c;
        fp32_directed(unit, i, &c);
        err = write_case(f, unit, &c);
    }
    for (unsigned long long i = 0; i < count && !err; i++) {
        fp32_case_t c;
        fp32_random(unit, &rng, &c);
        err = write_case(f, unit, &c);
    }
    if (fclose(f) != 0) err = -1;
    if (err) { perror(argv[4]); remove(argv[4]); return 1; }
    printf("fp32_vecgen %s: %zu directed + %llu random vectors -> %s\n", argv[1], nd, count, argv[4]);
    return 0;
}
