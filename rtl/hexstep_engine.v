// SPDX-License-Identifier: Apache-2.0
// hexstep: the frame engine: one shared add-only datapath that runs every axis's tick in turn,
// its state and move queues in four block-RAM banks, and the per-axis start/stop/queue control.
`default_nettype none

// Schedule (docs/ARCHITECTURE.md, "Frames and slots"). g counts cycles modulo 128; a frame is
// 32 cycles, slot i = frame cycles 4i..4i+3 belongs to axis i, so every axis advances by one
// tick per frame. Cycles with g[1:0] == 3 (the bus cycles) give the four banks to the bus block
// (staging registers, configuration mirror, loader, initialization); the engine uses the others.
// Axis i's slot is sampled at the edge that ends frame cycle 4i - 1 (its control state, the
// frame's START/STOP masks, taken at the edge that ends frame cycle 30, and its output stage's
// state decide whether a move starts and whether the generator runs) and commits its tick nine
// edges later, at the end of cycle 4i + 8; in between the datapath reads the axis's words
// (addresses in cycles 4i..4i+2, from registers; data two cycles later) and computes, in 32-bit
// halves:
//     P' = P + S                      (the carry out of the 64-bit fraction is a step)
//     S' = S + acc, clamped at v_max  (accelerate)      S' = S   (cruise)
//     S' = S - dec, not below floor   (decelerate; the first decelerating tick loads v_dec)
//     S' = S - dec                    (stopping: ends when the old speed is below dec)
// and the counters of steps to the end, to acc_steps and to dec_step. A step's sub-tick offset
// (cycles before the end of its tick) comes from a 5-bit restoring division of the top 12 bits
// (SUB_W) of the overshoot P' and of S; the step is handed to the axis's output stage due on cycle
// F + 68 - q (F: first cycle of the sample's frame). No multiplier, no divider: adders,
// comparators, three restoring steps (a subtraction each) and a look-ahead of two. Bit-exact
// counterpart: hexstep::AxisGen and hexstep::TopModel (cpp_model/src/axis.cpp, top_model.cpp).
//
// Memory map (address = {axis, word}; slot s of the queue at words 8 + 8s + offset):
//   bank 0: 0 S_lo, 1 S_hi, 2 steps-to-end;            3..7 staging;  slot: +0 V_START lo, +1 hi, +2 STEPS
//   bank 1: 0 P_lo, 1 P_hi, 2 steps-to-acc_steps;      3..7 staging;  slot: +0 ACC_STEPS, +7 zero
//   bank 2: 0 steps-to-dec_step;                       1..7 staging;  slot: +0 ACC lo, +1 hi, +2 ~DEC lo,
//                                                                         +3 hi, +4 V_DEC lo, +5 hi, +6 DEC_STEP, +7 zero
//   bank 3: 0..4 pulse configuration mirror;                          slot: +0 V_MAX lo, +1 hi, +2 FLOOR lo,
//                                                                         +3 hi, +4 DEC_FRAC (aligned to bit 31)
//
// Queue: three slots per axis, a ring: `act` is the slot of the running (or last) move and the
// qn queued moves follow it; the loader fills slot act + 1 + qn. Reset: synchronous, active
// high; control state is reset, the memory and the datapath registers are not (a word is read
// only after the engine or the loader has written it; pipeline registers only while valid).
module hexstep_engine #(
  // NAXES: axes (unit: axes). Range 1..8, the slots of a frame; default 6.
  parameter integer NAXES     = 6,
  // RAM_STYLE: implementation of the memory banks, see hexstep_ram ("DELAY" or "ECP5").
  parameter         RAM_STYLE = "DELAY"
) (
  input  wire               clk_i,
  input  wire               rst_i,          // synchronous, active high
  output wire [6:0]         g_o,            // cycle counter modulo 128
  output wire [6:0]         gn_o,           // g_o after this edge (g_o + 1), a register of its own
  output wire [3:0]         kph_o,          // its low two bits one-hot: kph_o[n] == (g_o[1:0] == n)
  // Control from the bus block; each acts at the edge that ends the cycle it is high in.
  input  wire [NAXES-1:0]   start_w_i,      // START written: start at the next frame boundary
  input  wire [NAXES-1:0]   stop_w_i,       // STOP written: stop at the next frame boundary
  input  wire [NAXES-1:0]   abort_i,        // abort now (ABORT strobe or e-stop latch)
  input  wire               push_i,         // the loader commits a move into slot act+1+qn
  input  wire [2:0]         push_axis_i,
  input  wire [6:0]         push_flags_i,   // {dec_zero, init[1:0], dir, jog, empty, bad}
  // The banks on bus cycles (g[1:0] == 3).
  input  wire               bus_re_i,
  input  wire [1:0]         bus_rbank_i,
  input  wire [7:0]         bus_raddr_i,
  output wire [31:0]        bus_rdata_o,    // data of the bus read two cycles earlier
  input  wire [3:0]         bus_we_i,       // one bit per bank
  input  wire [7:0]         bus_waddr_i,
  input  wire [31:0]        bus_wdata_i,
  input  wire               bus_init_i,     // initialization: banks 0..2 write 0
  // Queue and status per axis.
  output wire [NAXES*2-1:0] act_o,
  output wire [NAXES*2-1:0] qn_o,
  output wire [NAXES-1:0]   busy_o,         // not at rest
  output wire [NAXES-1:0]   run_o,          // STATUS.run
  output wire [NAXES*2-1:0] phase_o,        // 0 idle, 1 accelerate, 2 cruise, 3 decelerate
  output wire [NAXES-1:0]   done_o,         // busy fell in the last cycle, or a move was consumed
  output wire [NAXES-1:0]   refused_o,      // a refused move was consumed at this edge
  output wire [NAXES-1:0]   freed_o,        // a queue entry becomes free at this edge
  output wire [NAXES-1:0]   flush_o,        // the queue is flushed at this edge
  // Output stages.
  input  wire [NAXES-1:0]   pending_i,      // requests or owed steps wait
  input  wire [NAXES-1:0]   accepts_n_i,    // a request can be taken after this edge
  input  wire [NAXES-1:0]   pending_n_i,    // pending_i after this edge
  input  wire [NAXES-1:0]   tgt_i,
  output wire [NAXES-1:0]   req_o,
  output wire [6:0]         req_due_o,      // due cycle of the request (one request per edge)
  output wire [NAXES-1:0]   tgt_load_o,
  output wire               tgt_dir_o
);

`include "hexstep_defs.vh"
  // Per-axis state is kept for all 8 slots (indexed by the 3-bit slot number); slots NAXES..7
  // stay in reset and are never sampled.
  localparam integer NS = 8;
  localparam [6:0] DUE_OFFSET = 7'd68;
  // SUB_W: bits of the overshoot and of the speed (their top bits) that the sub-tick division
  // uses (cpp_model kSubtickBits): the rounding of 12 bits costs at most 2^-12 / v cycles, a
  // quarter of the 0.001-step allowance, and two restoring steps fit one cycle.
  localparam integer SUB_W = 12;
  // Bits of sf_q per axis: the flags (7 bits) of three moves of the queue ring.
  localparam integer SF_W = 21;

  // ---------------------------------------------------------------------------------------
  // Cycle counter.
  reg  [6:0] g_q;
  reg  [6:0] gn_q;   // g_q + 1, for the output stages' due compares of the next cycle
  wire [4:0] f = g_q[4:0];
  wire [1:0] kc = g_q[1:0];
  // kc one-hot, a register of its own (kph_q[n] == (kc == n)): the slot cycle's strobes and
  // enables (and the bus block's) come from a flip-flop rather than a decode of the counter.
  reg  [3:0] kph_q;
  wire       boundary = (f == 5'd30);

  // ---------------------------------------------------------------------------------------
  // Per-axis control state.
  reg  [NS-1:0]    run_q, decf_q, stop_q, chain_q, running_q, starting_q, busy_q;
  reg  [NS-1:0]    spend_q, ppend_q, fstart_q, fstop_q;
  reg  [NS*2-1:0]  ph_q, act_q, qn_q;
  // Flags of the moves in the queue ring by position: [6:0] the running (or last) move, [13:7]
  // the head of the queue, [20:14] the one after it (shifted on a pop).
  reg  [NS*SF_W-1:0] sf_q;
  reg  [NS-1:0]    run_d, decf_d, stop_d, chain_d, running_d, starting_d;
  reg  [NS-1:0]    spend_d, ppend_d, fstart_d, fstop_d;
  reg  [NS*2-1:0]  ph_d, act_d, qn_d;
  reg  [NS*SF_W-1:0] sf_d;

  // The per-axis inputs, padded to 8 slots.
  wire [NS-1:0] pending, accepts_n, pending_n, tgt, abort, start_w, stop_w;
  generate
    if (NAXES < NS) begin : g_pad
      assign pending = {{(NS-NAXES){1'b0}}, pending_i};
      assign accepts_n = {{(NS-NAXES){1'b0}}, accepts_n_i};
      assign pending_n = {{(NS-NAXES){1'b0}}, pending_n_i};
      assign tgt     = {{(NS-NAXES){1'b0}}, tgt_i};
      assign abort   = {{(NS-NAXES){1'b0}}, abort_i};
      assign start_w = {{(NS-NAXES){1'b0}}, start_w_i};
      assign stop_w  = {{(NS-NAXES){1'b0}}, stop_w_i};
    end else begin : g_full
      assign pending = pending_i;
      assign accepts_n = accepts_n_i;
      assign pending_n = pending_n_i;
      assign tgt     = tgt_i;
      assign abort   = abort_i;
      assign start_w = start_w_i;
      assign stop_w  = stop_w_i;
    end
  endgenerate

  // ---------------------------------------------------------------------------------------
  // Sample (edge ending cycle 4i - 1, a bus cycle): every axis's decision is computed in
  // parallel; a registered one-hot pointer (the axis of the next sample) selects the one that is
  // registered into stage 1 and updates that axis's state. The start decisions and the output
  // stage's accept flag are registered at the edge before (g[1:0] == 2), from the values that
  // their inputs have in the sample cycle: at that edge only the output stages' flags (their
  // next values, *_n), the frame flags (a boundary) and an abort change them, and an abort
  // clears what a start needs (the queue, the chain flag), so its decision is no start.
  reg  [NS-1:0]      smp_oh_q;                   // one-hot: the axis sampled at the next bus cycle
  reg  [2:0]         si_q;                       // its number
  wire [NS-1:0]      ax_mask = {NS{1'b1}} >> (NS - NAXES);   // the axes that exist
  wire               smp_slot = kph_q[3] && ((smp_oh_q & ax_mask) != {NS{1'b0}});
  wire [2:0]         si = si_q;
  wire [NS-1:0]      a_start, a_gen;
  reg  [NS-1:0]      sn_q, sc_q, sa_q;              // start new, start chained, accepts
  // The sample's per-axis strobes, registered at the same edge and 1 in that axis's sample
  // cycle only, so that neither the bus cycle flag (kph_q[3], a net of high fan-out) nor the
  // pointer is in front of the sample's state updates: the sample (ss_q); the sample with a
  // STOP of the frame, which flushes the queue (sfs_q: fstop_q in the sample cycle, which an
  // abort at the edge before clears); the sample with a start, which pops the queue's head
  // (sst_q; a start excludes a STOP). An abort in the sample cycle itself is applied to them
  // in the state update below.
  reg  [NS-1:0]      ss_q, sfs_q, sst_q;
  // The pointer in the sample cycle: the edge before it moves it only after frame cycle 30.
  localparam [NS-1:0] SMP_FIRST = {{(NS-1){1'b0}}, 1'b1};   // the pointer at axis 0
  wire [NS-1:0]      smp_nx = boundary ? SMP_FIRST : smp_oh_q;
  genvar ga;
  generate
    for (ga = 0; ga < NS; ga = ga + 1) begin : g_dec
      wire [6:0] hf = sf_q[ga*SF_W + 7 +: 7];       // flags of the head of the queue
      // Values in the sample cycle (see above).
      wire       n_fstart = boundary ? spend_q[ga] : fstart_q[ga];
      wire       n_fstop = boundary ? ppend_q[ga] : fstop_q[ga];
      wire       n_busy = run_q[ga] | chain_q[ga] | starting_q[ga] | pending_n[ga];
      wire       n_dir_ok = hf[F_BAD] | hf[F_EMPTY] | (hf[F_DIR] == tgt[ga]) | ~pending_n[ga];
      wire       n_sn = n_fstart & ~n_fstop & ~running_q[ga] & ~n_busy &
                        (qn_q[ga*2 +: 2] != 2'd0) & ~abort[ga];
      wire       n_sc = chain_q[ga] & ~n_fstop & accepts_n[ga] & n_dir_ok & ~abort[ga];
      wire       n_ss = kph_q[2] & smp_nx[ga];
      always @(posedge clk_i) begin
        if (rst_i) begin
          sn_q[ga] <= 1'b0;
          sc_q[ga] <= 1'b0;
          sa_q[ga] <= 1'b0;
          ss_q[ga] <= 1'b0;
          sfs_q[ga] <= 1'b0;
          sst_q[ga] <= 1'b0;
        end else begin
          if (kph_q[2]) begin
            sn_q[ga] <= n_sn;
            sc_q[ga] <= n_sc;
            sa_q[ga] <= accepts_n[ga];
          end
          ss_q[ga] <= n_ss;
          sfs_q[ga] <= n_ss & n_fstop & ~abort[ga];
          sst_q[ga] <= n_ss & (n_sn | n_sc);
        end
      end
      assign a_start[ga] = sn_q[ga] | sc_q[ga];
      assign a_gen[ga] = a_start[ga] ? ~(hf[F_BAD] | hf[F_EMPTY]) : (run_q[ga] & sa_q[ga]);
    end
  endgenerate
  wire [1:0]         s_act = act_q[si*2 +: 2];
  wire [1:0]         s_head = inc3(s_act);
  // The sampled axis's flags (running move, head of the queue): a case on si with constant
  // offsets (a part-select at si * SF_W is a shifter behind an adder).
  reg  [13:0]        s_sf;
  always @* begin
    case (si)
      3'd0: s_sf = sf_q[0*SF_W +: 14];
      3'd1: s_sf = sf_q[1*SF_W +: 14];
      3'd2: s_sf = sf_q[2*SF_W +: 14];
      3'd3: s_sf = sf_q[3*SF_W +: 14];
      3'd4: s_sf = sf_q[4*SF_W +: 14];
      3'd5: s_sf = sf_q[5*SF_W +: 14];
      3'd6: s_sf = sf_q[6*SF_W +: 14];
      default: s_sf = sf_q[7*SF_W +: 14];   // 3'd7
    endcase
  end
  wire [6:0]         s_af = s_sf[6:0];                 // flags of the running move
  wire [6:0]         s_hf = s_sf[13:7];                // flags of the head of the queue
  wire               s_valid = smp_slot & ~abort[si];
  wire               s_start = a_start[si];
  wire [1:0]         s_slot = s_start ? s_head : s_act;
  wire [6:0]         s_fl = s_start ? s_hf : s_af;
  wire [1:0]         s_ph = s_start ? s_fl[F_INIT +: 2] : ph_q[si*2 +: 2];
  wire               s_decf = s_start | decf_q[si];
  wire               s_stop = ~s_start & stop_q[si];
  wire               s_gen = a_gen[si];

  // Addend word offset in bank 2 and limit offset in bank 3 by phase.
  function [2:0] a_off(input [1:0] ph, input decf, input stp);
    a_off = (ph == PH_ACCEL) ? 3'd0 : (ph == PH_DECEL) ? ((decf & ~stp) ? 3'd4 : 3'd2) : 3'd7;
  endfunction

  // Pipeline stage 1 (loaded at the sample edge, end of 4i-1; read in cycles 4i..4i+3).
  reg        p1_valid, p1_start, p1_decf, p1_stop, p1_gen, p1_fstop, p1_abort;
  reg        p1_smask, p1_cin;                 // datapath masks (below)
  reg [2:0]  p1_ax;
  reg [1:0]  p1_slot, p1_ph, p1_frame;
  reg [6:0]  p1_fl;
  // Stage 2 (loaded at the end of 4i+3; read in cycles 4i+4..4i+7), stage 3 (the last write).
  reg        p2_valid, p2_start, p2_decf, p2_stop, p2_gen, p2_fstop, p2_abort;
  reg [2:0]  p2_ax;
  reg [1:0]  p2_ph, p2_frame;
  reg [6:0]  p2_fl;
  reg        p3_we, p3_dir;
  // The commit's per-axis strobes, each a register that is 1 in the commit cycle (4i+8) only:
  // stage 3 is that axis's and was not aborted since its sample (cm_q); and it makes a step
  // request (req_q) or loads the DIR target of a start (tl_q).
  reg [NAXES-1:0] req_q, tl_q, cm_q;
  reg [NAXES-1:0] cm_n;                  // cm_q's next value
  integer rk;
  always @* begin
    for (rk = 0; rk < NAXES; rk = rk + 1)
      cm_n[rk] = kph_q[3] && p2_valid && !(p2_abort | abort[p2_ax]) && ({29'd0, p2_ax} == rk);
  end
  reg [2:0]  p3_ax;
  // Commit decisions (registered at the end of 4i+5, applied at the end of 4i+8).
  reg        d_consume, d_bad, d_run, d_decf, d_stop, d_req;
  // ... and their combinations on the state's enables: the move's state is updated (d_upd),
  // it ended or was consumed (d_fin), a STOP of this frame applies to a move that runs on
  // (d_fs_run) or to whatever the axis does (d_fs_any: no step was generated).
  reg        d_upd, d_fin, d_fs_run, d_fs_any;
  reg [1:0]  d_ph;

  // ---------------------------------------------------------------------------------------
  // Memory banks.
  reg  [7:0]  ra0, ra1, ra2, ra3, wa0, wa1, wa2;
  reg  [31:0] wd0, wd1, wd2;
  reg         we0, we1, we2, re_e;
  wire [31:0] rd0, rd1, rd2, rd3;
  wire        bus_cyc = kph_q[3];
  wire [31:0] bwd012 = bus_init_i ? 32'd0 : bus_wdata_i;

  hexstep_ram #(.STYLE (RAM_STYLE)) u_bank0 (
    .clk_i (clk_i), .re_i (bus_cyc ? (bus_re_i && bus_rbank_i == 2'd0) : re_e),
    .raddr_i (bus_cyc ? bus_raddr_i : ra0), .rdata_o (rd0),
    .we_i (bus_cyc ? bus_we_i[0] : we0), .waddr_i (bus_cyc ? bus_waddr_i : wa0),
    .wdata_i (bus_cyc ? bwd012 : wd0));
  hexstep_ram #(.STYLE (RAM_STYLE)) u_bank1 (
    .clk_i (clk_i), .re_i (bus_cyc ? (bus_re_i && bus_rbank_i == 2'd1) : re_e),
    .raddr_i (bus_cyc ? bus_raddr_i : ra1), .rdata_o (rd1),
    .we_i (bus_cyc ? bus_we_i[1] : we1), .waddr_i (bus_cyc ? bus_waddr_i : wa1),
    .wdata_i (bus_cyc ? bwd012 : wd1));
  hexstep_ram #(.STYLE (RAM_STYLE)) u_bank2 (
    .clk_i (clk_i), .re_i (bus_cyc ? (bus_re_i && bus_rbank_i == 2'd2) : re_e),
    .raddr_i (bus_cyc ? bus_raddr_i : ra2), .rdata_o (rd2),
    .we_i (bus_cyc ? bus_we_i[2] : we2), .waddr_i (bus_cyc ? bus_waddr_i : wa2),
    .wdata_i (bus_cyc ? bwd012 : wd2));
  hexstep_ram #(.STYLE (RAM_STYLE)) u_bank3 (
    .clk_i (clk_i), .re_i (bus_cyc ? (bus_re_i && bus_rbank_i == 2'd3) : re_e),
    .raddr_i (bus_cyc ? bus_raddr_i : ra3), .rdata_o (rd3),
    .we_i (bus_cyc & bus_we_i[3]), .waddr_i (bus_waddr_i), .wdata_i (bus_wdata_i));

  // The bus read's bank, two cycles on.
  reg [1:0] bb1_q, bb2_q;
  always @(posedge clk_i) begin
    bb1_q <= bus_rbank_i;
    bb2_q <= bb1_q;
  end
  assign bus_rdata_o = (bb2_q == 2'd0) ? rd0 : (bb2_q == 2'd1) ? rd1 : (bb2_q == 2'd2) ? rd2 : rd3;

  // ---------------------------------------------------------------------------------------
  // Datapath registers (not reset).
  reg        cp0_q, ct0_q, step_q, ct1_q, cl0_q, gt_q;
  reg        dfh_q, dfe_q, dfl_q;        // P'_hi >= DEC_FRAC in halves: high >, high ==, low >=
  // tn_lo_q, tn_hi_q hold t inverted: the compare's operand as its carry chain takes it (no
  // inverting LUT in front of the chain; the write of t inverts it in its select LUT).
  reg [31:0] pn_lo_q, tn_lo_q, llo_q, pn_hi_q, tn_hi_q, lhi_q;
  reg [31:0] re_n_q, ra_n_q, rd_n_q;
  reg        zre_q, zra_q, zrd_q, zrd0_q, sell_q;
  // Sub-tick division: three restoring steps in a row, one per cycle, each a stage of its own
  // (4i+4: dra from the overshoot's top bits in pn_hi_q, 4i+5: drb from dra, 4i+6: drc from
  // drb), all with the divisor ds_q; the fourth and fifth quotient bits are a two-step
  // look-ahead on drc in 4i+7 (req_due_q below). pn_hi_q and ds_q are loaded at the end of
  // 4i+3 and hold until the end of 4i+7, so each stage's register is loaded at every edge and
  // keeps its value from the end of its cycle to the end of 4i+7: no clock enable, and no
  // select in front of a step (each step has one operand source).
  reg [SUB_W-1:0] dra_q, drb_q, drc_q;     // partial remainders after steps 1, 2, 3
  reg             dqa_q, dqb_q, dqc_q;     // quotient bits of steps 1, 2, 3
  reg [SUB_W-1:0] ds_q;                    // divisor: top bits of S
  reg             dz_q;                    // divisor zero

  // Masks of the stage-1 operation (cycles 4i+2, 4i+3).
  // p1_smask (t = 0 + V_DEC) and p1_cin (S + ~dec + 1) are registered at the end of cycle 4i
  // from stage 1's phase, first-decelerating-tick and stopping flags (not at the sample, so
  // that the sample's decisions do not feed them). p1_smask selects the other operand after
  // the adder (0 + x = x), so the adders take the block RAM data without a LUT in front of
  // their carry chains; the carries ct0_q, ct1_q are not masked: with p1_smask the high half
  // is masked too, and no decision of a first decelerating tick reads ct1_q (c_sell takes
  // gt_q then; c_clamp and c_stop_end are for ACCEL and stopping). At a start P is 0 without a
  // mask: bank 1 is read at the slot's zero word (offset 7, written 0 by every push), so
  // P' = 0 + V_START, no carry, no step.

  // a + b + ci ({carry out, sum}) with the carry out taken through one more sum bit,
  // u ^ v ^ carry, where u and v are two flags that are both 1 in the cycle the sum is
  // registered (kph_q[n] and a bit of g_q[1:0] that is 1 in slot cycle n, or its inverse).
  // Synthesis cannot see that u ^ v is 0, so it keeps that bit's LUT at the end of the carry
  // chain, with the carry on its I3, and packs the carry's flip-flop with it: the carry leaves
  // the chain without a pass-out logic cell and a route to a flip-flop elsewhere (iCE40; about
  // 1 ns of the HX8K's worst paths). The carry in is a constant-1 bottom bit beside ci, so that
  // ci enters the same chain (written as a + b + ci, synthesis chains a second adder for it).
  function [32:0] add_co(input [31:0] a, input [31:0] b, input ci, input u, input v);
    /* verilator lint_off UNUSEDSIGNAL */
    reg [34:0] t;   // t[0] is the constant bottom bit, t[34] unused
    begin
      t = {1'b0, u, a, 1'b1} + {1'b0, v, b, ci};
      add_co = t[33:1];
    end
    /* verilator lint_on UNUSEDSIGNAL */
  endfunction

  // The quotient bit of one restoring division step: 2*rem >= s.
  function dbit(input [SUB_W-1:0] rem, input [SUB_W-1:0] s);
    dbit = {rem, 1'b0} >= {1'b0, s};
  endfunction
  // One restoring division step: 2*rem >= s ? (2*rem - s, 1) : (2*rem, 0), as one subtraction
  // whose borrow is the compare (one carry chain). rem <= s holds throughout (the overshoot is
  // below the speed), so 2*rem - s <= s and, when 2*rem < s, 2*rem fit SUB_W bits.
  function [SUB_W:0] dstep(input [SUB_W-1:0] rem, input [SUB_W-1:0] s);
    reg [SUB_W+1:0] t;                   // 2*rem - s; t[SUB_W+1]: borrow (2*rem < s)
    begin
      t = {1'b0, rem, 1'b0} - {2'b00, s};
      dstep = t[SUB_W+1] ? {rem[SUB_W-2:0], 1'b0, 1'b0} : {t[SUB_W-1:0], 1'b1};
    end
  endfunction
  wire [SUB_W:0]  dva = dstep(pn_hi_q[31 -: SUB_W], ds_q);
  wire [SUB_W:0]  dvb = dstep(dra_q, ds_q);
  wire [SUB_W:0]  dvc = dstep(drb_q, ds_q);
  // Due cycle F + 68 - q of the request, with q = {h, q0} (h: the first four quotient bits):
  // 68 - q = 37 + ~q, so it is F + 37 + {~h, 0} when q0 = 1 and one more when q0 = 0, and
  // F + 68 when the divisor is zero (q = 0). It is registered (req_due_q) at the end of cycle
  // 4i+7, when drc_q holds the remainder r of three steps: the fourth bit is
  // q3 = 2r >= s, and the fifth, q0 = 2(2r - s) >= s = 4r >= 3s when q3 = 1, else 4r >= s
  // (exact: r <= s, so neither 4r nor 3s overflows SUB_W + 2 bits). So the fifth step of cycle
  // 4i+8 is not on the due's path, and the commit takes a register. With F = 32 * frame,
  // F + 37 + 2 * ~h = 2 * ({frame, ~h} + 18) + 1 (the frame and ~h do not overlap); the adds
  // are on registers only (see dhu below).
  reg  [6:0]      req_due_q;
  // 3 s, registered in every cycle (valid from 4i+5: ds_q is loaded at the end of 4i+3).
  reg  [SUB_W+1:0] ds3_q;
  // The fourth quotient bit, 2r >= s on the remainder of three steps (drc_q in 4i+7).
  wire            dq3 = dbit(drc_q, ds_q);
  wire            dc1 = {drc_q, 2'b00} >= {2'b00, ds_q};            // 4r >= s
  wire            dc3 = {drc_q, 2'b00} >= ds3_q;                     // 4r >= 3s
  wire            dq0 = dq3 ? dc3 : dc1;
  wire [6:0]      dbase = {p2_frame, 5'd0};
  localparam [5:0] DUE_HALF = DUE_OFFSET[6:1] - 6'd16;      // 18 = (68 - 32) / 2
  // {frame, ~h} + 18 with h = {dq[2:0], dq3} (dq = {dqa, dqb, dqc}, steps 1 to 3): 18 is
  // even, so the sum is {U, ~dq3} with U = {frame, ~dq[2:0]} + 9 (registers only), and one
  // more is {U, 1} or {U + 1, 0}: the quotient bits only select, after the adds. The due is
  // {U, ~q3, 1} when q0 = 1, {U, 1, 0} when q0 = 0 and q3 = 1, {U + 1, 0, 0} when both are 0:
  // its bits 1:0 are {q0 ^ q3, q0}, and the high bits are U + 1 only when q3 = 0 and 4r < s
  // (q0 = 0 then), off the q0 select.
  wire [4:0]      dhb = {p2_frame, ~dqa_q, ~dqb_q, ~dqc_q};
  wire [4:0]      dhu = dhb + DUE_HALF[5:1];
  wire [4:0]      dhu1 = dhb + (DUE_HALF[5:1] + 5'd1);
  wire            unused_due_half = DUE_HALF[0];
  wire [6:0]      due_n = {(dq3 | dc1) ? dhu : dhu1, dq0 ^ dq3, dq0};

  // The deceleration point P'_hi >= DEC_FRAC (cycle 4i+4), in 16-bit halves whose carry chains
  // take the block RAM word directly (P', a register, is the inverted operand):
  // rd3 + ~P' + 1 carries iff rd3 >= P' (high half), rd3 + ~P' iff rd3 > P' (low half).
  wire [17:0] dfc_hc = {1'b0, rd3[31:16], 1'b1} + {1'b0, ~pn_hi_q[31:16], 1'b1};
  wire [17:0] dfc_lc = {1'b0, rd3[15:0], 1'b1} + {1'b0, ~pn_hi_q[15:0], 1'b0};
  wire        unused_dfc = ^{dfc_hc[16:0], dfc_lc[16:0]};
  wire        dfc = dfh_q | (dfe_q & dfl_q);

  // Limit > t, as the carry out of L + ~t (+ the carry of the low half).
  wire c_gt_lo, c_gt_hi;
  wire [31:0] unused_lo, unused_hi;
  // (Registered in cycles 4i+3 and 4i+4: add_co's flags of those cycles.)
  assign {c_gt_lo, unused_lo} = add_co(llo_q, tn_lo_q, 1'b0, kph_q[3], g_q[0]);
  assign {c_gt_hi, unused_hi} = add_co(lhi_q, tn_hi_q, cl0_q, kph_q[0], ~g_q[1]);

  // Stage-2 decisions (cycles 4i+5, 4i+6), from registers.
  reg        c_sell1, c_sell0;
  reg        c_clamp, c_sell, c_stop_end, c_cnt_end, c_dec_trig, c_acc_end, c_ended;
  // A start of a refused or empty move: consumed at its commit, no step.
  wire       c_consume = p2_start & (p2_fl[F_BAD] | p2_fl[F_EMPTY]);
  reg [1:0]  c_ph_n;
  reg        c_decf_n;

  always @* begin
    c_clamp = ct1_q | ~gt_q;
    // The select of S (the limit instead of t), registered as sell_q with gt_q at the end of
    // 4i+4 from the compare's carry c_gt_hi itself (gt_q's next value), so that the S_lo and
    // S_hi writes take it from a flip-flop; written as the compare's select of two functions
    // of registers (c_sell1: the limit above t, c_sell0: not), so one LUT follows the chain.
    case (p2_ph)
      PH_ACCEL: begin c_sell1 = ct1_q; c_sell0 = 1'b1; end
      PH_DECEL: begin c_sell1 = ~p2_stop; c_sell0 = ~p2_stop & ~p2_decf & ~ct1_q; end
      default:  begin c_sell1 = 1'b0; c_sell0 = 1'b0; end
    endcase
    c_sell = c_gt_hi ? c_sell1 : c_sell0;
    c_stop_end = p2_stop & (~ct1_q | p2_fl[F_DZ]);
    c_cnt_end = ~p2_fl[F_JOG] & zre_q;
    c_dec_trig = ~p2_fl[F_JOG] & (p2_ph != PH_DECEL) & ((zrd_q & dfc) | (zrd0_q & step_q));
    c_acc_end = (p2_ph == PH_ACCEL) & (c_clamp | (~p2_fl[F_JOG] & zra_q));
    c_ended = c_cnt_end | c_stop_end;
    c_ph_n = c_ended ? PH_IDLE : c_dec_trig ? PH_DECEL : c_acc_end ? PH_CRUISE : p2_ph;
    c_decf_n = c_dec_trig ? 1'b1 : (p2_ph == PH_DECEL) ? 1'b0 : p2_decf;
  end

  // Engine addresses and write data, by cycle of the slot.
  always @* begin
    ra0 = 8'd0; ra1 = 8'd0; ra2 = 8'd0; ra3 = 8'd0;
    case (kc)
      2'd0: begin
        // Reads of the sampled axis: S (or V_START), P, addend, limit, low words.
        ra0 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd0)} : {p1_ax, 5'd0};
        ra1 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd7)} : {p1_ax, 5'd0};
        ra2 = {p1_ax, slot_word(p1_slot, a_off(p1_ph, p1_decf, p1_stop))};
        ra3 = {p1_ax, slot_word(p1_slot, (p1_ph == PH_DECEL) ? 3'd2 : 3'd0)};
      end
      2'd1: begin
        ra0 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd1)} : {p1_ax, 5'd1};
        ra1 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd7)} : {p1_ax, 5'd1};
        // High word of the addend: the next word, except the zero word (cruise) which serves both.
        ra2 = {p1_ax, slot_word(p1_slot, (a_off(p1_ph, p1_decf, p1_stop) == 3'd7) ? 3'd7 :
                                         a_off(p1_ph, p1_decf, p1_stop) + 3'd1)};
        ra3 = {p1_ax, slot_word(p1_slot, (p1_ph == PH_DECEL) ? 3'd3 : 3'd1)};
      end
      2'd2: begin
        ra0 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd2)} : {p1_ax, 5'd2};
        ra1 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd0)} : {p1_ax, 5'd2};
        ra2 = p1_start ? {p1_ax, slot_word(p1_slot, 3'd6)} : {p1_ax, 5'd0};
        ra3 = {p1_ax, slot_word(p1_slot, 3'd4)};
      end
      default: ;
    endcase
    // Writes by the one-hot slot cycle (kph_q; in the bus cycle the banks take the bus's):
    // 4i: steps-to-end of stage 3 (the axis two slots back), P_lo; 4i+1: S_lo, P_hi, to-dec;
    // 4i+2: S_hi, to-acc.
    wa0 = kph_q[0] ? {p3_ax, 5'd2} : {p2_ax, 4'd0, kph_q[2]};
    wd0 = kph_q[0] ? re_n_q : sell_q ? (kph_q[1] ? llo_q : lhi_q) : ~(kph_q[1] ? tn_lo_q : tn_hi_q);
    wa1 = {p2_ax, 3'd0, kph_q[2], kph_q[1]};
    wd1 = kph_q[0] ? pn_lo_q : kph_q[1] ? pn_hi_q : ra_n_q;
    wa2 = {p2_ax, 5'd0};
    wd2 = rd_n_q;
    // Read and write enables from the one-hot slot cycle (no decode of the counter): reads in
    // 4i..4i+2; writes of bank 0 (steps-to-end of stage 3 in 4i, S_lo, S_hi), bank 1 (P_lo,
    // P_hi, to-acc) and bank 2 (to-dec in 4i+1) of stage 2.
    re_e = ~kph_q[3] & p1_valid & p1_gen;
    we0 = (kph_q[0] & p3_we) | ((kph_q[1] | kph_q[2]) & p2_valid & p2_gen);
    we1 = ~kph_q[3] & p2_valid & p2_gen;
    we2 = kph_q[1] & p2_valid & p2_gen;
  end

  // Datapath (clock enables straight from the one-hot slot cycle kph_q).
  always @(posedge clk_i) begin
    if (kph_q[2]) begin  // low words of S, P, addend, limit (cycle 4i+2)
      {cp0_q, pn_lo_q} <= plo_sum;
      ct0_q <= s_lo_sum[32];
      tn_lo_q <= ~(p1_smask ? rd2 : s_lo_sum[31:0]);
      llo_q <= rd3;
    end
    if (kph_q[3]) begin  // high words (cycle 4i+3)
      {step_q, pn_hi_q} <= phi_sum;
      ct1_q <= s_hi_sum[32];
      tn_hi_q <= ~(p1_smask ? rd2 : s_hi_sum[31:0]);
      cl0_q <= c_gt_lo;
      lhi_q <= rd3;
    end
    if (kph_q[0]) begin  // counters, compare high, deceleration point (cycle 4i+4)
      gt_q <= c_gt_hi;
      sell_q <= c_sell;
      re_n_q <= rd0 - {31'd0, step_q};
      ra_n_q <= rd1 - {31'd0, step_q};
      rd_n_q <= rd2 - {31'd0, step_q};
      zre_q <= (rd0 == {31'd0, step_q});
      zra_q <= (rd1 == {31'd0, step_q});
      zrd_q <= (rd2 == {31'd0, step_q});
      zrd0_q <= (rd2 == 32'd0);
      dfh_q <= ~dfc_hc[17];
      dfe_q <= (pn_hi_q[31:16] == rd3[31:16]);
      dfl_q <= ~dfc_lc[17];
    end
    ds3_q <= {ds_q, 1'b0} + {2'b00, ds_q};
    if (kph_q[3]) req_due_q <= dz_q ? dbase + DUE_OFFSET : due_n;
    // Division: the divisor is loaded with the speed at the end of 4i+3; the steps' registers
    // at every edge (see above). The first step divides the overshoot's top bits straight from
    // pn_hi_q, so that the block RAM read and the 33-bit add behind it end in pn_hi_q alone.
    if (kph_q[3]) begin
      ds_q <= rd0[31 -: SUB_W];
      dz_q <= (rd0[31 -: SUB_W] == {SUB_W{1'b0}});
    end
    {dra_q, dqa_q} <= dva;
    {drb_q, dqb_q} <= dvb;
    {drc_q, dqc_q} <= dvc;
  end
  wire [32:0] phi_sum = add_co(rd1, rd0, cp0_q, kph_q[3], g_q[0]);
  wire [32:0] s_lo_sum = add_co(rd0, rd2, p1_cin, kph_q[2], g_q[1]);
  wire [32:0] s_hi_sum = add_co(rd0, rd2, ct0_q, kph_q[3], g_q[0]);
  wire [32:0] plo_sum = add_co(rd1, rd0, 1'b0, kph_q[2], g_q[1]);

  // ---------------------------------------------------------------------------------------
  // Control: next state of every axis.
  integer k;
  reg        cm, cm_ok, push_ok;
  reg [1:0]  qv, pos;
  reg [NS-1:0] flush, pop, consumed, refused, freed;
  reg [6:0]  req_due;
  reg [SF_W-1:0] sfk;

  always @* begin
    run_d = run_q; decf_d = decf_q; stop_d = stop_q; chain_d = chain_q;
    running_d = running_q; starting_d = starting_q; ph_d = ph_q; act_d = act_q; qn_d = qn_q;
    sf_d = sf_q; spend_d = spend_q; ppend_d = ppend_q; fstart_d = fstart_q; fstop_d = fstop_q;
    flush = {NS{1'b0}}; pop = {NS{1'b0}}; consumed = {NS{1'b0}};
    refused = {NS{1'b0}}; freed = {NS{1'b0}};
    req_due = req_due_q;
    pos = 2'd0; sfk = {SF_W{1'b0}};

    // Commit of the slot in stage 3 (edge ending 4i+8), from the decisions registered at 4i+5;
    // an abort since the sample cancels it. Per axis from its strobe cm_q (stage 3 is that
    // axis's, not aborted, and this is the commit cycle), so that neither a decode of the
    // stage's axis nor the slot cycle is on the state's enables.
    for (k = 0; k < NAXES; k = k + 1) begin
      cm = cm_q[k];
      cm_ok = cm && !abort[k];
      // (An aborted stage's axis has starting clear already: the abort cleared it.)
      if (cm) starting_d[k] = 1'b0;
      if (cm_ok) begin
        if (d_consume) begin
          consumed[k] = 1'b1;
          refused[k] = d_bad;
        end
        if (d_upd) begin   // not consumed, a step slot (its step request is req_q)
          run_d[k] = d_run;
          ph_d[k*2 +: 2] = d_ph;
          decf_d[k] = d_decf;
          stop_d[k] = d_stop;
        end
        // The move ended or was consumed: the next queued move chains if the axis runs and
        // one is queued.
        if (d_fin) begin
          if (running_q[k] && qn_q[k*2 +: 2] != 2'd0) chain_d[k] = 1'b1;
          else running_d[k] = 1'b0;
        end
        if (d_fs_run || (d_fs_any && run_q[k])) begin
          stop_d[k] = 1'b1;
          ph_d[k*2 +: 2] = PH_DECEL;
          decf_d[k] = 1'b0;
        end
      end
    end

    // Sample (edge ending 4i-1), per axis with its registered strobes (ss_q, sfs_q, sst_q; an
    // abort, below, overrides a STOP's flush, whose updates are its own).
    for (k = 0; k < NAXES; k = k + 1) begin
      if (sfs_q[k]) begin
        flush[k] = 1'b1;
        running_d[k] = 1'b0;
        chain_d[k] = 1'b0;
      end
      if (sst_q[k] && !abort[k]) begin
        pop[k] = 1'b1;
        act_d[k*2 +: 2] = inc3(act_q[k*2 +: 2]);
        if (sn_q[k]) running_d[k] = 1'b1;   // a new move (not chained)
        chain_d[k] = 1'b0;
        starting_d[k] = 1'b1;
      end
      if (ss_q[k]) begin
        fstart_d[k] = 1'b0;
        fstop_d[k] = 1'b0;
      end
    end

    // START/STOP act at frame boundaries.
    if (boundary) begin
      fstart_d = spend_q;
      fstop_d = ppend_q;
      spend_d = {NS{1'b0}};
      ppend_d = {NS{1'b0}};
    end
    spend_d = spend_d | start_w;
    ppend_d = ppend_d | stop_w;

    // Abort.
    for (k = 0; k < NAXES; k = k + 1) begin
      if (abort[k]) begin
        run_d[k] = 1'b0;
        ph_d[k*2 +: 2] = PH_IDLE;
        running_d[k] = 1'b0;
        chain_d[k] = 1'b0;
        starting_d[k] = 1'b0;
        spend_d[k] = 1'b0;
        ppend_d[k] = 1'b0;
        fstart_d[k] = 1'b0;
        fstop_d[k] = 1'b0;
        flush[k] = 1'b1;
      end
    end

    // Queue counts and flags: flush, pop (the flags shift down one position), the loader's
    // push into position 1 + qn after the pop (dropped by a flush at its commit edge).
    for (k = 0; k < NAXES; k = k + 1) begin
      qv = qn_q[k*2 +: 2];
      push_ok = push_i && ({29'd0, push_axis_i} == k) && !flush[k];
      sfk = sf_q[k*SF_W +: SF_W];
      if (pop[k]) sfk = {7'd0, sfk[20:7]};
      pos = qv + 2'd1 - {1'b0, pop[k]};
      if (push_ok) begin
        if (pos == 2'd1) sfk[13:7] = push_flags_i;
        else sfk[20:14] = push_flags_i;
      end
      sf_d[k*SF_W +: SF_W] = sfk;
      if (flush[k]) qn_d[k*2 +: 2] = 2'd0;
      else qn_d[k*2 +: 2] = qv - {1'b0, pop[k]} + {1'b0, push_ok};
      freed[k] = (qn_d[k*2 +: 2] < qv);
    end
  end

  // The loader's memory slot (act + 1 + qn mod 3) is computed in the bus block from act_o and
  // qn_o at the push's start; pops do not move it, a flush cancels the push.

  always @(posedge clk_i) begin
    if (rst_i) begin
      g_q <= 7'd0;
      gn_q <= 7'd1;
      kph_q <= 4'b0001;
      run_q <= {NS{1'b0}}; decf_q <= {NS{1'b0}}; stop_q <= {NS{1'b0}};
      chain_q <= {NS{1'b0}}; running_q <= {NS{1'b0}}; starting_q <= {NS{1'b0}};
      busy_q <= {NS{1'b0}};
      spend_q <= {NS{1'b0}}; ppend_q <= {NS{1'b0}};
      fstart_q <= {NS{1'b0}}; fstop_q <= {NS{1'b0}};
      ph_q <= {NS*2{1'b0}}; act_q <= {NS*2{1'b0}}; qn_q <= {NS*2{1'b0}};
      sf_q <= {NS*SF_W{1'b0}};
      p1_valid <= 1'b0; p2_valid <= 1'b0;
      req_q <= {NAXES{1'b0}}; tl_q <= {NAXES{1'b0}}; cm_q <= {NAXES{1'b0}};
      si_q <= 3'd0; smp_oh_q <= {NS{1'b0}};
    end else begin
      g_q <= g_q + 7'd1;
      gn_q <= gn_q + 7'd1;
      kph_q <= {kph_q[2:0], kph_q[3]};
      // The next sample's axis: axis 0 after frame cycle 30, then one slot further at each bus
      // cycle (none for slots NAXES..7).
      if (kph_q[3] || boundary) begin
        si_q <= boundary ? 3'd0 : si_q + 3'd1;
        smp_oh_q <= boundary ? SMP_FIRST : {smp_oh_q[NS-2:0], 1'b0};
      end
      run_q <= run_d; decf_q <= decf_d; stop_q <= stop_d; chain_q <= chain_d;
      running_q <= running_d; starting_q <= starting_d;
      busy_q <= busy8;
      spend_q <= spend_d; ppend_q <= ppend_d; fstart_q <= fstart_d; fstop_q <= fstop_d;
      ph_q <= ph_d; act_q <= act_d; qn_q <= qn_d; sf_q <= sf_d;
      // Pipeline valid bits.
      if (kph_q[3]) p1_valid <= s_valid;
      if (kph_q[3]) p2_valid <= p1_valid;
      // The commit's strobes: set at the edge ending 4i+7 (stage 2 becomes stage 3, d_* are
      // from 4i+5), cleared at the next one; an abort at the commit edge itself still cancels
      // the commit (cm_ok, req_o, tgt_load_o).
      cm_q <= cm_n;
      req_q <= cm_n & {NAXES{d_upd & d_req}};
      tl_q <= cm_n & {NAXES{~d_consume & p2_start}};
    end
  end

  // Pipeline payload (not reset: read only while valid).
  always @(posedge clk_i) begin
    if (kph_q[3]) begin
      // Stage 1 from the sample; stage 2 from stage 1.
      p1_start <= s_start; p1_decf <= s_decf; p1_stop <= s_stop;
      p1_gen <= s_gen; p1_fstop <= fstop_q[si]; p1_abort <= 1'b0;
      p1_ax <= si; p1_slot <= s_slot; p1_ph <= s_ph; p1_frame <= g_q[6:5] + {1'b0, (si == 3'd0)};
      p1_fl <= s_fl;
      p2_start <= p1_start; p2_decf <= p1_decf; p2_stop <= p1_stop;
      p2_gen <= p1_gen; p2_fstop <= p1_fstop; p2_abort <= p1_abort | abort[p1_ax];
      p2_ax <= p1_ax; p2_ph <= p1_ph; p2_frame <= p1_frame; p2_fl <= p1_fl;
      p3_we <= p2_valid & p2_gen;
      p3_ax <= p2_ax;
      p3_dir <= p2_fl[F_DIR];
    end else begin
      p1_abort <= p1_abort | abort[p1_ax];
      p2_abort <= p2_abort | abort[p2_ax];
    end
    if (kph_q[0]) begin
      // The datapath masks of stage 1, from its registers (used in cycles 4i+2, 4i+3).
      p1_smask <= (p1_ph == PH_DECEL) & p1_decf & ~p1_stop;
      p1_cin <= (p1_ph == PH_DECEL) & ~(p1_decf & ~p1_stop);
    end
    if (kph_q[1]) begin
      // Commit decisions, from the datapath registers of cycle 4i+4.
      d_consume <= c_consume;
      d_upd <= ~c_consume & p2_gen;
      d_fin <= c_consume | (p2_gen & c_ended);
      d_fs_run <= p2_fstop & p2_gen & ~c_ended;
      d_fs_any <= p2_fstop & ~p2_gen;
      d_bad <= p2_fl[F_BAD];
      d_run <= ~c_ended;
      d_ph <= c_ph_n;
      d_decf <= c_decf_n;
      d_stop <= p2_stop;
      d_req <= step_q;
    end
  end

  // ---------------------------------------------------------------------------------------
  // Outputs.
  wire [NS-1:0] busy8;
  genvar gk;
  generate
    for (gk = 0; gk < NS; gk = gk + 1) begin : g_busy
      assign busy8[gk] = run_q[gk] | chain_q[gk] | starting_q[gk] | pending[gk];
    end
    for (gk = 0; gk < NAXES; gk = gk + 1) begin : g_out
      assign busy_o[gk] = busy8[gk];
      assign run_o[gk] = running_q[gk] | spend_q[gk] | fstart_q[gk];
      assign phase_o[gk*2 +: 2] = run_q[gk] ? ph_q[gk*2 +: 2] : PH_IDLE;
      assign req_o[gk] = req_q[gk] && !abort[gk];
      assign tgt_load_o[gk] = tl_q[gk] && !abort[gk];
    end
  endgenerate
  assign g_o = g_q;
  assign gn_o = gn_q;
  assign kph_o = kph_q;
  assign act_o = act_q[NAXES*2-1:0];
  assign qn_o = qn_q[NAXES*2-1:0];
  wire [NS-1:0] done8 = (busy_q & ~busy8) | consumed;
  assign done_o = done8[NAXES-1:0];
  generate
    if (NAXES < NS) begin : g_tail
      wire unused_tail = ^{refused[NS-1:NAXES], freed[NS-1:NAXES], done8[NS-1:NAXES]};
    end
  endgenerate
  assign refused_o = refused[NAXES-1:0];
  assign freed_o = freed[NAXES-1:0];
  assign flush_o = flush[NAXES-1:0];
  assign req_due_o = req_due;
  assign tgt_dir_o = p3_dir;

endmodule

`default_nettype wire
