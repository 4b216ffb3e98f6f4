// SPDX-License-Identifier: Apache-2.0
// hexstep: co-simulation top for tests/spi: hexstep_spi_wb driving hexstep_top, with the
// Wishbone bus between them brought out so that the test can feed TopModel the same bus pins,
// compare the read data, and check that malformed frames never start a bus cycle.
`default_nettype none

module spi_tb_top (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        spi_sck_i,
  input  wire        spi_cs_n_i,
  input  wire        spi_mosi_i,
  output wire        spi_miso_o,
  output wire        spi_miso_oe_o,
  input  wire        estop_i,
  output wire        irq_o,
  output wire [5:0]  step_o,
  output wire [5:0]  dir_o,
  output wire        mon_cyc_o,
  output wire        mon_we_o,
  output wire [11:0] mon_adr_o,
  output wire [31:0] mon_dat_o,
  output wire [3:0]  mon_sel_o,
  output wire        mon_ack_o,
  output wire [31:0] mon_rdat_o
);

  wire        cyc, stb, we, ack;
  wire [11:0] adr;
  wire [31:0] wdat, rdat;
  wire [3:0]  sel;

  hexstep_spi_wb #(.ADDR_W (12)) u_spi (
    .clk_i (clk_i), .rst_i (rst_i),
    .spi_sck_i (spi_sck_i), .spi_cs_n_i (spi_cs_n_i), .spi_mosi_i (spi_mosi_i),
    .spi_miso_o (spi_miso_o), .spi_miso_oe_o (spi_miso_oe_o),
    .wb_cyc_o (cyc), .wb_stb_o (stb), .wb_we_o (we), .wb_adr_o (adr), .wb_dat_o (wdat),
    .wb_sel_o (sel), .wb_dat_i (rdat), .wb_ack_i (ack)
  );

  hexstep_top u_top (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (cyc), .wb_stb_i (stb), .wb_we_i (we), .wb_adr_i (adr), .wb_dat_i (wdat),
    .wb_sel_i (sel), .wb_dat_o (rdat), .wb_ack_o (ack),
    .estop_i (estop_i), .irq_o (irq_o), .step_o (step_o), .dir_o (dir_o)
  );

  assign mon_cyc_o  = cyc & stb;
  assign mon_we_o   = we;
  assign mon_adr_o  = adr;
  assign mon_dat_o  = wdat;
  assign mon_sel_o  = sel;
  assign mon_ack_o  = ack;
  assign mon_rdat_o = rdat;

endmodule

`default_nettype wire
