// SPDX-License-Identifier: Apache-2.0
// hexstep test bench: a behavioural model of the part of Lattice's ECP5 DP16KD block RAM that
// rtl/hexstep_ram.v (STYLE "ECP5") uses, for simulation only. Yosys's cells_sim_ecp5.v declares
// DP16KD without behaviour, so without this model the ECP5 memory wiring is never simulated.
//
// Written from the port description of Lattice TN1264 (ECP5 and ECP5-5G Memory Usage Guide) and
// the mapping Yosys itself uses (techlibs/lattice/brams_map_16kd.v):
//   - x18 (DATA_WIDTH 18: the 16 Kbit array as 1024 words of 18 bits): word address AD[13:4];
//     on a write port AD[1:0] are the byte enables, AD[0] for bits 8..0 and AD[1] for bits
//     17..9; AD[3:2] are not used;
//   - a port reads at the rising clock edge with CE high; REGMODE "OUTREG" adds the output
//     register, loaded at the next edge with OCE high; "NOREG" shows the read word directly;
//   - a write needs CE, WE, every byte enable of the bytes it writes, and the chip select.
// Anything else (other widths, among them the x36 pseudo-dual-port mode, chip-select decodes,
// write modes, a write on port B) stops the simulation: the model covers what the project
// instantiates, not the whole primitive.
`default_nettype none

// Lint: the module is named after the primitive, not the file; its string parameters are
// compared with literals of other lengths; not every pin is used (port B's data in, for one).
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

  wire [17:0] dia = {DIA17, DIA16, DIA15, DIA14, DIA13, DIA12, DIA11, DIA10, DIA9, DIA8, DIA7,
                     DIA6, DIA5, DIA4, DIA3, DIA2, DIA1, DIA0};
  wire [13:0] ada = {ADA13, ADA12, ADA11, ADA10, ADA9, ADA8, ADA7, ADA6, ADA5, ADA4, ADA3, ADA2,
                     ADA1, ADA0};
  wire [13:0] adb = {ADB13, ADB12, ADB11, ADB10, ADB9, ADB8, ADB7, ADB6, ADB5, ADB4, ADB3, ADB2,
                     ADB1, ADB0};

  reg [17:0] mem [0:1023];
  reg [17:0] lat_a, lat_b, out_a, out_b;

  initial begin
    if (DATA_WIDTH_A != 18 || DATA_WIDTH_B != 18 ||
        CSDECODE_A != "0b000" || CSDECODE_B != "0b000" ||
        WRITEMODE_A != "NORMAL" || WRITEMODE_B != "NORMAL" ||
        (REGMODE_A != "NOREG" && REGMODE_A != "OUTREG") ||
        (REGMODE_B != "NOREG" && REGMODE_B != "OUTREG")) begin
      $display("DP16KD model %m: a configuration this model does not cover");
      $stop;
    end
  end

  wire cs_a = {CSA2, CSA1, CSA0} == 3'b000;
  wire cs_b = {CSB2, CSB1, CSB0} == 3'b000;
  wire [9:0] wa = ada[13:4];  // port A's word
  wire [9:0] rb = adb[13:4];  // port B's word

  // Port A writes its byte lanes, or reads when it does not write.
  always @(posedge CLKA) begin
    if (CEA && cs_a) begin
      if (WEA) begin
        if (ada[0]) mem[wa][8:0]  <= dia[8:0];
        if (ada[1]) mem[wa][17:9] <= dia[17:9];
      end else begin
        lat_a <= mem[wa];
      end
    end
    if (OCEA) out_a <= lat_a;
  end

  // Port B reads.
  always @(posedge CLKB) begin
    if (CEB && cs_b) begin
      if (WEB) begin
        $display("DP16KD model %m: a write on port B, which this model does not cover");
        $stop;
      end
      lat_b <= mem[rb];
    end
    if (OCEB) out_b <= lat_b;
  end

  wire [17:0] doa = (REGMODE_A == "OUTREG") ? out_a : lat_a;
  wire [17:0] dob = (REGMODE_B == "OUTREG") ? out_b : lat_b;
  assign {DOA17, DOA16, DOA15, DOA14, DOA13, DOA12, DOA11, DOA10, DOA9, DOA8, DOA7, DOA6, DOA5,
          DOA4, DOA3, DOA2, DOA1, DOA0} = doa;
  assign {DOB17, DOB16, DOB15, DOB14, DOB13, DOB12, DOB11, DOB10, DOB9, DOB8, DOB7, DOB6, DOB5,
          DOB4, DOB3, DOB2, DOB1, DOB0} = dob;

endmodule

`default_nettype wire
