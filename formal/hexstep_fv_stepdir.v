// SPDX-License-Identifier: Apache-2.0
// hexstep formal: STEP/DIR timing checker, shared by the harnesses of every module that drives pins.
`default_nettype none

// Watches the STEP and DIR levels (polarity already removed) and asserts the output-stage
// promises of docs/ARCHITECTURE.md, "Output stage and pulse timing":
//   - every STEP pulse is high exactly max(step_high, 1) cycles;
//   - it is followed by at least max(step_low, 1) low cycles before the next rising edge;
//   - a DIR change edge comes at least dir_hold edges after the last STEP rising edge;
//   - a STEP rising edge comes at least dir_setup edges after the last DIR change.
// Distances are counted in clock edges between the two events (0: the same edge). The
// timing inputs must be constant (the harnesses tie them to $anyconst values): the design uses
// them live, so a change during a pulse changes that pulse (documented in docs/FORMAL.md).
// Only the harnesses use this file (never synthesized).
module hexstep_fv_stepdir #(
  parameter integer PULSE_W = 4
) (
  input wire               clk_i,
  input wire               rst_i,
  input wire               step_i,       // STEP level, 1 = pulse high
  input wire               dir_i,        // DIR level
  input wire [PULSE_W-1:0] step_high_i,
  input wire [PULSE_W-1:0] step_low_i,
  input wire [PULSE_W-1:0] dir_setup_i,
  input wire [PULSE_W-1:0] dir_hold_i,
  output wire              rise_o,       // STEP rose at the edge that started this cycle
  // Edges from the last STEP rising edge / DIR change to the edge that started this cycle
  // (saturating at 2^(PULSE_W+2)-1; the saturated value after reset): for the harnesses'
  // induction invariants.
  output wire [PULSE_W+1:0] dist_rise_o,
  output wire [PULSE_W+1:0] dist_dir_o
);
  localparam integer CW = PULSE_W + 2;
  localparam [CW-1:0] SAT = {CW{1'b1}};
  localparam [CW-1:0] ONE = 1;

  wire [CW-1:0] hi_t  = (step_high_i == 0) ? ONE : {2'b00, step_high_i};
  wire [CW-1:0] lo_t  = (step_low_i == 0) ? ONE : {2'b00, step_low_i};
  wire [CW-1:0] setup = {2'b00, dir_setup_i};
  wire [CW-1:0] hold  = {2'b00, dir_hold_i};

  reg          have_q = 1'b0;  // the previous cycle was out of reset
  reg          step_p, dir_p;  // levels in the previous cycle
  reg [CW-1:0] hi_q;           // high cycles up to the previous cycle
  reg [CW-1:0] lo_q;           // low cycles up to the previous cycle (saturating)
  reg [CW-1:0] sr_q;           // edges from the last rising edge to the previous cycle
  reg [CW-1:0] sd_q;           // edges from the last DIR change to the previous cycle

  wire rise = have_q && !step_p && step_i;
  wire fall = have_q && step_p && !step_i;
  wire dchg = have_q && (dir_p != dir_i);
  wire [CW-1:0] cur_hi   = !step_i ? {CW{1'b0}} : rise ? ONE : (hi_q == SAT ? SAT : hi_q + ONE);
  wire [CW-1:0] dist_r   = rise ? {CW{1'b0}} : sr_q;  // edges from the last rise to this edge
  wire [CW-1:0] dist_d   = dchg ? {CW{1'b0}} : sd_q;  // edges from the last DIR change to this edge

  always @(posedge clk_i) begin
    if (rst_i) begin
      have_q <= 1'b0;
      hi_q <= {CW{1'b0}};
      lo_q <= SAT;
      sr_q <= SAT;
      sd_q <= SAT;
    end else begin
      have_q <= 1'b1;
      hi_q <= cur_hi;
      lo_q <= step_i ? {CW{1'b0}} : (lo_q == SAT ? SAT : lo_q + ONE);
      sr_q <= rise ? ONE : (dist_r == SAT ? SAT : dist_r + ONE);
      sd_q <= dchg ? ONE : (dist_d == SAT ? SAT : dist_d + ONE);
    end
    step_p <= step_i;
    dir_p <= dir_i;
  end

  always @* begin
    if (!rst_i) begin
      // Out of reset STEP is low (reset never leaves a pulse high).
      if (!have_q) assert (!step_i);
      // High exactly hi_t cycles: never longer, and a fall only after hi_t cycles.
      assert (cur_hi <= hi_t);
      if (fall) assert (hi_q == hi_t);
      // Low at least lo_t cycles before a rising edge.
      if (rise) assert (lo_q >= lo_t);
      // DIR setup before a rising edge, DIR hold after it.
      if (rise) assert (dist_d >= setup);
      if (dchg) assert (dist_r >= hold);
      // Consistency of the counters above (what k-induction needs at full widths): a high run
      // began at the last rising edge, and the low run since the last fall is the time since
      // that rising edge minus the high time.
      if (step_i) assert ({1'b0, cur_hi} == {1'b0, dist_r} + 1'b1);
      if (!step_i && have_q) begin
        if (dist_r != SAT) assert ({1'b0, lo_q} + {1'b0, hi_t} == {1'b0, dist_r});
        else assert ({1'b0, lo_q} + {1'b0, hi_t} >= {1'b0, SAT});
      end
    end
  end

  assign rise_o = rise;
  assign dist_rise_o = dist_r;
  assign dist_dir_o = dist_d;
endmodule

`default_nettype wire
