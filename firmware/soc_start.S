/* SPDX-License-Identifier: Apache-2.0
 * hexstep SoC firmware: reset entry. The image runs where it is loaded (the program RAM from
 * 0), so only .bss (in the data RAM) needs setting up. The stack pointer is PicoRV32's reset
 * value (STACKADDR = 0x4000_0000 + DATA_WORDS * 4 in soc/hexstep_soc.v): the top of the data RAM
 * of this build, which a board build may make larger than the 8 KiB of firmware/soc.ld. */
  .section .text.start
  .globl _start
_start:
  la t0, _bss_start
  la t1, _bss_end
1:
  bgeu t0, t1, 2f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 1b
2:
  call main
3:
  j 3b
