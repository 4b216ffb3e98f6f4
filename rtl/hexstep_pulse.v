// SPDX-License-Identifier: Apache-2.0
// hexstep: STEP/DIR output stage of one axis (pulse timing, DIR setup/hold, position counter).
`default_nettype none

// Turns "a step is owed" into STEP pulses with the programmed high/low times, switches DIR to
// the target level only when the hold time after the last rising edge has passed, holds the
// next rising edge back until DIR has been stable for the setup time, and counts the signed
// position. Counterpart of the "pulse stage" lines of AxisModel::tick() (cpp_model/src/axis.cpp).
//
// Timing inputs are used live every cycle (not latched); a value of 0 for step_high_i or
// step_low_i acts as 1. The step level resets low and the DIR level and DIR target reset to 1
// (positive motion); the pins are these levels XOR the live polarity inputs.
module hexstep_pulse #(
  // PULSE_W: width of the pulse timing inputs, in bits (unit: clock cycles). Range 1..30;
  // default 12 (up to 4095 cycles, 40.95 us at 100 MHz, covers the slowest common drivers).
  // The cycles-since-rise counter is PULSE_W+1 bits so that it can reach high+low time.
  parameter integer PULSE_W = 12,
  // POS_W: width of the signed (two's complement) position counter, in bits (unit: steps).
  // Range 2..64; default 32. It wraps modulo 2^POS_W, like the model.
  parameter integer POS_W   = 32
) (
  input  wire               clk_i,
  input  wire               rst_i,        // synchronous, active high
  // From the generator.
  input  wire               owed_nz_i,    // at least one generated step still has to be pulsed
  input  wire               abort_i,      // abort strobe: no new rising edge this cycle
  input  wire               tgt_load_i,   // accepted start: load the DIR target
  input  wire               tgt_dir_i,    // DIR target of the new move (1: positive)
  // Live timing configuration (clock cycles).
  input  wire [PULSE_W-1:0] step_high_i,  // STEP high time (0 acts as 1)
  input  wire [PULSE_W-1:0] step_low_i,   // minimum STEP low time (0 acts as 1)
  input  wire [PULSE_W-1:0] dir_setup_i,  // DIR stable this long before a rising STEP edge
  input  wire [PULSE_W-1:0] dir_hold_i,   // DIR stable this long after a rising STEP edge
  input  wire               step_inv_i,   // STEP pin active low
  input  wire               dir_inv_i,    // DIR pin low for positive motion
  // To the generator.
  output wire               rise_o,       // a STEP rising edge is registered at this clock edge
  // Pins and position.
  output wire               step_o,
  output wire               dir_o,
  output wire [POS_W-1:0]   pos_o
);

  localparam integer CNT_W = PULSE_W + 1;  // width of the cycles-since-rise counter

  localparam [CNT_W-1:0]   C_MAX = {CNT_W{1'b1}};
  localparam [PULSE_W-1:0] D_MAX = {PULSE_W{1'b1}};
  localparam [CNT_W-1:0]   C_ONE = 1;
  localparam [PULSE_W-1:0] D_ONE = 1;
  localparam [POS_W-1:0]   P_ONE = 1;

  // State.
  reg               step_q, step_d;      // STEP level before polarity (1: pulse high)
  reg               dir_q, dir_d;        // DIR level before polarity (1: positive)
  reg               tgt_q, tgt_d;        // DIR level wanted by the current move
  reg [CNT_W-1:0]   c_q, c_d;            // cycles since the last rising edge, saturating
  reg [PULSE_W-1:0] d_q, d_d;            // cycles since the last DIR change, saturating
  reg [POS_W-1:0]   pos_q, pos_d;        // signed position

  // Combinational helpers.
  reg [PULSE_W-1:0] hi_t, lo_t;          // step high/low time with 0 read as 1
  reg [CNT_W-1:0]   hi_x, hold_x;        // the same, zero-extended to the counter width
  reg [CNT_W-1:0]   period;              // hi_t + lo_t (cannot overflow CNT_W bits)
  reg               dir_change, rise, fall;

  always @* begin
    // Timing with 0 acting as 1.
    hi_t = (step_high_i == {PULSE_W{1'b0}}) ? D_ONE : step_high_i;
    lo_t = (step_low_i == {PULSE_W{1'b0}}) ? D_ONE : step_low_i;
    hi_x = {1'b0, hi_t};
    hold_x = {1'b0, dir_hold_i};
    period = hi_x + {1'b0, lo_t};

    // Events, all from the old state.
    dir_change = (dir_q != tgt_q) && (c_q >= hold_x);
    rise = !abort_i && owed_nz_i && !step_q && (dir_q == tgt_q) && (c_q >= period) &&
           (d_q >= dir_setup_i);
    fall = step_q && (c_q >= hi_x);

    // Next state, defaults first.
    step_d = step_q;
    dir_d = dir_q;
    tgt_d = tgt_q;
    c_d = (c_q == C_MAX) ? C_MAX : c_q + C_ONE;
    d_d = (d_q == D_MAX) ? D_MAX : d_q + D_ONE;
    pos_d = pos_q;

    if (rise) begin
      step_d = 1'b1;
      c_d = C_ONE;
      pos_d = dir_q ? pos_q + P_ONE : pos_q - P_ONE;
    end else if (fall) begin
      step_d = 1'b0;
    end
    if (dir_change) begin
      dir_d = tgt_q;
      d_d = D_ONE;
    end
    if (tgt_load_i) begin
      tgt_d = tgt_dir_i;
    end
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      step_q <= 1'b0;
      dir_q <= 1'b1;
      tgt_q <= 1'b1;
      c_q <= C_MAX;
      d_q <= D_MAX;
      pos_q <= {POS_W{1'b0}};
    end else begin
      step_q <= step_d;
      dir_q <= dir_d;
      tgt_q <= tgt_d;
      c_q <= c_d;
      d_q <= d_d;
      pos_q <= pos_d;
    end
  end

  assign rise_o = rise;
  assign step_o = step_q ^ step_inv_i;
  assign dir_o = dir_q ^ dir_inv_i;
  assign pos_o = pos_q;

endmodule

`default_nettype wire
