// SPDX-License-Identifier: Apache-2.0
// hexstep formal: STEP/DIR timing checker on the pin levels, shared by the harnesses of the
// modules that drive pins (hexstep_pulse_fv, hexstep_engine_fv).
`default_nettype none

// Watches the STEP and DIR levels (polarity removed) and asserts the promises of
// docs/ARCHITECTURE.md, "Output stage and pulse timing", with t_x = max(x, 1):
//   - every STEP pulse is high exactly t_step_high cycles;
//   - at least t_step_low low cycles separate a fall from the next rising edge;
//   - a DIR change comes at least dir_hold edges after the last rising edge, a rising edge at
//     least t_dir_setup edges after the last DIR change, and never both at one edge.
// Counted in cycle x (the edge at the end of cycle e is "edge e"): c_rise = x - r for the last
// rising edge r, c_fall = x - f for the last fall f, c_dir = x - d for the last DIR change d,
// each saturating at SAT; SAT after reset (no event yet). A rising edge at edge x thus follows
// the last DIR change by c_dir(x) edges and the last fall by c_fall(x) low cycles. The timing
// inputs must be constant while the checker runs (the harnesses make them so: the design uses
// the configuration live, and a change during a pulse changes that pulse). Never synthesized.
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
  output wire              dchg_o,       // DIR changed at that edge
  // The distances above, in this cycle (for the harnesses' timing and induction assertions).
  output wire [PULSE_W:0]  c_rise_o,
  output wire [PULSE_W:0]  c_fall_o,
  output wire [PULSE_W:0]  c_dir_o
);
  localparam integer CW = PULSE_W + 1;
  localparam [CW-1:0] SAT = {CW{1'b1}};
  localparam [CW-1:0] ONE = 1;

  function [CW-1:0] at_least_1(input [PULSE_W-1:0] t);
    at_least_1 = (t == {PULSE_W{1'b0}}) ? ONE : {1'b0, t};
  endfunction
  function [CW-1:0] inc(input [CW-1:0] c);
    inc = (c == SAT) ? SAT : c + ONE;
  endfunction

  wire [CW-1:0] hi_t = at_least_1(step_high_i);
  wire [CW-1:0] lo_t = at_least_1(step_low_i);
  wire [CW-1:0] su_t = at_least_1(dir_setup_i);
  wire [CW-1:0] ho   = {1'b0, dir_hold_i};

  reg          have_q = 1'b0;   // the previous cycle was out of reset
  reg          step_p, dir_p;   // levels in the previous cycle
  reg [CW-1:0] cr_q, cf_q, cd_q;

  wire rise = have_q && !step_p && step_i;
  wire fall = have_q && step_p && !step_i;
  wire dchg = have_q && (dir_p != dir_i);
  wire [CW-1:0] c_r = !have_q ? SAT : rise ? ONE : inc(cr_q);
  wire [CW-1:0] c_f = !have_q ? SAT : fall ? ONE : inc(cf_q);
  wire [CW-1:0] c_d = !have_q ? SAT : dchg ? ONE : inc(cd_q);

  always @(posedge clk_i) begin
    have_q <= !rst_i;
    step_p <= step_i;
    dir_p <= dir_i;
    cr_q <= c_r;
    cf_q <= c_f;
    cd_q <= c_d;
  end

  always @* begin
    if (!rst_i) begin
      // Out of reset STEP is low.
      if (!have_q) assert (!step_i);
      // High exactly hi_t cycles: never longer, and the fall comes after hi_t cycles.
      if (step_i) assert (c_r <= hi_t);
      if (fall) assert (cr_q == hi_t);
      // Low at least lo_t cycles before a rising edge; DIR setup before it.
      if (rise) assert (cf_q >= lo_t && cd_q >= su_t);
      // DIR hold after a rising edge; never a DIR change at a rising edge.
      if (dchg) assert (cr_q >= ho);
      assert (!(rise && dchg));
      // Consistency of the distances (what k-induction needs): a low run began hi_t cycles
      // after the last rising edge.
      if (!step_i && c_r != SAT) assert ({1'b0, c_f} + {1'b0, hi_t} == {1'b0, c_r});
      if (!step_i && c_r == SAT) assert ({1'b0, c_f} + {1'b0, hi_t} >= {1'b0, SAT});
    end
  end

  assign rise_o = rise;
  assign dchg_o = dchg;
  assign c_rise_o = c_r;
  assign c_fall_o = c_f;
  assign c_dir_o = c_d;
endmodule

`default_nettype wire
