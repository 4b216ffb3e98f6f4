// SPDX-License-Identifier: Apache-2.0
// hexstep: out-of-context wrapper for utilization and Fmax: hexstep_top with every input driven
// by a free-running LFSR and every output folded into one registered XOR, so that synthesis can
// neither treat an input as constant nor remove logic whose output is unobserved.
`default_nettype none

// Pins: clk_i, rst_i, seed_i (XORed into the LFSR feedback: the sequence depends on a pin, so
// the LFSR itself cannot be folded into constants) and out_o. Every hexstep_top input is a
// distinct LFSR bit, registered; every output is registered and XOR-reduced into out_o. The
// registers add about 2 x 100 flip-flops and a 64-bit LFSR to the counts (reported as
// "wrapper" in docs/SYNTH.md); all their paths are register to register.
module hexstep_ooc #(
  parameter integer NAXES     = 6,
  parameter integer ACC_W     = 48,
  parameter integer STEP_W    = 32,
  parameter integer DFRAC_W   = 32,
  parameter integer PULSE_W   = 12,
  parameter integer POS_W     = 32,
  parameter         RAM_STYLE = "DELAY"
) (
  input  wire clk_i,
  input  wire rst_i,
  input  wire seed_i,
  output wire out_o
);

  localparam integer ADDR_W = 12;
  localparam integer NIN    = 3 + ADDR_W + 32 + 4 + 1;   // cyc, stb, we, adr, dat, sel, estop

  // 64-bit Fibonacci LFSR, taps 64, 63, 61, 60 (maximal length).
  reg [63:0] lfsr_q;
  reg        rst_q;
  always @(posedge clk_i) begin
    rst_q <= rst_i;
    if (rst_q) lfsr_q <= 64'h1;
    else       lfsr_q <= {lfsr_q[62:0], lfsr_q[63] ^ lfsr_q[62] ^ lfsr_q[60] ^ lfsr_q[59] ^ seed_i};
  end

  reg [NIN-1:0] in_q;
  always @(posedge clk_i) in_q <= lfsr_q[NIN-1:0];

  wire [31:0]      dat;
  wire             ack, irq;
  wire [NAXES-1:0] step, dir;

  hexstep_top #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W), .PULSE_W (PULSE_W),
    .POS_W (POS_W), .ADDR_W (ADDR_W), .RAM_STYLE (RAM_STYLE)
  ) u_top (
    .clk_i (clk_i), .rst_i (rst_q),
    .wb_cyc_i (in_q[0]), .wb_stb_i (in_q[1]), .wb_we_i (in_q[2]),
    .wb_adr_i (in_q[3 +: ADDR_W]), .wb_dat_i (in_q[3 + ADDR_W +: 32]),
    .wb_sel_i (in_q[3 + ADDR_W + 32 +: 4]), .estop_i (in_q[NIN-1]),
    .wb_dat_o (dat), .wb_ack_o (ack), .irq_o (irq), .step_o (step), .dir_o (dir)
  );

  reg [32+2+2*NAXES-1:0] out_q;
  reg                    x_q;
  always @(posedge clk_i) begin
    out_q <= {dat, ack, irq, step, dir};
    x_q   <= ^out_q;
  end
  assign out_o = x_q;

endmodule

`default_nettype wire
