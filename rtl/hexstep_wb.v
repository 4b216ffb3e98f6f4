// SPDX-License-Identifier: Apache-2.0
// hexstep: Wishbone B4 classic slave: registers, the memory-backed staging registers and the
// move loader of the frame engine.
`default_nettype none

// The register map is rdl/hexstep.rdl (docs/REGISTERS.md); this decode is hand-written and the
// tests drive the bus through the constants generated from that file. Counterpart:
// hexstep::TopModel (cpp_model/src/top_model.cpp).
//
// Bus: classic single cycles, 32-bit data, byte addresses (adr[1:0] ignored), sel gates each byte
// lane of a write (also for command and write-1-to-clear bits). A request is cyc & stb & !ack_q
// while the bus engine is idle; it is taken (decoded into registers) at the edge ending its first
// cycle and acted on at the next, the request's edge. Registers in flip-flops are acted on at the
// request's edge and acked in the next cycle. The staging words (STEPS..DEC_FRAC) and the pulse
// configuration mirror live in the engine's block RAM, reachable on the bus cycles of the frame
// (every fourth cycle, g[1:0] == 3): a staging read acks two cycles after the first bus cycle
// following the request, a staging write (read, merge byte lanes and implemented bits, write) at
// the second bus cycle; a configuration write is a read-modify-write of its mirror word like a
// staging write, and the live register takes the merged value on the edge of the mirror write,
// which acks; a configuration read answers from the mirror like a staging read. CMD.push runs the
// loader: 25 bus cycles reading the staging words and writing the queue slot (inverted
// deceleration, aligned deceleration fraction, resolved floor, zero words), checking the refusal
// rules on the way; it acks at the commit. ack_o is a register; there is no err_o and no stall_o.
// wb_dat_o is 0 except with the ack of a read. Unmapped addresses read 0 and are acked.
//
// After reset the bus engine first initializes the memory (staging words 0, the mirror to the
// reset configuration) on 8 * NAXES bus cycles; requests wait.
module hexstep_wb #(
  // NAXES: number of axes. Range 1..8; default 6. The register map documents the default build.
  parameter integer NAXES   = 6,
  // Register widths, as hexstep_top (same defaults).
  parameter integer ACC_W   = 48,
  parameter integer STEP_W  = 32,
  parameter integer DFRAC_W = 32,
  parameter integer PULSE_W = 12,
  parameter integer POS_W   = 32,
  // ADDR_W: byte address bits. Range 12..32; default 12 (the map uses 0x000..0x4FF).
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
  // Engine
  input  wire [3:0]               kph_i,        // cycle of the frame's slot (g[1:0]), one-hot
  output wire [NAXES-1:0]         start_w_o,
  output wire [NAXES-1:0]         stop_w_o,
  output wire [NAXES-1:0]         abort_o,
  output wire                     push_o,
  output wire [2:0]               push_axis_o,
  output wire [6:0]               push_flags_o,
  output wire                     bus_re_o,
  output wire [1:0]               bus_rbank_o,
  output wire [7:0]               bus_raddr_o,
  input  wire [31:0]              bus_rdata_i,
  output wire [3:0]               bus_we_o,
  output wire [7:0]               bus_waddr_o,
  output wire [31:0]              bus_wdata_o,
  output wire                     bus_init_o,
  input  wire [NAXES*2-1:0]       act_i,
  input  wire [NAXES*2-1:0]       qn_i,
  input  wire [NAXES-1:0]         busy_i,
  input  wire [NAXES-1:0]         run_i,
  input  wire [NAXES*2-1:0]       phase_i,
  input  wire [NAXES-1:0]         done_i,
  input  wire [NAXES-1:0]         refused_i,
  input  wire [NAXES-1:0]         freed_i,
  input  wire [NAXES-1:0]         flush_i,
  // Output stages: live configuration, positions
  output wire [NAXES*PULSE_W-1:0] step_high_o,
  output wire [NAXES*PULSE_W-1:0] step_low_o,
  output wire [NAXES*PULSE_W-1:0] dir_setup_o,
  output wire [NAXES*PULSE_W-1:0] dir_hold_o,
  output wire [NAXES*4-1:0]       cfg_over_o,   // per axis: each of the four above at most 1
  output wire [NAXES-1:0]         step_inv_o,
  output wire [NAXES-1:0]         dir_inv_o,
  input  wire [NAXES*POS_W-1:0]   pos_i
);

  // Word indexes (byte offset / 4) of rdl/hexstep.rdl. Global block at 0x000, axis k at
  // 0x100 + k * 0x80, that is 128-byte block number k + 2.
  localparam [4:0] G_ID = 5'd0, G_VERSION = 5'd1, G_START = 5'd2, G_ABORT = 5'd3,
                   G_GSTATUS = 5'd4, G_IRQ_EN = 5'd5, G_IRQ_PEND = 5'd6, G_STOP = 5'd7,
                   G_INFO0 = 5'd8, G_INFO1 = 5'd9;
  localparam [4:0] W_STEPS = 5'd0, W_DIR = 5'd1, W_V_START = 5'd2, W_V_MAX = 5'd4,
                   W_V_END = 5'd6, W_V_DEC = 5'd8, W_ACC = 5'd10, W_DEC = 5'd12,
                   W_ACC_STEPS = 5'd14, W_DEC_STEP = 5'd15, W_DEC_FRAC = 5'd16, W_CMD = 5'd17,
                   W_STATUS = 5'd18, W_ERR = 5'd19, W_POS_LO = 5'd20, W_POS_HI = 5'd21,
                   W_CFG = 5'd22;
  localparam [4:0] NW = 5'd17;          // staging words per axis (STEPS..DEC_FRAC)
  localparam integer NC = 5;            // config words per axis (STEP_HIGH..POLARITY)
  localparam [31:0]  ID_VALUE  = 32'h4858_5354;  // "HXST"
  localparam [7:0]   VER_MAJOR = 8'd1;
  localparam [7:0]   VER_MINOR = 8'd0;
  localparam [NAXES-1:0] ALL = {NAXES{1'b1}};
  localparam [NC*32-1:0] CFG_RESET = {32'd0, 32'd0, 32'd0, 32'd1, 32'd1};
  localparam [5:0] LOADER_STEPS = 6'd25;
`include "hexstep_defs.vh"
  // Bus engine operations.
  localparam [2:0] OP_IDLE = 3'd0, OP_INIT = 3'd1, OP_SRD = 3'd2, OP_SWR = 3'd3, OP_CRD = 3'd4,
                   OP_CWR = 3'd5, OP_PUSH = 3'd6;

  function [31:0] lo_mask(input integer w);
    lo_mask = (w >= 32) ? 32'hFFFF_FFFF : ((32'h1 << w) - 32'h1);
  endfunction
  function [31:0] hi_mask(input integer w);
    hi_mask = (w >= 64) ? 32'hFFFF_FFFF : (w <= 32) ? 32'h0 : ((32'h1 << (w - 32)) - 32'h1);
  endfunction
  // Implemented bits of staging word i: the rest are reserved (read 0, writes ignored).
  function [31:0] stg_mask(input [4:0] i);
    case (i)
      5'd0, 5'd14, 5'd15:                      stg_mask = lo_mask(STEP_W);   // STEPS, ACC_STEPS, DEC_STEP
      5'd1:                                    stg_mask = 32'h3;             // DIR
      5'd2, 5'd3, 5'd4, 5'd5, 5'd6, 5'd7, 5'd8, 5'd9: stg_mask = 32'hFFFF_FFFF;  // speeds
      5'd10, 5'd12:                            stg_mask = lo_mask(ACC_W);    // ACC, DEC low
      5'd11, 5'd13:                            stg_mask = hi_mask(ACC_W);    // ACC, DEC high
      5'd16:                                   stg_mask = lo_mask(DFRAC_W);  // DEC_FRAC
      default:                                 stg_mask = 32'h0;
    endcase
  endfunction
  function [31:0] cfg_mask(input [2:0] i);
    cfg_mask = (i == 3'd4) ? 32'h3 : lo_mask(PULSE_W);
  endfunction
  // Bank and word of staging word i (rtl/hexstep_engine.v, memory map).
  function [1:0] stg_bank(input [4:0] i);
    stg_bank = (i < 5'd5) ? 2'd0 : (i < 5'd10) ? 2'd1 : 2'd2;
  endfunction
  function [4:0] stg_word(input [4:0] i);
    stg_word = (i < 5'd5) ? i + 5'd3 : (i < 5'd10) ? i - 5'd2 : i - 5'd9;
  endfunction

  // ---- state ----
  reg              ack_q, ack_d;
  reg  [31:0]      dat_q, dat_d;
  reg              rdk_q;                     // the ack (if ack_q) is of a read: dat_q is its data
  reg              irq_q, irq_d;
  reg              es1_q, es2_q;              // e-stop pin synchronizer
  reg              estop_q, estop_d;          // latched e-stop
  reg  [NAXES-1:0] abort_cmd_d;               // ABORT written at this edge
  reg  [NAXES*3-1:0]  errf_q, errf_d;         // {estop, overrun, move} per axis
  // POS_HI: the bits above 31 latched by a POS_LO read (POS_W <= 32: the sign only).
  localparam integer PHW = (POS_W > 32) ? POS_W - 32 : 1;
  reg  [NAXES*PHW-1:0] poshi_q, poshi_d;
  reg  [31:0]      irq_en_q, irq_en_d;
  reg  [31:0]      pend_q, pend_d;
  reg  [NAXES*NC*32-1:0] cfg_q, cfg_d;        // pulse timing and polarity (live)
  reg  [NAXES*4-1:0]     cov_q;               // ... each timing word at most 1 (cfg_over_o)
  // Bus engine.
  reg  [2:0]       op_q, op_d;
  reg  [2:0]       oax_q, oax_d;              // axis of the operation
  reg  [4:0]       owd_q, owd_d;              // staging word / config word / init word
  reg  [31:0]      odat_q, odat_d;            // write data, merged word, loader data
  reg  [3:0]       osel_q, osel_d;            // byte enables of a memory write
  reg              oiss_q, oiss_d;            // the operation's read has been issued
  reg  [5:0]       ocnt_q, ocnt_d;            // init counter / loader step
  reg  [1:0]       otail_q, otail_d;          // loader: the slot being filled
  reg              ocan_q, ocan_d;            // loader: cancelled by a flush
  // Loader flags and holding register.
  reg  [31:0]      lh_q, lh_d;
  reg  [31:0]      rdqn_q;                    // the loader's read data, registered inverted
  reg              lc_q, lc_d;                // carry into a compare (1, or a low word's carry)
  localparam integer LZ_W = 14;              // the zero flags' width (bits below)
  localparam [LZ_W-1:0] LZ_ONE = 1;
  reg  [LZ_W-1:0]  lz_q, lz_d;                // zero flags
  reg  [5:0]       lg_q, lg_d;                // greater-than flags
  reg              ljog_q, ljog_d, ldir_q, ldir_d;
  // lz bits: 0 st, 1 as, 2 ds, 3 df, 4 vm_lo, 5 vm_hi, 6 vs_lo, 7 vs_hi, 8 ve_lo, 9 ve_hi,
  //          10 dec_lo, 11 dec_hi, 12 acc_lo, 13 acc_hi
  // lg bits: 0 as > st, 1 ds > st, 2 vs > vm, 3 ve > vm, 4 vd > vm, 5 dec > vm

  // ---- bus request decode ----
  wire        idle  = (op_q == OP_IDLE);
  wire [31:0] bmask = {{8{wb_sel_i[3]}}, {8{wb_sel_i[2]}}, {8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};
  wire [31:0] wdat  = wb_dat_i & bmask;
  // Block number (128-byte blocks): 0 global, 2..NAXES+1 the axes; higher address bits (a map
  // wider than ADDR_W = 12) select nothing. Decoded in a few bits, not in 32-bit arithmetic.
  wire [ADDR_W-8:0] blk = wb_adr_i[ADDR_W-1:7];
  wire        blk_lo = (blk[ADDR_W-8:4] == {(ADDR_W-11){1'b0}});   // block number < 16
  wire [4:0]  widx  = wb_adr_i[6:2];
  wire        g_hit = blk_lo && (blk[3:0] == 4'd0);
  // Decodes as lookups in constant masks (one LUT each, no comparator): blocks 2..NAXES+1;
  // staging words 0..NW-1; configuration words W_CFG..W_CFG+NC-1.
  localparam [15:0] AXIS_BLKS = ((16'd1 << NAXES) - 16'd1) << 2;
  localparam [31:0] STG_WORDS = (32'd1 << NW) - 32'd1;
  localparam [31:0] CFG_WORDS = ((32'd1 << NC) - 32'd1) << W_CFG;
  wire        a_hit = blk_lo && AXIS_BLKS[blk[3:0]];
  wire        w_stg = STG_WORDS[widx];
  wire        w_cfg = CFG_WORDS[widx];
  wire [2:0]  ak    = blk[2:0] - 3'd2;     // the axis (block number - 2, modulo 8)
  wire        unused_adr = &{1'b0, wb_adr_i[1:0]};
  // The request, decoded a cycle ahead: a request seen in cycle c (cyc & stb & !ack_q while
  // the bus engine is idle, not taken yet) is taken at the edge ending c (cap_q), which
  // registers the decodes of its address and direction; it is acted on at the edge ending c + 1
  // (req) and acked in c + 2. A B4 classic master holds the request (address, data, byte
  // enables) until its ack, so the registered decodes are those of the request still on the
  // bus, whose data and byte enables are read directly (asserted in hexstep_wb_fv:
  // fv_rq_ok). Every decision of the request therefore starts at flip-flops.
  reg              cap_q;                     // the request on the bus was taken: act on it
  // The decodes of the request on the bus (rq_d) and their register (rq_q, loaded on every
  // cycle), one vector, named by the slices below.
  localparam integer RQ_W = 21 + NAXES;
  reg  [RQ_W-1:0]  rq_d, rq_q;
  integer          rqk;
  always @* begin
    rq_d[0] = wb_we_i;                                  // a write
    rq_d[1] = a_hit && w_stg;                           // a staging word of an axis
    rq_d[2] = a_hit && w_cfg;                           // a configuration word of an axis
    for (rqk = 0; rqk < 8; rqk = rqk + 1)               // a write of global word i (0..7)
      rq_d[3 + rqk] = wb_we_i && g_hit && ({27'd0, widx} == rqk);
    // A write of CMD with its push bit (byte 0 enabled); ERR, POS_LO, STATUS, POS_HI of an
    // axis. (The held request's direction and data are as registered: the writes' decisions
    // take these flags, not the bus.)
    rq_d[11] = wb_we_i && a_hit && (widx == W_CMD) && wb_dat_i[0] && wb_sel_i[0];
    rq_d[12] = a_hit && (widx == W_ERR);
    rq_d[13] = a_hit && (widx == W_POS_LO);
    rq_d[14] = a_hit && (widx == W_STATUS);
    rq_d[15] = a_hit && (widx == W_POS_HI);
    rq_d[16] = g_hit && !widx[4];                       // global word 0..15 (read data: gwords)
    rq_d[20:17] = widx[3:0];                            // ... its number
    for (rqk = 0; rqk < NAXES; rqk = rqk + 1)           // the axis (one-hot)
      rq_d[21 + rqk] = a_hit && ({29'd0, ak} == rqk);
  end
  wire             rq_we_q = rq_q[0];
  wire             rq_stg_q = rq_q[1], rq_cfg_q = rq_q[2];
  wire [7:0]       rq_gw_q = rq_q[10:3];
  wire             rq_cmd_q = rq_q[11], rq_err_q = rq_q[12], rq_plo_q = rq_q[13];
  wire             rq_ast_q = rq_q[14], rq_phi_q = rq_q[15];
  wire             rq_gr_q = rq_q[16];
  wire [3:0]       rq_gidx_q = rq_q[20:17];
  wire [NAXES-1:0] rq_hit_q = rq_q[RQ_W-1:21];
  wire        take  = wb_cyc_i & wb_stb_i & ~ack_q & idle & ~cap_q;
  wire        req   = cap_q & wb_cyc_i & wb_stb_i;
  wire        wr    = req & rq_we_q;
  wire        rd    = req & ~rq_we_q;
  always @(posedge clk_i) begin
    cap_q <= !rst_i && take;
    rq_q <= rq_d;
  end
`ifdef FORMAL
  // The registered decodes against those of the request on the bus (asserted while cap_q).
  (* keep *) wire fv_rq_ok = (rq_q == rq_d);
`endif
  wire        bus_cyc = kph_i[3];
  wire        unused_kph = kph_i[0];           // (the commit cycle: the engine's)
  reg         arm_q;                             // an operation was there in the last cycle
  wire        bus_go = bus_cyc & arm_q;          // ... so the port registers hold its access
  wire        data_cyc = kph_i[1];               // read data of the last bus cycle
  wire        proc_cyc = kph_i[2];               // the loader checks that data (registered)

  wire [31:0] irq_mask = {8'd0, {(8-NAXES){1'b0}}, ALL, {(8-NAXES){1'b0}}, ALL,
                          {(8-NAXES){1'b0}}, ALL};
  // The engine's abort: ABORT written at the last edge or the e-stop latched, as one register
  // (so that the output stages see a flip-flop, not a gate).
  reg  [NAXES-1:0] abort_q;
  // flush_i padded to 8 axes, for indexing with a 3-bit axis number.
  wire [7:0] flush8;
  generate
    if (NAXES < 8) begin : g_pad
      assign flush8 = {{(8-NAXES){1'b0}}, flush_i};
    end else begin : g_full
      assign flush8 = flush_i;
    end
  endgenerate

  // Positions: the low word and the bits above it (POS_W <= 32: the sign) of every axis.
  wire [NAXES*32-1:0]  pos_lo;
  wire [NAXES*PHW-1:0] pos_up;
  genvar g;
  generate
    for (g = 0; g < NAXES; g = g + 1) begin : g_pos
      if (POS_W > 32) begin : g_wide
        assign pos_lo[g*32 +: 32] = pos_i[g*POS_W +: 32];
        assign pos_up[g*PHW +: PHW] = pos_i[g*POS_W + 32 +: PHW];
      end else if (POS_W == 32) begin : g_32
        assign pos_lo[g*32 +: 32] = pos_i[g*POS_W +: 32];
        assign pos_up[g*PHW +: PHW] = pos_i[g*POS_W + 31];
      end else begin : g_narrow
        assign pos_lo[g*32 +: 32] = {{(32-POS_W){pos_i[g*POS_W+POS_W-1]}}, pos_i[g*POS_W +: POS_W]};
        assign pos_up[g*PHW +: PHW] = pos_i[g*POS_W + POS_W - 1];
      end
    end
  endgenerate

  // ---- read data of the flip-flop registers ----
  wire [16*32-1:0] gwords;
  assign gwords[G_ID*32 +: 32]       = ID_VALUE;
  assign gwords[G_VERSION*32 +: 32]  = {8'd0, NAXES[7:0], VER_MAJOR, VER_MINOR};
  assign gwords[G_START*32 +: 32]    = 32'h0;
  assign gwords[G_ABORT*32 +: 32]    = 32'h0;
  assign gwords[G_GSTATUS*32 +: 32]  = {30'd0, es2_q, estop_q};
  assign gwords[G_IRQ_EN*32 +: 32]   = irq_en_q;
  assign gwords[G_IRQ_PEND*32 +: 32] = pend_q;
  assign gwords[G_STOP*32 +: 32]     = 32'h0;
  assign gwords[G_INFO0*32 +: 32]    = {DFRAC_W[7:0], STEP_W[7:0], ACC_W[7:0], 8'd64};
  assign gwords[G_INFO1*32 +: 32]    = {8'd8, 8'd5, POS_W[7:0], PULSE_W[7:0]};
  assign gwords[16*32-1:10*32]       = {(6*32){1'b0}};
  // (Read data by the registered decodes of the request, rq_*, valid at its request edge.)
  wire [31:0] grd = rq_gr_q ? gwords[{rq_gidx_q, 5'd0} +: 32] : 32'h0;
  // Axis blocks: STATUS, ERR, POS_LO, POS_HI (words 18..21) from flip-flops, selected field
  // by field over the axes (one small multiplexer per field, not one per word of every axis);
  // the other words read through the memory or 0.
  reg  [5:0]     r_status;
  reg  [2:0]     r_err;
  reg  [31:0]    r_pos;
  reg  [PHW-1:0] r_poshi;
  integer        m;
  // An OR over the axes of each axis's fields masked by its one-hot select (rq_hit_q): a
  // balanced tree, not a chain of priority selects.
  always @* begin
    r_status = 6'd0; r_err = 3'd0; r_pos = 32'd0; r_poshi = {PHW{1'b0}};
    for (m = 0; m < NAXES; m = m + 1) begin
      r_status = r_status | ({6{rq_hit_q[m]}} &
                             {2'd2 - qn_i[m*2 +: 2], run_i[m], phase_i[m*2 +: 2], busy_i[m]});
      r_err = r_err | ({3{rq_hit_q[m]}} & errf_q[m*3 +: 3]);
      r_pos = r_pos | ({32{rq_hit_q[m]}} & pos_lo[m*32 +: 32]);
      r_poshi = r_poshi | ({PHW{rq_hit_q[m]}} & poshi_q[m*PHW +: PHW]);
    end
  end
  wire [31:0] r_hi;
  generate
    if (POS_W > 32) begin : g_hi_wide
      if (POS_W < 64) begin : g_ext
        assign r_hi = {{(64-POS_W){r_poshi[PHW-1]}}, r_poshi};
      end else begin : g_full
        assign r_hi = r_poshi;
      end
    end else begin : g_hi_sign
      assign r_hi = {32{r_poshi[0]}};
    end
  endgenerate
  // The words by their one-hot selects (at most one of rq_ast_q .. rq_phi_q is set).
  wire [31:0] ard = ({32{rq_ast_q}} & {26'd0, r_status}) | ({32{rq_err_q}} & {29'd0, r_err}) |
                    ({32{rq_plo_q}} & r_pos) | ({32{rq_phi_q}} & r_hi);
  // The flip-flop registers' read data at the registered decodes of the request, whatever the
  // request: dat_q takes it on every cycle that does not ack a memory read, so that the
  // request decode (idle, cyc, stb) is not on the read data's path. wb_dat_o shows it only
  // with the ack of a read (rdk_q, from the operation and wb_we_i alone) and is 0 otherwise.
  // Unmapped addresses read 0.
  wire [31:0] rrd = grd | ard;   // (at most one of them is not 0)

  // ---- loader microprogram: staging word read at step j ----
  function [4:0] ld_src(input [5:0] j, input ve_zero);
    case (j)
      6'd0:  ld_src = W_DIR;
      6'd1:  ld_src = W_STEPS;
      6'd2:  ld_src = W_ACC_STEPS;
      6'd3:  ld_src = W_DEC_STEP;
      6'd4:  ld_src = W_DEC_FRAC;
      6'd5, 6'd9, 6'd13, 6'd17:  ld_src = W_V_MAX;
      6'd7, 6'd11, 6'd15, 6'd19: ld_src = W_V_MAX + 5'd1;
      6'd6:  ld_src = W_V_START;
      6'd8:  ld_src = W_V_START + 5'd1;
      6'd10: ld_src = W_V_END;
      6'd12: ld_src = W_V_END + 5'd1;
      6'd14: ld_src = W_V_DEC;
      6'd16: ld_src = W_V_DEC + 5'd1;
      6'd18: ld_src = W_DEC;
      6'd20: ld_src = W_DEC + 5'd1;
      6'd21: ld_src = W_ACC;
      6'd22: ld_src = W_ACC + 5'd1;
      6'd23: ld_src = ve_zero ? W_DEC : W_V_END;
      default: ld_src = ve_zero ? W_DEC + 5'd1 : W_V_END + 5'd1;
    endcase
  endfunction
  // Slot word written with the data of step j: {valid, bank, offset}.
  function [5:0] ld_dst(input [5:0] j);
    case (j)
      6'd1:  ld_dst = {1'b1, 2'd0, 3'd2};   // STEPS
      6'd2:  ld_dst = {1'b1, 2'd1, 3'd0};   // ACC_STEPS
      6'd3:  ld_dst = {1'b1, 2'd2, 3'd6};   // DEC_STEP
      6'd4:  ld_dst = {1'b1, 2'd3, 3'd4};   // DEC_FRAC, aligned
      6'd5:  ld_dst = {1'b1, 2'd3, 3'd0};   // V_MAX lo
      6'd6:  ld_dst = {1'b1, 2'd0, 3'd0};   // V_START lo
      6'd7:  ld_dst = {1'b1, 2'd3, 3'd1};   // V_MAX hi
      6'd8:  ld_dst = {1'b1, 2'd0, 3'd1};   // V_START hi
      6'd14: ld_dst = {1'b1, 2'd2, 3'd4};   // V_DEC lo
      6'd16: ld_dst = {1'b1, 2'd2, 3'd5};   // V_DEC hi
      6'd18: ld_dst = {1'b1, 2'd2, 3'd2};   // ~DEC lo
      6'd20: ld_dst = {1'b1, 2'd2, 3'd3};   // ~DEC hi
      6'd21: ld_dst = {1'b1, 2'd2, 3'd0};   // ACC lo
      6'd22: ld_dst = {1'b1, 2'd2, 3'd1};   // ACC hi
      6'd23: ld_dst = {1'b1, 2'd3, 3'd2};   // FLOOR lo
      6'd24: ld_dst = {1'b1, 2'd3, 3'd3};   // FLOOR hi
      default: ld_dst = 6'd0;
    endcase
  endfunction

  // The slot stores the word of step j shifted (DEC_FRAC left-aligned) / inverted (~DEC).
  function ld_shl(input [5:0] j);
    ld_shl = (j == 6'd4) && (DFRAC_W < 32);
  endfunction
  function ld_inv(input [5:0] j);
    ld_inv = (j == 6'd18) || (j == 6'd20);
  endfunction
  // Steps whose word is held (lh) for the compare of a later step.
  function ld_hold(input [5:0] j);
    ld_hold = (j == 6'd1) || (j == 6'd5) || (j == 6'd7) || (j == 6'd9) || (j == 6'd11) ||
              (j == 6'd13) || (j == 6'd15) || (j == 6'd17) || (j == 6'd19);
  endfunction
  // The zero flag of lz that the check of step j writes (one-hot over lz's bits; 0: none).
  function [LZ_W-1:0] ld_zf(input [5:0] j);
    case (j)
      6'd1:  ld_zf = LZ_ONE << 0;
      6'd2:  ld_zf = LZ_ONE << 1;
      6'd3:  ld_zf = LZ_ONE << 2;
      6'd4:  ld_zf = LZ_ONE << 3;
      6'd5:  ld_zf = LZ_ONE << 4;
      6'd6:  ld_zf = LZ_ONE << 6;
      6'd7:  ld_zf = LZ_ONE << 5;
      6'd8:  ld_zf = LZ_ONE << 7;
      6'd10: ld_zf = LZ_ONE << 8;
      6'd12: ld_zf = LZ_ONE << 9;
      6'd18: ld_zf = LZ_ONE << 10;
      6'd20: ld_zf = LZ_ONE << 11;
      6'd21: ld_zf = LZ_ONE << 12;
      6'd22: ld_zf = LZ_ONE << 13;
      default: ld_zf = {LZ_W{1'b0}};
    endcase
  endfunction
  // Steps whose compare is the high word of a 64-bit compare (the low word's borrow enters).
  function ld_hi_cmp(input [5:0] j);
    ld_hi_cmp = (j == 6'd8) || (j == 6'd12) || (j == 6'd16) || (j == 6'd20);
  endfunction

  // ---- memory port of the bus engine (bus cycles) ----
  // The word of a staging/configuration operation: bank, word, implemented bits.
  wire        mw_cfg = (op_q == OP_CRD) || (op_q == OP_CWR);
  wire [1:0]  mw_bank = mw_cfg ? 2'd3 : stg_bank(owd_q);
  wire [4:0]  mw_word = mw_cfg ? owd_q : stg_word(owd_q);
  // The implemented bits, a register of its own loaded on every idle cycle from the bus's word
  // (like owd_q; a staging or configuration operation starts from idle with the request's
  // word, held on the bus until its ack), so that it is not a function of owd_q, whose register
  // Yosys would move behind the mask's ROM, in front of the bus engine's bookkeeping
  // (asserted in hexstep_wb_fv: fv_mwm_ok).
  reg  [31:0] mwm_q;
  wire [2:0]  mwm_cw = widx[2:0] - W_CFG[2:0];
  always @(posedge clk_i)
    if (idle) mwm_q <= w_stg ? stg_mask(widx) : cfg_mask(mwm_cw);
  wire [31:0] mw_mask = mwm_q;
`ifdef FORMAL
  (* keep *) wire fv_mwm_ok = !(op_q == OP_SRD || op_q == OP_SWR || op_q == OP_CRD ||
                                op_q == OP_CWR) ||
                              (mwm_q == (mw_cfg ? cfg_mask(owd_q[2:0]) : stg_mask(owd_q)));
`endif
  wire [31:0] osel_mask = {{8{osel_q[3]}}, {8{osel_q[2]}}, {8{osel_q[1]}}, {8{osel_q[0]}}};
  reg         m_re, m_init;
  reg  [1:0]  m_rbank;
  reg  [7:0]  m_raddr, m_waddr;
  reg  [3:0]  m_we;
  reg  [31:0] m_wdata;

  // Loader commit: the slot flags from the checks.
  wire l_vm_z = lz_q[4] & lz_q[5], l_vs_z = lz_q[6] & lz_q[7], l_ve_z = lz_q[8] & lz_q[9];
  wire l_dec_z = lz_q[10] & lz_q[11], l_acc_z = lz_q[12] & lz_q[13];
  wire l_decel_now = lz_q[2] & lz_q[3];
  wire l_empty = ~ljog_q & lz_q[0];
  wire l_bad_jog = l_vm_z | lg_q[2] | (l_vs_z & l_acc_z) | l_dec_z;
  wire l_bad_mv = l_vm_z | lg_q[2] | lg_q[3] | (l_ve_z & lg_q[5]) | lg_q[4] | lg_q[0] | lg_q[1] |
                  (l_ve_z & l_dec_z) | (~l_decel_now & l_vs_z & (l_acc_z | lz_q[1]));
  wire l_bad = ~l_empty & (ljog_q ? l_bad_jog : l_bad_mv);
  wire [1:0] l_init = ljog_q ? (l_acc_z ? PH_CRUISE : PH_ACCEL) :
                      l_decel_now ? PH_DECEL : (~lz_q[1] ? PH_ACCEL : PH_CRUISE);
  reg  [6:0] l_flags;   // bit positions F_* of hexstep_defs.vh
  always @* begin
    l_flags = 7'd0;
    l_flags[F_BAD]       = l_bad;
    l_flags[F_EMPTY]     = l_empty;
    l_flags[F_JOG]       = ljog_q;
    l_flags[F_DIR]       = ldir_q;
    l_flags[F_INIT +: 2] = l_init;
    l_flags[F_DZ]        = l_dec_z;
  end

  // Decodes of the loader step, registered: while op_q == OP_PUSH each equals its function of
  // ocnt_q (asserted in hexstep_wb_fv). ocnt_q is 0 in idle, where a push starts, and changes
  // in a push only at its bus cycles, to ocnt + 1; the decodes load f(0) in idle and f(ocnt + 1)
  // at those edges, so no decode of the counter sits on the loader's paths. f(ocnt + 1) is
  // written as a function of ocnt itself (the step ocnt + 1 - 1 is ocnt; in a push ocnt <= 25),
  // and the staging word of the read as a table computed at elaboration, so no adder is in front
  // of these registers either.
  // LD_RD: entry 2 * j + v (8 bits, 7 used) is {stg_bank, stg_word} of ld_src(j + 1, v).
  function [1023:0] ld_rd_tab(input integer unused_arg);
    integer j;
    reg [4:0] w0, w1;
    begin
      ld_rd_tab = 1024'd0;
      for (j = 0; j < 64; j = j + 1) begin
        w0 = ld_src(j[5:0] + 6'd1, 1'b0);
        w1 = ld_src(j[5:0] + 6'd1, 1'b1);
        ld_rd_tab[j*16 +: 7] = {stg_bank(w0), stg_word(w0)};
        ld_rd_tab[j*16 + 8 +: 7] = {stg_bank(w1), stg_word(w1)};
      end
    end
  endfunction
  localparam [1023:0] LD_RD = ld_rd_tab(0);
  // The loader step whose data is in rdq after the edge (ocnt - 1): 63 from idle (ocnt = 0),
  // ocnt itself at a push's bus cycle. The functions need no guard for idle: ld_dst, ld_hi_cmp,
  // ld_shl, ld_inv and ld_hold are 0 at 63, and LD_RD's entry 63 is ld_src(0, v).
  wire [5:0] lnx = idle ? 6'h3F : ocnt_q;
  wire       ldc_ld = idle || (op_q == OP_PUSH && bus_go);
  reg  [5:0] lst_q;                  // ocnt - 1: the loader step whose data is in rdq
  reg        lz0_q, lz1_q, lrd_q;    // ocnt == 0, ocnt == 1, ocnt < LOADER_STEPS
  reg        lhc_q;                  // ld_hi_cmp(ocnt - 1)
  reg        lsh_q, linv_q;          // the word of step ocnt - 1 is stored shifted / inverted
  reg        lhe_q;                  // ... is held in lh (ld_hold), lh's enable
  reg  [5:0] ldst_q;                 // ld_dst(ocnt - 1)
  reg  [6:0] lsr0_q, lsr1_q;         // {bank, word} of the staging word that step ocnt reads,
                                     // for V_END nonzero (0) and zero (1): ld_src's two cases
  // ld_zf(ocnt - 1): the zero flag that the check of this step writes, each flag's enable with
  // the check cycle alone (no decode of the operation or the step in front of lz). 0 outside a
  // push (reset in the initialization; loaded in idle with ld_zf(63) and at a push's last edge
  // with ld_zf(LOADER_STEPS), both 0; asserted in hexstep_wb_fv: fv_lzs_ok).
  reg  [LZ_W-1:0] lzs_q;
  always @(posedge clk_i) begin
    if (rst_i) lzs_q <= {LZ_W{1'b0}};
    else if (ldc_ld) lzs_q <= ld_zf(lnx);
  end
  always @(posedge clk_i) begin
    if (ldc_ld) begin
      lst_q <= lnx;
      lz0_q <= idle;
      lz1_q <= (lnx == 6'd0);
      lrd_q <= idle || (ocnt_q < LOADER_STEPS - 6'd1);
      lhc_q <= ld_hi_cmp(lnx);
      lsh_q <= ld_shl(lnx);
      linv_q <= ld_inv(lnx);
      lhe_q <= ld_hold(lnx);
      ldst_q <= ld_dst(lnx);
      lsr0_q <= LD_RD[{lnx, 1'b0, 3'b000} +: 7];
      lsr1_q <= LD_RD[{lnx, 1'b1, 3'b000} +: 7];
    end
  end

`ifdef FORMAL
  // The decodes against their functions of ocnt_q (asserted while op_q == OP_PUSH).
  wire [5:0] fv_ls = ocnt_q - 6'd1;
  (* keep *) wire fv_ldc_ok =
      lst_q == fv_ls && lz0_q == (ocnt_q == 6'd0) && lz1_q == (ocnt_q == 6'd1) &&
      lrd_q == (ocnt_q < LOADER_STEPS) && lhc_q == ld_hi_cmp(fv_ls) &&
      lsh_q == ld_shl(fv_ls) && linv_q == ld_inv(fv_ls) && lhe_q == ld_hold(fv_ls) &&
      ldst_q == ld_dst(fv_ls) && lzs_q == ld_zf(fv_ls) &&
      lsr0_q == {stg_bank(ld_src(ocnt_q, 1'b0)), stg_word(ld_src(ocnt_q, 1'b0))} &&
      lsr1_q == {stg_bank(ld_src(ocnt_q, 1'b1)), stg_word(ld_src(ocnt_q, 1'b1))};
  // ... and lzs_q outside a push.
  (* keep *) wire fv_lzs_ok = (op_q == OP_PUSH) || (lzs_q == {LZ_W{1'b0}});
`endif

  // The loader's word of step ocnt - 1 (its data, read three cycles ago and registered, as the
  // slot stores it: DEC_FRAC left-aligned, DEC inverted). It is the write data of
  // the next bus cycle and odat's next value, a function of rdq and the step's decodes alone,
  // so that the operations' other data (the bus, the merge of a staging write) is not on its
  // path.
  // rdq: the data itself (rdqn_q holds it inverted, the compare's operand as the carry chain
  // takes it, with no LUT in front).
  wire [31:0] rdq = ~rdqn_q;
  // A staging or configuration write's merged word: the byte lanes written (odat_q) over the
  // word read (rdq), masked to the implemented bits.
  wire [31:0] mg = ((rdq & ~osel_mask) | (odat_q & osel_mask)) & mw_mask;
  wire [31:0] lw = lsh_q ? (rdq << (32 - DFRAC_W)) : linv_q ? rdqn_q : rdq;

  integer k, i, zi;
  reg        hit, overrun, estop_rise, drop;
  reg [2:0]  eset;
  reg [1:0]  qv;
  reg        lcv_q, lcy_q;                    // a compare was made: its carry (registered)
  reg  [5:0] lcs_q;                           // its loader step
  wire       cmp = ~lcy_q;                    // its borrow of held - data (- borrow): data > held
  // The loader's compare held + ~data + carry in 16-bit halves, the high half for both of its
  // carries in (carry select): its carry out (no borrow) is two 16-bit chains and a LUT
  // behind the registers rather than one 32-bit chain.
  wire [17:0] lcl  = {1'b0, lh_q[15:0], 1'b1} + {1'b0, rdqn_q[15:0], lc_q};
  wire [16:0] lch0 = {1'b0, lh_q[31:16]} + {1'b0, rdqn_q[31:16]};
  wire [17:0] lch1 = {1'b0, lh_q[31:16], 1'b1} + {1'b0, rdqn_q[31:16], 1'b1};
  wire        ccy = lcl[17] ? lch1[17] : lch0[16];
  wire        unused_lcmp = ^{lcl[16:0], lch0[15:0], lch1[16:0]};

  always @(*) begin
    cfg_d = cfg_q;  errf_d = errf_q;  poshi_d = poshi_q;
    irq_en_d = irq_en_q;  pend_d = pend_q;
    abort_cmd_d = {NAXES{1'b0}};
    op_d = op_q; oax_d = oax_q; owd_d = owd_q; odat_d = odat_q; oiss_d = oiss_q;
    ocnt_d = ocnt_q; otail_d = otail_q; ocan_d = ocan_q; osel_d = osel_q;
    lh_d = lh_q; lc_d = lc_q; lz_d = lz_q; lg_d = lg_q; ljog_d = ljog_q; ldir_d = ldir_q;
    ack_d = 1'b0;
    dat_d = rrd;
    overrun = 1'b0;
    drop = 1'b0; qv = 2'd0; i = 0;

    // The operation registers take the bus's address, data and byte enables on every idle
    // cycle (they are read only within an operation, which a request starts from idle), so
    // that the request decode is not on their paths.
    if (idle) begin
      oax_d = ak;
      owd_d = w_stg ? widx : widx - W_CFG;
      odat_d = wb_dat_i;
      osel_d = wb_sel_i;
      oiss_d = 1'b0;
      ocnt_d = 6'd0;
      // A push's slot and cancel (a flush at the request's edge drops it).
      otail_d = (qn_i[ak*2 +: 2] == 2'd0) ? inc3(act_i[ak*2 +: 2]) : inc3(inc3(act_i[ak*2 +: 2]));
      ocan_d = flush8[ak];
    end

    // ---- global registers ----
    estop_rise = es2_q & ~estop_q;
    estop_d    = es2_q | (estop_q & ~(req & rq_gw_q[G_GSTATUS[2:0]] & wdat[0]));
    if (req) begin
      ack_d = 1'b1;
      if (rq_gw_q[G_ABORT[2:0]])    abort_cmd_d = wdat[NAXES-1:0];
      if (rq_gw_q[G_IRQ_EN[2:0]])   irq_en_d = ((irq_en_q & ~bmask) | wdat) & irq_mask;
      if (rq_gw_q[G_IRQ_PEND[2:0]]) pend_d = pend_q & ~wdat;
      if (rq_stg_q || rq_cfg_q) begin
        // Staging word or configuration: a memory operation (configuration writes update the
        // live register when the merged word is written to its mirror).
        ack_d = 1'b0;
        op_d = rq_stg_q ? (wr ? OP_SWR : OP_SRD) : (wr ? OP_CWR : OP_CRD);
      end
      if (rq_cmd_q) begin
        // The axis's drop (e-stop, abort) and queue fill, selected by the one-hot axis.
        drop = estop_q | ((abort_q & rq_hit_q) != {NAXES{1'b0}});
        for (i = 0; i < NAXES; i = i + 1)
          if (rq_hit_q[i]) qv = qv | qn_i[i*2 +: 2];
        if (!drop && qv == 2'd2) begin
          overrun = 1'b1;
        end else if (!drop) begin
          ack_d = 1'b0;
          op_d = OP_PUSH;
        end
      end
    end

    // ---- the bus engine: bookkeeping at the bus cycles (the memory port itself is driven from
    // registers, see "memory port" below) ----
    case (op_q)
      OP_INIT: begin
        if (bus_go) begin
          owd_d = owd_q + 5'd1;
          if (owd_q == 5'd7) begin
            owd_d = 5'd0;
            oax_d = oax_q + 3'd1;
            if ({29'd0, oax_q} == NAXES - 1) op_d = OP_IDLE;
          end
        end
      end
      OP_SRD, OP_CRD, OP_SWR, OP_CWR: begin
        // Read the word at the first bus cycle; a read acks with its data two cycles later, a
        // write merges it (byte enables, implemented bits: mg, from the read data registered
        // in rdqn_q) in the cycle after the data and writes it at the next bus cycle.
        if (bus_go && !oiss_q) oiss_d = 1'b1;
        // (ocnt_q is 0 or 1 in these operations, asserted in hexstep_wb_fv: bit 0 tells.)
        if (data_cyc && oiss_q && !ocnt_q[0]) begin
          if (op_q == OP_SRD || op_q == OP_CRD) begin
            ack_d = 1'b1;
            dat_d = bus_rdata_i;
            op_d = OP_IDLE;
          end else begin
            ocnt_d = 6'd1;
          end
        end
        if (proc_cyc && oiss_q && ocnt_q[0]) odat_d = mg;
        if (bus_go && oiss_q && ocnt_q[0]) begin
          ack_d = 1'b1;
          op_d = OP_IDLE;
          ocnt_d = 6'd0;
        end
      end
      OP_PUSH: begin
        if (flush8[oax_q]) ocan_d = 1'b1;
        if (bus_go) begin
          if (ocnt_q == LOADER_STEPS) begin
            ack_d = 1'b1;
            op_d = OP_IDLE;
          end
          ocnt_d = ocnt_q + 6'd1;
        end
        if (proc_cyc && !lz0_q) begin
          // The data of step ocnt - 1 (read three cycles ago, registered): its checks (the
          // word it writes at the next bus cycle is lw).
          // held - data - borrow as held + ~data + carry (ccy, above). lc is the carry of a low
          // word's compare (steps 6, 10, 14, 18) until the high word's (8, 12, 16, 20) has used
          // it, and 1 at every other compare (set at step 0 and by each use), so no decode sits
          // in front of the chain. The compare's carry is registered (lcy_q; cmp, its borrow)
          // and written to lc / lg in the next cycle (the bus cycle, lcv_q), below: the next
          // compare is four cycles later, the commit's checks (l_flags) after step 24.
          if (lz1_q || lhc_q) lc_d = 1'b1;
          // The word held for a later compare: enabled by its registered decode (lhe_q) rather
          // than a decode of the step in front of 32 flip-flops.
          if (lhe_q) lh_d = rdq;
          if (lst_q == 6'd0) begin ljog_d = rdq[1]; ldir_d = rdq[0]; end
          odat_d = lw;
        end
      end
      default: ;
    endcase
    // The zero flags of the step's check (steps 1..8, 10, 12, 18, 20..22): lzs_q is 0 outside
    // a push and at its step 63 (lz0_q), so the check cycle alone enables them.
    for (zi = 0; zi < LZ_W; zi = zi + 1)
      if (proc_cyc && lzs_q[zi]) lz_d[zi] = (rdq == 32'd0);
    // The loader compare of the last cycle (its step lcs_q): lc for a low word's, a flag of lg
    // for a high or single word's.
    if (lcv_q) begin
      case (lcs_q)
        6'd2:  lg_d[0] = cmp;
        6'd3:  lg_d[1] = cmp;
        6'd6, 6'd10, 6'd14, 6'd18: lc_d = lcy_q;
        6'd8:  lg_d[2] = cmp;
        6'd12: lg_d[3] = cmp;
        6'd16: lg_d[4] = cmp;
        6'd20: lg_d[5] = cmp;
        default: ;
      endcase
    end

    // ---- per axis ----
    for (k = 0; k < NAXES; k = k + 1) begin
      hit = rq_hit_q[k];
      if (hit && wr && rq_err_q) errf_d[k*3 +: 3] = errf_q[k*3 +: 3] & ~wdat[2:0];
      if (hit && rd && rq_plo_q) poshi_d[k*PHW +: PHW] = pos_up[k*PHW +: PHW];
      for (i = 0; i < NC; i = i + 1)
        if (pcfg_q[k*NC+i])
          cfg_d[(k*NC+i)*32 +: 32] = odat_q;
      eset = {estop_rise, overrun & hit, refused_i[k]};
      errf_d[k*3 +: 3] = errf_d[k*3 +: 3] | eset;
      pend_d[k]      = pend_d[k] | done_i[k];
      pend_d[8 + k]  = pend_d[8 + k] | freed_i[k];
      pend_d[16 + k] = pend_d[16 + k] | (|eset);
    end

    // Registered from the pending and enable registers (one cycle after an event).
    irq_d = |(pend_q & irq_en_q);
  end

  // ---- memory port: what the bus engine does at the next bus cycle, decided in the cycle
  // before it (g[1:0] == 2) from the registers and registered, so that no decode sits between
  // the bus engine and the block RAMs. (An operation accepted at the edge just before a bus
  // cycle therefore starts at the bus cycle after.) The loader writes the word its check of
  // this cycle produces (odat_d). ----
  always @* begin
    m_re = 1'b0; m_init = 1'b0; m_rbank = 2'd0; m_raddr = 8'd0; m_waddr = 8'd0; m_we = 4'd0;
    m_wdata = 32'd0;
    case (op_q)
      OP_INIT: begin
        // Word owd of axis oax in every bank: staging 0, the mirror to the reset configuration.
        m_we = 4'hF;
        m_init = 1'b1;
        m_waddr = {oax_q, owd_q};
        m_wdata = (owd_q == 5'd0 || owd_q == 5'd1) ? 32'd1 : 32'd0;
      end
      OP_SRD, OP_CRD, OP_SWR, OP_CWR: begin
        if (!oiss_q) begin
          m_re = 1'b1;
          m_rbank = mw_bank;
          m_raddr = {oax_q, mw_word};
        end else if (ocnt_q == 6'd1) begin
          m_we[mw_bank] = 1'b1;
          m_waddr = {oax_q, mw_word};
          m_wdata = mg;
        end
      end
      OP_PUSH: begin
        // Read the staging word of step ocnt, write the data of step ocnt - 1.
        if (lrd_q) begin
          m_re = 1'b1;
          {m_rbank, m_raddr[4:0]} = (lz_q[8] & lz_q[9]) ? lsr1_q : lsr0_q;
          m_raddr[7:5] = oax_q;
        end
        if (lz0_q) begin
          m_we = 4'b0110;                              // the zero words of the slot
          m_waddr = {oax_q, slot_word(otail_q, 3'd7)};
          m_wdata = 32'd0;
        end else begin
          if (ldst_q[5]) begin
            m_we[ldst_q[4:3]] = 1'b1;
            m_waddr = {oax_q, slot_word(otail_q, ldst_q[2:0])};
            m_wdata = lw;
          end
        end
      end
      default: ;
    endcase
  end

  reg        pre_q, pinit_q;
  // Strobes for the bus cycle, registered at the cycle before it (high only in the bus cycle):
  reg        pcommit_q;                      // the loader commits (push_o)
  reg [NAXES*NC-1:0] pcfg_q;                 // a configuration write's merged word goes to
                                             // live register {axis, word} (one-hot)
  integer    pk, pi;
  reg [1:0]  prbank_q;
  reg [7:0]  praddr_q, pwaddr_q;
  reg [3:0]  pwe_q;
  reg [31:0] pwdata_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      arm_q <= 1'b0;
      pre_q <= 1'b0;
      pwe_q <= 4'd0;
      pcommit_q <= 1'b0;
      pcfg_q <= {NAXES*NC{1'b0}};
    end else begin
      // Decided in the cycle before the commit's bus cycle, with the cancel of that cycle's edge
      // (the engine drops the push itself if the queue is flushed at the commit's edge). The
      // operation's state does not change at that edge, so these equal the bus cycle's
      // conditions (bus_go and the operation's step).
      pcommit_q <= proc_cyc && (op_q == OP_PUSH) && (ocnt_q == LOADER_STEPS) && !ocan_d;
      for (pk = 0; pk < NAXES; pk = pk + 1)
        for (pi = 0; pi < NC; pi = pi + 1)
          pcfg_q[pk*NC+pi] <= proc_cyc && (op_q == OP_CWR) && oiss_q && (ocnt_q == 6'd1) &&
                              ({29'd0, oax_q} == pk) && ({27'd0, owd_q} == pi);
    end
    if (!rst_i && proc_cyc) begin
      arm_q <= (op_q != OP_IDLE);
      pre_q <= m_re;
      pwe_q <= m_we;
    end
    if (proc_cyc) begin
      pinit_q <= m_init;  prbank_q <= m_rbank;  praddr_q <= m_raddr;
      pwaddr_q <= m_waddr;  pwdata_q <= m_wdata;
    end
  end
  always @(posedge clk_i) begin
    if (rst_i) begin
      ack_q <= 1'b0;  dat_q <= 32'h0;  rdk_q <= 1'b0;  irq_q <= 1'b0;
      es1_q <= 1'b0;  es2_q <= 1'b0;  estop_q <= 1'b0;
      abort_q <= {NAXES{1'b0}};
      errf_q <= {NAXES*3{1'b0}};
      poshi_q <= {NAXES*PHW{1'b0}};  irq_en_q <= 32'h0;  pend_q <= 32'h0;
      cfg_q <= {NAXES{CFG_RESET}};
      op_q <= OP_INIT;  oax_q <= 3'd0;  owd_q <= 5'd0;  oiss_q <= 1'b0;  ocnt_q <= 6'd0;
      ocan_q <= 1'b0;
    end else begin
      ack_q <= ack_d;  dat_q <= dat_d;  irq_q <= irq_d;
      rdk_q <= idle ? !wb_we_i : (op_q == OP_SRD || op_q == OP_CRD);
      es1_q <= estop_i;  es2_q <= es1_q;  estop_q <= estop_d;
      abort_q <= abort_cmd_d | {NAXES{estop_d}};
      errf_q <= errf_d;
      poshi_q <= poshi_d;  irq_en_q <= irq_en_d;  pend_q <= pend_d;
      cfg_q <= cfg_d;
      op_q <= op_d;  oax_q <= oax_d;  owd_q <= owd_d;  oiss_q <= oiss_d;  ocnt_q <= ocnt_d;
      ocan_q <= ocan_d;
    end
  end

  // The flags of cfg_over_o, with the live timing words: one comparator on the merged word
  // (masked to PULSE_W bits) for every axis and word; at reset, those of CFG_RESET's words.
  wire    cov_w = (odat_q[31:1] == 31'd0);
  integer vk, vi;   // (loop variables of this block only)
  always @(posedge clk_i) begin
    for (vk = 0; vk < NAXES; vk = vk + 1)
      for (vi = 0; vi < 4; vi = vi + 1)
        if (rst_i) cov_q[vk*4+vi] <= (CFG_RESET[vi*32+1 +: 31] == 31'd0);
        else if (pcfg_q[vk*NC+vi]) cov_q[vk*4+vi] <= cov_w;
  end

  // Operation data and loader registers: not reset (read only within an operation, which
  // writes them before reading them).
  always @(posedge clk_i) begin
    odat_q <= odat_d;  osel_q <= osel_d;  otail_q <= otail_d;
    if (data_cyc) rdqn_q <= ~bus_rdata_i;
    lcv_q <= (op_q == OP_PUSH) && proc_cyc && !lz0_q;  lcs_q <= lst_q;  lcy_q <= ccy;
    lh_q <= lh_d;  lc_q <= lc_d;  lz_q <= lz_d;  lg_q <= lg_d;  ljog_q <= ljog_d;  ldir_q <= ldir_d;
  end

  assign wb_ack_o = ack_q;
  assign wb_dat_o = dat_q & {32{ack_q & rdk_q}};
  assign irq_o    = irq_q;
  // START and STOP: strobes at the request's edge; ABORT: a registered strobe for the next.
  assign start_w_o = (req && rq_gw_q[G_START[2:0]]) ? wdat[NAXES-1:0] : {NAXES{1'b0}};
  assign stop_w_o  = (req && rq_gw_q[G_STOP[2:0]]) ? wdat[NAXES-1:0] : {NAXES{1'b0}};
  assign abort_o   = abort_q;
  assign push_o       = pcommit_q;
  assign push_axis_o  = oax_q;
  assign push_flags_o = l_flags;
  // The port registers are read by the engine on the bus cycle only; an armed operation makes
  // them valid there.
  assign bus_re_o    = pre_q & arm_q;
  assign bus_rbank_o = prbank_q;
  assign bus_raddr_o = praddr_q;
  assign bus_we_o    = pwe_q & {4{arm_q}};
  assign bus_waddr_o = pwaddr_q;
  assign bus_wdata_o = pwdata_q;
  assign bus_init_o  = pinit_q;

  generate
    for (g = 0; g < NAXES; g = g + 1) begin : g_cfg
      assign step_high_o[g*PULSE_W +: PULSE_W] = cfg_q[(g*NC+0)*32 +: PULSE_W];
      assign step_low_o[g*PULSE_W +: PULSE_W]  = cfg_q[(g*NC+1)*32 +: PULSE_W];
      assign dir_setup_o[g*PULSE_W +: PULSE_W] = cfg_q[(g*NC+2)*32 +: PULSE_W];
      assign dir_hold_o[g*PULSE_W +: PULSE_W]  = cfg_q[(g*NC+3)*32 +: PULSE_W];
      assign step_inv_o[g]                     = cfg_q[(g*NC+4)*32];
      assign dir_inv_o[g]                      = cfg_q[(g*NC+4)*32 + 1];
      assign cfg_over_o[g*4 +: 4]              = cov_q[g*4 +: 4];
    end
  endgenerate

endmodule

`default_nettype wire
