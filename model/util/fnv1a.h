// SPDX-License-Identifier: Apache-2.0
/* fnv1a.h: the 64-bit FNV-1a hash of the image and state hashes (determinism checks). */
#ifndef PREE_FNV1A_H
#define PREE_FNV1A_H

#include <stddef.h>
#include <stdint.h>

#define FNV1A_BASIS 0xcbf29ce484222325ull

static inline uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; i++) { h ^= p[i]; h *= 0x100000001b3ull; }
    return h;
}

#endif
