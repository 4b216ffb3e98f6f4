// SPDX-License-Identifier: Apache-2.0
// hexstep: Wishbone B4 classic slave turning bus cycles into hexstep_core's plain ports.
`default_nettype none

// The register map is rdl/hexstep.rdl (docs/REGISTERS.md); this decode is hand-written and
// tests/rtl/test_wb.cpp checks it against the constants generated from that file.
//
// Bus: classic single cycles, 32-bit data, byte addresses (adr[1:0] ignored), sel gates each
// byte lane of a write (also for command and write-1-to-clear bits). A request is
// cyc & stb & !ack_q: it is acted on at the next rising edge, and ack_o is high for exactly the
// cycle after that edge (a registered ack: no path from bus inputs to ack_o). A master that
// holds cyc/stb until ack (B4 classic) therefore never sees ack without cyc & stb, and a
// request held through the ack cycle is not counted twice. There is no err_o and no stall_o.
// Unmapped addresses read 0 and are acked; read-only and reserved bits ignore writes.
//
// Moves: per axis, the staging words are pushed (CMD.push) into a 2-deep queue whose head
// drives the core's move inputs (the core latches them only on an accepted start). START
// (registered: the core sees it on the edge after the write's edge) starts the heads of the
// selected idle axes together and makes them "running"; a running axis starts its next queued
// move on the edge right after the core's done pulse, with no gap, and stops running when a
// move ends with an empty queue. ABORT and the latched e-stop abort the core, flush the queue
// and clear running. STOP (registered like START) sends the core's controlled-stop strobe,
// flushes the queue and clears running on the same edge; the axis then decelerates to rest
// (busy until it does) and a later START acts only once it is idle. A jog move (DIR.jog) runs
// until STOP.
//
// Reset: synchronous, active high, like hexstep_core. The queue slots are not reset (the core
// samples them only on a start, which needs a pushed entry).
module hexstep_wb #(
  // NAXES: number of axes. Range 1..8 (the IRQ registers give each event kind one byte);
  // default 6. The register map (rdl/hexstep.rdl) documents the default build.
  parameter integer NAXES   = 6,
  // Widths of the core's move and pulse ports, as hexstep_core (same defaults). The map holds
  // SPEED_W and ACC_W up to 64 bits, STEP_W, DFRAC_W and PULSE_W up to 32, POS_W up to 64.
  parameter integer SPEED_W = 64,
  parameter integer ACC_W   = 44,
  parameter integer STEP_W  = 32,
  parameter integer DFRAC_W = 32,
  parameter integer PULSE_W = 12,
  parameter integer POS_W   = 32,
  // ADDR_W: byte address bits. Range 10..32; default 12 (the map uses 0x000..0x3FF).
  parameter integer ADDR_W  = 12
) (
  input  wire                     clk_i,
  input  wire                     rst_i,        // synchronous, active high
  // Wishbone B4 classic slave
  input  wire                     wb_cyc_i,
  input  wire                     wb_stb_i,
  input  wire                     wb_we_i,
  input  wire [ADDR_W-1:0]        wb_adr_i,
  input  wire [31:0]              wb_dat_i,
  input  wire [3:0]               wb_sel_i,
  output wire [31:0]              wb_dat_o,
  output wire                     wb_ack_o,
  // E-stop pin (asynchronous, active high) and interrupt (level, active high)
  input  wire                     estop_i,
  output wire                     irq_o,
  // hexstep_core ports
  output wire [NAXES-1:0]         start_o,
  output wire [NAXES-1:0]         abort_o,
  output wire [NAXES-1:0]         stop_o,
  output wire [NAXES*STEP_W-1:0]  steps_o,
  output wire [NAXES-1:0]         dir_o,
  output wire [NAXES-1:0]         jog_o,
  output wire [NAXES*SPEED_W-1:0] v_start_o,
  output wire [NAXES*SPEED_W-1:0] v_max_o,
  output wire [NAXES*SPEED_W-1:0] v_end_o,
  output wire [NAXES*SPEED_W-1:0] v_dec_o,
  output wire [NAXES*ACC_W-1:0]   acc_o,
  output wire [NAXES*ACC_W-1:0]   dec_o,
  output wire [NAXES*STEP_W-1:0]  acc_steps_o,
  output wire [NAXES*STEP_W-1:0]  dec_step_o,
  output wire [NAXES*DFRAC_W-1:0] dec_frac_o,
  output wire [NAXES*PULSE_W-1:0] step_high_o,
  output wire [NAXES*PULSE_W-1:0] step_low_o,
  output wire [NAXES*PULSE_W-1:0] dir_setup_o,
  output wire [NAXES*PULSE_W-1:0] dir_hold_o,
  output wire [NAXES-1:0]         step_inv_o,
  output wire [NAXES-1:0]         dir_inv_o,
  input  wire [NAXES-1:0]         busy_i,
  input  wire [NAXES-1:0]         done_i,
  input  wire [NAXES-1:0]         err_i,
  input  wire [NAXES*2-1:0]       phase_i,
  input  wire [NAXES*POS_W-1:0]   pos_i
);

  // Word indexes (byte offset / 4) of rdl/hexstep.rdl. Global block at 0x000, axis k at
  // 0x100 + k * 0x80, that is 128-byte block number k + 2.
  localparam integer G_ID = 0, G_VERSION = 1, G_START = 2, G_ABORT = 3, G_GSTATUS = 4,
                     G_IRQ_EN = 5, G_IRQ_PEND = 6, G_STOP = 7;
  localparam integer W_STEPS = 0, W_DIR = 1, W_V_START = 2, W_V_MAX = 4, W_V_END = 6,
                     W_V_DEC = 8, W_ACC = 10, W_DEC = 12, W_ACC_STEPS = 14, W_DEC_STEP = 15,
                     W_DEC_FRAC = 16, W_CMD = 17, W_STATUS = 18, W_ERR = 19, W_POS_LO = 20,
                     W_POS_HI = 21, W_CFG = 22;
  localparam integer NW = 17;           // staging words per axis (STEPS..DEC_FRAC)
  localparam integer NC = 5;            // config words per axis (STEP_HIGH..POLARITY)
  localparam integer MW = NW * 32;      // bits of one queued move
  localparam [31:0]  ID_VALUE  = 32'h4858_5354;  // "HXST"
  localparam [7:0]   VER_MAJOR = 8'd0;
  localparam [7:0]   VER_MINOR = 8'd2;
  localparam [NAXES-1:0] ALL = {NAXES{1'b1}};
  // Reset of one axis's config words: STEP_HIGH = STEP_LOW = 1, the others 0.
  localparam [NC*32-1:0] CFG_RESET = {32'd0, 32'd0, 32'd0, 32'd1, 32'd1};

  function [31:0] lo_mask(input integer w);
    lo_mask = (w >= 32) ? 32'hFFFF_FFFF : ((32'h1 << w) - 32'h1);
  endfunction
  function [31:0] hi_mask(input integer w);
    hi_mask = (w >= 64) ? 32'hFFFF_FFFF : (w <= 32) ? 32'h0 : ((32'h1 << (w - 32)) - 32'h1);
  endfunction
  // Implemented bits of staging word i: the rest are reserved (read 0, writes ignored).
  function [31:0] stg_mask(input integer i);
    case (i)
      W_STEPS, W_ACC_STEPS, W_DEC_STEP:             stg_mask = lo_mask(STEP_W);
      W_DIR:                                        stg_mask = 32'h3;
      W_V_START, W_V_MAX, W_V_END, W_V_DEC:         stg_mask = lo_mask(SPEED_W);
      W_V_START+1, W_V_MAX+1, W_V_END+1, W_V_DEC+1: stg_mask = hi_mask(SPEED_W);
      W_ACC, W_DEC:                                 stg_mask = lo_mask(ACC_W);
      W_ACC+1, W_DEC+1:                             stg_mask = hi_mask(ACC_W);
      W_DEC_FRAC:                                   stg_mask = lo_mask(DFRAC_W);
      default:                                      stg_mask = 32'h0;
    endcase
  endfunction
  function [31:0] cfg_mask(input integer i);
    cfg_mask = (i == NC - 1) ? 32'h3 : lo_mask(PULSE_W);
  endfunction

  // ---- state ----
  reg              ack_q, ack_d;
  reg  [31:0]      dat_q, dat_d;
  reg              irq_q, irq_d;
  reg              es1_q, es2_q;              // e-stop pin synchronizer
  reg              estop_q, estop_d;          // latched e-stop
  reg  [NAXES-1:0] start_cmd_q, start_cmd_d;  // START written at the last edge
  reg  [NAXES-1:0] abort_cmd_q, abort_cmd_d;  // ABORT written at the last edge
  reg  [NAXES-1:0] stop_cmd_q, stop_cmd_d;    // STOP written at the last edge
  reg  [NAXES-1:0] run_q, run_d;
  reg  [NAXES*2-1:0]  cnt_q, cnt_d;           // queue entries, 0..2
  reg  [NAXES*3-1:0]  errf_q, errf_d;         // {estop, overrun, move} per axis
  reg  [NAXES*32-1:0] poshi_q, poshi_d;       // POS_HI latched by a POS_LO read
  reg  [31:0]      irq_en_q, irq_en_d;
  reg  [31:0]      pend_q, pend_d;
  reg  [NAXES*MW-1:0]    stg_q, stg_d;        // staging words
  // The 2-deep queue is a ring of two slots per axis: an entry stays in the slot it was pushed
  // into, and the head pointer selects the slot that drives the core. (A shifting queue needs a
  // 3-way multiplexer in front of every bit of the head; the ring only writes slots from the
  // staging words and reads the head through one 2-way multiplexer.)
  reg  [NAXES*MW-1:0]    s0_q, s0_d;          // slot 0
  reg  [NAXES*MW-1:0]    s1_q, s1_d;          // slot 1
  reg  [NAXES-1:0]       hp_q, hp_d;          // head slot: the entry the core starts next
  reg  [NAXES*NC*32-1:0] cfg_q, cfg_d;        // pulse timing and polarity

  // ---- bus request decode ----
  wire        req   = wb_cyc_i & wb_stb_i & ~ack_q;
  wire        wr    = req & wb_we_i;
  wire        rd    = req & ~wb_we_i;
  wire [31:0] bmask = {{8{wb_sel_i[3]}}, {8{wb_sel_i[2]}}, {8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};
  wire [31:0] wdat  = wb_dat_i & bmask;       // the written ones of command/W1C bits
  // 128-byte block number and word index, widened to 32 bits to compare with integers.
  wire [31:0] blk   = {{(32-(ADDR_W-7)){1'b0}}, wb_adr_i[ADDR_W-1:7]};
  wire [31:0] widx  = {27'd0, wb_adr_i[6:2]};
  wire        g_hit = (blk == 0);
  wire        unused_adr = &{1'b0, wb_adr_i[1:0]};

  // IRQ fields: done [7:0], slot [15:8], err [23:16], NAXES bits of each.
  wire [31:0] irq_mask = {8'd0, {(8-NAXES){1'b0}}, ALL, {(8-NAXES){1'b0}}, ALL,
                          {(8-NAXES){1'b0}}, ALL};

  // Sign-extended positions, 64 bits per axis.
  wire [NAXES*64-1:0] pos64;
  genvar g;
  generate
    for (g = 0; g < NAXES; g = g + 1) begin : g_pos
      if (POS_W >= 64) begin : g_full
        assign pos64[g*64 +: 64] = pos_i[g*POS_W +: 64];
      end else begin : g_ext
        assign pos64[g*64 +: 64] = {{(64-POS_W){pos_i[g*POS_W+POS_W-1]}}, pos_i[g*POS_W +: POS_W]};
      end
    end
  endgenerate

  // Core control: a start pops the queue head on the edge the core latches it.
  wire [NAXES-1:0] abort_w = abort_cmd_q | {NAXES{estop_q}};
  // A start: START for an idle axis that is not running (an axis still stopping after STOP is
  // busy but no longer running: START waits for it), or the chained next move of a running
  // axis on its done pulse. STOP and abort suppress both. A start the core refuses anyway
  // shows as AXIS_ERR.move.
  wire [NAXES-1:0] go;
  generate
    for (g = 0; g < NAXES; g = g + 1) begin : g_go
      assign go[g] = ~abort_w[g] & ~stop_cmd_q[g] & (cnt_q[g*2 +: 2] != 2'd0) &
                     ((start_cmd_q[g] & ~run_q[g] & ~busy_i[g]) | (run_q[g] & done_i[g]));
    end
  endgenerate

  // ---- read data ----
  // Every word of a block is placed in a flat vector and selected by the word index, then the
  // block by its number: parallel multiplexers of depth log2, not a priority chain (the read
  // path was the longest combinational path of the design; docs/SYNTH.md).
  // Global block: words 0..7 (START, ABORT and STOP read 0), the rest of the block reads 0.
  wire [8*32-1:0] gwords;
  assign gwords[G_ID*32 +: 32]       = ID_VALUE;
  assign gwords[G_VERSION*32 +: 32]  = {8'd0, NAXES[7:0], VER_MAJOR, VER_MINOR};
  assign gwords[G_START*32 +: 32]    = 32'h0;
  assign gwords[G_ABORT*32 +: 32]    = 32'h0;
  assign gwords[G_GSTATUS*32 +: 32]  = {30'd0, es2_q, estop_q};
  assign gwords[G_IRQ_EN*32 +: 32]   = irq_en_q;
  assign gwords[G_IRQ_PEND*32 +: 32] = pend_q;
  assign gwords[G_STOP*32 +: 32]     = 32'h0;
  wire [31:0] grd = (wb_adr_i[6:5] == 2'b00) ? gwords[{wb_adr_i[4:2], 5'd0} +: 32] : 32'h0;
  // Axis blocks: staging words 0..NW-1, CMD (reads 0), STATUS, ERR, POS_LO, POS_HI, config
  // words, then zeros up to word 31 (each word assigned once at its index: a gap or an overlap
  // is a lint error). Axis k's value is ard[k*32 +: 32]; slots NAXES..7 read 0.
  wire [8*32-1:0] ard;
  generate
    for (g = 0; g < 8; g = g + 1) begin : g_rd
      if (g < NAXES) begin : g_axis
        wire [32*32-1:0] words;
        assign words[0 +: MW]               = stg_q[g*MW +: MW];
        assign words[W_CMD*32 +: 32]        = 32'h0;
        assign words[W_STATUS*32 +: 32]     = {26'd0, 2'd2 - cnt_q[g*2 +: 2], run_q[g],
                                               phase_i[g*2 +: 2], busy_i[g]};
        assign words[W_ERR*32 +: 32]        = {29'd0, errf_q[g*3 +: 3]};
        assign words[W_POS_LO*32 +: 32]     = pos64[g*64 +: 32];
        assign words[W_POS_HI*32 +: 32]     = poshi_q[g*32 +: 32];
        assign words[W_CFG*32 +: NC*32]     = cfg_q[g*NC*32 +: NC*32];
        assign words[32*32-1:(W_CFG+NC)*32] = {((32-W_CFG-NC)*32){1'b0}};
        assign ard[g*32 +: 32] = words[{wb_adr_i[6:2], 5'd0} +: 32];
      end else begin : g_none
        assign ard[g*32 +: 32] = 32'h0;
      end
    end
  endgenerate
  wire [31:0] axn   = blk - 32'd2;            // axis number of an axis block
  wire        a_hit = (blk >= 32'd2) && (axn < NAXES);
  wire [31:0] rdata = g_hit ? grd : a_hit ? ard[{axn[2:0], 5'd0} +: 32] : 32'h0;

  integer k, i;
  reg        hit, push, overrun, ok_push, estop_rise;
  reg [1:0]  cnt;
  reg [2:0]  eset;
  reg [31:0] w;

  always @(*) begin
    stg_d = stg_q;  cfg_d = cfg_q;  s0_d = s0_q;  s1_d = s1_q;
    hp_d = hp_q;
    cnt_d = cnt_q;  run_d = run_q;  errf_d = errf_q;  poshi_d = poshi_q;
    irq_en_d = irq_en_q;  pend_d = pend_q;
    start_cmd_d = {NAXES{1'b0}};
    abort_cmd_d = {NAXES{1'b0}};
    stop_cmd_d = {NAXES{1'b0}};
    i = 0;

    // ---- global registers ----
    estop_rise = es2_q & ~estop_q;
    estop_d    = es2_q | (estop_q & ~(wr & g_hit & (widx == G_GSTATUS) & wdat[0]));
    if (g_hit) begin
      if (wr) begin
        if (widx == G_START)    start_cmd_d = wdat[NAXES-1:0];
        if (widx == G_ABORT)    abort_cmd_d = wdat[NAXES-1:0];
        if (widx == G_STOP)     stop_cmd_d = wdat[NAXES-1:0];
        if (widx == G_IRQ_EN)   irq_en_d = ((irq_en_q & ~bmask) | wdat) & irq_mask;
        if (widx == G_IRQ_PEND) pend_d = pend_q & ~wdat;
      end
    end

    // ---- per axis ----
    for (k = 0; k < NAXES; k = k + 1) begin
      hit = (blk == k + 2);
      cnt = cnt_q[k*2 +: 2];
      push = 1'b0;
      // bus access
      if (hit) begin
        for (i = 0; i < NW; i = i + 1)
          if (wr && widx == i) stg_d[(k*NW+i)*32 +: 32] =
            ((stg_q[(k*NW+i)*32 +: 32] & ~bmask) | wdat) & stg_mask(i);
        for (i = 0; i < NC; i = i + 1)
          if (wr && widx == W_CFG + i) cfg_d[(k*NC+i)*32 +: 32] =
            ((cfg_q[(k*NC+i)*32 +: 32] & ~bmask) | wdat) & cfg_mask(i);
        if (rd && widx == W_POS_LO) poshi_d[k*32 +: 32] = pos64[k*64+32 +: 32];
        if (wr && widx == W_CMD) push = wdat[0];
        if (wr && widx == W_ERR) errf_d[k*3 +: 3] = errf_q[k*3 +: 3] & ~wdat[2:0];
      end

      overrun = push & ~abort_w[k] & ~stop_cmd_q[k] & (cnt == 2'd2) & ~go[k];
      ok_push = push & ~abort_w[k] & ~stop_cmd_q[k] & ~overrun;
      if (abort_w[k] | stop_cmd_q[k]) begin
        cnt_d[k*2 +: 2] = 2'd0;           // flush; a push in this cycle is dropped too
        run_d[k] = 1'b0;
      end else begin
        if (go[k]) run_d[k] = 1'b1;
        else if (run_q[k] & done_i[k]) run_d[k] = 1'b0;
        // A start pops the head (the other slot becomes the head); a push writes the first
        // free slot behind the head as it was before this edge (with a pop on the same edge
        // and a full queue, that is the slot being popped).
        if (go[k]) begin
          hp_d[k] = ~hp_q[k];
          if (!ok_push) cnt_d[k*2 +: 2] = cnt - 2'd1;
        end else if (ok_push) begin
          cnt_d[k*2 +: 2] = cnt + 2'd1;
        end
        if (ok_push) begin
          if (hp_q[k] ^ cnt[0]) s1_d[k*MW +: MW] = stg_q[k*MW +: MW];
          else                  s0_d[k*MW +: MW] = stg_q[k*MW +: MW];
        end
      end

      // sticky errors and interrupts
      eset = {estop_rise, overrun, err_i[k]};
      errf_d[k*3 +: 3] = errf_d[k*3 +: 3] | eset;
      pend_d[k]      = pend_d[k] | done_i[k];
      pend_d[8 + k]  = pend_d[8 + k] | (cnt_d[k*2 +: 2] < cnt);
      pend_d[16 + k] = pend_d[16 + k] | (|eset);
    end

    ack_d = req;
    dat_d = rd ? rdata : 32'h0;
    w     = pend_d & irq_en_d;
    irq_d = |w;
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      ack_q <= 1'b0;  dat_q <= 32'h0;  irq_q <= 1'b0;
      es1_q <= 1'b0;  es2_q <= 1'b0;  estop_q <= 1'b0;
      start_cmd_q <= {NAXES{1'b0}};  abort_cmd_q <= {NAXES{1'b0}};
      stop_cmd_q <= {NAXES{1'b0}};
      run_q <= {NAXES{1'b0}};  cnt_q <= {NAXES*2{1'b0}};  errf_q <= {NAXES*3{1'b0}};
      hp_q <= {NAXES{1'b0}};
      poshi_q <= {NAXES*32{1'b0}};  irq_en_q <= 32'h0;  pend_q <= 32'h0;
      stg_q <= {NAXES*MW{1'b0}};  cfg_q <= {NAXES{CFG_RESET}};
    end else begin
      ack_q <= ack_d;  dat_q <= dat_d;  irq_q <= irq_d;
      es1_q <= estop_i;  es2_q <= es1_q;  estop_q <= estop_d;
      start_cmd_q <= start_cmd_d;  abort_cmd_q <= abort_cmd_d;
      stop_cmd_q <= stop_cmd_d;
      run_q <= run_d;  cnt_q <= cnt_d;  errf_q <= errf_d;  hp_q <= hp_d;
      poshi_q <= poshi_d;  irq_en_q <= irq_en_d;  pend_q <= pend_d;
      stg_q <= stg_d;  cfg_q <= cfg_d;
    end
    s0_q <= s0_d;
    s1_q <= s1_d;
  end

  assign wb_ack_o = ack_q;
  assign wb_dat_o = dat_q;
  assign irq_o    = irq_q;
  assign start_o  = go;
  assign abort_o  = abort_w;
  assign stop_o   = stop_cmd_q;

  // Core move inputs: the queue head, fields at their word positions (64-bit values span two
  // consecutive words, low word first).
  wire [NAXES*MW-1:0] head;                   // the head entry of every axis
  generate
    for (g = 0; g < NAXES; g = g + 1) begin : g_head
      assign head[g*MW +: MW] = hp_q[g] ? s1_q[g*MW +: MW] : s0_q[g*MW +: MW];
    end
  endgenerate
  generate
    for (g = 0; g < NAXES; g = g + 1) begin : g_ports
      assign steps_o[g*STEP_W +: STEP_W]       = head[g*MW + W_STEPS*32 +: STEP_W];
      assign dir_o[g]                          = head[g*MW + W_DIR*32];
      assign jog_o[g]                          = head[g*MW + W_DIR*32 + 1];
      assign v_start_o[g*SPEED_W +: SPEED_W]   = head[g*MW + W_V_START*32 +: SPEED_W];
      assign v_max_o[g*SPEED_W +: SPEED_W]     = head[g*MW + W_V_MAX*32 +: SPEED_W];
      assign v_end_o[g*SPEED_W +: SPEED_W]     = head[g*MW + W_V_END*32 +: SPEED_W];
      assign v_dec_o[g*SPEED_W +: SPEED_W]     = head[g*MW + W_V_DEC*32 +: SPEED_W];
      assign acc_o[g*ACC_W +: ACC_W]           = head[g*MW + W_ACC*32 +: ACC_W];
      assign dec_o[g*ACC_W +: ACC_W]           = head[g*MW + W_DEC*32 +: ACC_W];
      assign acc_steps_o[g*STEP_W +: STEP_W]   = head[g*MW + W_ACC_STEPS*32 +: STEP_W];
      assign dec_step_o[g*STEP_W +: STEP_W]    = head[g*MW + W_DEC_STEP*32 +: STEP_W];
      assign dec_frac_o[g*DFRAC_W +: DFRAC_W]  = head[g*MW + W_DEC_FRAC*32 +: DFRAC_W];
      assign step_high_o[g*PULSE_W +: PULSE_W] = cfg_q[(g*NC+0)*32 +: PULSE_W];
      assign step_low_o[g*PULSE_W +: PULSE_W]  = cfg_q[(g*NC+1)*32 +: PULSE_W];
      assign dir_setup_o[g*PULSE_W +: PULSE_W] = cfg_q[(g*NC+2)*32 +: PULSE_W];
      assign dir_hold_o[g*PULSE_W +: PULSE_W]  = cfg_q[(g*NC+3)*32 +: PULSE_W];
      assign step_inv_o[g]                     = cfg_q[(g*NC+4)*32];
      assign dir_inv_o[g]                      = cfg_q[(g*NC+4)*32 + 1];
    end
  endgenerate

endmodule

`default_nettype wire
