// SPDX-License-Identifier: Apache-2.0
// hexstep: board-independent part of every board top: reset and input synchronizers, the SPI
// bridge (hexstep_spi_wb) driving the Wishbone register block and core (hexstep_top).
`default_nettype none

// Clocking: everything runs on clk_i, the PLL output of the board top. Reset: rst_i is the
// asynchronous "not ready" of the board (PLL not locked, reset button); it is released into
// the clk_i domain through a RST_CYCLES power-on counter that restarts whenever rst_i is high, so
// the design leaves reset synchronously, RST_CYCLES cycles after the last request. The E-STOP
// pin passes a 2-flop synchronizer here (hexstep_wb synchronizes it again: harmless, 2 cycles);
// SCK/CS_N/MOSI are synchronized inside hexstep_spi_wb. Driver enables (active low, as the
// EN pin of A4988/DRV8825/TMC2209 drivers) are off in reset and while the E-STOP pin is active;
// E-STOP also aborts every axis in hexstep_wb (latched until software clears it).
module hexstep_board #(
  parameter integer NAXES      = 6,     // see hexstep_top
  parameter integer ACC_W      = 48,
  parameter integer STEP_W     = 32,
  parameter integer DFRAC_W    = 32,
  parameter integer PULSE_W    = 12,
  parameter integer POS_W      = 32,
  parameter         RAM_STYLE  = "DELAY", // "DELAY" on iCE40, "ECP5" on ECP5 (hexstep_ram)
  parameter integer RST_CYCLES = 16,    // cycles of reset after rst_i falls, 2..2^16
  parameter integer PINS       = 6      // STEP/DIR/EN pin triples of the board, >= NAXES
) (
  input  wire             clk_i,
  input  wire             rst_i,        // asynchronous, active high
  input  wire             spi_sck_i,
  input  wire             spi_cs_n_i,
  input  wire             spi_mosi_i,
  output wire             spi_miso_o,
  output wire             spi_miso_oe_o,
  input  wire             estop_i,      // asynchronous, active high
  output wire [PINS-1:0]  step_o,       // axis k on pin k; pins k >= NAXES: STEP/DIR low,
  output wire [PINS-1:0]  dir_o,        //   EN_N high (driver disabled)
  output wire [PINS-1:0]  en_n_o,       // driver enable, active low
  output wire             irq_o,
  output wire             estop_o       // synchronized E-STOP pin (for an LED)
);

  // ---- reset release, E-STOP synchronizer, driver enables (rtl/boards/hexstep_board_reset.v) ----
  wire board_rst, estop_sync;
  hexstep_board_reset #(.NAXES (NAXES), .PINS (PINS), .RST_CYCLES (RST_CYCLES)) u_rst (
    .clk_i (clk_i), .rst_i (rst_i), .estop_i (estop_i),
    .rst_o (board_rst), .estop_o (estop_sync), .en_n_o (en_n_o)
  );

  wire [NAXES-1:0] step, dir;

  localparam integer ADDR_W = 12;
  wire              cyc, stb, we, ack;
  wire [ADDR_W-1:0] adr;
  wire [31:0]       wdat, rdat;
  wire [3:0]        sel;

  hexstep_spi_wb #(.ADDR_W (ADDR_W)) u_spi (
    .clk_i (clk_i), .rst_i (board_rst),
    .spi_sck_i (spi_sck_i), .spi_cs_n_i (spi_cs_n_i), .spi_mosi_i (spi_mosi_i),
    .spi_miso_o (spi_miso_o), .spi_miso_oe_o (spi_miso_oe_o),
    .wb_cyc_o (cyc), .wb_stb_o (stb), .wb_we_o (we), .wb_adr_o (adr), .wb_dat_o (wdat),
    .wb_sel_o (sel), .wb_dat_i (rdat), .wb_ack_i (ack)
  );

  hexstep_top #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .ADDR_W (ADDR_W), .RAM_STYLE (RAM_STYLE)
  ) u_top (
    .clk_i (clk_i), .rst_i (board_rst),
    .wb_cyc_i (cyc), .wb_stb_i (stb), .wb_we_i (we), .wb_adr_i (adr), .wb_dat_i (wdat),
    .wb_sel_i (sel), .wb_dat_o (rdat), .wb_ack_o (ack),
    .estop_i (estop_sync), .irq_o (irq_o), .step_o (step), .dir_o (dir)
  );

  generate
    if (PINS > NAXES) begin : g_unused
      assign step_o = {{(PINS-NAXES){1'b0}}, step};
      assign dir_o  = {{(PINS-NAXES){1'b0}}, dir};
    end else begin : g_all
      assign step_o = step;
      assign dir_o  = dir;
    end
  endgenerate
  assign estop_o = estop_sync;

endmodule

`default_nettype wire
