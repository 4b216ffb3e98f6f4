// SPDX-License-Identifier: Apache-2.0
// hexstep: what software sees, the Wishbone register block (hexstep_wb) driving the core.
`default_nettype none

// Register map: rdl/hexstep.rdl, docs/REGISTERS.md. Parameters as hexstep_wb and
// hexstep_core (same defaults); NAXES is limited to 1..8 by the register map.
module hexstep_top #(
  parameter integer NAXES   = 6,   // axes, 1..8
  parameter integer SPEED_W = 64,  // see hexstep_core
  parameter integer ACC_W   = 44,
  parameter integer STEP_W  = 32,
  parameter integer DFRAC_W = 32,
  parameter integer PULSE_W = 12,
  parameter integer POS_W   = 32,
  parameter integer OWE_W   = 2,
  parameter integer ADDR_W  = 12   // byte address bits, 10..32
) (
  input  wire              clk_i,
  input  wire              rst_i,       // synchronous, active high
  input  wire              wb_cyc_i,
  input  wire              wb_stb_i,
  input  wire              wb_we_i,
  input  wire [ADDR_W-1:0] wb_adr_i,
  input  wire [31:0]       wb_dat_i,
  input  wire [3:0]        wb_sel_i,
  output wire [31:0]       wb_dat_o,
  output wire              wb_ack_o,
  input  wire              estop_i,     // asynchronous, active high
  output wire              irq_o,
  output wire [NAXES-1:0]  step_o,
  output wire [NAXES-1:0]  dir_o
);

  wire [NAXES-1:0]         start, abort, stop, jog, dir, step_inv, dir_inv, busy, done, err;
  wire [NAXES*STEP_W-1:0]  steps, acc_steps, dec_step;
  wire [NAXES*SPEED_W-1:0] v_start, v_max, v_end, v_dec;
  wire [NAXES*ACC_W-1:0]   acc, dec;
  wire [NAXES*DFRAC_W-1:0] dec_frac;
  wire [NAXES*PULSE_W-1:0] step_high, step_low, dir_setup, dir_hold;
  wire [NAXES*2-1:0]       phase;
  wire [NAXES*POS_W-1:0]   pos;

  hexstep_wb #(
    .NAXES (NAXES), .SPEED_W (SPEED_W), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .ADDR_W (ADDR_W)
  ) u_wb (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (wb_cyc_i), .wb_stb_i (wb_stb_i), .wb_we_i (wb_we_i), .wb_adr_i (wb_adr_i),
    .wb_dat_i (wb_dat_i), .wb_sel_i (wb_sel_i), .wb_dat_o (wb_dat_o), .wb_ack_o (wb_ack_o),
    .estop_i (estop_i), .irq_o (irq_o),
    .start_o (start), .abort_o (abort), .stop_o (stop), .steps_o (steps), .dir_o (dir),
    .jog_o (jog),
    .v_start_o (v_start), .v_max_o (v_max), .v_end_o (v_end), .v_dec_o (v_dec),
    .acc_o (acc), .dec_o (dec), .acc_steps_o (acc_steps), .dec_step_o (dec_step),
    .dec_frac_o (dec_frac), .step_high_o (step_high), .step_low_o (step_low),
    .dir_setup_o (dir_setup), .dir_hold_o (dir_hold), .step_inv_o (step_inv),
    .dir_inv_o (dir_inv),
    .busy_i (busy), .done_i (done), .err_i (err), .phase_i (phase), .pos_i (pos)
  );

  hexstep_core #(
    .NAXES (NAXES), .SPEED_W (SPEED_W), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .OWE_W (OWE_W)
  ) u_core (
    .clk_i (clk_i), .rst_i (rst_i),
    .start_i (start), .abort_i (abort), .stop_i (stop), .steps_i (steps), .dir_i (dir),
    .jog_i (jog),
    .v_start_i (v_start), .v_max_i (v_max), .v_end_i (v_end), .v_dec_i (v_dec),
    .acc_i (acc), .dec_i (dec), .acc_steps_i (acc_steps), .dec_step_i (dec_step),
    .dec_frac_i (dec_frac), .step_high_i (step_high), .step_low_i (step_low),
    .dir_setup_i (dir_setup), .dir_hold_i (dir_hold), .step_inv_i (step_inv),
    .dir_inv_i (dir_inv),
    .step_o (step_o), .dir_o (dir_o), .busy_o (busy), .done_o (done), .err_o (err),
    .phase_o (phase), .pos_o (pos)
  );

endmodule

`default_nettype wire
