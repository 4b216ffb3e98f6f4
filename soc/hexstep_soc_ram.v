// SPDX-License-Identifier: Apache-2.0
// hexstep SoC: on-chip RAM (Wishbone B4 classic slave): the program RAM holding the firmware
// from $readmemh, or the data RAM (optionally in iCE40 UP5K SPRAM).
`default_nettype none

// Synchronous single-port RAM, one wait state: a request seen at edge E is acked at E+1 with
// the read data. Byte enables on writes; a write does not update the read data (the ack of a
// write carries none), which is the read-during-write behaviour of the UP5K SPRAM ("no
// change") and lets Yosys map the same code to SB_RAM40_4K, SB_SPRAM256KA or DP16KD. Not reset
// (its contents are the firmware image or data). WORDS need not be a power of two: an address
// between WORDS and the next power of two (outside the firmware's memory) reads an undefined
// word, and a write there is dropped.
module hexstep_soc_ram #(
  parameter integer WORDS     = 2048,       // 32-bit words (8 KiB default); any size
  parameter         INIT_FILE = "",         // $readmemh image, one 32-bit word per line; "" = none
  parameter [0:0]   SPRAM     = 0           // 1: ask for the iCE40 UP5K SPRAM (ram_style "huge":
                                            //   16384 words in two SB_SPRAM256KA); no INIT_FILE
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

  wire [AW-1:0] idx = wb_adr_i[AW+1:2];
  wire          req = wb_cyc_i & wb_stb_i & ~wb_ack_o;
  wire          wen = req & wb_we_i & ({{(32-AW){1'b0}}, idx} < WORDS);

  generate
    if (SPRAM) begin : g_spram
      // The SPRAM cannot be initialised by the bitstream.
      if (INIT_FILE != "") begin : g_bad
        initial begin
          $display("hexstep_soc_ram: SPRAM = 1 takes no INIT_FILE");
          $finish;
        end
      end
      (* ram_style = "huge" *) reg [31:0] mem [0:WORDS-1];
      always @(posedge clk_i) begin
        if (wen) begin
          if (wb_sel_i[0]) mem[idx][7:0]   <= wb_dat_i[7:0];
          if (wb_sel_i[1]) mem[idx][15:8]  <= wb_dat_i[15:8];
          if (wb_sel_i[2]) mem[idx][23:16] <= wb_dat_i[23:16];
          if (wb_sel_i[3]) mem[idx][31:24] <= wb_dat_i[31:24];
        end else begin
          wb_dat_o <= mem[idx];
        end
      end
    end else begin : g_bram
      reg [31:0] mem [0:WORDS-1];
      initial begin
        if (INIT_FILE != "") $readmemh(INIT_FILE, mem);
      end
      always @(posedge clk_i) begin
        if (wen) begin
          if (wb_sel_i[0]) mem[idx][7:0]   <= wb_dat_i[7:0];
          if (wb_sel_i[1]) mem[idx][15:8]  <= wb_dat_i[15:8];
          if (wb_sel_i[2]) mem[idx][23:16] <= wb_dat_i[23:16];
          if (wb_sel_i[3]) mem[idx][31:24] <= wb_dat_i[31:24];
        end else begin
          wb_dat_o <= mem[idx];
        end
      end
    end
  endgenerate

  always @(posedge clk_i) begin
    if (rst_i) wb_ack_o <= 1'b0;
    else       wb_ack_o <= req;
  end

endmodule

`default_nettype wire
