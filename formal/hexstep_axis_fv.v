// SPDX-License-Identifier: Apache-2.0
// hexstep formal: harness of hexstep_axis (one axis with its hexstep_pulse child).
`default_nettype none

// Every move input, start, abort (and, with FV_STOPJOG, stop and jog) is free in every cycle;
// the pulse timing and polarity are $anyconst. The harness follows each move from its
// accepted start (seen at the ports: a start with the axis idle and not aborted after which
// busy_o rises) and counts the STEP rising edges of the move.
//
// Reduced widths for tractability (docs/FORMAL.md): SPEED_W = 8, ACC_W = 6, STEP_W = 4,
// DFRAC_W = 4, PULSE_W = 2, POS_W = 4, OWE_W = 2 (the default).
//
// Defines: FV_STOPJOG lets stop_i and jog_i run free (else both are tied to 0, the move
// behaviour of the first increment); FV_COVER adds the cover statements.
module hexstep_axis_fv #(
  parameter integer SPEED_W = 8,
  parameter integer ACC_W   = 6,
  parameter integer STEP_W  = 4,
  parameter integer DFRAC_W = 4,
  parameter integer PULSE_W = 2,
  parameter integer POS_W   = 4,
  parameter integer OWE_W   = 2
) (
  input wire               clk_i,
  input wire               rst_i,
  input wire               start_i,
  input wire               abort_i,
  input wire               stop_in,
  input wire               jog_in,
  input wire [STEP_W-1:0]  steps_i,
  input wire               dir_i,
  input wire [SPEED_W-1:0] v_start_i,
  input wire [SPEED_W-1:0] v_max_i,
  input wire [SPEED_W-1:0] v_end_i,
  input wire [SPEED_W-1:0] v_dec_i,
  input wire [ACC_W-1:0]   acc_i,
  input wire [ACC_W-1:0]   dec_i,
  input wire [STEP_W-1:0]  acc_steps_i,
  input wire [STEP_W-1:0]  dec_step_i,
  input wire [DFRAC_W-1:0] dec_frac_i
);
  (* anyconst *) reg [PULSE_W-1:0] f_high, f_low, f_setup, f_hold;
  (* anyconst *) reg               f_sinv, f_dinv;

  // ---- inputs added after the first increment: tied here, in one place ----
`ifdef FV_STOPJOG
  wire stop = stop_in;
  wire jog  = jog_in;
`else
  wire stop = 1'b0;
  wire jog  = 1'b0;
`endif

  wire             step, dir, busy, done, err;
  wire [1:0]       phase;
  wire [POS_W-1:0] pos;

  hexstep_axis #(
    .SPEED_W (SPEED_W), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .OWE_W (OWE_W)
  ) u_dut (
    .clk_i (clk_i), .rst_i (rst_i), .start_i (start_i), .abort_i (abort_i), .stop_i (stop),
    .steps_i (steps_i), .dir_i (dir_i), .jog_i (jog),
    .v_start_i (v_start_i), .v_max_i (v_max_i), .v_end_i (v_end_i), .v_dec_i (v_dec_i),
    .acc_i (acc_i), .dec_i (dec_i), .acc_steps_i (acc_steps_i), .dec_step_i (dec_step_i),
    .dec_frac_i (dec_frac_i),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .step_inv_i (f_sinv), .dir_inv_i (f_dinv),
    .step_o (step), .dir_o (dir), .busy_o (busy), .done_o (done), .err_o (err),
    .phase_o (phase), .pos_o (pos)
  );

  // Reset in the first cycle only.
  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  always @* assume (rst_i == !f_past);

  // STEP/DIR timing at the axis pins (the child's properties, asserted in the parent).
  wire step_l = step ^ f_sinv;
  wire dir_l  = dir ^ f_dinv;
  wire f_rise;
  hexstep_fv_stepdir #(.PULSE_W (PULSE_W)) u_chk (
    .clk_i (clk_i), .rst_i (rst_i), .step_i (step_l), .dir_i (dir_l),
    .step_high_i (f_high), .step_low_i (f_low), .dir_setup_i (f_setup), .dir_hold_i (f_hold),
    .rise_o (f_rise), .dist_rise_o (f_dist_r), .dist_dir_o (f_dist_d)
  );
  wire [PULSE_W+1:0] f_dist_r, f_dist_d;
  (* keep *) wire [PULSE_W:0]   f_pc;   // u_dut.u_pulse.c_q, cycles since the last rise
  (* keep *) wire [PULSE_W-1:0] f_pd;   // u_dut.u_pulse.d_q, cycles since the last DIR change


  // ---- previous-cycle samples ----
  reg               p_have = 1'b0;
  reg               p_start, p_abort, p_stop, p_busy, p_jog, p_dir;
  reg [1:0]         p_phase;
  reg [STEP_W-1:0]  p_steps;
  reg [SPEED_W-1:0] p_vstart, p_vmax, p_vend, p_vdec;
  reg [ACC_W-1:0]   p_dec;
  always @(posedge clk_i) begin
    p_have <= !rst_i;
    p_start <= start_i;  p_abort <= abort_i;  p_stop <= stop;  p_busy <= busy;
    p_jog <= jog;  p_dir <= dir_i;  p_phase <= phase;  p_steps <= steps_i;
    p_vstart <= v_start_i;  p_vmax <= v_max_i;  p_vend <= v_end_i;  p_vdec <= v_dec_i;
    p_dec <= dec_i;
  end

  // ---- the current move, from the ports ----
  // Accepted start at the last edge: start, idle, no abort, and busy rose.
  wire f_acc = p_have && p_start && !p_abort && !p_busy && busy;
  wire f_fall = p_have && p_busy && !busy;

  reg               m_valid = 1'b0;   // a move was accepted since reset
  reg [STEP_W-1:0]  m_n;              // its N
  reg               m_jog, m_stopped, m_dir;
  reg [STEP_W:0]    m_r;              // STEP rising edges of the move (saturating)
  reg [SPEED_W-1:0] m_vstart, m_vmax, m_floor, m_vdec;
  reg               m_acc_seen, m_cru_seen, m_dec_seen;   // covers only

  wire [SPEED_W-1:0] dec_x = {{(SPEED_W-ACC_W){1'b0}}, p_dec};
  // Current values (this cycle), the registers hold them from the next cycle on.
  wire              c_valid = m_valid || f_acc;
  wire [STEP_W-1:0] c_n     = f_acc ? p_steps : m_n;
  wire              c_jog   = f_acc ? p_jog : m_jog;
  wire              c_stopped = f_acc ? 1'b0 : (m_stopped || (p_have && p_stop && p_phase != 2'd0 && !p_abort));
  wire [STEP_W:0]   r_base  = f_acc ? {(STEP_W+1){1'b0}} : m_r;
  wire [STEP_W:0]   c_r     = (f_rise && r_base != {(STEP_W+1){1'b1}}) ? r_base + 1'b1 : r_base;
  wire [SPEED_W-1:0] c_vstart = f_acc ? p_vstart : m_vstart;
  wire [SPEED_W-1:0] c_vmax   = f_acc ? p_vmax : m_vmax;
  wire [SPEED_W-1:0] c_floor  = f_acc ? (p_vend != 0 ? p_vend : dec_x) : m_floor;
  wire [SPEED_W-1:0] c_vdec   = f_acc ? p_vdec : m_vdec;
  wire               c_dir    = f_acc ? p_dir : m_dir;

  always @(posedge clk_i) begin
    if (rst_i) begin
      m_valid <= 1'b0;
      m_r <= {(STEP_W+1){1'b0}};
      m_stopped <= 1'b0;
      m_jog <= 1'b0;
    end else begin
      m_valid <= c_valid;
      m_n <= c_n;  m_jog <= c_jog;  m_stopped <= c_stopped;  m_r <= c_r;  m_dir <= c_dir;
      m_vstart <= c_vstart;  m_vmax <= c_vmax;  m_floor <= c_floor;  m_vdec <= c_vdec;
    end
  end

  // ---- internal state for the speed bounds and the induction invariants ----
  // Connected by the .sby script after flattening (`connect -set`, which fails if a name is
  // gone). These are observations only: every property on them is asserted, none assumed.
  (* keep *) wire               f_run;       // u_dut.run_q
  (* keep *) wire [OWE_W-1:0]   f_owed;      // u_dut.owed_q
  (* keep *) wire [STEP_W-1:0]  f_cnt;       // u_dut.cnt_q
  (* keep *) wire [STEP_W-1:0]  f_steps;     // u_dut.steps_q
  (* keep *) wire [SPEED_W-1:0] f_s;         // u_dut.s_q, the speed accumulator
  (* keep *) wire               f_dfirst;    // u_dut.dec_first_q
  (* keep *) wire [SPEED_W-1:0] f_vmax_q;    // u_dut.v_max_q
  (* keep *) wire [SPEED_W-1:0] f_floor_q;   // u_dut.floor_q
  (* keep *) wire [SPEED_W-1:0] f_vdec_q;    // u_dut.v_dec_q
  (* keep *) wire               f_accept;    // u_dut.accept (the pulse child's tgt_load_i)
  (* keep *) wire               f_stop_q;    // u_dut.stop_q
  (* keep *) wire               f_jog_q;     // u_dut.jog_q
  (* keep *) wire               f_tgt;       // u_dut.u_pulse.tgt_q

  wire [SPEED_W-1:0] lo_bound = (c_vstart < c_floor) ? c_vstart : c_floor;
  wire [SPEED_W-1:0] dec_hi   = (c_vdec > c_floor) ? c_vdec : c_floor;
  reg  [SPEED_W-1:0] p_s;
  always @(posedge clk_i) p_s <= f_s;

  always @* begin
    if (!rst_i && p_have) begin
      // -- no STEP pulse while idle, none at an abort edge --
      if (f_rise) assert (p_busy && !p_abort);
      // -- ABORT: the move ends at the abort edge (busy low, done pulses) --
      if (p_abort) assert (!busy && (phase == 2'd0));
      if (p_abort && p_busy) assert (done);
      // -- at most N steps per move; busy falls only after the N-th step --
      if (c_valid && !c_jog) assert (c_r <= {1'b0, c_n});
      if (f_fall && !p_abort && !c_stopped && !c_jog) assert (c_r == {1'b0, c_n});
      // -- a jog move ends only by STOP or ABORT --
      if (f_fall && c_jog) assert (p_abort || c_stopped);
      if (!busy) assert (phase == 2'd0);
      // -- done exactly when busy falls, or for a start refused/empty at the last edge --
      if (f_fall) assert (done);
      if (done) assert (f_fall || (p_start && !p_abort && !p_busy && !busy));
      // -- a start while busy is refused with err and leaves the move alone --
      if (p_start && !p_abort && p_busy) assert (err && !f_acc);
      if (err) assert (p_start && !p_abort);
      // -- the pulse child's assumption, asserted here: the DIR target loads only with nothing owed --
      if (f_accept) assert (f_owed == {OWE_W{1'b0}});
      // -- pulses go out in the move's direction --
      if (f_rise) assert (dir_l == c_dir);

      // -- speed accumulator within the programmed bounds while a move runs --
      if (f_run) begin
        assert (f_s <= c_vmax);
        if (!c_stopped) begin
          assert (f_s >= lo_bound);
          if (phase == 2'd1 || phase == 2'd2) assert (f_s >= c_vstart);
          if (phase == 2'd3 && !f_dfirst) assert (f_s >= c_floor && f_s <= dec_hi);
        end else if (m_stopped && !f_acc) begin
          // stopping: from the first stopping tick on, the speed never grows again
          assert (f_s <= p_s);
        end
      end

      // -- induction invariants (asserted) --
      assert (f_run == (phase != 2'd0));
      assert (busy == (f_run || f_owed != {OWE_W{1'b0}}));
      if (busy) assert (c_valid);
      if (c_valid) begin
        assert (f_vmax_q == c_vmax && f_floor_q == c_floor && f_vdec_q == c_vdec);
        assert (c_vstart <= c_vmax && c_vmax != 0);
        if (!c_jog) assert (c_vdec <= c_vmax && c_floor <= c_vmax);
        assert (f_jog_q == c_jog);
        if (!c_jog) begin
          assert (f_steps == c_n);
          if (busy) assert ({1'b0, f_cnt} == c_r + f_owed);
          if (f_run) assert (f_cnt < f_steps);
          if (busy) assert (f_cnt <= f_steps);
          if (busy && !f_run && !c_stopped) assert (f_cnt == f_steps);
        end
      end
      if (f_run) assert (f_stop_q == c_stopped);
      if (f_run && f_stop_q) assert (phase == 2'd3 && !f_dfirst);
      if (f_run && c_jog && !f_stop_q) assert (phase != 2'd3);
      if (busy && !f_run && c_jog) assert (c_stopped);
      assert (f_tgt == (c_valid ? c_dir : 1'b1));
`ifndef FV_STOPJOG
      assert (!c_stopped && !c_jog);
`endif
    end
  end

  // Induction invariants linking the pulse stage's counters to the checker's (asserted):
  // cycles since the last rise / DIR change = edges since it + 1, both saturating.
  localparam integer FCW = PULSE_W + 3;
  wire [FCW-1:0] f_cr = {1'b0, f_dist_r} + 1'b1;
  wire [FCW-1:0] f_cd = {1'b0, f_dist_d} + 1'b1;
  wire [FCW-1:0] f_cmax = {FCW{1'b0}} | {(PULSE_W+1){1'b1}};
  wire [FCW-1:0] f_dmax = {FCW{1'b0}} | {PULSE_W{1'b1}};
  always @* if (!rst_i && p_have) begin
    assert ({2'b00, f_pc} == ((f_cr > f_cmax) ? f_cmax : f_cr));
    assert ({3'b000, f_pd} == ((f_cd > f_dmax) ? f_dmax : f_cd));
  end

`ifdef FV_COVER
  // Phases in which the current move pulsed a step (STEP rising edge while the generator was
  // in that phase).
  wire c_acc_seen = (f_acc ? 1'b0 : m_acc_seen) | (f_rise && p_phase == 2'd1);
  wire c_cru_seen = (f_acc ? 1'b0 : m_cru_seen) | (f_rise && p_phase == 2'd2);
  wire c_dec_seen = (f_acc ? 1'b0 : m_dec_seen) | (f_rise && p_phase == 2'd3);
  reg  [1:0] m_done_ok = 2'd0;        // moves that ended normally (saturating at 3)
  reg        p_done;
  always @(posedge clk_i) begin
    m_acc_seen <= c_acc_seen;  m_cru_seen <= c_cru_seen;  m_dec_seen <= c_dec_seen;
    p_done <= done;
    if (f_fall && !p_abort && !c_stopped && m_done_ok != 2'd3) m_done_ok <= m_done_ok + 2'd1;
  end
  wire end_ok = f_fall && !p_abort && !c_stopped && !c_jog;
  always @* if (!rst_i && p_have) begin
    // A complete triangular move: steps while accelerating and while decelerating, none
    // while cruising, all N steps.
    cover (end_ok && c_acc_seen && c_dec_seen && !c_cru_seen && c_n >= 3);
    // A complete trapezoidal move: steps in each of the three phases.
    cover (end_ok && c_acc_seen && c_cru_seen && c_dec_seen);
    // A chained pair: a move starts on the edge right after the previous one's done pulse.
    cover (f_acc && p_done && m_done_ok != 2'd0 && c_valid);
`ifdef FV_STOPJOG
    // A STOP: a move that was stopped comes to rest before its N-th step, after a step.
    cover (f_fall && !p_abort && c_stopped && !c_jog && c_r != {1'b0, c_n} && c_r != 0);
    // A jog move that STOP ends after two steps.
    cover (f_fall && !p_abort && c_jog && c_r >= 2);
`endif
  end
`endif
endmodule

`default_nettype wire
