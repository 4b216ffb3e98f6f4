// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of hexstep_top (hexstep_wb + hexstep_core), NAXES = 1, tiny widths.
`default_nettype none

// Joins the register block to the core and checks what each relies on from the other:
// hexstep_wb starts an axis only when the core can accept it (START waits for idle, a chained
// start comes right after the done pulse), so the core never sees a start while busy; and
// the STEP/DIR timing holds at the pins for the reset pulse configuration (software does not
// write the pulse configuration words here: the timing inputs are used live).
// Covers: a chained pair of moves from the queue, and a STOP (with jog) through the bus.
//
// The core's internal wires of hexstep_top are connected by the .sby script (`connect`).
// Widths: NAXES = 1, SPEED_W = 4, ACC_W = 2, STEP_W = 2, DFRAC_W = 2, PULSE_W = 2, POS_W = 4.
module hexstep_top_fv #(
  parameter integer SPEED_W = 4,
  parameter integer ACC_W   = 2,
  parameter integer STEP_W  = 2,
  parameter integer DFRAC_W = 2,
  parameter integer PULSE_W = 2,
  parameter integer POS_W   = 4,
  parameter integer ADDR_W  = 10
) (
  input wire              clk_i,
  input wire              rst_i,
  input wire              wb_cyc_i,
  input wire              wb_stb_i,
  input wire              wb_we_i,
  input wire [ADDR_W-1:0] wb_adr_i,
  input wire [31:0]       wb_dat_i,
  input wire [3:0]        wb_sel_i,
  input wire              estop_i
);
  wire [31:0] dat_o;
  wire        ack, irq, step, dir;

  hexstep_top #(
    .NAXES (1), .SPEED_W (SPEED_W), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .OWE_W (2), .ADDR_W (ADDR_W)
  ) u_dut (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (wb_cyc_i), .wb_stb_i (wb_stb_i), .wb_we_i (wb_we_i), .wb_adr_i (wb_adr_i),
    .wb_dat_i (wb_dat_i), .wb_sel_i (wb_sel_i), .wb_dat_o (dat_o), .wb_ack_o (ack),
    .estop_i (estop_i), .irq_o (irq), .step_o (step), .dir_o (dir)
  );

  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);

  // B4 classic master: hold the request until ack; never touch the pulse configuration words
  // (axis 0, offsets 0x58..0x68: words 86..90).
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
  wire [ADDR_W-3:0] wadr = wb_adr_i[ADDR_W-1:2];
  always @* if (cs && wb_we_i) assume (wadr < 86 || wadr > 90);

  // Core ports inside hexstep_top.
  (* keep *) wire f_start, f_abort, f_stop, f_busy, f_done;

  // Timing at the pins with the reset configuration: high 1, low 1, setup 0, hold 0, no
  // inversion.
  wire f_rise;
  hexstep_fv_stepdir #(.PULSE_W (PULSE_W)) u_chk (
    .clk_i (clk_i), .rst_i (rst_i), .step_i (step), .dir_i (dir),
    .step_high_i (2'd1), .step_low_i (2'd1), .dir_setup_i (2'd0), .dir_hold_i (2'd0),
    .rise_o (f_rise)
  );

  reg p_done, p_busy, p_start, p_abort;
  always @(posedge clk_i) begin
    p_done <= f_done;  p_busy <= f_busy;  p_start <= f_start;  p_abort <= f_abort;
  end
  // Accepted core start at the last edge (port level, as in hexstep_axis_fv).
  wire f_acc = p_have && p_start && !p_abort && !p_busy && f_busy;

  // End to end at the pins: the e-stop pin high in cycle t is first sampled at edge t+1 and
  // the core aborts at edge t+4 (the fourth): no STEP rising edge there; ABORT written by a
  // request in cycle t (acted on at edge t+1) aborts the core at edge t+2: no rise there.
  reg [3:0] f_pin = 4'd0;             // estop_i of the last four cycles, newest in bit 0
  reg [1:0] f_abw = 2'd0;             // an ABORT write of axis 0 one / two cycles ago
  wire      abort_wr = cs && !ack && wb_we_i && wadr == 8'd3 && wb_sel_i[0] && wb_dat_i[0];
  always @(posedge clk_i) begin
    f_pin <= {f_pin[2:0], estop_i && !rst_i};
    f_abw <= {f_abw[0], abort_wr && !rst_i};
  end

  always @* if (!rst_i && p_have) begin
    // hexstep_wb never starts a busy axis (the core would refuse it with err).
    if (f_start) assert (!f_busy);
    if (f_pin[3]) assert (!f_rise);
    if (f_abw[1]) assert (!f_rise);
  end

`ifdef FV_COVER
  (* keep *) wire f_jog;              // the core's jog input (queue head DIR.jog)
  reg [1:0] n_ok = 2'd0;           // moves that ended without abort or stop (saturating)
  reg       chained = 1'b0;        // a move started on the edge right after a done pulse
  reg [2:0] n_rise = 3'd0;         // STEP rising edges since reset (saturating)
  reg       stop_any = 1'b0, abort_any = 1'b0;
  reg       jog_run = 1'b0;        // the running move is a jog move
  always @(posedge clk_i) begin
    if (f_stop) stop_any <= 1'b1;
    if (f_abort) abort_any <= 1'b1;
    if (p_have && p_busy && !f_busy && n_ok != 2'd3) n_ok <= n_ok + 2'd1;
    if (f_acc && p_done && n_ok != 2'd0) chained <= 1'b1;
    if (f_rise && n_rise != 3'd7) n_rise <= n_rise + 3'd1;
    if (f_acc) jog_run <= p_jog;
  end
  reg p_jog;
  always @(posedge clk_i) p_jog <= f_jog;
  always @* if (!rst_i && p_have) begin
    // A chained pair from the queue: two moves, no idle cycle between them, both complete
    // (no ABORT, STOP or e-stop anywhere, at least one step each).
    cover (chained && n_ok == 2'd2 && !f_busy && !stop_any && !abort_any && n_rise >= 3'd2);
    // A STOP through the bus ends a jog move (which has no step count) after two steps.
    cover (p_busy && !f_busy && !p_abort && jog_run && stop_any && !abort_any && n_rise >= 3'd2);
  end
`endif
endmodule

`default_nettype wire
