// SPDX-License-Identifier: Apache-2.0
// hexstep: STEP/DIR output stage of one axis: step requests due at a cycle, pulse timing, DIR
// setup/hold, position counter.
`default_nettype none

// The engine hands over each generated step as a request due at a given cycle (the cycle
// counter g modulo 128); on that cycle the step becomes owed, and an owed step rises as
// soon as the pulse timing allows. Counterpart of hexstep::PulseStage (cpp_model/src/axis.cpp).
//
// Timing, with four intervals loaded from the live configuration at the event that starts
// each (a counter counts down and stops at 1, or stays at 0 if loaded with 0; an interval is
// over when its counter is at most 1):
//   rise:        STEP goes high; high <- step_high, hold <- dir_hold.
//   fall:        at the edge of the last high cycle (high over); low <- step_low.
//   DIR change:  to the target direction when hold is over; setup <- dir_setup.
//   next rise:   a step is owed, STEP is low, low is over, DIR shows the target and setup is
//                over.
// Two counters hold the four intervals: high and low never matter at the same time (STEP high:
// only high; low: only low, reloaded at every fall), nor do hold and setup (a DIR change needs
// hold over and setup is only reloaded then; a rise needs setup over and only then reloads
// hold), so c_step serves high/low by the STEP level and c_dir serves hold/setup by a mode bit.
// So every pulse is exactly step_high cycles high (0 acts as 1), rising edges are at least
// step_high + step_low cycles apart, DIR changes at least dir_hold cycles after a rising edge
// and at least dir_setup cycles before the next one. A configuration written in the middle of
// an interval applies from the next interval on. The step level resets low, DIR level and
// target to 1 (positive motion); the pins are these levels XOR the live polarity inputs.
//
// Three request entries: a request is due up to 68 cycles after the start of its tick's frame,
// so at one step per tick the requests of two earlier ticks can still wait when the next one is
// decided. accepts_o tells the engine that a new request fits (fewer than 3 steps wait, entries
// and owed together); it never sends one otherwise.
module hexstep_pulse #(
  // PULSE_W: width of the pulse timing inputs, in bits (unit: clock cycles). Range 1..16;
  // default 12 (up to 4095 cycles, 40.95 us at 100 MHz, covers the slowest common drivers).
  parameter integer PULSE_W = 12,
  // POS_W: width of the signed (two's complement) position counter, in bits (unit: steps).
  // Range 2..64; default 32. It wraps modulo 2^POS_W, like the model.
  parameter integer POS_W   = 32
) (
  input  wire               clk_i,
  input  wire               rst_i,        // synchronous, active high
  // The cycle counter (modulo 128) after this edge: the engine's g + 1, a register of its own.
  input  wire [6:0]         gn_i,
  // From the engine.
  input  wire               abort_i,      // abort: drop requests and owed steps, no rise
  input  wire               req_i,        // a step request, committed at this edge
  input  wire [6:0]         req_due_i,    // ... due on the cycle with g == req_due_i
  input  wire               tgt_load_i,   // a move starts at this edge: load the DIR target
  input  wire               tgt_dir_i,    // its direction (1: positive)
  // Live timing configuration (clock cycles).
  input  wire [PULSE_W-1:0] step_high_i,  // STEP high time (0 acts as 1)
  input  wire [PULSE_W-1:0] step_low_i,   // minimum STEP low time (0 acts as 1)
  input  wire [PULSE_W-1:0] dir_setup_i,  // DIR stable this long before a rising STEP edge
  input  wire [PULSE_W-1:0] dir_hold_i,   // DIR stable this long after a rising STEP edge
  // Each of {dir_hold_i, dir_setup_i, step_low_i, step_high_i} at most 1 (an interval loaded
  // with it is over at once), from where the values are written: one comparator for all axes.
  input  wire [3:0]         over_i,
  input  wire               step_inv_i,   // STEP pin active low
  input  wire               dir_inv_i,    // DIR pin low for positive motion
  // To the engine.
  output wire               accepts_o,    // a request can be taken
  output wire               pending_o,    // requests or owed steps wait
  output wire               accepts_n_o,  // accepts_o and pending_o after this edge
  output wire               pending_n_o,
  output wire               tgt_o,        // DIR target
  // Pins and position.
  output wire               step_o,
  output wire               dir_o,
  output wire [POS_W-1:0]   pos_o
);

  localparam [PULSE_W-1:0] T_ONE = 1;
  localparam [PULSE_W-1:0] T_TWO = 2;

  // State.
  reg               v0_q, v0_d, v1_q, v1_d, v2_q, v2_d;  // request entries valid
  reg [6:0]         t0_q, t0_d, t1_q, t1_d, t2_q, t2_d;  // ... and their due cycles
  // Each entry's due compare of the next cycle (t == g after this edge), so that no compare
  // of the cycle counter sits in front of the rise condition: mK_q == (tK_q == g) in every
  // cycle of a valid entry (asserted in hexstep_pulse_fv).
  reg               m0_q, m0_d, m1_q, m1_d, m2_q, m2_d;
  reg [1:0]         owed_q, owed_d;      // steps due but not yet pulsed (at most 3)
  reg               step_q, step_d;      // STEP level before polarity (1: pulse high)
  reg               dir_q, dir_d;        // DIR level before polarity (1: positive)
  reg               tgt_q, tgt_d;        // DIR level wanted by the current move
  reg [PULSE_W-1:0] cs_q, cs_d;          // STEP high: high time left; low: low time left
  reg [PULSE_W-1:0] cd_q, cd_d;          // hold mode: DIR hold left; setup mode: setup left
  reg               md_q, md_d;          // c_dir mode (1: hold, 0: setup)
  reg [POS_W-1:0]   pos_q, pos_d;        // signed position
  // Each counter's "interval over" (at most 1), kept in a register beside it so that the rise
  // condition is a few gates of registers.
  reg               cso_q, cso_d, cdo_q, cdo_d;
  // A rise may happen now (rdy): STEP low, low time over, DIR at the target, setup over; and a
  // step is owed. Registered from the next state (rz_q: rdy and a step owed), so that a rise
  // (which loads both counters, the mode and the position) is an abort's gate on a register.
  reg               rdy_d;
  reg               rz_q, rz_d;

  reg dir_change, rise, fall, due0, due1, due2;
  wire req_gn = (req_due_i == gn_i);   // a request due at the next cycle (the same in every stage)

  always @* begin
    // Events, all from the old state.
    due0 = v0_q && m0_q;
    due1 = v1_q && m1_q;
    due2 = v2_q && m2_q;
    // hold over: in hold mode the counter, in setup mode always (hold ended before setup began);
    // setup over: in setup mode the counter, in hold mode always (likewise).
    dir_change = (dir_q != tgt_q) && (cdo_q || !md_q);
    rise = !abort_i && rz_q;
    fall = step_q && cso_q;

    // Next state, defaults first.
    v0_d = v0_q && !due0;
    v1_d = v1_q && !due1;
    v2_d = v2_q && !due2;
    t0_d = t0_q;
    t1_d = t1_q;
    t2_d = t2_q;
    m0_d = (t0_q == gn_i);
    m1_d = (t1_q == gn_i);
    m2_d = (t2_q == gn_i);
    // At most one entry is due per cycle (requests are due on distinct cycles).
    owed_d = owed_q + {1'b0, due0 | due1 | due2} - {1'b0, rise};
    step_d = step_q;
    dir_d = dir_q;
    tgt_d = tgt_q;
    // Count down while the interval runs (a clock enable, not a multiplexer).
    cs_d = cso_q ? cs_q : cs_q - T_ONE;
    cd_d = cdo_q ? cd_q : cd_q - T_ONE;
    md_d = md_q;
    pos_d = pos_q;

    // A request takes the first entry that is free now: accepts_o promised fewer than three
    // waiting steps, so one is (an entry that falls due at this edge is not reused before the
    // next one).
    if (req_i) begin
      if (!v0_q) begin
        v0_d = 1'b1;
        t0_d = req_due_i;
        m0_d = req_gn;
      end else if (!v1_q) begin
        v1_d = 1'b1;
        t1_d = req_due_i;
        m1_d = req_gn;
      end else begin
        v2_d = 1'b1;
        t2_d = req_due_i;
        m2_d = req_gn;
      end
    end
    if (abort_i) begin
      v0_d = 1'b0;
      v1_d = 1'b0;
      v2_d = 1'b0;
      owed_d = 2'd0;
    end
    // The reload value of c_step depends only on the STEP level: high at a rise, low at a fall.
    if (rise || fall) begin
      step_d = !step_q;
      cs_d = step_q ? step_low_i : step_high_i;
    end
    if (rise) begin
      cd_d = dir_hold_i;
      md_d = 1'b1;
      pos_d = pos_q + {{(POS_W-1){~dir_q}}, 1'b1};   // +1 or -1: one adder
    end
    if (dir_change) begin   // never with a rise (DIR differs from the target)
      dir_d = tgt_q;
      cd_d = dir_setup_i;
      md_d = 1'b0;
    end
    if (tgt_load_i) begin
      tgt_d = tgt_dir_i;
    end
    // The same as "cs_d, cd_d at most 1", without the counters' next values on the path: a
    // reload is over if the loaded value is (over_i); a counting counter (at least 2, as its
    // flag is 0) is over next if it is at 2 now.
    cso_d = (rise || fall) ? (step_q ? over_i[1] : over_i[0]) : (cso_q || cs_q == T_TWO);
    cdo_d = rise ? over_i[3] : dir_change ? over_i[2] : (cdo_q || cd_q == T_TWO);
    // !step_d && cso_d && (dir_d == tgt_d) && (cdo_d || md_d), written out: a rise makes STEP
    // high (rdy_d = 0); without one, STEP high falls iff its time is over (then the low time
    // is loaded), DIR follows a change (then setup is loaded and the mode is setup). None of
    // the terms depends on rise, so the rise decision is one gate in front of rz_q.
    rdy_d = !rise && (step_q ? (cso_q && over_i[1]) : (cso_q || cs_q == T_TWO))
            && ((dir_change ? tgt_q : dir_q) == tgt_d)
            && (dir_change ? over_i[2] : (cdo_q || cd_q == T_TWO || md_q));
    // rdy_d && owed_d != 0: with rdy_d there is no rise, so owed_d is owed_q plus a due entry
    // (0 at an abort).
    rz_d = rdy_d && !abort_i && (owed_q != 2'd0 || due0 || due1 || due2);
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      v0_q <= 1'b0;
      v1_q <= 1'b0;
      v2_q <= 1'b0;
      owed_q <= 2'd0;
      step_q <= 1'b0;
      dir_q <= 1'b1;
      tgt_q <= 1'b1;
      cs_q <= {PULSE_W{1'b0}};
      cd_q <= {PULSE_W{1'b0}};
      md_q <= 1'b1;
      pos_q <= {POS_W{1'b0}};
      cso_q <= 1'b1; cdo_q <= 1'b1;
      rz_q <= 1'b0;    // nothing owed (STEP low, both intervals over, DIR at the target)
    end else begin
      cso_q <= cso_d; cdo_q <= cdo_d; md_q <= md_d; rz_q <= rz_d;
      v0_q <= v0_d;
      v1_q <= v1_d;
      v2_q <= v2_d;
      owed_q <= owed_d;
      step_q <= step_d;
      dir_q <= dir_d;
      tgt_q <= tgt_d;
      cs_q <= cs_d;
      cd_q <= cd_d;
      pos_q <= pos_d;
    end
  end

  // Due cycles and their compares: not reset (read only while their entry is valid).
  always @(posedge clk_i) begin
    t0_q <= t0_d;
    t1_q <= t1_d;
    t2_q <= t2_d;
    m0_q <= m0_d;
    m1_q <= m1_d;
    m2_q <= m2_d;
  end

  // A request fits: at most two steps (entries + owed) wait, so an entry is free. Both flags
  // are registers of their next values, accepts_n_o and pending_n_o (the engine registers its
  // start decision from those); they describe the state now, like the unregistered expressions
  // would.
  // The number of waiting steps (entries and owed together, 0..3) is kept as a counter: a
  // request adds one, a rise takes one, an abort clears it (a request falling due only moves
  // from an entry to owed).
  reg  [1:0] wait_q;
  wire [1:0] wait_d = abort_i ? 2'd0 : wait_q + {1'b0, req_i} - {1'b0, rise};
  reg        acc_q, pend_q;
  always @(posedge clk_i) begin
    wait_q <= rst_i ? 2'd0 : wait_d;
    acc_q <= accepts_n_o;
    pend_q <= pending_n_o;
  end
  assign accepts_o = acc_q;
  assign pending_o = pend_q;
  assign accepts_n_o = rst_i | (wait_d != 2'd3);    // reset: nothing waits
  assign pending_n_o = ~rst_i & (wait_d != 2'd0);
  assign tgt_o = tgt_q;
  assign step_o = step_q ^ step_inv_i;
  assign dir_o = dir_q ^ dir_inv_i;
  assign pos_o = pos_q;

endmodule

`default_nettype wire
