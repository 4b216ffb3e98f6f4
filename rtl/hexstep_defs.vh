// SPDX-License-Identifier: Apache-2.0
// hexstep: encodings shared by hexstep_wb (the loader writes them) and hexstep_engine (it reads
// them), included inside both modules: the phase codes, the bit positions of a queued move's
// flags, the ring of three queue slots and the slot words of the memory map
// (docs/ARCHITECTURE.md, "Memory map").

// Phases (STATUS.phase).
localparam [1:0] PH_IDLE = 2'd0, PH_ACCEL = 2'd1, PH_CRUISE = 2'd2, PH_DECEL = 2'd3;
// Flags of a queued move, {dec_zero, init[1:0], dir, jog, empty, bad}: bit positions.
localparam integer F_BAD = 0, F_EMPTY = 1, F_JOG = 2, F_DIR = 3, F_INIT = 4, F_DZ = 6;

// The next slot of the ring of three.
function [1:0] inc3(input [1:0] x);
  inc3 = (x == 2'd2) ? 2'd0 : x + 2'd1;
endfunction
// Word of queue slot s at offset off: 8 + 8s + off.
function [4:0] slot_word(input [1:0] s, input [2:0] off);
  slot_word = {s + 2'd1, off};
endfunction
