// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of the frame engine (hexstep_engine, NAXES = 1) with its output stage
// (hexstep_pulse), as in hexstep_top: the step-level properties at the stage's ports and the
// STEP/DIR levels, and the pulse stage's contract asserted where the engine drives it.
`default_nettype none

// The harness is the bus block: a scripted sequence, not a free bus (a free bus makes every
// cover hundreds of cycles deeper). Move A, and with f_two a move B, are $anyconst values of a
// kind: a move that passes the loader's refusal rules (docs/ARCHITECTURE.md, "Refusal rules";
// steps 1..7), and with FV_KINDS also a jog (passes the jog rules), a refused move (steps 1..7,
// breaks a rule) or an empty move (steps 0).
// The harness pushes A at cycle 1 and B at cycle 2 (push_i with the flags the loader computes),
// writes their queue-slot words straight into the engine's banks on the bus cycles (one word per
// bus cycle, each before a tick can read it: A's 15 words of its first tick by t = 59, its ~DEC
// at t = 63, 67 (first read at the second tick, t >= 96); B's first-tick words by t = 127, its
// ~DEC by t = 135: a move's first tick never steps (P starts at 0, S < 1 step/tick), so A lasts
// at least two ticks and B's first tick is sampled at t = 127 or later), and writes START at
// cycle 40 (t counts cycles from the first after reset, g = t mod 128): the boundary at g = 62
// takes it, A's first tick is sampled at g = 63. If A is refused or empty (FV_KINDS) it is
// consumed at that sample without a read of its words and B starts at the next (t = 95), so
// then B's words are written first, in the same cycles, and A's after them. STOP (stop_w) and
// abort are free inputs: STOP only from cycle 64 on, abort from cycle 3 on (after the pushes, so
// nothing is queued after an abort); in the deep bounded
// checks of the concrete moves (bmc_tri, bmc_chain: no STOP, no abort; bmc_abort: the triangle
// with one abort strobe at any cycle of 136..143) the pulse timing is that of the covers, and so
// it is with FV_STOP1 (bmc_stop, bmc_cnt, bmc_cons: one STOP strobe at a free cycle from 64 on,
// or none; no abort). Elsewhere the pulse timing and polarity are $anyconst (PULSE_W = 2).
//
// Asserted (task bmc: bounded, to the depth in hexstep_engine.sby):
//   - no STEP rising edge while the engine is not busy, none before the first tick can commit;
//   - the step requests of each move (from its start, tgt_load, to the next move taken) are at
//     most its N, none for a refused or empty move; all STEP rising edges are at most the sum
//     of N over the moves taken (both unless a jog started);
//   - busy falls only after the N-th step: when busy falls without a STOP or an abort before,
//     every queued move was taken, the last is no jog, and the rising edges are exactly the sum
//     of N (the last move issued exactly its N requests);
//   - refused and empty moves are consumed, moves and jogs start; refused_o exactly when a
//     refused move is consumed;
//   - STOP: no move leaves the queue from 42 cycles after the strobe; each stopping tick after
//     the first reads S = S_prev - dec (S_prev >= dec); no tick of a move after its tick with
//     old S < dec while stopping;
//   - abort: no STEP rising edge at or after the first abort edge; STEP is low at most
//     max(step_high, 1) cycles after it; busy is low from the cycle after it;
//   - the pulse stage's contract C1-C3 (hexstep_pulse_fv): a request only while accepts_o, due
//     1..127 cycles ahead and after every waiting request, the DIR target changes only while
//     nothing is pending;
//   - the STEP/DIR timing checker (hexstep_fv_stepdir) on the pins;
//   - hexstep_wb_fv's assumptions on the engine: act, qn in 0..2; the engine writes only the
//     per-axis state words, never staging/mirror/queue words;
//   - the speed accumulator: the speed S every tick reads (V_START at a start) is at most the
//     move's v_max and, unless stopping, at least min(v_start, floor) (floor = v_end, or dec if
//     v_end = 0); internal datapath signals connected by the .sby script, asserted only.
// Covers (task cover): a complete triangular move (accelerate, decelerate, no cruise), a
// trapezoidal move (accelerate, cruise, decelerate), a chained pair (B starts in the slot after
// A's last tick, both complete), a STOP (the move ends early at rest).
module hexstep_engine_fv #(
  parameter integer PULSE_W = 2,
  parameter integer POS_W   = 6
) (
  input wire clk_i,
  input wire rst_i,
  input wire stop_i,
  input wire abort_i
);
`include "hexstep_defs.vh"
  // ---- the moves ----
  (* anyconst *) reg        f_two;
  (* anyconst *) reg [2:0]  a_n, b_n, a_as, b_as, a_ds, b_ds;     // steps, acc_steps, dec_step
  (* anyconst *) reg        a_dir, b_dir;
  (* anyconst *) reg [63:0] a_vs, a_vm, a_ve, a_vd, b_vs, b_vm, b_ve, b_vd;
  (* anyconst *) reg [47:0] a_acc, a_dec, b_acc, b_dec;
  (* anyconst *) reg [31:0] a_df, b_df;                          // DEC_FRAC aligned to bit 31
  (* anyconst *) reg [PULSE_W-1:0] f_high, f_low, f_setup, f_hold;
  // over_i of the output stage: each timing value at most 1.
  wire [3:0] f_over = {f_hold <= 1, f_setup <= 1, f_low <= 1, f_high <= 1};
  (* anyconst *) reg        f_sinv, f_dinv;
  // Kind of each move: a move, a jog, a refused move (it breaks a refusal rule), an empty move
  // (steps 0). Only with FV_KINDS; elsewhere both are moves.
  localparam [1:0] K_MOVE = 2'd0, K_JOG = 2'd1, K_BAD = 2'd2, K_EMPTY = 2'd3;
`ifdef FV_KINDS
  (* anyconst *) reg [1:0]  a_kind, b_kind;
`else
  // Constants, so that the kind logic folds away (as $anyconst values held by an assumption it
  // made bmc_chain eight times slower).
  wire [1:0] a_kind = K_MOVE, b_kind = K_MOVE;
`endif

  // The refusal rules of a move (docs/ARCHITECTURE.md), but for steps != 0 (empty, not refused).
  function rules(input [2:0] n, input [2:0] as, input [2:0] ds, input [63:0] vs,
                 input [63:0] vm, input [63:0] ve, input [63:0] vd, input [47:0] acc,
                 input [47:0] dec, input [31:0] df);
    rules = vm != 64'd0 && vs <= vm && ve <= vm && vd <= vm &&
            !(ve == 64'd0 && {16'd0, dec} > vm) && as <= n && ds <= n &&
            !(ve == 64'd0 && dec == 48'd0) &&
            !(vs == 64'd0 && !(ds == 3'd0 && df == 32'd0) && (acc == 48'd0 || as == 3'd0));
  endfunction
  // The rules of a jog (it ignores the step counts, v_end, v_dec, dec_frac).
  function rules_jog(input [63:0] vs, input [63:0] vm, input [47:0] acc, input [47:0] dec);
    rules_jog = vm != 64'd0 && vs <= vm && !(vs == 64'd0 && acc == 48'd0) && dec != 48'd0;
  endfunction
  function valid(input [1:0] kind, input [2:0] n, input [2:0] as, input [2:0] ds,
                 input [63:0] vs, input [63:0] vm, input [63:0] ve, input [63:0] vd,
                 input [47:0] acc, input [47:0] dec, input [31:0] df);
    case (kind)
      K_MOVE:  valid = n != 3'd0 && rules(n, as, ds, vs, vm, ve, vd, acc, dec, df);
      K_JOG:   valid = rules_jog(vs, vm, acc, dec);
      K_BAD:   valid = n != 3'd0 && !rules(n, as, ds, vs, vm, ve, vd, acc, dec, df);
      default: valid = n == 3'd0;
    endcase
  endfunction
  // Flags the loader computes for a move (bit positions F_*, phase codes PH_* of
  // hexstep_defs.vh, the encoding hexstep_wb writes and hexstep_engine reads).
  function [6:0] flags(input [1:0] kind, input [2:0] as, input [2:0] ds, input [31:0] df,
                       input dir, input [47:0] dec, input [47:0] acc);
    begin
      flags = 7'd0;
      flags[F_BAD] = kind == K_BAD;
      flags[F_EMPTY] = kind == K_EMPTY;
      flags[F_JOG] = kind == K_JOG;
      flags[F_DIR] = dir;
      flags[F_INIT +: 2] = (kind == K_JOG) ? ((acc == 48'd0) ? PH_CRUISE : PH_ACCEL) :
                           (ds == 3'd0 && df == 32'd0) ? PH_DECEL :
                           (as != 3'd0) ? PH_ACCEL : PH_CRUISE;
      flags[F_DZ] = dec == 48'd0;
    end
  endfunction
  always @* begin
    assume (valid(a_kind, a_n, a_as, a_ds, a_vs, a_vm, a_ve, a_vd, a_acc, a_dec, a_df));
    if (f_two) assume (valid(b_kind, b_n, b_as, b_ds, b_vs, b_vm, b_ve, b_vd, b_acc, b_dec,
                             b_df));
  end
  // Concrete moves for the cover tasks and the deep bounded checks (a free move makes the
  // solver too slow beyond about 100 cycles): speeds near one step per tick (P starts at 0 and
  // S < 1 step/tick, so the first tick of a move never steps).
  localparam [63:0] V_HI = 64'hF000_0000_0000_0000, V_MID = 64'hE000_0000_0000_0000;
  localparam [63:0] V_LO = 64'hC000_0000_0000_0000;
  localparam [47:0] A_SM = 48'h0100_0000_0000;
  localparam [31:0] D_GRID = 32'hF000_0000;
`ifdef FV_MOVE_TRI      // triangle: N = 2, accelerate to the deceleration point after step 1
  always @* assume (!f_two && a_n == 3'd2 && a_as == 3'd1 && a_ds == 3'd1 && a_df == 32'd0 &&
                    a_vs == V_MID && a_vm == V_HI && a_ve == V_LO && a_vd == V_MID &&
                    a_acc == A_SM && a_dec == A_SM);
`endif
`ifdef FV_MOVE_TRAP     // trapezoid: N = 3, accelerate 1 step, cruise, decelerate from step 2
  always @* assume (!f_two && a_n == 3'd3 && a_as == 3'd1 && a_ds == 3'd2 && a_df == 32'd0 &&
                    a_vs == V_MID && a_vm == V_HI && a_ve == V_LO && a_vd == V_MID &&
                    a_acc == A_SM && a_dec == A_SM);
`endif
`ifdef FV_MOVE_CHAIN    // A: 1 step at cruise, B: 1 step at cruise, the other direction
  always @* assume (f_two && a_n == 3'd1 && a_as == 3'd0 && a_ds == 3'd1 && a_df == 32'd0 &&
                    a_vs == V_HI && a_vm == V_HI && a_ve == V_LO && a_vd == V_MID &&
                    a_acc == 48'd0 && a_dec == A_SM && a_dir &&
                    b_n == 3'd1 && b_as == 3'd0 && b_ds == 3'd1 && b_df == 32'd0 &&
                    b_vs == V_HI && b_vm == V_HI && b_ve == V_LO && b_vd == V_MID &&
                    b_acc == 48'd0 && b_dec == A_SM && !b_dir);
`endif
`ifdef FV_MOVE_STOP     // 7 steps at a crawl that a STOP brings to rest within a few ticks
  always @* assume (!f_two && a_n == 3'd7 && a_as == 3'd0 && a_ds == 3'd7 && a_df == 32'd0 &&
                    a_vs == 64'h0000_8000_0000_0000 && a_vm == 64'h0000_8000_0000_0000 &&
                    a_ve == 64'h0000_4000_0000_0000 && a_vd == 64'h0000_4000_0000_0000 &&
                    a_acc == 48'd0 && a_dec == 48'h8000_0000_0000);
`endif
`ifdef FV_MOVE_CNT      // two moves of free kind, steps, acc_steps, dec_step, dir, dec_frac
  // (bits 31:28), at the speeds of the triangle
  always @* assume (a_vs == V_MID && a_vm == V_HI && a_ve == V_LO && a_vd == V_MID &&
                    a_acc == A_SM && a_dec == A_SM && (a_df & ~D_GRID) == 0 &&
                    b_vs == V_MID && b_vm == V_HI && b_ve == V_LO && b_vd == V_MID &&
                    b_acc == A_SM && b_dec == A_SM && (b_df & ~D_GRID) == 0);
`endif
`ifdef FV_COVER
  // The covers run one concrete scenario each: no abort, STOP only in the STOP cover, pulse
  // timing high 2, low 1, setup 1, hold 1, no inversion.
  always @* begin
    assume (!abort_i && f_high == 2 && f_low == 1 && f_setup == 1 && f_hold == 1 && !f_sinv &&
            !f_dinv);
`ifndef FV_MOVE_STOP
    assume (!stop_i);
`endif
  end
`endif
  wire [63:0] a_fl = (a_ve != 64'd0) ? a_ve : {16'd0, a_dec};
  wire [63:0] b_fl = (b_ve != 64'd0) ? b_ve : {16'd0, b_dec};
  wire [63:0] a_nd = ~{16'd0, a_dec}, b_nd = ~{16'd0, b_dec};

  // ---- reset in the first cycle only; cycle count ----
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);
  reg [9:0] t;                   // cycles since the first after reset (t = 0: g = 0)
  always @(posedge clk_i) t <= rst_i ? 10'd0 : (t == 10'd1023) ? t : t + 10'd1;

  // ---- the bus block's side ----
  wire [6:0]  g, gn;
  wire [3:0]  kph;
  wire        bus_cyc = (g[1:0] == 2'd3);
  wire [7:0]  n_bus = t[9:2];    // bus cycle number at g = 4n + 3
  reg  [3:0]  bwe;
  reg  [7:0]  bwa;
  reg  [31:0] bwd;
  // A refused or empty A is consumed at its first sample without reading its words, and B then
  // starts one frame later: B's words come first. With FV_KINDS the task fixes which
  // (FV_A_CONS: A is refused or empty, else a move or a jog), so that the order of the words is
  // a constant.
`ifdef FV_A_CONS
  wire a_cons = 1'b1;
  always @* assume (a_kind == K_BAD || a_kind == K_EMPTY);
`else
  wire a_cons = 1'b0;
  always @* assume (a_kind == K_MOVE || a_kind == K_JOG);
`endif
  // One word per bus cycle: queue slot s (words 8 + 8s ..), bank, offset, data.
  task put(input [1:0] bank, input [1:0] s, input [2:0] off, input [31:0] d);
    begin
      bwe = 4'd1 << bank;
      bwa = {3'd0, slot_word(s, off)};
      bwd = d;
    end
  endtask
  // The words of a move in the order its ticks need them.
  task move_word(input [4:0] i, input [1:0] s, input [2:0] n, input [2:0] as, input [2:0] ds,
                 input [63:0] vs, input [63:0] vm, input [63:0] vd, input [63:0] fl,
                 input [47:0] acc, input [63:0] nd, input [31:0] df);
    case (i)
      5'd0:  put(2'd0, s, 3'd0, vs[31:0]);
      5'd1:  put(2'd0, s, 3'd1, vs[63:32]);
      5'd2:  put(2'd0, s, 3'd2, {29'd0, n});
      5'd3:  put(2'd1, s, 3'd0, {29'd0, as});
      5'd4:  put(2'd2, s, 3'd6, {29'd0, ds});
      5'd5:  put(2'd3, s, 3'd4, df);
      5'd6:  put(2'd2, s, 3'd0, acc[31:0]);
      5'd7:  put(2'd2, s, 3'd1, {16'd0, acc[47:32]});
      5'd8:  put(2'd3, s, 3'd0, vm[31:0]);
      5'd9:  put(2'd3, s, 3'd1, vm[63:32]);
      5'd10: put(2'd2, s, 3'd4, vd[31:0]);
      5'd11: put(2'd2, s, 3'd5, vd[63:32]);
      5'd12: put(2'd3, s, 3'd2, fl[31:0]);
      5'd13: put(2'd3, s, 3'd3, fl[63:32]);
      5'd14: begin put(2'd2, s, 3'd7, 32'd0); bwe = 4'b0110; end   // the zero words (banks 1, 2)
      5'd15: put(2'd2, s, 3'd2, nd[31:0]);
      5'd16: put(2'd2, s, 3'd3, nd[63:32]);
      default: ;
    endcase
  endtask
  always @* begin
    bwe = 4'd0; bwa = 8'd0; bwd = 32'd0;
    if (!rst_i && bus_cyc && t < 10'd1020) begin
      if (n_bus < 8'd17 && !(a_cons && f_two))
        move_word(n_bus[4:0], 2'd1, a_n, a_as, a_ds, a_vs, a_vm, a_vd, a_fl, a_acc, a_nd, a_df);
      else if (f_two && n_bus < 8'd17)
        move_word(n_bus[4:0], 2'd2, b_n, b_as, b_ds, b_vs, b_vm, b_vd, b_fl, b_acc, b_nd, b_df);
      else if (f_two && n_bus < 8'd34 && !a_cons)
        move_word(n_bus[4:0] - 5'd17, 2'd2, b_n, b_as, b_ds, b_vs, b_vm, b_vd, b_fl, b_acc, b_nd,
                  b_df);
      else if (f_two && n_bus < 8'd34)
        move_word(n_bus[4:0] - 5'd17, 2'd1, a_n, a_as, a_ds, a_vs, a_vm, a_vd, a_fl, a_acc, a_nd,
                  a_df);
    end
  end
  wire       push = !rst_i && (t == 10'd1 || (f_two && t == 10'd2));
  wire [6:0] push_flags = (t == 10'd1) ? flags(a_kind, a_as, a_ds, a_df, a_dir, a_dec, a_acc)
                                       : flags(b_kind, b_as, b_ds, b_df, b_dir, b_dec, b_acc);
  wire       start_w = !rst_i && t == 10'd40;
  always @* begin
    if (rst_i || t < 10'd64) assume (!stop_i);
    if (rst_i || t < 10'd3) assume (!abort_i);
  end
`ifndef FV_COVER
`ifdef FV_MOVE_TRI
  `define FV_CONCRETE
`endif
`ifdef FV_MOVE_CHAIN
  `define FV_CONCRETE
`endif
`endif
`ifdef FV_CONCRETE
  // The deep bounded checks of concrete moves: the pulse timing of the covers, no STOP, and no
  // abort except in bmc_abort: one abort strobe at any cycle of 136..143 (before, at and during
  // the first pulse, which rises at 139). With free strobes and free timing the solver took
  // minutes per 10 cycles at these depths.
  (* anyconst *) reg [9:0] f_tabort;
  always @* begin
    assume (f_high == 2 && f_low == 1 && f_setup == 1 && f_hold == 1 && !f_sinv && !f_dinv);
    assume (!stop_i);
`ifdef FV_ABORT_WIN
    assume (f_tabort >= 10'd136 && f_tabort <= 10'd143);
    assume (abort_i == (!rst_i && t == f_tabort));
`else
    assume (!abort_i);
`endif
  end
`endif
`ifdef FV_STOP1
  // One STOP strobe at any cycle from 64 on (or none: f_tstop beyond the depth), no abort, the
  // pulse timing of the covers.
  (* anyconst *) reg [9:0] f_tstop;
  always @* begin
    assume (f_high == 2 && f_low == 1 && f_setup == 1 && f_hold == 1 && !f_sinv && !f_dinv);
    assume (stop_i == (!rst_i && t == f_tstop));
    assume (!abort_i);
  end
`endif

  // ---- engine + output stage ----
  wire        busy, run, done, refused, freed, flush, accepts, pending, tgt, req, tgt_load;
  wire        accepts_n, pending_n;
  wire        tgt_dir, step, dir;
  wire [1:0]  act, qn, phase;
  wire [6:0]  req_due;
  wire [31:0] bus_rdata;
  wire [POS_W-1:0] pos;

  hexstep_engine #(.NAXES (1)) u_eng (
    .clk_i (clk_i), .rst_i (rst_i), .g_o (g), .gn_o (gn), .kph_o (kph),
    .start_w_i (start_w), .stop_w_i (stop_i), .abort_i (abort_i),
    .push_i (push), .push_axis_i (3'd0), .push_flags_i (push_flags),
    .bus_re_i (1'b0), .bus_rbank_i (2'd0), .bus_raddr_i (8'd0), .bus_rdata_o (bus_rdata),
    .bus_we_i (bwe), .bus_waddr_i (bwa), .bus_wdata_i (bwd), .bus_init_i (1'b0),
    .act_o (act), .qn_o (qn), .busy_o (busy), .run_o (run), .phase_o (phase), .done_o (done),
    .refused_o (refused), .freed_o (freed), .flush_o (flush),
    .pending_i (pending), .tgt_i (tgt),
    .accepts_n_i (accepts_n), .pending_n_i (pending_n),
    .req_o (req), .req_due_o (req_due), .tgt_load_o (tgt_load), .tgt_dir_o (tgt_dir)
  );
  hexstep_pulse #(.PULSE_W (PULSE_W), .POS_W (POS_W)) u_pulse (
    .clk_i (clk_i), .rst_i (rst_i), .gn_i (gn),
    .abort_i (abort_i), .req_i (req), .req_due_i (req_due),
    .tgt_load_i (tgt_load), .tgt_dir_i (tgt_dir),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .over_i (f_over), .step_inv_i (f_sinv), .dir_inv_i (f_dinv),
    .accepts_o (accepts), .pending_o (pending), .tgt_o (tgt),
    .accepts_n_o (accepts_n), .pending_n_o (pending_n),
    .step_o (step), .dir_o (dir), .pos_o (pos)
  );

  wire step_l = step ^ f_sinv, dir_l = dir ^ f_dinv;
  wire              f_rise, f_dchg;
  wire [PULSE_W:0]  c_r, c_f, c_d;
  hexstep_fv_stepdir #(.PULSE_W (PULSE_W)) u_chk (
    .clk_i (clk_i), .rst_i (rst_i), .step_i (step_l), .dir_i (dir_l),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .rise_o (f_rise), .dchg_o (f_dchg), .c_rise_o (c_r), .c_fall_o (c_f), .c_dir_o (c_d)
  );

  // ---- shadow state ----
  reg        p_have = 1'b0, p_busy;
  reg [1:0]  f_nst_q;            // moves taken from the queue (started or consumed), 0..2
  reg [3:0]  f_nr_q;             // STEP rising edges so far
  reg [2:0]  f_nq_q;             // requests of the current move
  reg        f_stopped, f_aborted_q, f_jogt;
  reg [3:0]  f_since_ab;         // cycles since the first abort edge (saturating)
  reg [5:0]  f_since_st;         // cycles since the first STOP strobe (saturating)
  // u_eng.cm_q (the commit cycle of stage 3, not aborted since its sample: the one axis's
  // strobe), d_consume: the commit of a consumed (refused or empty) move
  (* keep *) wire       f_cm, f_d_consume;
  // Requests waiting in the stage (the contract's order), as in hexstep_pulse_fv.
  reg [1:0]  f_n;
  reg [6:0]  f_t0, f_t1, f_t2;
  wire [6:0] f_d0 = f_t0 - g, f_d1 = f_t1 - g, f_d2 = f_t2 - g;
  wire [6:0] f_dl = (f_n == 2'd3) ? f_d2 : (f_n == 2'd2) ? f_d1 : f_d0;
  wire       f_due = (f_n != 2'd0) && (f_d0 == 7'd0);
  wire [6:0] f_dreq = req_due - g;

  wire [3:0] f_nr = f_nr_q + {3'd0, f_rise};       // rising edges including this cycle's
  wire [1:0] f_nst = f_nst_q;
  wire       f_cons = f_cm && !abort_i && f_d_consume;
  wire       f_take = tgt_load | f_cons;            // a move leaves the queue at this edge
  // The steps a move makes: N for a move, none for a refused or empty one (a jog: unbounded).
  wire [2:0] a_ne = (a_kind == K_MOVE) ? a_n : 3'd0, b_ne = (b_kind == K_MOVE) ? b_n : 3'd0;
  wire [2:0] n_cur = (f_nst == 2'd2) ? b_ne : a_ne;  // of the move taken last
  wire [1:0] k_cur = (f_nst == 2'd2) ? b_kind : a_kind;
  wire [1:0] k_take = (f_nst == 2'd0) ? a_kind : b_kind;   // of the move taken at this edge
  wire [3:0] n_sum = (f_nst == 2'd0) ? 4'd0 : (f_nst == 2'd1) ? {1'b0, a_ne}
                                                               : {1'b0, a_ne} + {1'b0, b_ne};
  wire       f_aborted = f_aborted_q || abort_i;     // an abort at this cycle's edge or before

  always @(posedge clk_i) begin
    p_have <= !rst_i;
    p_busy <= busy;
    if (rst_i) begin
      f_nst_q <= 2'd0; f_nr_q <= 4'd0; f_nq_q <= 3'd0; f_stopped <= 1'b0;
      f_aborted_q <= 1'b0; f_since_ab <= 4'd0; f_since_st <= 6'd0; f_n <= 2'd0;
      f_jogt <= 1'b0;
    end else begin
      if (f_take && f_nst_q != 2'd3) f_nst_q <= f_nst_q + 2'd1;
      if (tgt_load && k_take == K_JOG) f_jogt <= 1'b1;
      f_nr_q <= f_nr;
      f_nq_q <= f_take ? {2'd0, req} : f_nq_q + {2'd0, req};
      if (stop_i) f_stopped <= 1'b1;
      if (abort_i) f_aborted_q <= 1'b1;
      if (f_aborted && f_since_ab != 4'd15) f_since_ab <= f_since_ab + 4'd1;
      if ((f_stopped || stop_i) && f_since_st != 6'd63) f_since_st <= f_since_st + 6'd1;
      if (abort_i) f_n <= 2'd0;
      else case ({f_due, req})
        2'b10: begin f_n <= f_n - 2'd1; f_t0 <= f_t1; f_t1 <= f_t2; end
        2'b01: begin
          f_n <= f_n + 2'd1;
          if (f_n == 2'd0) f_t0 <= req_due;
          if (f_n == 2'd1) f_t1 <= req_due;
          if (f_n == 2'd2) f_t2 <= req_due;
        end
        2'b11: begin
          f_t0 <= (f_n == 2'd1) ? req_due : f_t1;
          f_t1 <= (f_n == 2'd2) ? req_due : f_t2;
          f_t2 <= req_due;
        end
        default: ;
      endcase
    end
  end
  wire [3:0] hi_t = (f_high == 0) ? 4'd1 : {2'd0, f_high};

  always @* if (!rst_i && p_have) begin
    // The one-hot slot cycle is the counter's low two bits.
    assert (kph == 4'b0001 << g[1:0]);
    // No STEP while idle: a rising edge only while the engine was busy, and none before the
    // first tick's step can be due (sampled at g = 63, due at the earliest on 64 + 68 - 31).
    if (f_rise) assert (p_busy && t > 10'd100);
    // At most N steps per move (none for a refused or empty one); the rising edges never
    // outrun the moves taken (unless a jog was started: it has no N).
    if (!f_jogt) begin
      assert (f_nq_q <= n_cur || f_nst == 2'd0);
      assert (f_nr <= n_sum);
    end
    if (f_nst == 2'd0) assert (f_nq_q == 3'd0);
    // Busy falls only after the N-th step (unless stopped or aborted), when every queued move
    // has been taken; a jog never ends but by STOP or abort.
    if (p_busy && !busy && !f_stopped && !f_aborted_q) begin
      assert (k_cur != K_JOG && f_nst == (f_two ? 2'd2 : 2'd1));
      if (!f_jogt) assert (f_nr == n_sum && f_nq_q == n_cur);
    end
    // Refused and empty moves are consumed without motion, moves and jogs start; the refusal
    // is flagged exactly for a refused move.
    if (f_take) assert (f_nst_q < (f_two ? 2'd2 : 2'd1));
    if (f_cons) assert (k_take == K_BAD || k_take == K_EMPTY);
    if (tgt_load) assert (k_take == K_MOVE || k_take == K_JOG);
    assert (refused == (f_cons && k_take == K_BAD));
    // STOP: from 42 cycles after the strobe (the next frame boundary takes it, then the axis's
    // sample flushes the queue; a start sampled before commits 9 cycles after its sample) no
    // move leaves the queue.
    if (f_since_st >= 6'd42) assert (!f_take);
    // Abort: no rise at or after the abort edge; a pulse high completes its high time; busy
    // falls at once.
    if (f_aborted_q) assert (!f_rise && !busy);
    if (f_aborted_q && {1'b0, f_since_ab} >= {1'b0, hi_t}) assert (!step_l);
    // The pulse stage's contract, asserted where the engine drives it.
    if (req) assert (accepts);                                            // C1
    if (req) assert (f_dreq != 7'd0 && (f_n == 2'd0 || f_dreq > f_dl));    // C2
    if (tgt_load && tgt_dir != tgt) assert (!pending);                    // C3
  end

  // ---- the speed accumulator (connected by the .sby script; asserted on, never assumed) ----
  (* keep *) wire        f_p1_valid, f_p1_gen, f_p1_stop;   // u_eng.p1_valid, p1_gen, p1_stop
  (* keep *) wire        f_p1_start;                         // u_eng.p1_start
  (* keep *) wire [1:0]  f_p1_slot;                          // u_eng.p1_slot
  (* keep *) wire [31:0] f_rd0;                              // u_eng.rd0 (bank 0 read data)
  reg [31:0] f_rd0_p;
  always @(posedge clk_i) f_rd0_p <= f_rd0;
  wire [63:0] f_s = {f_rd0, f_rd0_p};                        // S (V_START at a start), cycle 4i+3
  wire        f_tick = g[1:0] == 2'd3 && f_p1_valid && f_p1_gen;
  wire [63:0] s_vm = (f_p1_slot == 2'd1) ? a_vm : b_vm;
  wire [63:0] s_vs = (f_p1_slot == 2'd1) ? a_vs : b_vs;
  wire [63:0] s_fl = (f_p1_slot == 2'd1) ? a_fl : b_fl;
  wire [63:0] s_lo = (s_vs < s_fl) ? s_vs : s_fl;
  wire [63:0] s_dec = {16'd0, (f_p1_slot == 2'd1) ? a_dec : b_dec};
  // The previous tick: its S, whether it was stopping, whether it ended the move by the stop
  // rule (old S < dec).
  reg         f_pt_have = 1'b0, f_pt_stop, f_pt_end;
  reg  [63:0] f_pt_s;
  always @(posedge clk_i) begin
    if (rst_i) f_pt_have <= 1'b0;
    else if (f_tick) begin
      f_pt_have <= 1'b1;
      f_pt_s <= f_s;
      f_pt_stop <= f_p1_stop;
      f_pt_end <= f_p1_stop && f_s < s_dec;
    end
  end
  always @* if (!rst_i && p_have && f_tick) begin
    assert (f_p1_slot == 2'd1 || (f_two && f_p1_slot == 2'd2));
    assert (f_s <= s_vm);
    if (!f_p1_stop) assert (f_s >= s_lo);
    // Stopping: every stopping tick after the first takes exactly dec off the speed (and the
    // one before it had at least dec); after the tick whose old speed was below dec no tick of
    // the move runs (the next tick, if any, starts a new move).
    if (f_pt_have && f_pt_stop && f_p1_stop) assert (f_pt_s >= s_dec && f_s == f_pt_s - s_dec);
    if (f_pt_have && f_pt_end) assert (f_p1_start);
  end

  // ---- what hexstep_wb_fv assumes of the engine: the queue ring stays in 0..2, and the
  // engine's own writes (the cycles that are not bus cycles) touch only the per-axis state words
  // (bank 0, 1: words 0..2; bank 2: word 0), never staging, mirror or queue-slot words ----
  (* keep *) wire       f_we0, f_we1, f_we2;      // u_eng.we0 .. we2
  (* keep *) wire [7:0] f_wa0, f_wa1, f_wa2;      // u_eng.wa0 .. wa2
  always @* if (!rst_i && p_have) begin
    assert (act != 2'd3 && qn != 2'd3);
    if (!bus_cyc && f_we0) assert (f_wa0[4:0] <= 5'd2);
    if (!bus_cyc && f_we1) assert (f_wa1[4:0] <= 5'd2);
    if (!bus_cyc && f_we2) assert (f_wa2[4:0] == 5'd0);
  end

`ifdef FV_COVER
  // Phases seen while the engine runs the first move / the second.
  reg f_acc, f_cru, f_dec, f_gap;
  always @(posedge clk_i) begin
    if (rst_i) begin
      f_acc <= 1'b0; f_cru <= 1'b0; f_dec <= 1'b0; f_gap <= 1'b0;
    end else begin
      if (phase == PH_ACCEL) f_acc <= 1'b1;
      if (phase == PH_CRUISE) f_cru <= 1'b1;
      if (phase == PH_DECEL) f_dec <= 1'b1;
      if (f_nst != 2'd0 && !busy) f_gap <= 1'b1;   // busy fell after a start
    end
  end
  wire f_end = p_busy && !busy && !f_aborted_q;    // busy falls
  always @* if (!rst_i && p_have) begin
    // A complete triangular move: accelerate, decelerate, no cruise, all N steps.
`ifdef FV_MOVE_TRI
    cover (f_end && !f_two && !f_stopped && f_acc && f_dec && !f_cru && f_nr == n_sum &&
           a_n >= 3'd2);
`endif
    // A complete trapezoidal move: accelerate, cruise, decelerate.
`ifdef FV_MOVE_TRAP
    cover (f_end && !f_two && !f_stopped && f_acc && f_cru && f_dec && f_nr == n_sum);
`endif
    // A chained pair: B started with busy never low in between, both complete.
`ifdef FV_MOVE_CHAIN
    cover (f_end && f_two && f_nst == 2'd2 && !f_gap && !f_stopped && f_nr == n_sum);
`endif
    // A STOP: the move comes to rest before its N-th step (with FV_MOVE_STOP at a crawl, before
    // its first: a STOP from a speed with steps takes about 2^16 ticks at the largest dec).
`ifdef FV_MOVE_STOP
    cover (f_end && !f_two && f_stopped && f_nr < n_sum);
`endif
  end
`endif
endmodule

`default_nettype wire
