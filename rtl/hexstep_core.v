// SPDX-License-Identifier: Apache-2.0
// hexstep: the multi-axis core, NAXES independent hexstep_axis instances on flattened ports.
`default_nettype none

// Axis k uses bit k of every one-bit port and slice [k*W +: W] of every W-bit-per-axis port
// (phase_o: [k*2 +: 2]). The axes share nothing but the clock and reset; a multi-axis start is
// a start_i vector with several bits set in the same cycle. See hexstep_axis for the
// meaning of each field.
module hexstep_core #(
  // NAXES: number of axes (unit: axes). Range 1..32 (the model's start/abort masks are
  // uint32_t); default 6, the six axes of a hexapod.
  parameter integer NAXES   = 6,
  // SPEED_W: bits of speed and position fraction (unit: 2^-SPEED_W step per clock cycle).
  // Range 2..64; default 64: speeds from 100 MHz / 2^64 up to 1 step per cycle.
  parameter integer SPEED_W = 64,
  // ACC_W: bits of acceleration/deceleration (unit: 2^-SPEED_W step per cycle per cycle).
  // Range 1..SPEED_W; default 44: full speed reachable in 2^20 cycles.
  parameter integer ACC_W   = 44,
  // STEP_W: bits of step counts (unit: steps). Range 1..32; default 32.
  parameter integer STEP_W  = 32,
  // DFRAC_W: fraction bits of the deceleration start position (unit: 2^-DFRAC_W step).
  // Range 1..SPEED_W; default 32: fine enough to place the threshold between the positions of
  // two consecutive ticks down to 1 step/s at 100 MHz.
  parameter integer DFRAC_W = 32,
  // PULSE_W: bits of pulse timing (unit: clock cycles). Range 1..30; default 12: up to 4095
  // cycles, 40.95 us at 100 MHz.
  parameter integer PULSE_W = 12,
  // POS_W: bits of the signed, wrapping position counter (unit: steps). Range 2..64;
  // default 32.
  parameter integer POS_W   = 32,
  // OWE_W: bits of the generated-but-not-pulsed step counter (unit: steps). Range 1..16;
  // default 2: up to 3 steps may wait for their pulse before the generator pauses.
  parameter integer OWE_W   = 2
) (
  input  wire                       clk_i,
  input  wire                       rst_i,        // synchronous, active high
  input  wire [NAXES-1:0]           start_i,
  input  wire [NAXES-1:0]           abort_i,
  input  wire [NAXES-1:0]           stop_i,
  input  wire [NAXES*STEP_W-1:0]    steps_i,
  input  wire [NAXES-1:0]           dir_i,
  input  wire [NAXES-1:0]           jog_i,
  input  wire [NAXES*SPEED_W-1:0]   v_start_i,
  input  wire [NAXES*SPEED_W-1:0]   v_max_i,
  input  wire [NAXES*SPEED_W-1:0]   v_end_i,
  input  wire [NAXES*SPEED_W-1:0]   v_dec_i,
  input  wire [NAXES*ACC_W-1:0]     acc_i,
  input  wire [NAXES*ACC_W-1:0]     dec_i,
  input  wire [NAXES*STEP_W-1:0]    acc_steps_i,
  input  wire [NAXES*STEP_W-1:0]    dec_step_i,
  input  wire [NAXES*DFRAC_W-1:0]   dec_frac_i,
  input  wire [NAXES*PULSE_W-1:0]   step_high_i,
  input  wire [NAXES*PULSE_W-1:0]   step_low_i,
  input  wire [NAXES*PULSE_W-1:0]   dir_setup_i,
  input  wire [NAXES*PULSE_W-1:0]   dir_hold_i,
  input  wire [NAXES-1:0]           step_inv_i,
  input  wire [NAXES-1:0]           dir_inv_i,
  output wire [NAXES-1:0]           step_o,
  output wire [NAXES-1:0]           dir_o,
  output wire [NAXES-1:0]           busy_o,
  output wire [NAXES-1:0]           done_o,
  output wire [NAXES-1:0]           err_o,
  output wire [NAXES*2-1:0]         phase_o,
  output wire [NAXES*POS_W-1:0]     pos_o
);

  genvar k;
  generate
    for (k = 0; k < NAXES; k = k + 1) begin : g_axis
      hexstep_axis #(
        .SPEED_W (SPEED_W),
        .ACC_W   (ACC_W),
        .STEP_W  (STEP_W),
        .DFRAC_W (DFRAC_W),
        .PULSE_W (PULSE_W),
        .POS_W   (POS_W),
        .OWE_W   (OWE_W)
      ) u_axis (
        .clk_i       (clk_i),
        .rst_i       (rst_i),
        .start_i     (start_i[k]),
        .abort_i     (abort_i[k]),
        .stop_i      (stop_i[k]),
        .steps_i     (steps_i[k*STEP_W +: STEP_W]),
        .dir_i       (dir_i[k]),
        .jog_i       (jog_i[k]),
        .v_start_i   (v_start_i[k*SPEED_W +: SPEED_W]),
        .v_max_i     (v_max_i[k*SPEED_W +: SPEED_W]),
        .v_end_i     (v_end_i[k*SPEED_W +: SPEED_W]),
        .v_dec_i     (v_dec_i[k*SPEED_W +: SPEED_W]),
        .acc_i       (acc_i[k*ACC_W +: ACC_W]),
        .dec_i       (dec_i[k*ACC_W +: ACC_W]),
        .acc_steps_i (acc_steps_i[k*STEP_W +: STEP_W]),
        .dec_step_i  (dec_step_i[k*STEP_W +: STEP_W]),
        .dec_frac_i  (dec_frac_i[k*DFRAC_W +: DFRAC_W]),
        .step_high_i (step_high_i[k*PULSE_W +: PULSE_W]),
        .step_low_i  (step_low_i[k*PULSE_W +: PULSE_W]),
        .dir_setup_i (dir_setup_i[k*PULSE_W +: PULSE_W]),
        .dir_hold_i  (dir_hold_i[k*PULSE_W +: PULSE_W]),
        .step_inv_i  (step_inv_i[k]),
        .dir_inv_i   (dir_inv_i[k]),
        .step_o      (step_o[k]),
        .dir_o       (dir_o[k]),
        .busy_o      (busy_o[k]),
        .done_o      (done_o[k]),
        .err_o       (err_o[k]),
        .phase_o     (phase_o[k*2 +: 2]),
        .pos_o       (pos_o[k*POS_W +: POS_W])
      );
    end
  endgenerate

endmodule

`default_nettype wire
