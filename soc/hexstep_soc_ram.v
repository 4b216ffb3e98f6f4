// SPDX-License-Identifier: Apache-2.0
// hexstep SoC: on-chip RAM (Wishbone B4 classic slave) holding the firmware from $readmemh.
`default_nettype none

// Synchronous single-port RAM, one wait state: a request seen at edge E is acked at E+1 with
// the read data. Byte enables on writes. Not reset (its contents are the firmware image).
// WORDS need not be a power of two: an address between WORDS and the next power of two
// (outside the firmware's memory) reads an undefined word, and a write there is dropped.
module hexstep_soc_ram #(
  parameter integer WORDS     = 4096,       // 32-bit words (16 KiB default: firmware + stack); any
                                            //   size, e.g. 3072 (12 KiB, 24 iCE40 BRAMs)
  parameter         INIT_FILE = ""          // $readmemh image, one 32-bit word per line; "" = none
) (
  input  wire        clk_i,
  input  wire        rst_i,                 // synchronous, active high (only the ack)
  input  wire        wb_cyc_i,
  input  wire        wb_stb_i,
  input  wire        wb_we_i,
  input  wire [31:0] wb_adr_i,              // byte address; bits above the RAM size ignored
  input  wire [31:0] wb_dat_i,
  input  wire [3:0]  wb_sel_i,
  output reg  [31:0] wb_dat_o,
  output reg         wb_ack_o
);
  localparam integer AW = $clog2(WORDS);

  reg [31:0] mem [0:WORDS-1];
  wire [AW-1:0] idx = wb_adr_i[AW+1:2];
  wire          req = wb_cyc_i & wb_stb_i & ~wb_ack_o;
  wire          wen = req & wb_we_i & ({{(32-AW){1'b0}}, idx} < WORDS);

  initial begin
    if (INIT_FILE != "") $readmemh(INIT_FILE, mem);
  end

  always @(posedge clk_i) begin
    if (wen & wb_sel_i[0]) mem[idx][7:0]   <= wb_dat_i[7:0];
    if (wen & wb_sel_i[1]) mem[idx][15:8]  <= wb_dat_i[15:8];
    if (wen & wb_sel_i[2]) mem[idx][23:16] <= wb_dat_i[23:16];
    if (wen & wb_sel_i[3]) mem[idx][31:24] <= wb_dat_i[31:24];
    wb_dat_o <= mem[idx];
  end

  always @(posedge clk_i) begin
    if (rst_i) wb_ack_o <= 1'b0;
    else       wb_ack_o <= req;
  end

endmodule

`default_nettype wire
