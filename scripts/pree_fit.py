#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""pree_fit.py: which pree_axi configurations fit which FPGA parts, by block RAM (and UltraRAM)
count, from the memories pree_top builds (rtl/pree_top.v; docs/integration_resources.md, "Memories and fit"):

  index table   NumPreu banks of 2^(IdxAW - log2 NumPreu) x HpAW
  hit points    2^HpBankW banks of 2^(HpAW - HpBankW) x (PxAW + 192)  (constant part)
                2^HpBankW banks of 2^(HpAW - HpBankW) x StateW        (state: 160 paper, 320 stable)
  pixels        2^PxBankW banks of 2^(PxAW - PxBankW) x 96

Each bank is a separate simple dual-port RAM (one write, one read port), mapped on its own: the
cheapest tiling of its depth x width by the primitive's aspect ratios (Xilinx RAMB36 / RAMB18 in
SDP mode, counted in RAMB36 units; UltraRAM 4K x 72; ECP5 EBR 18 kbit). Banks follow the
co-simulation builds (HpBankW = log2 NumPreu + 4, PxBankW = log2 NumPreu + 2) or are lean
(log2 NumPreu + 1 and log2 NumPreu; more bank conflicts, utilization not measured). The wrapper's own
FIFOs and the hazard windows are registers (LUTs / flops), not counted here.
Usage: pree_fit.py [--datapath paper|stable]   (prints Markdown)"""
import math
import sys

RAMB36 = [(32768, 1), (16384, 2), (8192, 4), (4096, 9), (2048, 18), (1024, 36), (512, 72)]
RAMB18 = [(16384, 1), (8192, 2), (4096, 4), (2048, 9), (1024, 18), (512, 36)]
EBR = [(16384, 1), (8192, 2), (4096, 4), (2048, 9), (1024, 18), (512, 36)]
URAM = [(4096, 72)]


def tiles(depth, width, prims):
    return min(math.ceil(depth / d) * math.ceil(width / w) for d, w in prims)


def xil_bram(depth, width):
    """RAMB36 units: whole RAMB36s or RAMB18 halves, whichever is cheaper."""
    return min(tiles(depth, width, RAMB36), 0.5 * tiles(depth, width, RAMB18))


def memories(np_, hp_aw, px_aw, idx_aw, state_w, lean):
    lg = int(math.log2(np_))
    hb, pb = (lg + 1, lg) if lean else (lg + 4, lg + 2)
    return {
        "index": (np_, 1 << (idx_aw - lg), hp_aw),
        "hp_const": (1 << hb, 1 << (hp_aw - hb), px_aw + 192),
        "hp_state": (1 << hb, 1 << (hp_aw - hb), state_w),
        "pixels": (1 << pb, 1 << (px_aw - pb), 96),
    }


def count(mems, kind, blocks, urams):
    """kind: 'bram' (block RAM), 'uram' (each memory in block RAM or UltraRAM, the assignment
    that leaves the larger share of both free), 'ebr' (ECP5)."""
    names = list(mems)
    best = None
    for mask in range(1 << len(names)) if kind == "uram" else [0]:
        bram = uram = 0
        for i, name in enumerate(names):
            banks, depth, width = mems[name]
            if mask >> i & 1:
                uram += banks * tiles(depth, width, URAM)
            elif kind == "ebr":
                bram += banks * tiles(depth, width, EBR)
            else:
                bram += banks * xil_bram(depth, width)
        load = max(bram / blocks, uram / urams if urams else (0 if uram == 0 else 9e9))
        if best is None or load < best[0]:
            best = (load, bram, uram)
    return best[1], best[2]


# Part: (name, kind, RAMB36 or EBR blocks, URAM blocks), from the vendors' product tables.
PARTS = [
    ("XC7A200T", "bram", 365, 0),
    ("XC7K325T", "bram", 445, 0),
    ("XCKU040", "bram", 600, 0),
    ("XCZU7EV", "uram", 312, 96),
    ("XCVU9P", "uram", 2160, 960),
    ("LFE5U-85F", "ebr", 208, 0),
]
CONFIGS = [(12, 12), (14, 14), (16, 16), (17, 17), (18, 17)]   # (HpAW, PxAW)


def main():
    dp = "paper"
    if len(sys.argv) == 3 and sys.argv[1] == "--datapath" and sys.argv[2] in ("paper", "stable"):
        dp = sys.argv[2]
    elif len(sys.argv) != 1:
        sys.exit("usage: pree_fit.py [--datapath paper|stable]")
    state_w = 160 if dp == "paper" else 320
    print(f"Datapath {dp} (StateW {state_w}), IdxAW 12. Cells: blocks needed / blocks in the part "
          "(RAMB36 units; XCZU7EV and XCVU9P: hit points in UltraRAM, RAMB36 + URAM; LFE5U-85F: "
          "EBR); a dash where it does not fit.\n")
    print("| NumPreu | banks hp / px | hit points (HpAW) | pixels (PxAW) | Mbit | " + " | ".join(p[0] for p in PARTS) + " |")
    print("|---|---|---|---|---|" + "---|" * len(PARTS))
    for np_ in (4, 8, 16):
        for lean in (False, True):
            for hp_aw, px_aw in CONFIGS:
                row(np_, lean, hp_aw, px_aw, state_w)
    print("\nPart capacities: " + ", ".join(
        f"{n} {b} {'EBR' if k == 'ebr' else 'RAMB36'}" + (f" + {u} URAM" if u else "") for n, k, b, u in PARTS) + ".")


def row(np_, lean, hp_aw, px_aw, state_w):
            mems = memories(np_, hp_aw, px_aw, 12, state_w, lean)
            mbit = sum(b * d * w for b, d, w in mems.values()) / 1e6
            cells = []
            for name, kind, blocks, urams in PARTS:
                b, u = count(mems, kind, blocks, urams)
                fits = b <= blocks and u <= urams
                txt = f"{b:g}" + (f" + {u}U" if kind == "uram" else "")
                cells.append(txt if fits else f"- ({txt})")
            hbk, pbk = mems["hp_const"][0], mems["pixels"][0]
            print(f"| {np_} | {hbk} / {pbk} | {1 << hp_aw} ({hp_aw}) | {1 << px_aw} ({px_aw}) | {mbit:.1f} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
