// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of hexstep_wb (Wishbone B4 classic register block).
`default_nettype none

// The master follows B4 classic: once cyc & stb are up it holds them and we/adr/dat/sel
// unchanged until the cycle in which it sees ack (assumed). Everything else is free: the
// core's outputs (busy, done, err, phase, pos) and the e-stop pin, in every cycle, so the
// properties hold whatever the core does.
//
// Widths (docs/FORMAL.md): task prove NAXES = 1, SPEED_W = 16, ACC_W = 12, STEP_W = 6,
// DFRAC_W = 8, PULSE_W = 4, POS_W = 8, ADDR_W = 10; task prove_wide NAXES = 2 and the
// default widths. The watched read/write word is any word of any axis or IRQ_ENABLE.
module hexstep_wb_fv #(
  parameter integer NAXES   = 1,
  parameter integer SPEED_W = 16,
  parameter integer ACC_W   = 12,
  parameter integer STEP_W  = 6,
  parameter integer DFRAC_W = 8,
  parameter integer PULSE_W = 4,
  parameter integer POS_W   = 8,
  parameter integer ADDR_W  = 10
) (
  input wire                   clk_i,
  input wire                   rst_i,
  input wire                   wb_cyc_i,
  input wire                   wb_stb_i,
  input wire                   wb_we_i,
  input wire [ADDR_W-1:0]      wb_adr_i,
  input wire [31:0]            wb_dat_i,
  input wire [3:0]             wb_sel_i,
  input wire                   estop_i,
  input wire [NAXES-1:0]       busy_i,
  input wire [NAXES-1:0]       done_i,
  input wire [NAXES-1:0]       err_i,
  input wire [NAXES*2-1:0]     phase_i,
  input wire [NAXES*POS_W-1:0] pos_i
);
  // Register map (rdl/hexstep.rdl, docs/REGISTERS.md), word indexes.
  localparam integer G_ID = 0, G_START = 2, G_ABORT = 3, G_GSTATUS = 4, G_IRQ_EN = 5,
                     G_STOP = 7;
  localparam integer AX0 = 64;        // axis 0 at byte 0x100: word 64
  // Implemented bits of the DIR word: positive (bit 0) and jog (bit 1).
  localparam [31:0]  DIR_MASK = 32'h3;

  function [31:0] lo(input integer w);
    lo = (w >= 32) ? 32'hFFFF_FFFF : ((32'h1 << w) - 32'h1);
  endfunction
  function [31:0] hi(input integer w);
    hi = (w >= 64) ? 32'hFFFF_FFFF : (w <= 32) ? 32'h0 : ((32'h1 << (w - 32)) - 32'h1);
  endfunction
  // Implemented bits and reset value of read/write word w of axis 0 (offsets 0x00..0x68).
  function [31:0] ax_mask(input integer w);
    case (w)
      0, 14, 15:      ax_mask = lo(STEP_W);     // STEPS, ACC_STEPS, DEC_STEP
      1:              ax_mask = DIR_MASK;
      2, 4, 6, 8:     ax_mask = lo(SPEED_W);    // V_START/V_MAX/V_END/V_DEC low words
      3, 5, 7, 9:     ax_mask = hi(SPEED_W);
      10, 12:         ax_mask = lo(ACC_W);      // ACC, DEC
      11, 13:         ax_mask = hi(ACC_W);
      16:             ax_mask = lo(DFRAC_W);    // DEC_FRAC
      22, 23, 24, 25: ax_mask = lo(PULSE_W);    // STEP_HIGH, STEP_LOW, DIR_SETUP, DIR_HOLD
      26:             ax_mask = 32'h3;          // POLARITY
      default:        ax_mask = 32'h0;
    endcase
  endfunction

  // The masks as one constant table (evaluated at elaboration), indexed by the axis word.
  function [32*32-1:0] ax_masks(input integer dummy);
    integer j;
    begin
      ax_masks = {32*32{1'b0}};
      for (j = 0; j < 32; j = j + 1) ax_masks[j*32 +: 32] = ax_mask(j + dummy);
    end
  endfunction
  localparam [32*32-1:0] AX_MASKS = ax_masks(0);

  wire [31:0]            dat_o;
  wire                   ack, irq;
  wire [NAXES-1:0]       start_o, abort_o, stop_o;

  hexstep_wb #(
    .NAXES (NAXES), .SPEED_W (SPEED_W), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .ADDR_W (ADDR_W)
  ) u_dut (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (wb_cyc_i), .wb_stb_i (wb_stb_i), .wb_we_i (wb_we_i), .wb_adr_i (wb_adr_i),
    .wb_dat_i (wb_dat_i), .wb_sel_i (wb_sel_i), .wb_dat_o (dat_o), .wb_ack_o (ack),
    .estop_i (estop_i), .irq_o (irq),
    .start_o (start_o), .abort_o (abort_o), .stop_o (stop_o),
    .steps_o (), .dir_o (), .jog_o (), .v_start_o (), .v_max_o (), .v_end_o (), .v_dec_o (),
    .acc_o (), .dec_o (), .acc_steps_o (), .dec_step_o (), .dec_frac_o (),
    .step_high_o (), .step_low_o (), .dir_setup_o (), .dir_hold_o (), .step_inv_o (),
    .dir_inv_o (),
    .busy_i (busy_i), .done_i (done_i), .err_i (err_i), .phase_i (phase_i), .pos_i (pos_i)
  );

  // ---- reset in the first cycle only; a B4 classic master ----
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);

  wire cs = wb_cyc_i && wb_stb_i;
  reg  p_have = 1'b0, p_cs, p_ack, p_we;
  reg  [ADDR_W-1:0] p_adr;
  reg  [31:0] p_dat;
  reg  [3:0]  p_sel;
  always @(posedge clk_i) begin
    p_have <= !rst_i;
    p_cs <= cs;  p_ack <= ack;  p_we <= wb_we_i;  p_adr <= wb_adr_i;  p_dat <= wb_dat_i;
    p_sel <= wb_sel_i;
  end
  always @* if (p_have && p_cs && !p_ack)
    assume (cs && wb_we_i == p_we && wb_adr_i == p_adr && wb_dat_i == p_dat && wb_sel_i == p_sel);

  // A request the slave acts on at the coming edge: cyc & stb, not the ack cycle of the last one.
  wire        req   = cs && !ack;
  wire        wr    = req && wb_we_i;
  wire [31:0] bmask = {{8{wb_sel_i[3]}}, {8{wb_sel_i[2]}}, {8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};
  wire [ADDR_W-3:0] wadr = wb_adr_i[ADDR_W-1:2];

  // ---- B4 classic handshake ----
  always @* if (!rst_i && p_have) begin
    // No ack without cyc & stb.
    if (ack) assert (cs);
    // Every request is acked in the cycle after it is presented ...
    if (p_cs && !p_ack) assert (ack);
    // ... and only once: never two acks in a row, so the held request is not acked again.
    if (ack) assert (!p_ack);
  end
  always @* if (!rst_i && !p_have) assert (!ack);

  // ---- read-back under byte enables: one $anyconst read/write word ----
  (* anyconst *) reg [ADDR_W-3:0] f_w;  // word address of the watched register
  wire is_irqen = (f_w == G_IRQ_EN);
  wire is_axis  = (f_w >= AX0) && (f_w < AX0 + 32 * NAXES);
  wire [4:0] ax_w = f_w[4:0];                           // word within the axis block
  wire [ADDR_W-3:0] ax_k = (f_w - AX0) >> 5;            // axis number
  always @* assume (is_irqen || (is_axis && AX_MASKS[ax_w*32 +: 32] != 32'h0));

  wire [31:0] f_mask = is_irqen ? {8'd0, {(8-NAXES){1'b0}}, {NAXES{1'b1}},
                                   {(8-NAXES){1'b0}}, {NAXES{1'b1}},
                                   {(8-NAXES){1'b0}}, {NAXES{1'b1}}} : AX_MASKS[ax_w*32 +: 32];
  wire [31:0] f_reset = (is_axis && (ax_w == 5'd22 || ax_w == 5'd23)) ? 32'd1 : 32'd0;
  reg  [31:0] f_val;
  always @(posedge clk_i)
    if (rst_i) f_val <= f_reset;
    else if (wr && wadr == f_w) f_val <= ((f_val & ~bmask) | (wb_dat_i & bmask)) & f_mask;

  // The register itself, for the induction invariant (connected by the .sby script).
  (* keep *) wire [NAXES*17*32-1:0] f_stg;   // u_dut.stg_q
  (* keep *) wire [NAXES*5*32-1:0]  f_cfg;   // u_dut.cfg_q
  (* keep *) wire [31:0]            f_irqen; // u_dut.irq_en_q
  wire [31:0] f_int = is_irqen ? f_irqen : (ax_w < 17) ? f_stg[(ax_k*17 + ax_w)*32 +: 32]
                                                       : f_cfg[(ax_k*5 + ax_w - 22)*32 +: 32];

  always @* if (!rst_i && p_have) begin
    assert (f_int == f_val);
    if (ack && !wb_we_i && wadr == f_w) assert (dat_o == f_val);
    // The ID word reads its constant.
    if (ack && !wb_we_i && wadr == G_ID) assert (dat_o == 32'h4858_5354);
  end

  // ---- E-STOP: two-flop synchronizer into a latch, cleared by writing 1 to GSTATUS.estop ----
  reg f_es1, f_es2, f_latch;
  reg [2:0] f_pin;                      // estop_i of the last three cycles, newest in bit 0
  wire f_clr = wr && wadr == G_GSTATUS && wb_sel_i[0] && wb_dat_i[0];
  always @(posedge clk_i) begin
    if (rst_i) begin
      f_es1 <= 1'b0;  f_es2 <= 1'b0;  f_latch <= 1'b0;  f_pin <= 3'b000;
    end else begin
      f_es1 <= estop_i;  f_es2 <= f_es1;
      f_latch <= f_es2 || (f_latch && !f_clr);
      f_pin <= {f_pin[1:0], estop_i};
    end
  end

  // ---- command strobes written at the last edge ----
  reg [NAXES-1:0] f_start_w, f_abort_w, f_stop_w;
  wire [31:0] wd = wb_dat_i & bmask;
  always @(posedge clk_i) begin
    f_start_w <= (!rst_i && wr && wadr == G_START) ? wd[NAXES-1:0] : {NAXES{1'b0}};
    f_abort_w <= (!rst_i && wr && wadr == G_ABORT) ? wd[NAXES-1:0] : {NAXES{1'b0}};
    f_stop_w  <= (!rst_i && wr && wadr == G_STOP)  ? wd[NAXES-1:0] : {NAXES{1'b0}};
  end

  always @* if (!rst_i && p_have) begin
    // The core's abort is exactly the ABORT mask written at the last edge or the e-stop latch.
    assert (abort_o == (f_abort_w | {NAXES{f_latch}}));
    // The pin's first sampled-high edge E: the core's abort is high after edge E+2, so the
    // core aborts at edge E+3 (the fourth), and stays aborted while the latch holds.
    if (f_pin[2]) assert (abort_o == {NAXES{1'b1}});
    // GSTATUS reads {pin (synchronized), latch} as sampled at the request edge.
    if (ack && !wb_we_i && wadr == G_GSTATUS) assert (dat_o == {30'd0, f_es2_p, f_latch_p});
    // STOP is exactly the mask written at the last edge.
    assert (stop_o == f_stop_w);
    // A start only for START written at the last edge or a done pulse (chaining), never with
    // an abort, a stop or the e-stop latch.
    assert ((start_o & ~(f_start_w | done_i)) == {NAXES{1'b0}});
    assert ((start_o & (abort_o | stop_o)) == {NAXES{1'b0}});
    if (f_latch) assert (start_o == {NAXES{1'b0}});
    // Invariants for induction (asserted): the synchronizer and latch equal the shadows.
    assert (f_es1_i == f_es1 && f_es2_i == f_es2 && f_latch_i == f_latch);
  end
  reg f_es2_p, f_latch_p;
  always @(posedge clk_i) begin
    f_es2_p <= f_es2;  f_latch_p <= f_latch;
  end
  (* keep *) wire f_es1_i, f_es2_i, f_latch_i;   // u_dut.es1_q, es2_q, estop_q

`ifdef FV_COVER
  reg f_partial = 1'b0;                 // a write with 1..3 byte lanes to the watched word
  always @(posedge clk_i)
    if (!rst_i && wr && wadr == f_w && wb_sel_i != 4'h0 && wb_sel_i != 4'hF) f_partial <= 1'b1;
  always @* if (!rst_i && p_have) begin
    // A write under a partial byte enable, then its read-back.
    cover (ack && !wb_we_i && wadr == f_w && f_partial && f_val != f_reset && !is_irqen);
    // The e-stop latched, the pin released, and the latch cleared by software.
    cover (f_latch_p && !f_latch && !f_es2);
    // A STOP strobe.
    cover (stop_o != {NAXES{1'b0}});
  end
`endif
endmodule

`default_nettype wire
