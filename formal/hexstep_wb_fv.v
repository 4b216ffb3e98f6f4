// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of hexstep_wb (Wishbone B4 classic register block, bus engine,
// loader), alone: the engine's outputs are free inputs.
`default_nettype none

// Free in every cycle: the Wishbone master within B4 classic (once cyc & stb are up it holds
// them and we/adr/dat/sel until the cycle in which it sees ack: assumed), the e-stop pin, and
// the engine's outputs (act, qn, busy, run, phase, done, refused, freed, flush, positions),
// except that act and qn stay in 0..2 (the engine's queue ring; asserted in hexstep_engine_fv).
// The cycle counter (g; kph_i is g[1:0] one-hot) counts from any value.
//
// The memory behind the bus port is modelled for one watched word (any staging or pulse
// configuration word of any axis, $anyconst): the harness keeps that word, writes it when the
// bus port writes it on a bus cycle, and returns it two cycles after a bus-cycle read of it, as
// hexstep_ram does; every other read returns free data. The engine's own accesses never touch
// staging or mirror words (asserted in hexstep_engine_fv), so they are not modelled here.
module hexstep_wb_fv #(
  parameter integer NAXES   = 1,
  parameter integer ACC_W   = 12,
  parameter integer STEP_W  = 6,
  parameter integer DFRAC_W = 8,
  parameter integer PULSE_W = 4,
  parameter integer POS_W   = 8,
  parameter integer ADDR_W  = 12
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
  input wire [NAXES*2-1:0]     act_i,
  input wire [NAXES*2-1:0]     qn_i,
  input wire [NAXES-1:0]       busy_i,
  input wire [NAXES-1:0]       run_i,
  input wire [NAXES*2-1:0]     phase_i,
  input wire [NAXES-1:0]       done_i,
  input wire [NAXES-1:0]       refused_i,
  input wire [NAXES-1:0]       freed_i,
  input wire [NAXES-1:0]       flush_i,
  input wire [NAXES*POS_W-1:0] pos_i,
  input wire [31:0]            mem_any_i    // read data of the words not modelled
);
  // Register map (rdl/hexstep.rdl), word indexes: global block, axis block at 0x100 + 0x80 k.
  localparam integer G_ID = 0, G_VERSION = 1, G_START = 2, G_ABORT = 3, G_GSTATUS = 4,
                     G_IRQ_EN = 5, G_IRQ_PEND = 6, G_STOP = 7;
  localparam integer W_CMD = 17, W_CFG = 22;

  function [31:0] lo(input integer w);
    lo = (w >= 32) ? 32'hFFFF_FFFF : ((32'h1 << w) - 32'h1);
  endfunction
  function [31:0] hi(input integer w);
    hi = (w >= 64) ? 32'hFFFF_FFFF : (w <= 32) ? 32'h0 : ((32'h1 << (w - 32)) - 32'h1);
  endfunction
  // Implemented bits of axis word w (docs/REGISTERS.md; speeds are 64 bits).
  function [31:0] ax_mask(input [4:0] w);
    case (w)
      5'd0, 5'd14, 5'd15:                  ax_mask = lo(STEP_W);
      5'd1:                                ax_mask = 32'h3;
      5'd10, 5'd12:                        ax_mask = lo(ACC_W);
      5'd11, 5'd13:                        ax_mask = hi(ACC_W);
      5'd16:                               ax_mask = lo(DFRAC_W);
      5'd22, 5'd23, 5'd24, 5'd25:          ax_mask = lo(PULSE_W);
      5'd26:                               ax_mask = 32'h3;
      default:                             ax_mask = (w >= 5'd2 && w <= 5'd9) ? 32'hFFFF_FFFF : 32'h0;
    endcase
  endfunction
  // Where axis word w lives (docs/ARCHITECTURE.md, memory map): bank and word 0..7.
  function [1:0] ax_bank(input [4:0] w);
    ax_bank = (w < 5'd5) ? 2'd0 : (w < 5'd10) ? 2'd1 : (w < 5'd17) ? 2'd2 : 2'd3;
  endfunction
  function [2:0] ax_word(input [4:0] w);
    ax_word = (w < 5'd5) ? w + 5'd3 : (w < 5'd10) ? w - 5'd2 : (w < 5'd17) ? w - 5'd9 : w - 5'd22;
  endfunction

  reg [6:0] g;
  (* anyconst *) reg [6:0] f_g0;
  always @(posedge clk_i) g <= rst_i ? f_g0 : g + 7'd1;
  wire [1:0] kc = g[1:0];

  wire [31:0]              dat_o, bus_wdata;
  wire                     ack, irq, push, bus_re, bus_init;
  wire [NAXES-1:0]         start_w, stop_w, abort;
  wire [2:0]               push_axis;
  wire [6:0]               push_flags;
  wire [1:0]               bus_rbank;
  wire [7:0]               bus_raddr, bus_waddr;
  wire [3:0]               bus_we;
  wire [NAXES*PULSE_W-1:0] step_high, step_low, dir_setup, dir_hold;
  wire [NAXES-1:0]         step_inv, dir_inv;
  reg  [31:0]              bus_rdata;

  hexstep_wb #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W), .PULSE_W (PULSE_W),
    .POS_W (POS_W), .ADDR_W (ADDR_W)
  ) u_dut (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (wb_cyc_i), .wb_stb_i (wb_stb_i), .wb_we_i (wb_we_i), .wb_adr_i (wb_adr_i),
    .wb_dat_i (wb_dat_i), .wb_sel_i (wb_sel_i), .wb_dat_o (dat_o), .wb_ack_o (ack),
    .estop_i (estop_i), .irq_o (irq),
    .kph_i (4'b0001 << kc), .start_w_o (start_w), .stop_w_o (stop_w), .abort_o (abort),
    .push_o (push), .push_axis_o (push_axis), .push_flags_o (push_flags),
    .bus_re_o (bus_re), .bus_rbank_o (bus_rbank), .bus_raddr_o (bus_raddr),
    .bus_rdata_i (bus_rdata), .bus_we_o (bus_we), .bus_waddr_o (bus_waddr),
    .bus_wdata_o (bus_wdata), .bus_init_o (bus_init),
    .act_i (act_i), .qn_i (qn_i), .busy_i (busy_i), .run_i (run_i), .phase_i (phase_i),
    .done_i (done_i), .refused_i (refused_i), .freed_i (freed_i), .flush_i (flush_i),
    .step_high_o (step_high), .step_low_o (step_low), .dir_setup_o (dir_setup),
    .dir_hold_o (dir_hold), .step_inv_o (step_inv), .dir_inv_o (dir_inv), .pos_i (pos_i)
  );

  // ---- reset in the first cycle only; a B4 classic master; the engine's queue ring ----
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
  genvar gk;
  generate
    for (gk = 0; gk < NAXES; gk = gk + 1) begin : g_q
      always @* assume (act_i[gk*2 +: 2] != 2'd3 && qn_i[gk*2 +: 2] != 2'd3);
    end
  endgenerate

  // The held request, decoded. It ends in the cycle of its ack.
  wire [31:0]       bmask = {{8{wb_sel_i[3]}}, {8{wb_sel_i[2]}}, {8{wb_sel_i[1]}}, {8{wb_sel_i[0]}}};
  wire [31:0]       wd    = wb_dat_i & bmask;
  wire [ADDR_W-3:0] wadr  = wb_adr_i[ADDR_W-1:2];
  wire              in_g  = (wadr >> 5) == 0;
  wire [4:0]        gw    = wadr[4:0];
  wire [ADDR_W-3:0] ablk  = (wadr >> 5) - 2;                 // axis number if an axis block
  wire              in_ax = (wadr >> 5) >= 2 && ablk < NAXES;
  wire [2:0]        rax   = ablk[2:0];
  wire              ack_w = ack && wb_we_i;
  wire              ack_r = ack && !wb_we_i;

  // ---- B4 classic: one ack per request ----
  // ack only inside cyc & stb, never in two consecutive cycles (so a request held through its
  // ack cycle is not acked again); a request is acked within ACK_MAX cycles (below).
  always @* if (!rst_i) begin
    if (!p_have) assert (!ack);
    if (ack) assert (cs);
    if (p_have && ack) assert (!p_ack);
  end
  // Latency (docs/ARCHITECTURE.md, bus interface): a request is taken at the edge ending its
  // first cycle and accepted at the next; an operation accepted at the edge ending cycle c
  // starts at the first bus cycle b >= c + 2 (b <= c + 5); the longest is CMD.push, acked on
  // the edge b + 100, so in cycle b + 101: at most 106 + TAKE = 107 cycles after the request's
  // first cycle. A request that came while the memory initialization ran waits for it too
  // (8 * NAXES bus cycles from reset). TAKE: the cycle in which a request is taken before it
  // is acted on (kTakeCycles in cpp_model/include/hexstep/widths.hpp); every bound from the
  // request's first cycle below counts it once.
  localparam integer TAKE = 1;
  localparam [8:0]   TK = TAKE;
  localparam integer ACK_MAX = 106 + TAKE;
  localparam integer ACK_MAX_INIT = 32 * NAXES + 5 + ACK_MAX;
  (* keep *) wire [2:0] f_op, f_oax;     // u_dut.op_q, u_dut.oax_q (connected by the .sby)
  reg [8:0] f_wait;                 // cycles the current request has waited for its ack
  reg       f_post_q;
  wire      f_fresh = cs && (f_wait == 9'd0);
  wire      f_post = f_fresh ? (f_op != 3'd1) : f_post_q;   // it began after the initialization
  always @(posedge clk_i) begin
    f_wait <= (rst_i || !cs || ack) ? 9'd0 : (f_wait == 9'd511) ? f_wait : f_wait + 9'd1;
    f_post_q <= f_post;
  end

  // ---- the watched memory word ----
  (* anyconst *) reg [2:0] f_ax;
  (* anyconst *) reg [4:0] f_w;          // staging 0..16 or configuration 22..26
  always @* assume (f_ax < NAXES && (f_w <= 5'd16 || (f_w >= 5'd22 && f_w <= 5'd26)));
  wire        f_cfg = f_w >= 5'd22;
  wire [1:0]  f_b = ax_bank(f_w);
  wire [7:0]  f_a = {f_ax, 2'b00, ax_word(f_w)};
  wire [31:0] f_mask = ax_mask(f_w);
  wire [31:0] f_reset = (f_w == 5'd22 || f_w == 5'd23) ? 32'd1 : 32'd0;   // STEP_HIGH/LOW 1
  wire        f_req = in_ax && rax == f_ax && gw == f_w;                // the request is to it

  reg  [31:0] f_val;                     // what the register map says it holds
  reg  [31:0] f_mem;                     // the memory word
  reg         f_init;                    // the bus engine's initialization wrote it
  // Its value from this cycle's edge on: an acked write takes effect at its ack.
  wire [31:0] f_new = (ack_w && f_req) ? ((f_val & ~bmask) | wd) & f_mask : f_val;
  wire        bus_cyc = (kc == 2'd3);
  wire        f_mwr = bus_cyc && bus_we[f_b] && bus_waddr == f_a;
  wire [31:0] f_mwd = (bus_init && f_b != 2'd3) ? 32'd0 : bus_wdata;  // banks 0..2: init 0
  reg         r1_hit, r2_hit;
  always @(posedge clk_i) begin
    if (rst_i) f_val <= f_reset;
    else f_val <= f_new;
    if (f_mwr) f_mem <= f_mwd;
    if (rst_i) f_init <= 1'b0;
    else if (f_mwr && bus_init) f_init <= 1'b1;
    // hexstep_ram: address registered, then the word read at the next edge.
    r1_hit <= bus_cyc && bus_re && bus_rbank == f_b && bus_raddr == f_a;
    r2_hit <= r1_hit;
    bus_rdata <= r1_hit ? f_mem : mem_any_i;
  end
  // (bus_rdata is the data of the read two cycles back when that read was on a bus cycle; the
  // bus block samples it only then.)

  wire [PULSE_W-1:0] f_live = (f_w == 5'd22) ? step_high[f_ax*PULSE_W +: PULSE_W] :
                              (f_w == 5'd23) ? step_low[f_ax*PULSE_W +: PULSE_W] :
                              (f_w == 5'd24) ? dir_setup[f_ax*PULSE_W +: PULSE_W] :
                                               dir_hold[f_ax*PULSE_W +: PULSE_W];
  always @* if (!rst_i && p_have) begin
    // Read-back under byte enables and the implemented bits.
    if (ack_r && f_req) assert (dat_o == f_val);
    // The memory holds it once initialized (initialized to the reset value), and the live
    // pulse configuration is the mirror's value from the edge of its write on.
    if (f_mwr && bus_init) assert (f_mwd == f_reset);
    if (f_init) assert (f_mem == f_new);
    if (f_cfg && f_w != 5'd26) assert ({{(32-PULSE_W){1'b0}}, f_live} == f_new);
    if (f_w == 5'd26) assert ({30'd0, dir_inv[f_ax], step_inv[f_ax]} == f_new);
    // Requests are served only after the initialization.
    if (ack) assert (f_init);
  end
  // A write of the watched word other than the initialization is the last edge of a write
  // request to it (the ack follows).
  reg p_mwr_bus;
  always @(posedge clk_i) p_mwr_bus <= !rst_i && f_mwr && !bus_init;
  always @* if (!rst_i && p_have && p_mwr_bus) assert (ack_w && f_req);

  // ---- flip-flop registers: IRQ_ENABLE read-back, ID, VERSION ----
  wire [31:0] irq_mask = {8'd0, {(8-NAXES){1'b0}}, {NAXES{1'b1}}, {(8-NAXES){1'b0}}, {NAXES{1'b1}},
                          {(8-NAXES){1'b0}}, {NAXES{1'b1}}};
  reg  [31:0] f_irqen;
  // As a flip-flop register it takes a write at the edge before the ack.
  wire [31:0] f_irqen_now = (ack_w && in_g && gw == G_IRQ_EN) ? ((f_irqen & ~bmask) | wd) & irq_mask
                                                              : f_irqen;
  always @(posedge clk_i)
    if (rst_i) f_irqen <= 32'd0;
    else f_irqen <= f_irqen_now;
  always @* if (!rst_i && p_have && ack_r && in_g) begin
    if (gw == G_IRQ_EN) assert (dat_o == f_irqen);
    if (gw == G_ID) assert (dat_o == 32'h4858_5354);
    if (gw == G_VERSION) assert (dat_o == {8'd0, NAXES[7:0], 8'd1, 8'd0});
  end
  (* keep *) wire [31:0] f_irqen_i;      // u_dut.irq_en_q (induction invariant)
  always @* if (!rst_i && p_have) assert (f_irqen_i == f_irqen_now && (f_irqen & ~irq_mask) == 32'd0);

  // ---- E-STOP: two-flop synchronizer into a latch, cleared by writing 1 to GSTATUS.estop ----
  // A flip-flop register's write acts at the edge before its ack, so the latch of this cycle
  // follows from the last cycle's synchronizer and latch and this cycle's ack.
  reg  f_es1, f_es2, f_es2_p, f_latch_q;
  reg  [2:0] f_pin;                     // estop_i of the last three cycles, newest in bit 0
  wire f_clr = ack_w && in_g && gw == G_GSTATUS && wd[0];
  wire f_latch = f_es2_p || (f_latch_q && !f_clr);
  always @(posedge clk_i) begin
    if (rst_i) begin
      f_es1 <= 1'b0;  f_es2 <= 1'b0;  f_es2_p <= 1'b0;  f_latch_q <= 1'b0;  f_pin <= 3'b000;
    end else begin
      f_es1 <= estop_i;  f_es2 <= f_es1;  f_es2_p <= f_es2;  f_latch_q <= f_latch;
      f_pin <= {f_pin[1:0], estop_i};
    end
  end

  // ---- strobes: START/STOP at the edge before the ack of their write, ABORT one edge later
  // (abort_o is high in the ack cycle) ----
  reg [NAXES-1:0] p_start_w, p_stop_w;
  reg             p_push;
  reg [2:0]       p_push_axis;
  always @(posedge clk_i) begin
    p_start_w <= start_w;  p_stop_w <= stop_w;  p_push <= push;  p_push_axis <= push_axis;
  end
  wire            w_start = ack_w && in_g && gw == G_START;
  wire            w_stop  = ack_w && in_g && gw == G_STOP;
  wire            w_abort = ack_w && in_g && gw == G_ABORT;
  wire            w_push  = ack_w && in_ax && gw == W_CMD && wd[0];
  always @* if (!rst_i && p_have) begin
    assert (p_start_w == (w_start ? wd[NAXES-1:0] : {NAXES{1'b0}}));
    assert (p_stop_w == (w_stop ? wd[NAXES-1:0] : {NAXES{1'b0}}));
    // The engine's abort: the ABORT mask written at the last edge, or the e-stop latch; the
    // pin first sampled high at edge E makes it high after edge E+2 (the engine aborts at edge
    // E+3, the fourth), for every axis, until the latch is cleared.
    assert (abort == ((w_abort ? wd[NAXES-1:0] : {NAXES{1'b0}}) | {NAXES{f_latch}}));
    if (f_pin[2]) assert (abort == {NAXES{1'b1}});
    if (ack_r && in_g && gw == G_GSTATUS) assert (dat_o == {30'd0, f_es2_p, f_latch_q});
    // A push only as the last edge of a CMD.push write of its axis (so at most one each).
    if (p_push) assert (w_push && rax == p_push_axis);
  end
  (* keep *) wire f_es1_i, f_es2_i, f_latch_i;   // u_dut.es1_q, es2_q, estop_q
  always @* if (!rst_i && p_have) assert (f_es1_i == f_es1 && f_es2_i == f_es2 && f_latch_i == f_latch);

  // ---- induction invariants on the bus engine (connected by the .sby script; asserted, never
  // assumed): the operation in progress belongs to the held request, and the initialization
  // has written the words below its pointer ----
  localparam [2:0] OP_IDLE = 3'd0, OP_INIT = 3'd1, OP_SRD = 3'd2, OP_SWR = 3'd3, OP_CRD = 3'd4,
                   OP_CWR = 3'd5, OP_PUSH = 3'd6;
  (* keep *) wire [4:0]  f_owd;          // u_dut.owd_q
  (* keep *) wire [5:0]  f_ocnt;         // u_dut.ocnt_q
  (* keep *) wire [1:0]  f_otail;        // u_dut.otail_q
  (* keep *) wire [31:0] f_odat;         // u_dut.odat_q
  (* keep *) wire [3:0]  f_osel;         // u_dut.osel_q
  (* keep *) wire        f_oiss;         // u_dut.oiss_q
  (* keep *) wire        f_ldc_ok;       // u_dut.fv_ldc_ok: the loader's step decodes are right
  (* keep *) wire        f_cap;          // u_dut.cap_q: the request was taken (decoded)
  (* keep *) wire        f_rq_ok;        // u_dut.fv_rq_ok: its registered decodes are the bus's
  (* keep *) wire        f_lzs_ok;       // u_dut.fv_lzs_ok: no zero flag enabled outside a push
  (* keep *) wire        f_mwm_ok;       // u_dut.fv_mwm_ok: the mask register is the operation word's
  wire f_busy_op = f_op != OP_IDLE && f_op != OP_INIT;
  wire f_stg_op = f_op == OP_SRD || f_op == OP_SWR;
  wire f_cfg_op = f_op == OP_CRD || f_op == OP_CWR;
  always @* if (!rst_i && p_have) begin
    assert (f_op <= OP_PUSH);
    assert (f_lzs_ok);
    assert (f_mwm_ok);
    if (f_op == OP_INIT) assert (!ack && f_oax < NAXES && f_owd <= 5'd7 &&
                                 f_init == ({f_oax, f_owd} > f_a) && f_val == f_reset);
    else assert (f_init);
    if (ack) assert (f_op == OP_IDLE);
    if (f_busy_op) assert (cs && !ack && in_ax && f_oax == rax);
    if (f_stg_op) assert (f_owd == gw && gw < 5'd17 && wb_we_i == (f_op == OP_SWR));
    if (f_cfg_op) assert (f_owd == gw - 5'd22 && gw >= 5'd22 && gw <= 5'd26 &&
                          wb_we_i == (f_op == OP_CWR));
    if (f_op == OP_SRD || f_op == OP_CRD) assert (f_ocnt == 6'd0);
    if (f_op == OP_SWR || f_op == OP_CWR) assert (f_ocnt <= 6'd1 && (f_ocnt == 6'd0 || f_oiss));
    if ((f_op == OP_SWR || f_op == OP_CWR) && f_ocnt == 6'd0)
      assert (f_odat == wb_dat_i && f_osel == wb_sel_i);
    // The merged word from the cycle after the read data on (kc = 3, the bus cycle of the
    // write); in the cycle before (kc = 2) the held write data.
    if ((f_op == OP_SWR || f_op == OP_CWR) && f_ocnt == 6'd1 && kc == 2'd2)
      assert (f_odat == wb_dat_i && f_osel == wb_sel_i);
    if ((f_op == OP_SWR || f_op == OP_CWR) && f_ocnt == 6'd1 && kc == 2'd3 && f_req)
      assert (f_odat == (((f_val & ~bmask) | wd) & f_mask));
    if (f_op == OP_PUSH) assert (wb_we_i && gw == W_CMD && wd[0] && f_otail != 2'd3 &&
                                 f_ocnt <= 6'd25 && f_ldc_ok);
  end

  // ---- bounded ack latency, proved by k-induction: the request's wait against the progress of
  // the operation (the memory port is armed, `arm_q`, from the cycle before the first bus cycle
  // of an operation on). Base: 0 for a request that began after the initialization, else the
  // longest wait for the initialization to end (32 * NAXES + 5). ----
  (* keep *) wire        f_arm;          // u_dut.arm_q
  wire [8:0]  f_base = f_post ? 9'd0 : 32 * NAXES + 5;
  wire [8:0]  f_idx = {3'd0, f_oax, 3'd0} + {4'd0, f_owd};  // init: words done (8 per axis)
  wire [8:0]  f_kc = {7'd0, kc};
  wire        f_preiss = (f_busy_op && f_op != OP_PUSH && !f_oiss) || (f_op == OP_PUSH && f_ocnt == 6'd0);
  always @* if (!rst_i && p_have) begin
    if (ack) assert (f_wait <= f_base + ACK_MAX);
    if (ack && f_post) assert (f_wait <= ACK_MAX);
    if (f_op == OP_INIT) begin
      assert (f_arm ? f_wait <= 4 * f_idx + 5 + f_kc : (f_idx == 9'd0 && f_wait <= 9'd3));
      assert (f_owd <= 5'd7 && f_oax < NAXES);
      if (cs) assert (!f_post);
    end
    // In idle a request is taken (f_cap) at its first edge once the initialization is over, and
    // accepted at the next.
    if (f_op == OP_IDLE && cs && !ack)
      assert (f_cap ? (f_wait >= TK && f_wait <= f_base + TK && (!f_post || f_wait == TK))
                    : (f_wait <= f_base && (!f_post || f_wait == 9'd0)));
    if (f_cap) assert (cs && !ack && f_op == OP_IDLE && f_rq_ok);
    if (f_busy_op) begin
      // Before the first bus cycle: accepted at most kc + 2 cycles ago (at a bus cycle: armed
      // at the edge before, or accepted at that edge and not armed).
      if (f_preiss) assert ((kc == 2'd3 ? (f_arm ? f_wait <= f_base + 5 + TK : f_wait == f_base + 1 + TK)
                                        : f_wait <= f_base + f_kc + 2 + TK) && f_wait >= 1 + TK);
      else assert (f_arm);
      if (f_op != OP_PUSH && f_oiss) begin
        assert (f_wait <= f_base + f_kc + 6 + TK);
        if (f_ocnt == 6'd0) assert (kc <= 2'd1);
        else assert (kc >= 2'd2);
      end
      if (f_op == OP_PUSH && f_ocnt != 6'd0)
        assert (f_wait <= f_base + 4 * {3'd0, f_ocnt} + 2 + TK + f_kc);
    end
  end

  // ---- IRQ_PENDING and irq_o: bits set by the engine's done/freed and by every AXIS_ERR
  // flag set (e-stop latching, push overrun, refused move), cleared only by writing 1, set
  // winning over the clear; irq_o is high from the edge after pending & enabled became
  // non-zero. The pending register is connected (u_dut.pend_q) and asserted on. ----
  (* keep *) wire [31:0] f_pend_i;       // u_dut.pend_q
  reg  [31:0]        p_pend, p_irqen_i, p_w1c;
  reg  [NAXES-1:0]   p_done, p_freed, p_refused, p_ovr;
  reg                p_es_rise, p_es_latch, p_idle;
  reg  [NAXES*2-1:0] p_qn;
  reg  [NAXES-1:0]   p_abort;
  wire [31:0] f_w1c = (ack_w && in_g && gw == G_IRQ_PEND) ? wd : 32'd0;   // acts at the edge before
  integer ik;
  reg [31:0] f_set;
  reg [NAXES-1:0] f_ovr;
  always @* begin
    f_set = 32'd0;
    f_ovr = {NAXES{1'b0}};
    for (ik = 0; ik < NAXES; ik = ik + 1) begin
      // A CMD.push with the queue full (and not dropped) is acked at once (the bus engine was
      // idle at its edge), with an overrun.
      f_ovr[ik] = ack_w && p_idle && in_ax && rax == ik && gw == W_CMD && wd[0] &&
                  !(p_es_latch || p_abort[ik]) && p_qn[ik*2 +: 2] == 2'd2;
      f_set[ik] = p_done[ik];
      f_set[8 + ik] = p_freed[ik];
      f_set[16 + ik] = p_es_rise || p_refused[ik] || f_ovr[ik];
    end
  end
  always @(posedge clk_i) begin
    p_pend <= f_pend_i;  p_irqen_i <= f_irqen_i;
    p_done <= done_i;  p_freed <= freed_i;  p_refused <= refused_i;
    p_es_rise <= f_es2_i && !f_latch_i;  p_es_latch <= f_latch_i;
    p_qn <= qn_i;  p_abort <= abort;  p_idle <= (f_op == 3'd0);
  end
  always @* if (!rst_i && p_have) begin
    assert (f_pend_i == ((p_pend & ~f_w1c) | f_set));
    assert ((f_pend_i & ~irq_mask) == 32'd0);
    assert (irq == |(p_pend & p_irqen_i));
    if (ack_r && in_g && gw == G_IRQ_PEND) assert (dat_o == p_pend);
  end

`ifdef FV_COVER
  reg f_partial = 1'b0;                 // an acked write with 1..3 byte lanes to the watched word
  always @(posedge clk_i)
    if (!rst_i && ack_w && f_req && wb_sel_i != 4'h0 && wb_sel_i != 4'hF) f_partial <= 1'b1;
  always @* if (!rst_i && p_have) begin
    // A write under a partial byte enable, then its read-back.
    cover (ack_r && f_req && f_partial && f_val != f_reset && !f_cfg);
    // A configuration word written and read back.
    cover (ack_r && f_req && f_cfg && f_val != f_reset);
    // The e-stop latched, the pin released, and the latch cleared by software.
    cover (f_latch_q && !f_latch && !f_es2_p);
    // An interrupt from a done event, then cleared by writing 1 to its pending bit.
    cover (irq && p_pend[0] && !f_pend_i[0] && f_w1c[0]);
  end
`endif
endmodule

`default_nettype wire
