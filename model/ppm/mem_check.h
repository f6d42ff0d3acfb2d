// SPDX-License-Identifier: Apache-2.0
/* mem_check.h: the render's memory, estimated before it is allocated and checked against a
 * limit, so that an image or scene too large for the machine is a one-line error naming the
 * limit instead of swapping, crawling on failed reallocations or being killed.
 *
 * The costs are measured (docs/engine.md, "Memory"): per hit point 148 bytes (cells grid,
 * double), 159 (smallppm), 142 (fp32 paper), 161 (fp32 stable) between 0.6 M and 2.4 M hit points
 * (cornell3, peak resident size; 200 allowed), and 12 more for the screening's binary32 prefilter
 * at a vector level (update_prefilter.h); the photon blocks add about 32 MiB whatever the
 * photon count; the BVH
 * holds 24 to 98 bytes a triangle once built (conference, sibenik), 128 allowed for its build. */
#ifndef PREE_MEM_CHECK_H
#define PREE_MEM_CHECK_H

#include <stddef.h>
#include <stdint.h>

#define MEM_HIT_POINT_BYTES 200u
#define MEM_PIXEL_BYTES 48u
#define MEM_TRIANGLE_BYTES 128u
#define MEM_BASE_BYTES (64u << 20)

/* The estimate before the BVH and the image are built: one hit point an eye ray assumed
 * (eye_rays a pixel). */
static inline uint64_t mem_estimate_start(uint64_t triangles, uint64_t pixels, uint64_t eye_rays)
{
    return MEM_BASE_BYTES + triangles * MEM_TRIANGLE_BYTES + pixels * MEM_PIXEL_BYTES
         + pixels * eye_rays * MEM_HIT_POINT_BYTES;
}
#define MEM_START_WHAT "one hit point an eye ray assumed"

/* The bytes this process holds now (resident), and its virtual size; 0 when unknown. */
uint64_t mem_resident_bytes(void);

/* Check that `need` more bytes fit: within max_memory (bytes; 0: none given) counted with
 * what the process holds now, within RLIMIT_AS counted with its virtual size, and within
 * the system's MemAvailable. 0, or -1 with "... needs about X but LIMIT is Y" in err; `what`
 * says what the estimate counts. */
int mem_check(uint64_t need, uint64_t max_memory, const char *what, char *err, size_t errlen);

#endif
