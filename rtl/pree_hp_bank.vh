// SPDX-License-Identifier: Apache-2.0
// pree_hp_bank.vh: the hit-point bank of an address (included by the modules that bank hit
// points; they declare HpBankW). The low HpBankW bits XOR the next HpBankW bits, so that hit
// points a multiple of 2^HpBankW apart (neighbours one image row apart) still spread over the
// banks; the row inside the bank is the address without its low HpBankW bits. The host's model
// of it: model/pree/hp_bank.h. (VARHIDDEN: Verilator inlines pree_top_hpmem into pree_top, and
// then sees the two modules' copies of this function as nested scopes.)
  /* verilator lint_off VARHIDDEN */
  function [HpBankW-1:0] hp_bank;
    input [2*HpBankW-1:0] a;      // the low 2*HpBankW address bits
    begin
      hp_bank = a[HpBankW-1:0] ^ a[HpBankW +: HpBankW];
    end
  endfunction
  /* verilator lint_on VARHIDDEN */
