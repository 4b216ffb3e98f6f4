// SPDX-License-Identifier: Apache-2.0
// hexstep: one memory bank of the frame engine: 256 x 32 bits, one write port, one read port,
// read data two cycles after the address.
`default_nettype none

// Timing: raddr_i driven during cycle c gives rdata_o valid during cycle c+2; a write with
// we_i during cycle c changes the word at the edge that ends cycle c. The schedules of the
// engine and the bus block never write a word during the cycle its read address is driven or
// the cycle after (re_i marks the reads whose data is used), and under that rule the two
// implementations below behave the same:
//   STYLE "DELAY" (default): the address is registered, then the block RAM reads at the next
//     edge into its own output register (iCE40 SB_RAM40_4K: no fabric flip-flops on the data).
//   STYLE "ECP5": two DP16KD (18 bits each) reading at the first edge into their output
//     register (REGMODE OUTREG): the ECP5 block RAM's clock-to-output without that register is
//     about 5.6 ns, more than a 150 MHz cycle leaves for the logic behind it. In the x18 mode
//     address bits 1..0 of the write port are its byte enables (Lattice TN1264; Yosys maps them
//     so too), tied high here: tied low, the block RAM would never be written.
// Simulation with Verilator checks that rule and stops on a violation. tests/ram runs both
// styles side by side, STYLE "ECP5" on a model of DP16KD (tests/ram/dp16kd_sim.v).
//
// No reset: the memory holds data only; the engine reads a word only after writing it.
module hexstep_ram #(
  // STYLE: "DELAY" (generic, iCE40) or "ECP5" (DP16KD primitives).
  parameter STYLE = "DELAY"
) (
  input  wire        clk_i,
  input  wire        re_i,      // the data of this read is used (simulation check only)
  input  wire [7:0]  raddr_i,
  output wire [31:0] rdata_o,
  input  wire        we_i,
  input  wire [7:0]  waddr_i,
  input  wire [31:0] wdata_i
);

  generate
    if (STYLE == "ECP5") begin : g_ecp5
      wire [35:0] q;
      wire [3:0]  unused_q = {q[35:34], q[17:16]};  // the parity bits, written 0
      genvar h;
      for (h = 0; h < 2; h = h + 1) begin : g_half
        wire [17:0] d = {2'b00, wdata_i[h*16 +: 16]};
        wire [17:0] o;
        wire [17:0] unused_a;  // port A's read data: port A only writes
        DP16KD #(
          .DATA_WIDTH_A (18), .DATA_WIDTH_B (18),
          .REGMODE_A ("NOREG"), .REGMODE_B ("OUTREG"),
          .WRITEMODE_A ("NORMAL"), .WRITEMODE_B ("NORMAL"),
          .CSDECODE_A ("0b000"), .CSDECODE_B ("0b000"),
          .GSR ("DISABLED")
        ) u_bram (
          // Port A: write, both byte enables (ADA1, ADA0) on.
          .CLKA (clk_i), .CEA (1'b1), .OCEA (1'b1), .WEA (we_i), .RSTA (1'b0),
          .CSA0 (1'b0), .CSA1 (1'b0), .CSA2 (1'b0),
          .ADA0 (1'b1), .ADA1 (1'b1), .ADA2 (1'b0), .ADA3 (1'b0),
          .ADA4 (waddr_i[0]), .ADA5 (waddr_i[1]), .ADA6 (waddr_i[2]), .ADA7 (waddr_i[3]),
          .ADA8 (waddr_i[4]), .ADA9 (waddr_i[5]), .ADA10 (waddr_i[6]), .ADA11 (waddr_i[7]),
          .ADA12 (1'b0), .ADA13 (1'b0),
          .DIA0 (d[0]), .DIA1 (d[1]), .DIA2 (d[2]), .DIA3 (d[3]), .DIA4 (d[4]), .DIA5 (d[5]),
          .DIA6 (d[6]), .DIA7 (d[7]), .DIA8 (d[8]), .DIA9 (d[9]), .DIA10 (d[10]), .DIA11 (d[11]),
          .DIA12 (d[12]), .DIA13 (d[13]), .DIA14 (d[14]), .DIA15 (d[15]), .DIA16 (d[16]),
          .DIA17 (d[17]),
          .DOA0 (unused_a[0]), .DOA1 (unused_a[1]), .DOA2 (unused_a[2]), .DOA3 (unused_a[3]),
          .DOA4 (unused_a[4]), .DOA5 (unused_a[5]), .DOA6 (unused_a[6]), .DOA7 (unused_a[7]),
          .DOA8 (unused_a[8]), .DOA9 (unused_a[9]), .DOA10 (unused_a[10]),
          .DOA11 (unused_a[11]), .DOA12 (unused_a[12]), .DOA13 (unused_a[13]),
          .DOA14 (unused_a[14]), .DOA15 (unused_a[15]), .DOA16 (unused_a[16]),
          .DOA17 (unused_a[17]),
          // Port B: read, through the output register.
          .CLKB (clk_i), .CEB (1'b1), .OCEB (1'b1), .WEB (1'b0), .RSTB (1'b0),
          .CSB0 (1'b0), .CSB1 (1'b0), .CSB2 (1'b0),
          .ADB0 (1'b0), .ADB1 (1'b0), .ADB2 (1'b0), .ADB3 (1'b0),
          .ADB4 (raddr_i[0]), .ADB5 (raddr_i[1]), .ADB6 (raddr_i[2]), .ADB7 (raddr_i[3]),
          .ADB8 (raddr_i[4]), .ADB9 (raddr_i[5]), .ADB10 (raddr_i[6]), .ADB11 (raddr_i[7]),
          .ADB12 (1'b0), .ADB13 (1'b0),
          .DIB0 (1'b0), .DIB1 (1'b0), .DIB2 (1'b0), .DIB3 (1'b0), .DIB4 (1'b0), .DIB5 (1'b0),
          .DIB6 (1'b0), .DIB7 (1'b0), .DIB8 (1'b0), .DIB9 (1'b0), .DIB10 (1'b0), .DIB11 (1'b0),
          .DIB12 (1'b0), .DIB13 (1'b0), .DIB14 (1'b0), .DIB15 (1'b0), .DIB16 (1'b0),
          .DIB17 (1'b0),
          .DOB0 (o[0]), .DOB1 (o[1]), .DOB2 (o[2]), .DOB3 (o[3]), .DOB4 (o[4]), .DOB5 (o[5]),
          .DOB6 (o[6]), .DOB7 (o[7]), .DOB8 (o[8]), .DOB9 (o[9]), .DOB10 (o[10]),
          .DOB11 (o[11]), .DOB12 (o[12]), .DOB13 (o[13]), .DOB14 (o[14]), .DOB15 (o[15]),
          .DOB16 (o[16]), .DOB17 (o[17])
        );
        assign q[h*18 +: 18] = o;
      end
      assign rdata_o = {q[33:18], q[15:0]};
    end else begin : g_delay
      (* no_rw_check *) reg [31:0] mem [0:255];
      reg [7:0]  ra_q;
      reg [31:0] rd_q;
      always @(posedge clk_i) begin
        ra_q <= raddr_i;
        rd_q <= mem[ra_q];
        if (we_i) mem[waddr_i] <= wdata_i;
      end
      assign rdata_o = rd_q;
    end
  endgenerate

`ifdef VERILATOR
  // The rule above: no write to a word during the cycle of a used read of it or the next one.
  reg [7:0] r1_q;
  reg       re1_q;
  always @(posedge clk_i) begin
    re1_q <= re_i;
    r1_q <= raddr_i;
    if (we_i && ((re_i && waddr_i == raddr_i) || (re1_q && waddr_i == r1_q))) begin
      $display("hexstep_ram %m: write to word %0d during its read", waddr_i);
      $stop;
    end
  end
`endif

endmodule

`default_nettype wire
