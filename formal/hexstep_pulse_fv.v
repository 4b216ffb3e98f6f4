// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of hexstep_pulse (STEP/DIR output stage), port-level properties.
`default_nettype none

// The inputs from the generator (owed_nz, abort, tgt_load, tgt_dir) are free every cycle. The
// timing and polarity inputs are $anyconst (any value, constant during the proof). One
// assumption on the generator: a new DIR target is loaded only while no step is owed (the
// axis loads it at an accepted start, which needs !busy, so owed == 0; hexstep_axis_fv
// asserts that at the axis level). Only the "pulse in the move's direction" property needs
// it (the whole proof runs under it).
module hexstep_pulse_fv #(
  parameter integer PULSE_W = 3,
  parameter integer POS_W   = 4
) (
  input wire clk_i,
  input wire rst_i,
  input wire owed_nz_i,
  input wire abort_i,
  input wire tgt_load_i,
  input wire tgt_dir_i
);
  (* anyconst *) reg [PULSE_W-1:0] f_high, f_low, f_setup, f_hold;
  (* anyconst *) reg               f_sinv, f_dinv;

  wire             rise, step, dir;
  wire [POS_W-1:0] pos;

  hexstep_pulse #(.PULSE_W (PULSE_W), .POS_W (POS_W)) u_dut (
    .clk_i (clk_i), .rst_i (rst_i),
    .owed_nz_i (owed_nz_i), .abort_i (abort_i), .tgt_load_i (tgt_load_i), .tgt_dir_i (tgt_dir_i),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .step_inv_i (f_sinv), .dir_inv_i (f_dinv),
    .rise_o (rise), .step_o (step), .dir_o (dir), .pos_o (pos)
  );

  // Reset in the first cycle only.
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);
  always @* if (tgt_load_i) assume (!owed_nz_i);

  wire step_l = step ^ f_sinv;   // levels without polarity
  wire dir_l  = dir ^ f_dinv;

  wire f_rise;
  hexstep_fv_stepdir #(.PULSE_W (PULSE_W)) u_chk (
    .clk_i (clk_i), .rst_i (rst_i), .step_i (step_l), .dir_i (dir_l),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .rise_o (f_rise), .dist_rise_o (f_dist_r), .dist_dir_o (f_dist_d)
  );
  wire [PULSE_W+1:0] f_dist_r, f_dist_d;
  (* keep *) wire [PULSE_W:0]   f_pc;   // u_dut.c_q, cycles since the last rise
  (* keep *) wire [PULSE_W-1:0] f_pd;   // u_dut.d_q, cycles since the last DIR change


  // Shadow state: previous inputs and outputs, the DIR target of the latest load.
  reg             p_owed, p_abort, p_rise, p_dir, p_have = 1'b0;
  reg [POS_W-1:0] p_pos;
  reg             f_tgt;
  always @(posedge clk_i) begin
    p_owed <= owed_nz_i;
    p_abort <= abort_i;
    p_rise <= rise;
    p_dir <= dir_l;
    p_pos <= pos;
    p_have <= !rst_i;
    if (rst_i) f_tgt <= 1'b1;
    else if (tgt_load_i) f_tgt <= tgt_dir_i;
  end

  // Internal state, connected by the .sby script after flattening (`connect -set`; the script
  // fails if a name disappears). Used only in invariants that make k-induction close: each is
  // itself asserted, never assumed.
  (* keep *) wire f_int_tgt;            // u_dut.tgt_q

  always @* begin
    if (!rst_i && p_have) begin
      assert (f_int_tgt == f_tgt);
      // rise_o announces exactly the edges at which STEP rises.
      assert (f_rise == p_rise);
      // No pulse without an owed step, none at an abort edge.
      if (f_rise) assert (p_owed && !p_abort);
      // A pulse goes out in the current target direction; DIR never moves at a rising edge.
      if (f_rise) assert (dir_l == f_tgt && p_dir == dir_l);
      // Position: +1/-1 by DIR at each rising edge, unchanged otherwise.
      assert (pos == (!f_rise ? p_pos : p_dir ? p_pos + 1'b1 : p_pos - 1'b1));
    end
    if (!rst_i && !p_have) begin
      // Reset state: STEP low, DIR positive, position 0.
      assert (!step_l && dir_l && pos == {POS_W{1'b0}});
    end
  end

  // Induction invariants linking the pulse stage's counters to the checker's (asserted):
  // cycles since the last rise / DIR change = edges since it + 1, both saturating.
  localparam integer FCW = PULSE_W + 3;
  wire [FCW-1:0] f_cr = {1'b0, f_dist_r} + 1'b1;
  wire [FCW-1:0] f_cd = {1'b0, f_dist_d} + 1'b1;
  wire [FCW-1:0] f_cmax = {FCW{1'b0}} | {(PULSE_W+1){1'b1}};
  wire [FCW-1:0] f_dmax = {FCW{1'b0}} | {PULSE_W{1'b1}};
  always @* if (!rst_i && p_have) begin
    assert ({2'b00, f_pc} == ((f_cr > f_cmax) ? f_cmax : f_cr));
    assert ({3'b000, f_pd} == ((f_cd > f_dmax) ? f_dmax : f_cd));
  end

`ifdef FV_COVER
  // A pulse after a DIR reversal that followed an earlier pulse (high 2, low 1, setup 2, hold 2).
  reg [1:0] f_npulse = 2'd0;
  reg       f_rev = 1'b0;
  always @(posedge clk_i) begin
    if (f_rise && f_npulse != 2'd3) f_npulse <= f_npulse + 2'd1;
    if (p_have && dir_l != p_dir && f_npulse != 2'd0) f_rev <= 1'b1;
  end
  always @* cover (f_rise && f_rev && f_high == 2 && f_low == 1 && f_setup == 2 && f_hold == 2);
`endif
endmodule

`default_nettype wire
