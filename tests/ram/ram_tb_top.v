// SPDX-License-Identifier: Apache-2.0
// hexstep test bench: rtl/hexstep_ram.v in both implementations side by side on the same
// ports, the ECP5 one on the DP16KD model of tests/ram/dp16kd_sim.v (tests/ram/test_ram.cpp).
`default_nettype none

module ram_tb_top (
  input  wire        clk_i,
  input  wire        re_i,
  input  wire [7:0]  raddr_i,
  input  wire        we_i,
  input  wire [7:0]  waddr_i,
  input  wire [31:0] wdata_i,
  output wire [31:0] rdata_delay_o,
  output wire [31:0] rdata_ecp5_o
);

  hexstep_ram #(.STYLE ("DELAY")) u_delay (
    .clk_i (clk_i), .re_i (re_i), .raddr_i (raddr_i), .rdata_o (rdata_delay_o),
    .we_i (we_i), .waddr_i (waddr_i), .wdata_i (wdata_i));

  hexstep_ram #(.STYLE ("ECP5")) u_ecp5 (
    .clk_i (clk_i), .re_i (re_i), .raddr_i (raddr_i), .rdata_o (rdata_ecp5_o),
    .we_i (we_i), .waddr_i (waddr_i), .wdata_i (wdata_i));

endmodule

`default_nettype wire
