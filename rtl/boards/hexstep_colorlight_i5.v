// SPDX-License-Identifier: Apache-2.0
// hexstep: Colorlight i5 (ECP5 LFE5U-25F) board top: EHXPLLL from the 25 MHz oscillator, the SPI slave and six
// STEP/DIR/EN outputs on connector pins (pinout: constraints/colorlight_i5.lpf, docs/SYNTH.md).
`default_nettype none

module hexstep_colorlight_i5 #(
  parameter integer NAXES   = 6,
  parameter integer ACC_W   = 48,
  parameter integer STEP_W  = 32,
  parameter integer DFRAC_W = 32,
  parameter integer PULSE_W = 12,
  parameter integer POS_W   = 32,
  parameter         RAM_STYLE = "ECP5",  // ECP5: DP16KD with its output register (hexstep_ram)
  // PLL (see hexstep_ecp5_pll), set by synth/flow.py from synth/targets.json; the defaults
  // (ecppll -i 25 -o 50) give 50 MHz.
  parameter integer PLL_CLKI_DIV     = 1,
  parameter integer PLL_CLKFB_DIV    = 2,
  parameter integer PLL_CLKOP_DIV    = 12,
  parameter integer PLL_CLKOP_CPHASE = 5
) (
  input  wire             CLK25,      // 25 MHz oscillator
  output wire             LED_N,      // on-module LED D2 (active low): E-STOP pin active
  input  wire             SPI_SCK,
  input  wire             SPI_CS_N,
  input  wire             SPI_MOSI,
  output wire             SPI_MISO,
  input  wire             ESTOP,      // active high
  output wire [5:0]       STEP,       // six pin triples; axes >= NAXES stay idle and disabled
  output wire [5:0]       DIR,
  output wire [5:0]       EN_N
);

  wire clk, locked;
  hexstep_ecp5_pll #(
    .CLKI_DIV (PLL_CLKI_DIV), .CLKFB_DIV (PLL_CLKFB_DIV), .CLKOP_DIV (PLL_CLKOP_DIV),
    .CLKOP_CPHASE (PLL_CLKOP_CPHASE)
  ) u_pll (.clk_i (CLK25), .clk_o (clk), .locked_o (locked));

  wire miso, miso_oe, irq, estop;
  hexstep_board #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .RAM_STYLE (RAM_STYLE), .PINS (6)
  ) u_board (
    .clk_i (clk), .rst_i (~locked),
    .spi_sck_i (SPI_SCK), .spi_cs_n_i (SPI_CS_N), .spi_mosi_i (SPI_MOSI),
    .spi_miso_o (miso), .spi_miso_oe_o (miso_oe),
    .estop_i (ESTOP), .step_o (STEP), .dir_o (DIR), .en_n_o (EN_N), .irq_o (irq),
    .estop_o (estop)
  );

  // MISO released while CS_N is high (a shared MISO line): the ECP5 tristate output buffer
  // OBZ (T high = high impedance), instantiated rather than inferred from 1'bz.
  OBZ u_miso (.I (miso), .T (~miso_oe), .O (SPI_MISO));
  assign LED_N = ~estop;
  wire   unused_irq = irq;   // no spare LED on the module

endmodule

`default_nettype wire
