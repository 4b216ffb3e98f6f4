// SPDX-License-Identifier: Apache-2.0
// hexstep: iCEBreaker (iCE40 UP5K) board top: SB_PLL40_PAD from the 12 MHz oscillator, the SPI
// slave and six STEP/DIR/EN outputs on the PMOD connectors (pinout: constraints/icebreaker.pcf,
// docs/SYNTH.md).
`default_nettype none

// The PLL dividers are parameters set by synth/flow.py from the core clock chosen in
// synth/targets.json (computed with icepll): f_out = 12 MHz * (DIVF + 1) / (2^DIVQ * (DIVR + 1)).
module hexstep_icebreaker #(
  parameter integer NAXES   = 6,
  parameter integer ACC_W   = 48,
  parameter integer STEP_W  = 32,
  parameter integer DFRAC_W = 32,
  parameter integer PULSE_W = 12,
  parameter integer POS_W   = 32,
  parameter         RAM_STYLE = "DELAY",  // iCE40: registered address, SB_RAM40_4K output (hexstep_ram)
  parameter integer PLL_DIVR = 0,    // defaults: 12 MHz -> 18 MHz (icepll)
  parameter integer PLL_DIVF = 47,
  parameter integer PLL_DIVQ = 5,
  parameter integer PLL_FILTER_RANGE = 1
) (
  input  wire             CLK,        // 12 MHz oscillator
  input  wire             BTN_N,      // user button: reset while pressed
  output wire             LEDR_N,     // red LED: E-STOP pin active
  output wire             LEDG_N,     // green LED: interrupt pending
  input  wire             SPI_SCK,
  input  wire             SPI_CS_N,
  input  wire             SPI_MOSI,
  inout  wire             SPI_MISO,   // tristate (SB_IO below)
  input  wire             ESTOP,      // active high
  output wire [5:0]       STEP,       // six pin triples; axes >= NAXES stay idle and disabled
  output wire [5:0]       DIR,
  output wire [5:0]       EN_N
);

  wire clk, locked;
  SB_PLL40_PAD #(
    .FEEDBACK_PATH ("SIMPLE"),
    .DIVR (PLL_DIVR[3:0]),
    .DIVF (PLL_DIVF[6:0]),
    .DIVQ (PLL_DIVQ[2:0]),
    .FILTER_RANGE (PLL_FILTER_RANGE[2:0])
  ) u_pll (
    .PACKAGEPIN (CLK),
    .PLLOUTGLOBAL (clk),
    .LOCK (locked),
    .RESETB (1'b1),
    .BYPASS (1'b0)
  );

  wire miso, miso_oe, irq, estop;
  hexstep_board #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .RAM_STYLE (RAM_STYLE), .PINS (6)
  ) u_board (
    .clk_i (clk), .rst_i (~locked | ~BTN_N),
    .spi_sck_i (SPI_SCK), .spi_cs_n_i (SPI_CS_N), .spi_mosi_i (SPI_MOSI),
    .spi_miso_o (miso), .spi_miso_oe_o (miso_oe),
    .estop_i (ESTOP), .step_o (STEP), .dir_o (DIR), .en_n_o (EN_N), .irq_o (irq),
    .estop_o (estop)
  );

  // MISO released while CS_N is high (a shared MISO line): SB_IO with an unregistered
  // tristate output (PIN_TYPE 1010_01: output with enable, plain input).
  SB_IO #(.PIN_TYPE (6'b1010_01), .PULLUP (1'b0)) u_miso (
    .PACKAGE_PIN (SPI_MISO), .OUTPUT_ENABLE (miso_oe), .D_OUT_0 (miso)
  );
  assign LEDR_N = ~estop;
  assign LEDG_N = ~irq;

endmodule

`default_nettype wire
