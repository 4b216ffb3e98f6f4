// SPDX-License-Identifier: Apache-2.0
// hexstep: what software sees: the Wishbone register block (hexstep_wb), the frame engine
// (hexstep_engine) and one STEP/DIR output stage per axis (hexstep_pulse).
`default_nettype none

// Register map: rdl/hexstep.rdl, docs/REGISTERS.md. Counterpart: hexstep::TopModel
// (cpp_model/src/top_model.cpp), compared with this module after every clock edge by the
// co-simulation tests. The clock frequency is not a parameter: it enters through the register
// values (one tick of every axis per frame of 32 cycles; docs/ARCHITECTURE.md).
module hexstep_top #(
  // NAXES: axes (unit: axes). Range 1..8 (the slots of a frame); default 6.
  parameter integer NAXES     = 6,
  // ACC_W: bits of the acceleration/deceleration registers (unit: 2^-64 step per tick per
  // tick). Range 1..64; default 48: 2^48 LSB = 2^-16 step/tick^2, 1.5e8 steps/s^2 at 100 MHz.
  parameter integer ACC_W     = 48,
  // STEP_W: bits of the step counts (unit: steps). Range 1..32; default 32.
  parameter integer STEP_W    = 32,
  // DFRAC_W: fraction bits of the deceleration start position (unit: 2^-DFRAC_W step).
  // Range 1..32; default 32.
  parameter integer DFRAC_W   = 32,
  // PULSE_W: bits of the pulse timing registers (unit: clock cycles). Range 1..16; default 12:
  // up to 4095 cycles, 40.95 us at 100 MHz.
  parameter integer PULSE_W   = 12,
  // POS_W: bits of the signed, wrapping position counter (unit: steps). Range 2..64; default 32.
  parameter integer POS_W     = 32,
  // ADDR_W: byte address bits. Range 12..32; default 12.
  parameter integer ADDR_W    = 12,
  // RAM_STYLE: memory implementation, "DELAY" (generic, iCE40) or "ECP5" (hexstep_ram).
  parameter         RAM_STYLE = "DELAY"
) (
  input  wire              clk_i,
  input  wire              rst_i,       // synchronous, active high
  input  wire              wb_cyc_i,
  input  wire              wb_stb_i,
  input  wire              wb_we_i,
  input  wire [ADDR_W-1:0] wb_adr_i,
  input  wire [31:0]       wb_dat_i,
  input  wire [3:0]        wb_sel_i,
  output wire [31:0]       wb_dat_o,
  output wire              wb_ack_o,
  input  wire              estop_i,     // asynchronous, active high
  output wire              irq_o,
  output wire [NAXES-1:0]  step_o,
  output wire [NAXES-1:0]  dir_o
);

  // The speed and position fraction (SPEED_W) are 64 bits, fixed by the engine's two 32-bit
  // halves; INFO0 reports it.

  wire [6:0]               unused_g;   // the cycle counter (the engine's harness reads it)
  wire [6:0]               gn;         // ... after this edge (the output stages' due compares)
  wire [3:0]               kph;
  wire [NAXES-1:0]         start_w, stop_w, abort, busy, run, done, refused, freed, flush;
  wire [NAXES-1:0]         accepts, pending, tgt, req, tgt_load, step_inv, dir_inv;
  wire [NAXES-1:0]         accepts_n, pending_n;
  // The engine registers its start decisions from the stages' next flags (accepts_n_o);
  // accepts_o itself is what the formal contract checks a request against (formal/).
  wire                     unused_accepts = ^accepts;
  wire [NAXES*2-1:0]       act, qn, phase;
  wire                     push, bus_re, bus_init, tgt_dir;
  wire [2:0]               push_axis;
  wire [6:0]               push_flags, req_due;
  wire [1:0]               bus_rbank;
  wire [7:0]               bus_raddr, bus_waddr;
  wire [31:0]              bus_rdata, bus_wdata;
  wire [3:0]               bus_we;
  wire [NAXES*PULSE_W-1:0] step_high, step_low, dir_setup, dir_hold;
  wire [NAXES*4-1:0]       cfg_over;
  wire [NAXES*POS_W-1:0]   pos;

  hexstep_wb #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W), .PULSE_W (PULSE_W),
    .POS_W (POS_W), .ADDR_W (ADDR_W)
  ) u_wb (
    .clk_i (clk_i), .rst_i (rst_i),
    .wb_cyc_i (wb_cyc_i), .wb_stb_i (wb_stb_i), .wb_we_i (wb_we_i), .wb_adr_i (wb_adr_i),
    .wb_dat_i (wb_dat_i), .wb_sel_i (wb_sel_i), .wb_dat_o (wb_dat_o), .wb_ack_o (wb_ack_o),
    .estop_i (estop_i), .irq_o (irq_o),
    .kph_i (kph), .start_w_o (start_w), .stop_w_o (stop_w), .abort_o (abort),
    .push_o (push), .push_axis_o (push_axis), .push_flags_o (push_flags),
    .bus_re_o (bus_re), .bus_rbank_o (bus_rbank), .bus_raddr_o (bus_raddr),
    .bus_rdata_i (bus_rdata), .bus_we_o (bus_we), .bus_waddr_o (bus_waddr),
    .bus_wdata_o (bus_wdata), .bus_init_o (bus_init),
    .act_i (act), .qn_i (qn), .busy_i (busy), .run_i (run), .phase_i (phase), .done_i (done),
    .refused_i (refused), .freed_i (freed), .flush_i (flush),
    .step_high_o (step_high), .step_low_o (step_low), .dir_setup_o (dir_setup),
    .dir_hold_o (dir_hold), .cfg_over_o (cfg_over), .step_inv_o (step_inv),
    .dir_inv_o (dir_inv), .pos_i (pos)
  );

  hexstep_engine #(.NAXES (NAXES), .RAM_STYLE (RAM_STYLE)) u_engine (
    .clk_i (clk_i), .rst_i (rst_i), .g_o (unused_g), .gn_o (gn), .kph_o (kph),
    .start_w_i (start_w), .stop_w_i (stop_w), .abort_i (abort),
    .push_i (push), .push_axis_i (push_axis), .push_flags_i (push_flags),
    .bus_re_i (bus_re), .bus_rbank_i (bus_rbank), .bus_raddr_i (bus_raddr),
    .bus_rdata_o (bus_rdata), .bus_we_i (bus_we), .bus_waddr_i (bus_waddr),
    .bus_wdata_i (bus_wdata), .bus_init_i (bus_init),
    .act_o (act), .qn_o (qn), .busy_o (busy), .run_o (run), .phase_o (phase), .done_o (done),
    .refused_o (refused), .freed_o (freed), .flush_o (flush),
    .pending_i (pending), .tgt_i (tgt),
    .accepts_n_i (accepts_n), .pending_n_i (pending_n),
    .req_o (req), .req_due_o (req_due), .tgt_load_o (tgt_load), .tgt_dir_o (tgt_dir)
  );

  genvar k;
  generate
    for (k = 0; k < NAXES; k = k + 1) begin : g_axis
      hexstep_pulse #(.PULSE_W (PULSE_W), .POS_W (POS_W)) u_pulse (
        .clk_i (clk_i), .rst_i (rst_i), .gn_i (gn),
        .abort_i (abort[k]), .req_i (req[k]), .req_due_i (req_due),
        .tgt_load_i (tgt_load[k]), .tgt_dir_i (tgt_dir),
        .step_high_i (step_high[k*PULSE_W +: PULSE_W]), .step_low_i (step_low[k*PULSE_W +: PULSE_W]),
        .dir_setup_i (dir_setup[k*PULSE_W +: PULSE_W]), .dir_hold_i (dir_hold[k*PULSE_W +: PULSE_W]),
        .over_i (cfg_over[k*4 +: 4]),
        .step_inv_i (step_inv[k]), .dir_inv_i (dir_inv[k]),
        .accepts_o (accepts[k]), .pending_o (pending[k]), .tgt_o (tgt[k]),
        .accepts_n_o (accepts_n[k]), .pending_n_o (pending_n[k]),
        .step_o (step_o[k]), .dir_o (dir_o[k]), .pos_o (pos[k*POS_W +: POS_W])
      );
    end
  endgenerate

endmodule

`default_nettype wire
