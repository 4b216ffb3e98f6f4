// SPDX-License-Identifier: Apache-2.0
// hexstep test bench: a behavioural model of the part of Lattice's ECP5 DP16KD block RAM that
// rtl/hexstep_ram.v (STYLE "ECP5") uses, for simulation only. Yosys's cells_sim_ecp5.v declares
// DP16KD without behaviour, so without this model the ECP5 memory wiring is never simulated.
//
// Written from the port description of Lattice TN1264 (ECP5 and ECP5-5G Memory Usage Guide) and
// the mapping Yosys itself uses (techlibs/lattice/brams_map_16kd.v):
//   - the array is 16 Kbit, seen as 1024 units of 18 bits;
//   - x18 (DATA_WIDTH 18): word address AD[13:4] (1024 words); on a write port AD[1:0] are the
//     byte enables, AD[0] for bits 8..0 and AD[1] for bits 17..9; AD[3:2] are not used;
//   - x36 (DATA_WIDTH_A = DATA_WIDTH_B = 36, the pseudo-dual-port mode): port A writes, port B
//     reads; word address AD[13:5] (512 words of two units); data bits 17..0 on DIA/DOA and
//     35..18 on DIB/DOB; ADA[3:0] are the byte enables of bits 8..0, 17..9, 26..18, 35..27;
//   - a port reads at the rising clock edge with CE high; REGMODE "OUTREG" adds the output
//     register, loaded at the next edge with OCE high; "NOREG" shows the read word directly;
//   - a write needs CE, WE, every byte enable of the bytes it writes, and the chip select.
// Anything else (other widths, chip-select decodes, write modes, a write on port B) stops the
// simulation: the model covers what the project instantiates, not the whole primitive.
`default_nettype none

// Lint: the module is named after the primitive, not the file; its string parameters are
// compared with literals of other lengths; not every pin is used in every mode.
/* verilator lint_off DECLFILENAME */
/* verilator lint_off WIDTH */
/* verilator lint_off UNUSED */
module DP16KD #(
  parameter integer DATA_WIDTH_A = 18,
  parameter integer DATA_WIDTH_B = 18,
  parameter REGMODE_A = "NOREG",
  parameter REGMODE_B = "NOREG",
  parameter RESETMODE = "SYNC",
  parameter ASYNC_RESET_RELEASE = "SYNC",
  parameter CSDECODE_A = "0b000",
  parameter CSDECODE_B = "0b000",
  parameter WRITEMODE_A = "NORMAL",
  parameter WRITEMODE_B = "NORMAL",
  parameter GSR = "ENABLED"
) (
  input  wire DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7, DIA6,
  input  wire DIA5, DIA4, DIA3, DIA2, DIA1, DIA0,
  input  wire ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2, ADA1,
  input  wire ADA0,
  input  wire CEA, OCEA, CLKA, WEA, RSTA, CSA2, CSA1, CSA0,
  output wire DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6,
  output wire DOA5, DOA4, DOA3, DOA2, DOA1, DOA0,
  input  wire DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7, DIB6,
  input  wire DIB5, DIB4, DIB3, DIB2, DIB1, DIB0,
  input  wire ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2, ADB1,
  input  wire ADB0,
  input  wire CEB, OCEB, CLKB, WEB, RSTB, CSB2, CSB1, CSB0,
  output wire DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6,
  output wire DOB5, DOB4, DOB3, DOB2, DOB1, DOB0
);

  localparam PDP = (DATA_WIDTH_A == 36);

  wire [17:0] dia = {DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7,
                     DIA6, DIA5, DIA4, DIA3, DIA2, DIA1, DIA0};
  wire [17:0] dib = {DIB17, DIB16, DIB15, DIB14, DIB13, DIB12, DIB11, DIB10, DIB9, DIB8, DIB7,
                     DIB6, DIB5, DIB4, DIB3, DIB2, DIB1, DIB0};
  wire [13:0] ada = {ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2,
                     ADA1, ADA0};
  wire [13:0] adb = {ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2,
                     ADB1, ADB0};

  reg [17:0] mem [0:1023];
  reg [17:0] lat_a, lat_b, out_a, out_b;

  initial begin
    if (!((DATA_WIDTH_A == 18 && DATA_WIDTH_B == 18) ||
          (DATA_WIDTH_A == 36 && DATA_WIDTH_B == 36)) ||
        CSDECODE_A != "0b000" || CSDECODE_B != "0b000" ||
        WRITEMODE_A != "NORMAL" || WRITEMODE_B != "NORMAL" ||
        (REGMODE_A != "NOREG" && REGMODE_A != "OUTREG") ||
        (REGMODE_B != "NOREG" && REGMODE_B != "OUTREG") ||
        (PDP && REGMODE_A != REGMODE_B)) begin
      $display("DP16KD model %m: a configuration this model does not cover");
      $stop;
    end
  end

  wire cs_a = {CSA2, CSA1, CSA0} == 3'b000;
  wire cs_b = {CSB2, CSB1, CSB0} == 3'b000;
  // The two units of an x36 word, and the unit of an x18 word.
  wire [9:0] ua_lo = PDP ? {ada[13:5], 1'b0} : ada[13:4];
  wire [9:0] ub_lo = PDP ? {adb[13:5], 1'b0} : adb[13:4];

  // Port A writes in both modes.
  always @(posedge CLKA) begin
    if (CEA && cs_a && WEA) begin
      if (ada[0]) mem[ua_lo][8:0]  <= dia[8:0];
      if (ada[1]) mem[ua_lo][17:9] <= dia[17:9];
      if (PDP) begin
        if (ada[2]) mem[ua_lo | 10'd1][8:0]  <= dib[8:0];
        if (ada[3]) mem[ua_lo | 10'd1][17:9] <= dib[17:9];
      end
    end
  end

  always @(posedge CLKB) begin
    if (CEB && cs_b && WEB) begin
      $display("DP16KD model %m: a write on port B, which this model does not cover");
      $stop;
    end
  end

  generate
    if (PDP) begin : g_pdp
      // x36: port B reads both units of the word, the low one onto DOA.
      always @(posedge CLKB) begin
        if (CEB && cs_b) begin
          lat_a <= mem[ub_lo];
          lat_b <= mem[ub_lo | 10'd1];
        end
        if (OCEB) begin
          out_a <= lat_a;
          out_b <= lat_b;
        end
      end
    end else begin : g_x18
      // x18: each port reads when it does not write.
      always @(posedge CLKA) begin
        if (CEA && cs_a && !WEA) lat_a <= mem[ua_lo];
        if (OCEA) out_a <= lat_a;
      end
      always @(posedge CLKB) begin
        if (CEB && cs_b) lat_b <= mem[ub_lo];
        if (OCEB) out_b <= lat_b;
      end
    end
  endgenerate

  wire [17:0] doa = (REGMODE_A == "OUTREG") ? out_a : lat_a;
  wire [17:0] dob = (REGMODE_B == "OUTREG") ? out_b : lat_b;
  assign {DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6, DOA5,
          DOA4, DOA3, DOA2, DOA1, DOA0} = doa;
  assign {DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5,
          DOB4, DOB3, DOB2, DOB1, DOB0} = dob;

endmodule

`default_nettype wire
