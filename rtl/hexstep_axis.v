// SPDX-License-Identifier: Apache-2.0
// hexstep: one axis: move validation, speed/position accumulators, phase sequencer, step counter.
`default_nettype none

// Bit-exact counterpart of AxisModel::tick() (cpp_model/src/axis.cpp); the STEP/DIR pulse
// stage is the submodule hexstep_pulse.
//
// The generator runs one tick per clock cycle while a move is running and fewer than
// 2^OWE_W-1 generated steps wait for their STEP pulse: the position fraction p accumulates the
// speed s (unit 2^-SPEED_W step per tick), and every carry out of p is one step, counted in cnt
// and handed to the pulse stage through the owed counter. The phase sequencer ramps s up by
// acc (clamped at v_max) until acc_steps steps are done, cruises, and decelerates once the
// position reaches dec_step + dec_frac/2^DFRAC_W: the first decelerating tick loads v_dec, later
// ones subtract dec, and neither goes below the floor (v_end or, if that is 0, dec). The move
// ends when cnt reaches steps.
//
// STOP (stop_i, a strobe while the move runs) is a controlled stop: from the next tick on the
// axis decelerates from its current speed by dec per tick, ignoring v_dec and the floor, and
// the move ends on the first such tick whose old speed is below dec (the speed would reach or
// cross zero), or at once on the next tick if dec is 0; it also still ends at N steps. No step
// is generated beyond the position the decelerating motion reaches.
// A jog move (jog_i at the start) ignores steps, acc_steps, dec_step and dec_frac: it ramps
// from v_start by acc up to v_max, cruises, and ends only by STOP (or ABORT).
//
// Move inputs are sampled only at an accepted start strobe (not busy, no abort, valid move
// with steps != 0 or jog). Pulse timing and polarity inputs are used live every cycle.
//
// Reset: all control state is reset (run, phase, dec_first, stop, jog, owed, cnt, done, err and all of
// hexstep_pulse). The speed accumulator s_q, the position fraction p_q and the latched move
// registers (*_q of the "move registers" group) are not reset: each of them is read only while
// run_q is set, and run_q can only become set at an accepted start, which writes all of them
// in the same cycle. Their reset value can therefore never reach an output.
module hexstep_axis #(
  // SPEED_W: bits of the speed accumulator and of the position fraction (unit: 2^-SPEED_W
  // step per clock cycle). Range 2..64 (the C++ model holds them in uint64_t); default 64,
  // which resolves 100 MHz / 2^64, far below any useful step rate, and makes the speed
  // register span 0..1 step per cycle.
  parameter integer SPEED_W = 64,
  // ACC_W: bits of the acceleration/deceleration registers (unit: 2^-SPEED_W step per cycle
  // per cycle). Range 1..SPEED_W; default 44, enough to reach full speed in 2^20 cycles.
  parameter integer ACC_W   = 44,
  // STEP_W: bits of the step counts steps/acc_steps/dec_step (unit: steps). Range 1..32 (the
  // model holds them in uint32_t); default 32, the longest move of 2^32-1 steps.
  parameter integer STEP_W  = 32,
  // DFRAC_W: fraction bits of the deceleration start position (unit: 2^-DFRAC_W step).
  // Range 1..SPEED_W; default 32, compared with the top 32 bits of the position fraction: at
  // 1 step/s and 100 MHz consecutive tick positions differ by 1e-8 step > 2^-27, so the 2^-32
  // grid can place the threshold between any two of them.
  parameter integer DFRAC_W = 32,
  // PULSE_W: bits of the pulse timing inputs (unit: clock cycles). Range 1..30 (the model
  // counts high+low time in uint32_t); default 12, up to 4095 cycles (40.95 us at 100 MHz).
  parameter integer PULSE_W = 12,
  // POS_W: bits of the signed position counter (unit: steps). Range 2..64; default 32. It
  // wraps modulo 2^POS_W.
  parameter integer POS_W   = 32,
  // OWE_W: bits of the counter of steps generated but not yet pulsed. Range 1..16; default 2:
  // up to 3 steps may wait (the generator pauses when 3 do), which absorbs the DIR setup time
  // and a STEP period longer than the step interval for a few steps without a pause.
  parameter integer OWE_W   = 2
) (
  input  wire               clk_i,
  input  wire               rst_i,         // synchronous, active high
  input  wire               start_i,       // start strobe (ignored while abort_i is high)
  input  wire               abort_i,       // abort: stop the move and drop owed steps
  input  wire               stop_i,        // controlled stop strobe (ignored unless running)
  // Move, sampled at an accepted start strobe.
  input  wire [STEP_W-1:0]  steps_i,       // exact number of steps (0: no move, done only)
  input  wire               dir_i,         // 1: positive direction
  input  wire               jog_i,         // continuous move: runs until STOP
  input  wire [SPEED_W-1:0] v_start_i,     // initial speed
  input  wire [SPEED_W-1:0] v_max_i,       // speed ceiling while accelerating
  input  wire [SPEED_W-1:0] v_end_i,       // speed floor while decelerating (0: floor = dec)
  input  wire [SPEED_W-1:0] v_dec_i,       // speed loaded on the first decelerating tick
  input  wire [ACC_W-1:0]   acc_i,         // added to the speed every tick while accelerating
  input  wire [ACC_W-1:0]   dec_i,         // subtracted every later decelerating tick
  input  wire [STEP_W-1:0]  acc_steps_i,   // acceleration ends after this many steps
  input  wire [STEP_W-1:0]  dec_step_i,    // deceleration starts at dec_step + dec_frac/2^DFRAC_W
  input  wire [DFRAC_W-1:0] dec_frac_i,
  // Pulse timing and polarity, used live.
  input  wire [PULSE_W-1:0] step_high_i,   // STEP high time in cycles (0 acts as 1)
  input  wire [PULSE_W-1:0] step_low_i,    // minimum STEP low time in cycles (0 acts as 1)
  input  wire [PULSE_W-1:0] dir_setup_i,   // DIR setup before a rising STEP edge, cycles
  input  wire [PULSE_W-1:0] dir_hold_i,    // DIR hold after a rising STEP edge, cycles
  input  wire               step_inv_i,    // STEP pin active low
  input  wire               dir_inv_i,     // DIR pin low for positive motion
  // Status.
  output wire               step_o,        // STEP pin
  output wire               dir_o,         // DIR pin
  output wire               busy_o,        // move running or steps still to be pulsed
  output wire               done_o,        // one-cycle pulse: move finished/aborted/refused
  output wire               err_o,         // one-cycle pulse: invalid move or start while busy
  output wire [1:0]         phase_o,       // 0 idle, 1 accelerate, 2 cruise, 3 decelerate
  output wire [POS_W-1:0]   pos_o          // signed position, two's complement, wraps
);

  localparam [1:0] PH_IDLE   = 2'd0;
  localparam [1:0] PH_ACCEL  = 2'd1;
  localparam [1:0] PH_CRUISE = 2'd2;
  localparam [1:0] PH_DECEL  = 2'd3;

  localparam [OWE_W-1:0]  OWE_MAX = {OWE_W{1'b1}};
  localparam [OWE_W-1:0]  OWE_ONE = 1;
  localparam [STEP_W-1:0] CNT_ONE = 1;

  // ---- registers ----
  // Control state (reset).
  reg               run_q, run_d;
  reg [1:0]         phase_q, phase_d;
  reg               dec_first_q, dec_first_d;  // the next decelerating tick loads v_dec
  reg               stop_q, stop_d;        // stopping: decelerate to rest by dec per tick
  reg [OWE_W-1:0]   owed_q, owed_d;        // steps generated but not yet pulsed
  reg [STEP_W-1:0]  cnt_q, cnt_d;          // steps generated in this move
  reg               done_q, done_d;
  reg               err_q, err_d;
  // Generator datapath (not reset, see the header).
  reg [SPEED_W-1:0] s_q, s_d;              // speed
  reg [SPEED_W-1:0] p_q, p_d;              // position fraction
  // Move registers, latched at an accepted start (not reset, see the header).
  reg [STEP_W-1:0]  steps_q, steps_d;
  reg [SPEED_W-1:0] v_max_q, v_max_d;
  reg [SPEED_W-1:0] floor_q, floor_d;      // v_end != 0 ? v_end : dec
  reg [SPEED_W-1:0] v_dec_q, v_dec_d;
  reg [ACC_W-1:0]   acc_q, acc_d;
  reg [ACC_W-1:0]   dec_q, dec_d;
  reg [STEP_W-1:0]  acc_steps_q, acc_steps_d;
  reg [STEP_W-1:0]  dec_step_q, dec_step_d;
  reg [DFRAC_W-1:0] dec_frac_q, dec_frac_d;
  reg               jog_q, jog_d;          // jog move: no step count end, no planned decel

  // ---- combinational signals ----
  wire              rise;                  // from the pulse stage: a step is pulsed now
  // run || owed != 0 before this edge (a wire of registers only: hexstep_wb gates START with
  // it, so it must not share an always block with start_i) and after it.
  wire              busy_now = run_q || (owed_q != {OWE_W{1'b0}});
  reg               busy_nxt;
  reg               accept;                // accepted start: load the move
  // Validation of the move inputs (validate_move()).
  reg               steps_nz, decel_now, bad, bad_jog;
  // Generator.
  reg               gen, carry, clamp, borrow, dec_trig, stop_end, cnt_end;
  reg [SPEED_W:0]   p_sum;                 // p + s, carry in the top bit
  reg [STEP_W-1:0]  cnt_inc;               // cnt + carry
  reg [SPEED_W-1:0] acc_x, dec_x, dec_in_x;  // acc/dec zero-extended to SPEED_W
  reg [SPEED_W:0]   s_up;                  // s + acc (65-bit sum for the clamp)
  reg [SPEED_W:0]   s_dn;                  // s - dec, borrow in the top bit
  reg [SPEED_W-1:0] s_dt;                  // decelerating target: v_dec on the first tick

  always @* begin
    // ---- defaults: hold ----
    run_d = run_q;
    phase_d = phase_q;
    dec_first_d = dec_first_q;
    stop_d = stop_q;
    owed_d = owed_q;
    cnt_d = cnt_q;
    s_d = s_q;
    p_d = p_q;
    done_d = 1'b0;
    err_d = 1'b0;
    steps_d = steps_q;
    v_max_d = v_max_q;
    floor_d = floor_q;
    v_dec_d = v_dec_q;
    acc_d = acc_q;
    dec_d = dec_q;
    acc_steps_d = acc_steps_q;
    dec_step_d = dec_step_q;
    dec_frac_d = dec_frac_q;
    jog_d = jog_q;
    accept = 1'b0;

    // ---- validation of the move at the inputs ----
    dec_in_x = {SPEED_W{1'b0}};
    dec_in_x[ACC_W-1:0] = dec_i;
    steps_nz = (steps_i != {STEP_W{1'b0}});
    decel_now = (dec_step_i == {STEP_W{1'b0}}) && (dec_frac_i == {DFRAC_W{1'b0}});
    bad = (v_max_i == {SPEED_W{1'b0}}) ||
          (v_start_i > v_max_i) ||
          (v_end_i > v_max_i) ||
          ((v_end_i == {SPEED_W{1'b0}}) && (dec_in_x > v_max_i)) ||   // floor dec above v_max
          (v_dec_i > v_max_i) ||
          (acc_steps_i > steps_i) || (dec_step_i > steps_i) ||
          ((v_end_i == {SPEED_W{1'b0}}) && (dec_i == {ACC_W{1'b0}})) ||
          (!decel_now && (v_start_i == {SPEED_W{1'b0}}) &&
           ((acc_i == {ACC_W{1'b0}}) || (acc_steps_i == {STEP_W{1'b0}})));
    bad_jog = (v_max_i == {SPEED_W{1'b0}}) ||
              (v_start_i > v_max_i) ||
              ((v_start_i == {SPEED_W{1'b0}}) && (acc_i == {ACC_W{1'b0}})) ||
              (dec_i == {ACC_W{1'b0}});

    // ---- generator, from the old state ----
    gen = run_q && (owed_q != OWE_MAX);
    p_sum = {1'b0, p_q} + {1'b0, s_q};
    carry = gen && p_sum[SPEED_W];
    cnt_inc = carry ? cnt_q + CNT_ONE : cnt_q;

    acc_x = {SPEED_W{1'b0}};
    acc_x[ACC_W-1:0] = acc_q;
    dec_x = {SPEED_W{1'b0}};
    dec_x[ACC_W-1:0] = dec_q;
    s_up = {1'b0, s_q} + {1'b0, acc_x};
    s_dn = {1'b0, s_q} - {1'b0, dec_x};
    clamp = (phase_q == PH_ACCEL) && (s_up >= {1'b0, v_max_q});
    borrow = !dec_first_q && s_dn[SPEED_W];
    s_dt = dec_first_q ? v_dec_q : s_dn[SPEED_W-1:0];
    // Stopping: this tick's old speed is below dec (or dec is 0), so the motion is at rest.
    stop_end = stop_q && (s_dn[SPEED_W] || (dec_q == {ACC_W{1'b0}}));
    cnt_end = !jog_q && (cnt_inc == steps_q);

    dec_trig = !jog_q && (phase_q != PH_DECEL) &&
               (((cnt_inc == dec_step_q) && (p_sum[SPEED_W-1 -: DFRAC_W] >= dec_frac_q)) ||
                ((cnt_q == dec_step_q) && carry));

    if (gen) begin
      p_d = p_sum[SPEED_W-1:0];
      cnt_d = cnt_inc;
      if (phase_q == PH_ACCEL) begin
        s_d = clamp ? v_max_q : s_up[SPEED_W-1:0];
      end else if (phase_q == PH_DECEL) begin
        if (stop_q) begin
          s_d = s_dn[SPEED_W-1:0];
        end else begin
          s_d = (borrow || (s_dt < floor_q)) ? floor_q : s_dt;
        end
        dec_first_d = 1'b0;
      end
      if (cnt_end || stop_end) begin
        run_d = 1'b0;
        phase_d = PH_IDLE;
      end else if (dec_trig) begin
        phase_d = PH_DECEL;
        dec_first_d = 1'b1;
      end else if ((phase_q == PH_ACCEL) &&
                   (clamp || (!jog_q && (cnt_inc == acc_steps_q)))) begin
        phase_d = PH_CRUISE;
      end
    end

    // STOP: from the next tick on, decelerate by dec from the speed reached (a stop strobe in
    // the tick that ends the move, or while not running, does nothing).
    if (stop_i && run_d && !abort_i) begin
      stop_d = 1'b1;
      phase_d = PH_DECEL;
      dec_first_d = 1'b0;
    end

    // owed + carry - rise (a carry needs owed < max, a rise needs owed > 0: no wrap)
    if (carry && !rise) begin
      owed_d = owed_q + OWE_ONE;
    end else if (!carry && rise) begin
      owed_d = owed_q - OWE_ONE;
    end

    // ---- start / abort ----
    if (abort_i) begin
      run_d = 1'b0;
      phase_d = PH_IDLE;
      owed_d = {OWE_W{1'b0}};
    end else if (start_i) begin
      if (busy_now) begin
        err_d = 1'b1;                      // start strobe for a busy axis: refused
      end else if (jog_i ? bad_jog : (!steps_nz || bad)) begin
        done_d = 1'b1;                     // empty move (done only) or invalid move
        err_d = jog_i || steps_nz;
      end else begin
        accept = 1'b1;
        steps_d = steps_i;
        v_max_d = v_max_i;
        floor_d = (v_end_i != {SPEED_W{1'b0}}) ? v_end_i : dec_in_x;
        v_dec_d = v_dec_i;
        acc_d = acc_i;
        dec_d = dec_i;
        acc_steps_d = acc_steps_i;
        dec_step_d = dec_step_i;
        dec_frac_d = dec_frac_i;
        s_d = v_start_i;
        p_d = {SPEED_W{1'b0}};
        cnt_d = {STEP_W{1'b0}};
        run_d = 1'b1;
        dec_first_d = 1'b1;
        stop_d = 1'b0;
        jog_d = jog_i;
        if (jog_i) begin
          phase_d = (acc_i != {ACC_W{1'b0}}) ? PH_ACCEL : PH_CRUISE;
        end else begin
          phase_d = decel_now ? PH_DECEL :
                    (acc_steps_i != {STEP_W{1'b0}}) ? PH_ACCEL : PH_CRUISE;
        end
      end
    end

    busy_nxt = run_d || (owed_d != {OWE_W{1'b0}});
    if (busy_now && !busy_nxt) begin
      done_d = 1'b1;
    end
  end

  // Control state.
  always @(posedge clk_i) begin
    if (rst_i) begin
      run_q <= 1'b0;
      phase_q <= PH_IDLE;
      dec_first_q <= 1'b0;
      stop_q <= 1'b0;
      jog_q <= 1'b0;
      owed_q <= {OWE_W{1'b0}};
      cnt_q <= {STEP_W{1'b0}};
      done_q <= 1'b0;
      err_q <= 1'b0;
    end else begin
      run_q <= run_d;
      phase_q <= phase_d;
      dec_first_q <= dec_first_d;
      stop_q <= stop_d;
      jog_q <= jog_d;
      owed_q <= owed_d;
      cnt_q <= cnt_d;
      done_q <= done_d;
      err_q <= err_d;
    end
  end

  // Datapath and move registers: no reset (see the header).
  always @(posedge clk_i) begin
    s_q <= s_d;
    p_q <= p_d;
    steps_q <= steps_d;
    v_max_q <= v_max_d;
    floor_q <= floor_d;
    v_dec_q <= v_dec_d;
    acc_q <= acc_d;
    dec_q <= dec_d;
    acc_steps_q <= acc_steps_d;
    dec_step_q <= dec_step_d;
    dec_frac_q <= dec_frac_d;
  end

  hexstep_pulse #(
    .PULSE_W (PULSE_W),
    .POS_W   (POS_W)
  ) u_pulse (
    .clk_i       (clk_i),
    .rst_i       (rst_i),
    .owed_nz_i   (owed_q != {OWE_W{1'b0}}),
    .abort_i     (abort_i),
    .tgt_load_i  (accept),
    .tgt_dir_i   (dir_i),
    .step_high_i (step_high_i),
    .step_low_i  (step_low_i),
    .dir_setup_i (dir_setup_i),
    .dir_hold_i  (dir_hold_i),
    .step_inv_i  (step_inv_i),
    .dir_inv_i   (dir_inv_i),
    .rise_o      (rise),
    .step_o      (step_o),
    .dir_o       (dir_o),
    .pos_o       (pos_o)
  );

  assign busy_o = busy_now;
  assign done_o = done_q;
  assign err_o = err_q;
  assign phase_o = phase_q;

endmodule

`default_nettype wire
