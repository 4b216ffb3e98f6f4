// SPDX-License-Identifier: Apache-2.0
// hexstep SoC: 8N1 UART with a receive FIFO (Wishbone B4 classic slave) for the host link.
`default_nettype none

// Registers (byte offsets):
//   0x0 DATA   write: send the byte in [7:0] (dropped unless STATUS.tx_ready);
//              read: [7:0] oldest received byte, [31] = 1 if the FIFO was empty (then nothing
//              is popped); a read with [31] = 0 pops that byte.
//   0x4 STATUS [0] rx byte available, [1] tx_ready, [2] rx overrun (sticky), [3] rx framing
//              error (sticky); write 1 to [2]/[3] to clear them.
//   0x8 DIV    clock cycles per bit, 4..65535 (reset: DIV_RESET).
// Receive: two-flop synchroniser, start bit confirmed at half a bit, data sampled mid-bit;
// a missing stop bit drops the byte and sets the framing flag; a byte arriving to a full FIFO
// is dropped and sets the overrun flag. The ack waits one cycle after any FIFO change so the
// registered FIFO read port is never stale.
module hexstep_soc_uart #(
  parameter integer DIV_RESET = 868,  // cycles per bit at reset (100 MHz / 115200 baud = 868)
  parameter integer FIFO_AW   = 7     // receive FIFO of 2^FIFO_AW bytes (128: a whole frame)
) (
  input  wire        clk_i,
  input  wire        rst_i,           // synchronous, active high
  input  wire        wb_cyc_i,
  input  wire        wb_stb_i,
  input  wire        wb_we_i,
  input  wire [3:2]  wb_adr_i,
  input  wire [31:0] wb_dat_i,
  output reg  [31:0] wb_dat_o,
  output reg         wb_ack_o,
  input  wire        rx_i,
  output reg         tx_o
);
  // ---- bus ----
  reg  [15:0] div_q;
  wire        req = wb_cyc_i & wb_stb_i & ~wb_ack_o;
  reg         stale_q;
  wire        go = req & ~stale_q;
  wire        wr = go & wb_we_i;
  wire        rd = go & ~wb_we_i;

  // ---- receive FIFO ----
  reg  [7:0]         fifo [0:(1<<FIFO_AW)-1];
  reg  [FIFO_AW:0]   wp_q, rp_q;
  reg  [7:0]         head_q;
  wire               empty = (wp_q == rp_q);
  wire               full  = (wp_q[FIFO_AW] != rp_q[FIFO_AW]) &&
                             (wp_q[FIFO_AW-1:0] == rp_q[FIFO_AW-1:0]);
  wire               pop   = rd & (wb_adr_i == 2'd0) & ~empty;
  wire               rx_done;            // a byte with a valid stop bit
  wire [7:0]         rx_byte;
  wire               push  = rx_done & ~full;
  reg                ovr_q, ferr_q;
  wire               rx_ferr;

  always @(posedge clk_i) begin
    if (push) fifo[wp_q[FIFO_AW-1:0]] <= rx_byte;
    head_q <= fifo[rp_q[FIFO_AW-1:0]];
  end

  // ---- transmit ----
  reg  [9:0]  tx_sh_q;
  reg  [3:0]  tx_bits_q;
  reg  [15:0] tx_cnt_q;
  wire        tx_ready = (tx_bits_q == 4'd0);
  wire        tx_load = wr & (wb_adr_i == 2'd0) & tx_ready;

  always @(posedge clk_i) begin
    if (rst_i) begin
      tx_bits_q <= 4'd0;
      tx_cnt_q  <= 16'd0;
      tx_sh_q   <= 10'h3FF;
      tx_o      <= 1'b1;
    end else if (tx_load) begin
      tx_sh_q   <= {1'b1, wb_dat_i[7:0], 1'b0};
      tx_bits_q <= 4'd10;
      tx_cnt_q  <= 16'd0;
    end else if (tx_bits_q != 4'd0) begin
      tx_o <= tx_sh_q[0];
      if (tx_cnt_q == div_q - 16'd1) begin
        tx_cnt_q  <= 16'd0;
        tx_sh_q   <= {1'b1, tx_sh_q[9:1]};
        tx_bits_q <= tx_bits_q - 4'd1;
      end else begin
        tx_cnt_q <= tx_cnt_q + 16'd1;
      end
    end else begin
      tx_o <= 1'b1;
    end
  end

  // ---- receive ----
  reg  [1:0]  rx_sync_q;
  reg  [3:0]  rx_bits_q;    // 0 idle; 10..1 start, 8 data, stop
  reg  [15:0] rx_cnt_q;
  reg  [8:0]  rx_sh_q;
  wire        rx = rx_sync_q[1];
  wire        rx_sample = (rx_bits_q != 4'd0) && (rx_cnt_q == 16'd0);
  assign rx_done = rx_sample && (rx_bits_q == 4'd1) && rx;
  assign rx_ferr = rx_sample && (rx_bits_q == 4'd1) && !rx;
  assign rx_byte = rx_sh_q[8:1];

  always @(posedge clk_i) begin
    if (rst_i) begin
      rx_sync_q <= 2'b11;
      rx_bits_q <= 4'd0;
      rx_cnt_q  <= 16'd0;
      rx_sh_q   <= 9'd0;
    end else begin
      rx_sync_q <= {rx_sync_q[0], rx_i};
      if (rx_bits_q == 4'd0) begin
        if (!rx) begin                    // start edge: sample again at half a bit
          rx_bits_q <= 4'd10;
          rx_cnt_q  <= {1'b0, div_q[15:1]};
        end
      end else if (rx_cnt_q != 16'd0) begin
        rx_cnt_q <= rx_cnt_q - 16'd1;
      end else begin
        rx_cnt_q <= div_q - 16'd1;
        if (rx_bits_q == 4'd10 && rx) rx_bits_q <= 4'd0;   // glitch, not a start bit
        else begin
          rx_sh_q   <= {rx, rx_sh_q[8:1]};
          rx_bits_q <= rx_bits_q - 4'd1;
        end
      end
    end
  end

  // ---- registers, pointers, flags ----
  always @(posedge clk_i) begin
    if (rst_i) begin
      wp_q     <= {(FIFO_AW+1){1'b0}};
      rp_q     <= {(FIFO_AW+1){1'b0}};
      ovr_q    <= 1'b0;
      ferr_q   <= 1'b0;
      div_q    <= DIV_RESET[15:0];
      wb_ack_o <= 1'b0;
      stale_q  <= 1'b0;
      wb_dat_o <= 32'd0;
    end else begin
      if (push) wp_q <= wp_q + 1'b1;
      if (pop)  rp_q <= rp_q + 1'b1;
      stale_q <= push | pop;
      if (rx_done & full) ovr_q <= 1'b1;
      else if (wr && wb_adr_i == 2'd1 && wb_dat_i[2]) ovr_q <= 1'b0;
      if (rx_ferr) ferr_q <= 1'b1;
      else if (wr && wb_adr_i == 2'd1 && wb_dat_i[3]) ferr_q <= 1'b0;
      if (wr && wb_adr_i == 2'd2 && wb_dat_i[15:0] >= 16'd4) div_q <= wb_dat_i[15:0];
      wb_ack_o <= go;
      case (wb_adr_i)
        2'd0:    wb_dat_o <= {empty, 23'd0, head_q};
        2'd1:    wb_dat_o <= {28'd0, ferr_q, ovr_q, tx_ready, ~empty};
        2'd2:    wb_dat_o <= {16'd0, div_q};
        default: wb_dat_o <= 32'd0;
      endcase
    end
  end

endmodule

`default_nettype wire
