// SPDX-License-Identifier: Apache-2.0
// hexstep formal: the SPI bridge (hexstep_spi_wb) as the Wishbone master of hexstep_wb.
`default_nettype none

// hexstep_wb_fv assumes a B4 classic master: cyc/stb/we/adr/dat/sel held from a request until
// its ack. Here that assumption is asserted in a parent context: the SPI bridge drives
// hexstep_wb (NAXES = 1, small widths) with the SPI pins, the e-stop pin, the engine's outputs
// and the memory read data free in every cycle, so the slave's acks come after any number of
// wait states the bus engine can produce (registers: 1 cycle; staging/configuration words:
// several; CMD.push: about 105; after reset: the initialization first).
module hexstep_spi_wb_fv #(
  parameter integer ADDR_W = 12
) (
  input wire        clk_i,
  input wire        rst_i,
  input wire        spi_sck_i,
  input wire        spi_cs_n_i,
  input wire        spi_mosi_i,
  input wire        estop_i,
  input wire [1:0]  act_i,
  input wire [1:0]  qn_i,
  input wire        busy_i,
  input wire        run_i,
  input wire [1:0]  phase_i,
  input wire        done_i,
  input wire        refused_i,
  input wire        freed_i,
  input wire        flush_i,
  input wire [7:0]  pos_i,
  input wire [31:0] bus_rdata_i
);
  wire              cyc, stb, we, ack, miso, miso_oe;
  wire [ADDR_W-1:0] adr;
  wire [31:0]       wdat, rdat;
  wire [3:0]        sel;

  reg [6:0] g;
  (* anyconst *) reg [6:0] f_g0;
  always @(posedge clk_i) g <= rst_i ? f_g0 : g + 7'd1;

  hexstep_spi_wb #(.ADDR_W (ADDR_W)) u_spi (
    .clk_i (clk_i), .rst_i (rst_i),
    .spi_sck_i (spi_sck_i), .spi_cs_n_i (spi_cs_n_i), .spi_mosi_i (spi_mosi_i),
    .spi_miso_o (miso), .spi_miso_oe_o (miso_oe),
    .wb_cyc_o (cyc), .wb_stb_o (stb), .wb_we_o (we), .wb_adr_o (adr), .wb_dat_o (wdat),
    .wb_sel_o (sel), .wb_dat_i (rdat), .wb_ack_i (ack)
  );

  hexstep_wb #(
    .NAXES (1), .ACC_W (12), .STEP_W (6), .DFRAC_W (8), .PULSE_W (4), .POS_W (8),
    .ADDR_W (ADDR_W)
  ) u_wb (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (cyc), .wb_stb_i (stb), .wb_we_i (we), .wb_adr_i (adr), .wb_dat_i (wdat),
    .wb_sel_i (sel), .wb_dat_o (rdat), .wb_ack_o (ack),
    .estop_i (estop_i), .irq_o (),
    .kph_i (4'b0001 << g[1:0]), .start_w_o (), .stop_w_o (), .abort_o (),
    .push_o (), .push_axis_o (), .push_flags_o (),
    .bus_re_o (), .bus_rbank_o (), .bus_raddr_o (), .bus_rdata_i (bus_rdata_i),
    .bus_we_o (), .bus_waddr_o (), .bus_wdata_o (), .bus_init_o (),
    .act_i (act_i), .qn_i (qn_i), .busy_i (busy_i), .run_i (run_i), .phase_i (phase_i),
    .done_i (done_i), .refused_i (refused_i), .freed_i (freed_i), .flush_i (flush_i),
    .step_high_o (), .step_low_o (), .dir_setup_o (), .dir_hold_o (), .step_inv_o (),
    .dir_inv_o (), .pos_i (pos_i)
  );

  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);

  wire cs = cyc && stb;
  reg  p_have = 1'b0, p_cs, p_ack, p_we;
  reg  [ADDR_W-1:0] p_adr;
  reg  [31:0] p_dat;
  reg  [3:0]  p_sel;
  always @(posedge clk_i) begin
    p_have <= !rst_i;
    p_cs <= cs;  p_ack <= ack;  p_we <= we;  p_adr <= adr;  p_dat <= wdat;  p_sel <= sel;
  end

  always @* if (!rst_i && p_have) begin
    // The B4 classic master rule that hexstep_wb_fv assumes.
    if (p_cs && !p_ack) assert (cs && we == p_we && adr == p_adr && wdat == p_dat && sel == p_sel);
    // stb only inside cyc; after its ack the bridge drops cyc for at least one cycle.
    if (stb) assert (cyc);
    if (p_cs && p_ack) assert (!cyc);
  end
endmodule

`default_nettype wire
