// SPDX-License-Identifier: Apache-2.0
/* preu_vecgen.c: writes the Icarus bench's vector file for tb/preu/tb_preu.v.
 * Usage: preu_vecgen COUNT SEED DATAPATH OUT.hex   (PREU_VEC_WORDS hex words per operation, see
 * preu_vec_words; DATAPATH 0 paper, 1 stable) */
#include <stdio.h>
#include <stdlib.h>

#include "preu_vec.h"

int main(int argc, char **argv)
{
    if (argc != 5) { fprintf(stderr, "usage: preu_vecgen COUNT SEED DATAPATH OUT.hex\n"); return 2; }
    int n = atoi(argv[1]), dp = atoi(argv[3]);
    if (n < 1) { fprintf(stderr, "preu_vecgen: COUNT must be >= 1\n"); return 2; }
    if (dp != 0 && dp != 1) { fprintf(stderr, "preu_vecgen: DATAPATH must be 0 or 1\n"); return 2; }
    preu_vec_t *v = malloc((size_t)n * sizeof *v);
    if (!v) { fprintf(stderr, "preu_vecgen: out of memory\n"); return 1; }
    preu_seq_gen(v, n, strtoull(argv[2], NULL, 0), dp);
    FILE *f = fopen(argv[4], "w");
    if (!f) { perror(argv[4]); free(v); return 1; }
    for (int i = 0; i < n; i++) {
        uint32_t w[PREU_VEC_WORDS];
        preu_vec_words(w, &v[i]);
        for (int k = 0; k < PREU_VEC_WORDS; k++) fprintf(f, "%08x\n", w[k]);
    }
    free(v);
    if (fclose(f) != 0) { perror(argv[4]); remove(argv[4]); return 1; }
    return 0;
}
