// SPDX-License-Identifier: Apache-2.0
// hexstep SoC on the iCEBreaker (iCE40 UP5K): PicoRV32 + firmware + a one-axis hexstep_top (see
// synth/targets.json soc_icebreaker), host link over the FTDI channel B UART, six STEP/DIR/EN
// triples and E-STOP on the pins of the core-only build (constraints/icebreaker.pcf).
`default_nettype none

// Clock: the 12 MHz oscillator directly (no PLL: clock_mhz 12 = osc_mhz in targets.json; pin 35
// reaches a global buffer, nextpnr promotes it). UART_DIV is set by synth/flow.py from the clock and the baud rate.
module hexstep_soc_icebreaker #(
  parameter integer RAM_WORDS = 2048,  // program RAM, 8 KiB: 16 of the 30 SB_RAM40_4K (the core
                                       //   takes 8)
  parameter integer DATA_WORDS = 16384, // data RAM, 64 KiB: two of the four SB_SPRAM256KA
  parameter [0:0]   DATA_SPRAM = 1,
  parameter         INIT_FILE = "",
  parameter integer UART_DIV  = 104,   // 12 MHz / 115200
  parameter integer NAXES     = 1,
  parameter integer ACC_W     = 48,
  parameter integer STEP_W    = 32,
  parameter integer DFRAC_W   = 32,
  parameter integer PULSE_W   = 12,
  parameter integer POS_W     = 32,
  parameter         RAM_STYLE = "DELAY",  // iCE40 (hexstep_ram)
  parameter [0:0]   CPU_BARREL_SHIFTER  = 0,
  parameter [0:0]   CPU_TWO_STAGE_SHIFT = 1,
  parameter [0:0]   CPU_CATCH_MISALIGN  = 0,
  parameter [0:0]   CPU_CATCH_ILLINSN   = 0
) (
  input  wire       CLK,        // 12 MHz oscillator
  input  wire       BTN_N,      // user button: reset while pressed
  output wire       LEDR_N,     // red LED: E-STOP pin active or CPU trapped
  output wire       LEDG_N,     // green LED: interrupt pending
  input  wire       UART_RX,    // FTDI channel B: the host transmits, the FPGA receives
  output wire       UART_TX,    // the FPGA transmits
  input  wire       ESTOP,      // active high
  output wire [5:0] STEP,       // six pin triples; axes >= NAXES stay idle and disabled
  output wire [5:0] DIR,
  output wire [5:0] EN_N
);

  wire irq, estop, trap;
  hexstep_soc_board #(
    .RAM_WORDS (RAM_WORDS), .DATA_WORDS (DATA_WORDS), .DATA_SPRAM (DATA_SPRAM),
    .INIT_FILE (INIT_FILE), .UART_DIV (UART_DIV), .NAXES (NAXES),
    .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .RAM_STYLE (RAM_STYLE),
    .CPU_BARREL_SHIFTER (CPU_BARREL_SHIFTER), .CPU_TWO_STAGE_SHIFT (CPU_TWO_STAGE_SHIFT),
    .CPU_CATCH_MISALIGN (CPU_CATCH_MISALIGN), .CPU_CATCH_ILLINSN (CPU_CATCH_ILLINSN)
  ) u_board (
    .clk_i (CLK), .rst_i (~BTN_N), .uart_rx_i (UART_RX), .uart_tx_o (UART_TX),
    .estop_i (ESTOP), .step_o (STEP), .dir_o (DIR), .en_n_o (EN_N), .irq_o (irq),
    .estop_o (estop), .trap_o (trap)
  );

  assign LEDR_N = ~(estop | trap);
  assign LEDG_N = ~irq;

endmodule

`default_nettype wire
