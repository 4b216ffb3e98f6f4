// SPDX-License-Identifier: Apache-2.0
// hexstep SoC on the ULX3S (ECP5 LFE5U-85F): PicoRV32 + firmware + the default six-axis
// hexstep_top, host link over the FT231X USB UART, six STEP/DIR/EN triples and E-STOP on the
// pins of the core-only build (pinout: constraints/ulx3s.lpf, docs/SYNTH.md).
`default_nettype none

// Clock: the 25 MHz oscillator directly (no PLL: synth/targets.json soc_ulx3s, clock_mhz 25 =
// osc_mhz). UART_DIV is set by synth/flow.py from the clock and the baud rate of targets.json.
module hexstep_soc_ulx3s #(
  parameter integer RAM_WORDS = 2048,  // program RAM, 8 KiB
  parameter integer DATA_WORDS = 2048, // data RAM, 8 KiB
  parameter         INIT_FILE = "",
  parameter integer UART_DIV  = 217,   // 25 MHz / 115200
  parameter integer NAXES     = 6,
  parameter integer ACC_W     = 48,
  parameter integer STEP_W    = 32,
  parameter integer DFRAC_W   = 32,
  parameter integer PULSE_W   = 12,
  parameter integer POS_W     = 32,
  parameter         RAM_STYLE = "ECP5",   // DP16KD with its output register (hexstep_ram)
  parameter [0:0]   CPU_BARREL_SHIFTER  = 1,
  parameter [0:0]   CPU_TWO_STAGE_SHIFT = 1,
  parameter [0:0]   CPU_CATCH_MISALIGN  = 1,
  parameter [0:0]   CPU_CATCH_ILLINSN   = 1
) (
  input  wire       CLK25,      // 25 MHz oscillator
  input  wire       BTN_FIRE1,  // FIRE1 button (active high): reset while pressed
  output wire [1:0] LED,        // LED[0]: E-STOP pin active, LED[1]: interrupt pending
  input  wire       UART_RX,    // ftdi_txd: the FT231X transmits, the FPGA receives
  output wire       UART_TX,    // ftdi_rxd: the FPGA transmits
  input  wire       ESTOP,      // active high
  output wire [5:0] STEP,       // six pin triples; axes >= NAXES stay idle and disabled
  output wire [5:0] DIR,
  output wire [5:0] EN_N
);

  wire irq, estop, trap;
  hexstep_soc_board #(
    .RAM_WORDS (RAM_WORDS), .DATA_WORDS (DATA_WORDS), .DATA_SPRAM (1'b0),
    .INIT_FILE (INIT_FILE), .UART_DIV (UART_DIV), .NAXES (NAXES),
    .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .RAM_STYLE (RAM_STYLE),
    .CPU_BARREL_SHIFTER (CPU_BARREL_SHIFTER), .CPU_TWO_STAGE_SHIFT (CPU_TWO_STAGE_SHIFT),
    .CPU_CATCH_MISALIGN (CPU_CATCH_MISALIGN), .CPU_CATCH_ILLINSN (CPU_CATCH_ILLINSN)
  ) u_board (
    .clk_i (CLK25), .rst_i (BTN_FIRE1), .uart_rx_i (UART_RX), .uart_tx_o (UART_TX),
    .estop_i (ESTOP), .step_o (STEP), .dir_o (DIR), .en_n_o (EN_N), .irq_o (irq),
    .estop_o (estop), .trap_o (trap)
  );

  assign LED = {irq | trap, estop};   // LED[1] also lights on a CPU trap

endmodule

`default_nettype wire
