// SPDX-License-Identifier: Apache-2.0
// vport.h: bit fields of a Verilated model's ports, whatever C type Verilator gave the port:
// integral ports (up to 64 bits: CData, SData, IData, QData) and wide ones (VlWide). So a bench
// fills a field the same way when a parameter (a lane count) moves a port across 64 bits.
//   put(port, lsb, w, v)   write the w-bit field at lsb          get(port, lsb, w)   read it
//   put32(port, lsb, v)    a 32-bit field (one word when aligned) get32(port, lsb)    read it (wide)
#ifndef PREE_VPORT_H
#define PREE_VPORT_H

#include <cstddef>
#include <cstdint>

#include "verilated.h"

namespace vport {

template <typename T>
void put(T &port, unsigned lsb, unsigned w, uint64_t v)
{
    const uint64_t mask = (w >= 64 ? ~0ull : ((1ull << w) - 1)) << lsb;
    port = static_cast<T>((static_cast<uint64_t>(port) & ~mask) | ((v << lsb) & mask));
}
template <std::size_t N>
void put(VlWide<N> &port, unsigned lsb, unsigned w, uint64_t v)
{
    for (unsigned b = 0; b < w; b++) {
        unsigned bit = lsb + b, word = bit / 32, off = bit % 32;
        uint32_t x = port[word];
        x = (x & ~(1u << off)) | (static_cast<uint32_t>((v >> b) & 1u) << off);
        port[word] = x;
    }
}
template <typename T>
void put32(T &port, unsigned lsb, uint32_t v)
{
    put(port, lsb, 32, v);
}
template <std::size_t N>
void put32(VlWide<N> &port, unsigned lsb, uint32_t v)
{
    if (lsb % 32 == 0) port[lsb / 32] = v;
    else put(port, lsb, 32, v);
}
template <typename T>
uint64_t get(const T &port, unsigned lsb, unsigned w)
{
    return (static_cast<uint64_t>(port) >> lsb) & (w >= 64 ? ~0ull : ((1ull << w) - 1));
}
template <std::size_t N>
uint64_t get(const VlWide<N> &port, unsigned lsb, unsigned w)
{
    uint64_t v = 0;
    for (unsigned b = 0; b < w; b++) {
        unsigned bit = lsb + b;
        v |= static_cast<uint64_t>((port[bit / 32] >> (bit % 32)) & 1u) << b;
    }
    return v;
}
template <std::size_t N>
uint32_t get32(const VlWide<N> &port, unsigned lsb)
{
    return lsb % 32 == 0 ? port[lsb / 32] : static_cast<uint32_t>(get(port, lsb, 32));
}

}  // namespace vport

#endif
