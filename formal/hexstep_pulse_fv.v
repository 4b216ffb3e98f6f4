// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of hexstep_pulse (STEP/DIR output stage of one axis).
`default_nettype none

// The engine's side (abort, requests, DIR target loads) is free in every cycle except for the
// contract below, which hexstep_engine_fv asserts where the engine drives the stage:
//   C1  a request comes only while accepts_o is high;
//   C2  a request is due 1..127 cycles ahead (d = req_due - g modulo 128, d != 0), and later
//       than every request still waiting (so requests are due in order, on distinct cycles);
//   C3  the DIR target changes only while nothing is pending (pending_o low).
// The timing and polarity inputs are $anyconst. The cycle counter g counts from any value.
//
// Port-level shadow: the waiting requests in order (due cycles), the owed steps (due, not yet
// risen) and the DIR target. Asserted: the timing checker; STEP rises exactly when the model
// says it may (a step owed, no abort, the low time and DIR setup over, DIR at the target: no
// pulse without an owed step, none at an abort edge, none later than the timing allows); DIR
// moves to the target exactly when the hold time is over; position +-1 by DIR at each rise;
// accepts_o and pending_o tell the waiting count.
module hexstep_pulse_fv #(
  parameter integer PULSE_W = 3,
  parameter integer POS_W   = 4
) (
  input wire       clk_i,
  input wire       rst_i,
  input wire       abort_i,
  input wire       req_i,
  input wire [6:0] req_due_i,
  input wire       tgt_load_i,
  input wire       tgt_dir_i
);
  localparam integer CW = PULSE_W + 1;
  (* anyconst *) reg [PULSE_W-1:0] f_high, f_low, f_setup, f_hold;
  // over_i of the output stage: each timing value at most 1.
  wire [3:0] f_over = {f_hold <= 1, f_setup <= 1, f_low <= 1, f_high <= 1};
  (* anyconst *) reg               f_sinv, f_dinv;
  (* anyconst *) reg [6:0]         f_g0;

  reg [6:0] g;
  always @(posedge clk_i) g <= rst_i ? f_g0 : g + 7'd1;

  wire             accepts, pending, accepts_n, pending_n, tgt, step, dir;
  wire [POS_W-1:0] pos;

  hexstep_pulse #(.PULSE_W (PULSE_W), .POS_W (POS_W)) u_dut (
    .clk_i (clk_i), .rst_i (rst_i), .gn_i (g + 7'd1),
    .abort_i (abort_i), .req_i (req_i), .req_due_i (req_due_i),
    .tgt_load_i (tgt_load_i), .tgt_dir_i (tgt_dir_i),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .over_i (f_over), .step_inv_i (f_sinv), .dir_inv_i (f_dinv),
    .accepts_o (accepts), .pending_o (pending), .tgt_o (tgt),
    .accepts_n_o (accepts_n), .pending_n_o (pending_n),
    .step_o (step), .dir_o (dir), .pos_o (pos)
  );

  // Reset in the first cycle only.
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);

  wire step_l = step ^ f_sinv;   // levels without polarity
  wire dir_l  = dir ^ f_dinv;

  wire          f_rise, f_dchg;
  wire [CW-1:0] c_r, c_f, c_d;
  hexstep_fv_stepdir #(.PULSE_W (PULSE_W)) u_chk (
    .clk_i (clk_i), .rst_i (rst_i), .step_i (step_l), .dir_i (dir_l),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .rise_o (f_rise), .dchg_o (f_dchg), .c_rise_o (c_r), .c_fall_o (c_f), .c_dir_o (c_d)
  );

  // ---- shadow: waiting requests in due order (f_t[0] first), owed steps, target ----
  reg [1:0] f_n;                 // waiting requests
  reg [6:0] f_t0, f_t1, f_t2;    // their due cycles
  reg [1:0] f_od;                // owed after the last edge's due, before its rise
  reg       f_tgt;
  wire [6:0] f_d0 = f_t0 - g, f_d1 = f_t1 - g, f_d2 = f_t2 - g;   // cycles until due
  wire [6:0] f_dl = (f_n == 2'd3) ? f_d2 : (f_n == 2'd2) ? f_d1 : f_d0;   // the last one
  wire       f_due = (f_n != 2'd0) && (f_d0 == 7'd0);
  // Owed now: the steps due at earlier edges minus the rises so far (the rise at the last edge
  // is seen now, as f_rise).
  wire [1:0] f_owed = f_od - {1'b0, f_rise};
  wire [2:0] f_wait = {1'b0, f_n} + {1'b0, f_owed};

  // ---- the contract (asserted in hexstep_engine_fv) ----
  wire [6:0] f_dreq = req_due_i - g;
  always @* if (!rst_i) begin
    if (req_i) assume (accepts);
    if (req_i) assume (f_dreq != 7'd0 && (f_n == 2'd0 || f_dreq > f_dl));
    if (tgt_load_i && tgt_dir_i != tgt) assume (!pending);
  end

  always @(posedge clk_i) begin
    if (rst_i || abort_i) begin
      f_n <= 2'd0;
      f_od <= 2'd0;
    end else begin
      f_od <= f_owed + {1'b0, f_due};
      // Pop the head if due now, append a new request.
      case ({f_due, req_i})
        2'b10: begin f_n <= f_n - 2'd1; f_t0 <= f_t1; f_t1 <= f_t2; end
        2'b01: begin
          f_n <= f_n + 2'd1;
          if (f_n == 2'd0) f_t0 <= req_due_i;
          if (f_n == 2'd1) f_t1 <= req_due_i;
          if (f_n == 2'd2) f_t2 <= req_due_i;
        end
        2'b11: begin
          f_t0 <= (f_n == 2'd1) ? req_due_i : f_t1;
          f_t1 <= (f_n == 2'd2) ? req_due_i : f_t2;
          f_t2 <= req_due_i;
        end
        default: ;
      endcase
    end
    if (rst_i) f_tgt <= 1'b1;
    else if (tgt_load_i) f_tgt <= tgt_dir_i;
  end

  // ---- previous cycle ----
  reg             p_have = 1'b0, p_may, p_turn, p_dir;
  reg [POS_W-1:0] p_pos;
  reg             p_acc_n, p_pend_n;   // accepts_n_o, pending_n_o at the last edge
  wire [CW-1:0]   lo_t = (f_low == 0) ? 1 : {1'b0, f_low};
  wire [CW-1:0]   su_t = (f_setup == 0) ? 1 : {1'b0, f_setup};
  wire [CW-1:0]   ho_t = (f_hold == 0) ? 1 : {1'b0, f_hold};
  // STEP may (and so must) rise at the coming edge; DIR must move to the target.
  wire f_may  = (f_owed != 2'd0) && !abort_i && !step_l && c_f >= lo_t && dir_l == f_tgt &&
                c_d >= su_t;
  wire f_turn = (dir_l != f_tgt) && c_r >= ho_t;
  always @(posedge clk_i) begin
    p_have <= !rst_i;
    p_may <= f_may;
    p_turn <= f_turn;
    p_dir <= dir_l;
    p_pos <= pos;
    p_acc_n <= accepts_n;
    p_pend_n <= pending_n;
  end

  always @* if (!rst_i) begin
    assert (tgt == f_tgt);
    assert (f_wait <= 3'd3);
    assert (accepts == (f_wait != 3'd3));
    assert (pending == (f_wait != 3'd0));
    if (p_have) begin
      assert (f_rise == p_may);
      assert (f_dchg == p_turn);
      assert (pos == (!f_rise ? p_pos : p_dir ? p_pos + 1'b1 : p_pos - 1'b1));
      // The next-value outputs (the engine registers its start decision from them).
      assert (accepts == p_acc_n && pending == p_pend_n);
    end else begin
      // Reset state: STEP low, DIR positive, position 0, nothing waiting.
      assert (!step_l && dir_l && pos == {POS_W{1'b0}} && accepts && !pending);
    end
  end

  // ---- induction invariants on the stage's state (connected by the .sby script; asserted,
  // never assumed) ----
  (* keep *) wire               f_v0, f_v1, f_v2;       // u_dut.v0_q .. v2_q
  (* keep *) wire [6:0]         f_e0, f_e1, f_e2;       // u_dut.t0_q .. t2_q
  (* keep *) wire               f_m0, f_m1, f_m2;       // u_dut.m0_q .. m2_q
  (* keep *) wire [1:0]         f_owed_i, f_wait_i;     // u_dut.owed_q, u_dut.wait_q
  (* keep *) wire [PULSE_W-1:0] f_cs, f_cd;             // u_dut.cs_q, u_dut.cd_q
  (* keep *) wire               f_cso, f_cdo, f_md;     // u_dut.cso_q, cdo_q, md_q
  (* keep *) wire               f_rz;                   // u_dut.rz_q

  function has(input [6:0] t);
    has = (f_v0 && f_e0 == t) || (f_v1 && f_e1 == t) || (f_v2 && f_e2 == t);
  endfunction
  // A down-counter loaded with `t` at an event c cycles ago (c = 1 in the cycle after it).
  function [PULSE_W-1:0] left(input [PULSE_W-1:0] t, input [CW-1:0] c);
    left = ({1'b0, t} > c) ? t - c[PULSE_W-1:0] + 1'b1 : (t == 0) ? 0 : 1;
  endfunction
  wire [CW-1:0] hi_t = (f_high == 0) ? 1 : {1'b0, f_high};
  wire [1:0] f_nv = {1'b0, f_v0} + {1'b0, f_v1} + {1'b0, f_v2};
  always @* if (!rst_i && p_have) begin
    assert (f_nv == f_n);
    // A valid entry's registered due compare is its due cycle's compare with g.
    if (f_v0) assert (f_m0 == (f_e0 == g));
    if (f_v1) assert (f_m1 == (f_e1 == g));
    if (f_v2) assert (f_m2 == (f_e2 == g));
    if (f_n != 2'd0) assert (has(f_t0));
    if (f_n >= 2'd2) assert (has(f_t1) && f_d1 > f_d0);
    if (f_n == 2'd3) assert (has(f_t2) && f_d2 > f_d1);
    assert (f_owed_i == f_owed && f_wait_i == f_wait[1:0]);
    assert (f_cso == (f_cs <= 1) && f_cdo == (f_cd <= 1));
    // The registered rise condition: STEP low, low over, DIR at the target, setup over, a step
    // owed.
    assert (f_rz == (!step_l && f_cso && dir_l == f_tgt && (f_cdo || f_md) && f_owed_i != 2'd0));
    // c_step: the high time while STEP is high, the low time while it is low.
    if (step_l) assert (f_cs == left(f_high, c_r));
    else assert (c_f >= lo_t ? f_cs <= 1 : f_cs == left(f_low, c_f));
    // c_dir: hold mode since the last rising edge (setup of the DIR change before it over),
    // setup mode since the last DIR change (hold of the rise before it over).
    if (f_md) begin
      assert (c_r <= c_d && c_d >= su_t);
      assert (c_r >= ho_t ? f_cd <= 1 : f_cd == left(f_hold, c_r));
    end else begin
      assert (c_d <= c_r && c_r >= ho_t);
      assert (c_d >= su_t ? f_cd <= 1 : f_cd == left(f_setup, c_d));
    end
  end

`ifdef FV_COVER
  // Two pulses with a DIR reversal between them, at non-trivial timing (high 2, low 3,
  // setup 2, hold 3).
  reg [1:0] f_np = 2'd0;
  reg       f_rev = 1'b0;
  always @(posedge clk_i) begin
    if (f_rise && f_np != 2'd3) f_np <= f_np + 2'd1;
    if (f_dchg && f_np != 2'd0) f_rev <= 1'b1;
  end
  always @* if (!rst_i && p_have)
    cover (f_rise && f_rev && f_np == 2'd1 && f_high == 2 && f_low == 3 && f_setup == 2 &&
           f_hold == 3);
`endif
endmodule

`default_nettype wire
