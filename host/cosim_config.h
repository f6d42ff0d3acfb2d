// SPDX-License-Identifier: Apache-2.0
/* cosim_config.h: GENERATED from config/pree_config.json by scripts/pree_config.py (make config): do not edit.
 * The pree_top parameters of the co-simulation models (mk/config.mk passes the same). */
#ifndef COSIM_CONFIG_H
#define COSIM_CONFIG_H

#define COSIM_HPAW 18
#define COSIM_IDXAW 12
#define COSIM_PXAW 17
#define COSIM_CNTW 16
#define COSIM_HPB_1 4
#define COSIM_PXB_1 2
#define COSIM_PPC_1 1
#define COSIM_HPB_2 5
#define COSIM_PXB_2 3
#define COSIM_PPC_2 1
#define COSIM_HPB_4 6
#define COSIM_PXB_4 4
#define COSIM_PPC_4 1
#define COSIM_HPB_8 7
#define COSIM_PXB_8 5
#define COSIM_PPC_8 2
#define COSIM_HPB_16 8
#define COSIM_PXB_16 6
#define COSIM_PPC_16 4
/* X(n) for each PREU count n with a configuration above. */
#define COSIM_PREU_COUNTS X(1) X(2) X(4) X(8) X(16)
#define COSIM_MAX_PREU 16
#define COSIM_MAX_PPC 4 /* photon slots (PhotonsPerCycle) of the widest model */

#endif
