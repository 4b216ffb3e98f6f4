// SPDX-License-Identifier: Apache-2.0
// hexstep SoC board builds: board-independent part of every SoC board top (reset release, driver
// enables, the SoC of soc/hexstep_soc.v). The host talks to the firmware over the board's
// USB UART (docs/PROTOCOL.md) instead of the SPI slave of the core-only board builds.
`default_nettype none

// Clocking: everything runs on clk_i (oscillator or PLL output of the board top). Reset: rst_i
// is the asynchronous "not ready" of the board (PLL not locked, reset button); it is released
// into the clk_i domain through a RST_CYCLES counter that restarts whenever rst_i is high, as in
// rtl/boards/hexstep_board.v, so the CPU starts the firmware RST_CYCLES cycles after the last
// request. Driver enables (active low) are off in reset and while the E-STOP pin is active
// (after a 2-flop synchroniser); E-STOP also aborts every axis in hexstep_top (latched until the
// host's CLEAR). Pins k >= NAXES: STEP/DIR low, EN_N high.
module hexstep_soc_board #(
  parameter integer RAM_WORDS  = 2048,  // see hexstep_soc
  parameter integer DATA_WORDS = 2048,
  parameter [0:0]   DATA_SPRAM = 0,
  parameter         INIT_FILE  = "",
  parameter integer UART_DIV   = 868,
  parameter integer NAXES      = 6,
  parameter integer ACC_W      = 48,
  parameter integer STEP_W     = 32,
  parameter integer DFRAC_W    = 32,
  parameter integer PULSE_W    = 12,
  parameter integer POS_W      = 32,
  parameter         RAM_STYLE  = "DELAY",
  parameter [0:0]   CPU_BARREL_SHIFTER  = 1,
  parameter [0:0]   CPU_TWO_STAGE_SHIFT = 1,
  parameter [0:0]   CPU_CATCH_MISALIGN  = 1,
  parameter [0:0]   CPU_CATCH_ILLINSN   = 1,
  parameter integer RST_CYCLES = 16     // cycles of reset after rst_i falls, 2..2^16
) (
  input  wire       clk_i,
  input  wire       rst_i,        // asynchronous, active high
  input  wire       uart_rx_i,    // from the host (idle high)
  output wire       uart_tx_o,    // to the host
  input  wire       estop_i,      // asynchronous, active high
  output wire [5:0] step_o,
  output wire [5:0] dir_o,
  output wire [5:0] en_n_o,       // driver enable, active low
  output wire       irq_o,        // hexstep_top's interrupt line (for an LED)
  output wire       estop_o,      // synchronised E-STOP pin (for an LED)
  output wire       trap_o        // the CPU trapped (for an LED)
);

  // ---- reset release, E-STOP synchronizer, driver enables (rtl/boards/hexstep_board_reset.v) ----
  wire board_rst, estop_sync;
  hexstep_board_reset #(.NAXES (NAXES), .PINS (6), .RST_CYCLES (RST_CYCLES)) u_rst (
    .clk_i (clk_i), .rst_i (rst_i), .estop_i (estop_i),
    .rst_o (board_rst), .estop_o (estop_sync), .en_n_o (en_n_o)
  );

  hexstep_soc #(
    .RAM_WORDS (RAM_WORDS), .DATA_WORDS (DATA_WORDS), .DATA_SPRAM (DATA_SPRAM),
    .INIT_FILE (INIT_FILE), .UART_DIV (UART_DIV), .NAXES (NAXES),
    .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .RAM_STYLE (RAM_STYLE),
    .CPU_BARREL_SHIFTER (CPU_BARREL_SHIFTER), .CPU_TWO_STAGE_SHIFT (CPU_TWO_STAGE_SHIFT),
    .CPU_CATCH_MISALIGN (CPU_CATCH_MISALIGN), .CPU_CATCH_ILLINSN (CPU_CATCH_ILLINSN)
  ) u_soc (
    .clk_i (clk_i), .rst_i (board_rst), .uart_rx_i (uart_rx_i), .uart_tx_o (uart_tx_o),
    .estop_i (estop_sync), .irq_o (irq_o), .step_o (step_o), .dir_o (dir_o), .trap_o (trap_o)
  );

  assign estop_o = estop_sync;

endmodule

`default_nettype wire
