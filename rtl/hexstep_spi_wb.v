// SPDX-License-Identifier: Apache-2.0
// hexstep: SPI slave (mode 0) bridging an external host to a Wishbone B4 classic master port.
`default_nettype none

// Everything runs on the core clock clk_i: SCK, CS_N and MOSI are oversampled through
// SYNC_STAGES-flop synchronizers and their edges detected in the clk_i domain. So the SPI clock
// must be slow against clk_i: each SCK half period and the CS_N setup (CS_N fall to first SCK
// rise) and hold (last SCK fall to CS_N rise) must last at least SYNC_STAGES + 2 clk_i cycles
// (4 with the default 2 stages: SCK <= f_clk / 8, 6 MHz at a 48 MHz core clock).
//
// Frames (MSB first, mode 0: MOSI/MISO change on the falling SCK edge, sampled on the rising one;
// CS_N low for exactly one frame). CRC-8: polynomial x^8+x^2+x+1 (0x07), initial value 0, no
// reflection, no final XOR (CRC-8/SMBUS), over the bytes listed.
//
//   write (8 bytes):  MOSI  CMD=0xA0|sel  ADR[15:8] ADR[7:0] D[31:24] D[23:16] D[15:8] D[7:0] CRC
//                     MISO  STATUS        0x00 ...
//                     CRC over CMD..D[7:0]. The Wishbone write is issued after CS_N rises, and
//                     only if the frame had exactly 64 bits, a valid CMD and address and the CRC
//                     matched: a truncated, overlong or corrupted write never reaches the bus.
//   read (10 bytes):  MOSI  CMD=0x50  ADR[15:8] ADR[7:0] CRC  (6 more bytes, ignored)
//                     MISO  STATUS    0x00      0x00     0x00 RSTAT D[31:24] D[23:16] D[15:8] D[7:0] RCRC
//                     CRC over CMD, ADR[15:8], ADR[7:0]. The Wishbone read is issued once the
//                     32nd bit is in and valid; RSTAT tells the host whether it was (0xA1) or
//                     the request was rejected (0xA2, data bytes then read 0). RCRC is the CRC over
//                     CMD, ADR[15:8], ADR[7:0], D[31:24]..D[7:0] as sent, so the host can check
//                     that the data belong to its request. A read frame cut short after its 32nd
//                     bit has issued its read (the only read side effect of hexstep_top's map:
//                     POS_LO latches POS_HI).
//   STATUS = 0xA0 | {rejected, accepted} of the previous frame (0xA0 after reset): the host
//            learns whether its last write was executed, or its last read answered in time.
//            Any frame that is not exactly a valid write or read (CS_N toggled without clocks
//            included) counts as rejected.
//   sel = Wishbone byte enables of the write; ADR = Wishbone byte address, must be < 2^ADDR_W
//   (adr[1:0] are passed on; the slave ignores them). Other CMD values are rejected.
//
// Bus: a Wishbone B4 classic master for a slave with any number of wait states. One request at
// a time; cyc, stb, we, adr, dat and sel are held from the request until the cycle in which ack
// is sampled, then cyc and stb fall for at least one cycle. A frame whose request comes while
// the previous request still waits for its ack is rejected without a bus cycle (a write: STATUS
// of the next frame says rejected; a read: RSTAT 0xA2). The read data must be acked before the
// falling SCK edge that starts D[31:24], 17 SCK half periods after the rising edge of bit 32
// (at least 68 clk_i cycles at the fastest SCK). A read acked later is late: its data bytes are
// not valid, RCRC is sent inverted (it never matches), and the next STATUS says rejected; the
// host repeats the read. With hexstep_top (a register read acks in 2 cycles, a staging or
// configuration read in at most 9) no read is late; its slowest access, CMD.push (about 106
// cycles), and the initialization after reset (32 * NAXES cycles) end before the next frame can
// issue a request (at least 260 cycles at the fastest SCK). Reset: synchronous, active high;
// every register is reset.
module hexstep_spi_wb #(
  // ADDR_W: Wishbone byte address bits. Range 1..16; default 12 as hexstep_top.
  parameter integer ADDR_W      = 12,
  // SYNC_STAGES: flip-flops in each SPI input synchronizer. Range 2..4; default 2.
  parameter integer SYNC_STAGES = 2
) (
  input  wire              clk_i,
  input  wire              rst_i,        // synchronous, active high
  // SPI slave pins (asynchronous to clk_i)
  input  wire              spi_sck_i,
  input  wire              spi_cs_n_i,
  input  wire              spi_mosi_i,
  output wire              spi_miso_o,
  output wire              spi_miso_oe_o,  // high while CS_N is low (for a shared MISO line)
  // Wishbone B4 classic master
  output wire              wb_cyc_o,
  output wire              wb_stb_o,
  output wire              wb_we_o,
  output wire [ADDR_W-1:0] wb_adr_o,
  output wire [31:0]       wb_dat_o,
  output wire [3:0]        wb_sel_o,
  input  wire [31:0]       wb_dat_i,
  input  wire              wb_ack_i
);

  localparam [3:0] OP_WRITE = 4'hA;
  localparam [7:0] CMD_READ = 8'h50;
  localparam [7:0] CRC_POLY = 8'h07;
  localparam [6:0] CNT_MAX  = 7'd127;   // bit counter saturates: longer frames are invalid

  // --- synchronizers: {sck, cs_n, mosi}, the last stage kept for edge detection ---------------
  reg  [SYNC_STAGES:0] sck_q, csn_q, mosi_q;
  wire sck  = sck_q[SYNC_STAGES-1];
  wire csn  = csn_q[SYNC_STAGES-1];
  wire mosi = mosi_q[SYNC_STAGES-1];
  wire sck_rise = sck & ~sck_q[SYNC_STAGES];
  wire sck_fall = ~sck & sck_q[SYNC_STAGES];
  wire cs_fall  = ~csn & csn_q[SYNC_STAGES];
  wire cs_rise  = csn & ~csn_q[SYNC_STAGES];
  wire active   = ~csn;

  // --- frame state -----------------------------------------------------------------------------
  reg  [6:0]  cnt_q, cnt_d;           // bits received in this frame
  reg  [63:0] rx_q, rx_d;             // received bits, newest in bit 0
  reg  [7:0]  crc_q, crc_d;           // CRC of the bits received so far
  reg  [7:0]  tcrc_q, tcrc_d;         // CRC of a read reply (request bytes, then data sent)
  reg  [7:0]  tx_q, tx_d;             // MISO shift register
  reg  [1:0]  stat_q, stat_d;         // {rejected, accepted} of the previous frame
  reg         rd_ok_q, rd_ok_d;       // this frame's read request was issued
  reg         rd_done_q, rd_done_d;   // ... and acked (rdat holds its data)
  reg         rd_late_q, rd_late_d;   // ... and its first data byte went out before the ack
  reg  [31:0] rdat_q, rdat_d;         // read data
  // --- bus ---------------------------------------------------------------------------------------
  reg         cyc_q, cyc_d, we_q, we_d;
  reg  [ADDR_W-1:0] adr_q, adr_d;
  reg  [31:0] wdat_q, wdat_d;
  reg  [3:0]  sel_q, sel_d;

  // Frame fields by position. rx_sh is rx after taking in the bit sampled now.
  wire [63:0] rx_sh  = {rx_q[62:0], mosi};
  wire [7:0]  w_cmd  = rx_q[63:56];   // a complete 64-bit frame: CMD ADR ADR D D D D CRC
  wire [15:0] w_adr  = rx_q[55:40];
  wire [31:0] w_dat  = rx_q[39:8];
  wire [7:0]  r_cmd  = rx_sh[31:24];  // a read request as its 32nd bit arrives: CMD ADR ADR CRC
  wire [15:0] r_adr  = rx_sh[23:8];

  function adr_ok(input [15:0] a);
    adr_ok = (ADDR_W >= 16) || ((a >> ADDR_W) == 16'd0);
  endfunction

  function [7:0] crc_bit(input [7:0] c, input b);
    crc_bit = {c[6:0], 1'b0} ^ ((c[7] ^ b) ? CRC_POLY : 8'h00);
  endfunction

  reg [7:0] crc_n;
  reg       w_valid, r_valid;
  reg [3:0] byte_n;                   // index of the byte the next MISO bit belongs to

  always @* begin
    cnt_d = cnt_q;  rx_d = rx_q;  crc_d = crc_q;  tcrc_d = tcrc_q;  tx_d = tx_q;
    stat_d = stat_q;  rd_ok_d = rd_ok_q;  rd_done_d = rd_done_q;  rd_late_d = rd_late_q;  rdat_d = rdat_q;
    cyc_d = cyc_q;  we_d = we_q;  adr_d = adr_q;  wdat_d = wdat_q;  sel_d = sel_q;

    crc_n   = crc_bit(crc_q, mosi);
    // A write is complete with exactly 64 bits whose CRC (over all 8 bytes) leaves 0.
    w_valid = (cnt_q == 7'd64) && (crc_q == 8'h00) && (w_cmd[7:4] == OP_WRITE) && adr_ok(w_adr);
    // A read request is complete when its 32nd bit arrives (CRC over 4 bytes leaves 0).
    r_valid = (cnt_q == 7'd31) && (crc_n == 8'h00) && (r_cmd == CMD_READ) && adr_ok(r_adr);
    byte_n  = cnt_q[6:3];

    // Bus master: one request, held until its ack; a new one only once cyc has been low (the
    // request registers change only then).
    if (cyc_q && wb_ack_i) begin
      cyc_d = 1'b0;
      if (!we_q && rd_ok_q) begin
        rdat_d = wb_dat_i;
        rd_done_d = 1'b1;
      end
    end

    if (cs_fall) begin
      cnt_d     = 7'd0;
      crc_d     = 8'h00;
      rd_ok_d   = 1'b0;
      rd_done_d = 1'b0;
      rd_late_d = 1'b0;
      rdat_d    = 32'h0;
      tx_d      = {4'hA, 2'b00, stat_q};
    end else if (cs_rise) begin
      // End of frame: execute a valid write (if the bus is free), record the outcome for the
      // next STATUS byte.
      if (w_valid && !cyc_q) begin
        cyc_d = 1'b1;  we_d = 1'b1;  adr_d = w_adr[ADDR_W-1:0];
        wdat_d = w_dat;  sel_d = w_cmd[3:0];
        stat_d = 2'b01;
      end else if (!w_valid && rd_ok_q && !rd_late_q && cnt_q == 7'd80) begin
        stat_d = 2'b01;
      end else begin
        stat_d = 2'b10;
      end
    end else if (active && sck_rise) begin
      if (cnt_q != CNT_MAX) cnt_d = cnt_q + 7'd1;
      rx_d  = rx_sh;
      crc_d = crc_n;
      if (r_valid && !cyc_q) begin
        cyc_d = 1'b1;  we_d = 1'b0;  adr_d = r_adr[ADDR_W-1:0];  sel_d = 4'hF;
        rd_ok_d = 1'b1;
      end
      // Reply CRC: the request bytes (the receive CRC after 24 bits), then each data bit sent.
      if (cnt_q == 7'd23) tcrc_d = crc_n;
      if (cnt_q >= 7'd40 && cnt_q < 7'd72) tcrc_d = crc_bit(tcrc_q, tx_q[7]);
    end else if (active && sck_fall) begin
      // Next MISO bit: a new byte on a byte boundary, else shift.
      if (cnt_q[2:0] == 3'd0) begin
        case (byte_n)
          // RSTAT of a read frame (rx holds CMD ADR ADR CRC now); 0x00 in any other frame.
          4'd4:    tx_d = rd_ok_q ? 8'hA1 : (rx_q[31:24] == CMD_READ) ? 8'hA2 : 8'h00;
          4'd5: begin
            tx_d = rdat_q[31:24];
            if (rd_ok_q && !rd_done_q) rd_late_d = 1'b1;
          end
          4'd6:    tx_d = rdat_q[23:16];
          4'd7:    tx_d = rdat_q[15:8];
          4'd8:    tx_d = rdat_q[7:0];
          // A late read's data are not its data: RCRC inverted, so that it never matches.
          4'd9:    tx_d = !rd_ok_q ? 8'h00 : rd_late_q ? ~tcrc_q : tcrc_q;
          default: tx_d = 8'h00;
        endcase
      end else begin
        tx_d = {tx_q[6:0], 1'b0};
      end
    end
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      sck_q <= {(SYNC_STAGES+1){1'b0}};  csn_q <= {(SYNC_STAGES+1){1'b1}};
      mosi_q <= {(SYNC_STAGES+1){1'b0}};
      cnt_q <= 7'd0;  rx_q <= 64'd0;  crc_q <= 8'h00;  tcrc_q <= 8'h00;  tx_q <= 8'h00;
      stat_q <= 2'b00;  rd_ok_q <= 1'b0;  rd_done_q <= 1'b0;  rd_late_q <= 1'b0;  rdat_q <= 32'h0;
      cyc_q <= 1'b0;  we_q <= 1'b0;  adr_q <= {ADDR_W{1'b0}};  wdat_q <= 32'h0;  sel_q <= 4'h0;
    end else begin
      sck_q  <= {sck_q[SYNC_STAGES-1:0], spi_sck_i};
      csn_q  <= {csn_q[SYNC_STAGES-1:0], spi_cs_n_i};
      mosi_q <= {mosi_q[SYNC_STAGES-1:0], spi_mosi_i};
      cnt_q <= cnt_d;  rx_q <= rx_d;  crc_q <= crc_d;  tcrc_q <= tcrc_d;  tx_q <= tx_d;
      stat_q <= stat_d;  rd_ok_q <= rd_ok_d;  rd_done_q <= rd_done_d;  rd_late_q <= rd_late_d;  rdat_q <= rdat_d;
      cyc_q <= cyc_d;  we_q <= we_d;  adr_q <= adr_d;  wdat_q <= wdat_d;  sel_q <= sel_d;
    end
  end

  assign spi_miso_o    = tx_q[7];
  assign spi_miso_oe_o = ~csn;
  assign wb_cyc_o = cyc_q;
  assign wb_stb_o = cyc_q;
  assign wb_we_o  = we_q;
  assign wb_adr_o = adr_q;
  assign wb_dat_o = wdat_q;
  assign wb_sel_o = sel_q;

endmodule

`default_nettype wire
