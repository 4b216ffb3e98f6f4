// SPDX-License-Identifier: Apache-2.0
// hexstep: reset release, E-STOP synchronizer and driver enables shared by every board top
// (rtl/boards/hexstep_board.v for the SPI builds, soc/boards/hexstep_soc_board.v for the SoC).
`default_nettype none

// rst_i is the asynchronous "not ready" of the board (PLL not locked, reset button). rst_o
// follows it at once and is released into the clk_i domain RST_CYCLES cycles after rst_i was last
// high (a counter that restarts whenever rst_i is high): the design leaves reset synchronously.
// estop_o is the E-STOP pin through a 2-flop synchronizer. Driver enables en_n_o (active low, as
// the EN pin of A4988/DRV8825/TMC2209 drivers) are off (high) in reset and while the
// synchronized E-STOP is active; pins k >= NAXES of PINS are always off.
module hexstep_board_reset #(
  parameter integer NAXES      = 6,
  parameter integer PINS       = 6,     // >= NAXES
  parameter integer RST_CYCLES = 16     // 2..2^16
) (
  input  wire            clk_i,
  input  wire            rst_i,         // asynchronous, active high
  input  wire            estop_i,       // asynchronous, active high
  output wire            rst_o,         // synchronous release, active high
  output wire            estop_o,       // synchronized E-STOP
  output wire [PINS-1:0] en_n_o
);

  reg [1:0]  rs_q;
  reg [15:0] rcnt_q;
  reg        rst_q;
  always @(posedge clk_i or posedge rst_i) begin
    if (rst_i) begin
      rs_q <= 2'b00;  rcnt_q <= 16'd0;  rst_q <= 1'b1;
    end else begin
      rs_q <= {rs_q[0], 1'b1};
      if (!rs_q[1]) begin
        rcnt_q <= 16'd0;  rst_q <= 1'b1;
      end else if (rcnt_q != RST_CYCLES[15:0] - 16'd1) begin
        rcnt_q <= rcnt_q + 16'd1;  rst_q <= 1'b1;
      end else begin
        rst_q <= 1'b0;
      end
    end
  end

  reg [1:0] es_q;
  always @(posedge clk_i) es_q <= {es_q[0], estop_i};

  reg [NAXES-1:0] en_n_q;
  always @(posedge clk_i) en_n_q <= {NAXES{rst_q | es_q[1]}};

  generate
    if (PINS > NAXES) begin : g_unused
      assign en_n_o = {{(PINS-NAXES){1'b1}}, en_n_q};
    end else begin : g_all
      assign en_n_o = en_n_q;
    end
  endgenerate
  assign rst_o   = rst_q;
  assign estop_o = es_q[1];

endmodule

`default_nettype wire
