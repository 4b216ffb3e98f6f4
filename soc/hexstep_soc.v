// SPDX-License-Identifier: Apache-2.0
// hexstep SoC: PicoRV32 (Wishbone) + RAMs + UART + hexstep_top, the soft MCU that runs the firmware.
`default_nettype none

// Memory map (byte addresses, decoded on address bits [31:28]; docs/PROTOCOL.md):
//   0x0000_0000  program RAM, RAM_WORDS * 4 bytes: the firmware image (INIT_FILE: code,
//                constants, initialised data)
//   0x1000_0000  UART (hexstep_soc_uart: DATA, STATUS, DIV)
//   0x2000_0000  hexstep_top registers (rdl/hexstep.rdl, 0x400 bytes in a 4 KiB window)
//   0x3000_0000  SYS: [0] hexstep irq_o level, [1] e-stop pin (after a two-flop synchroniser)
//   0x4000_0000  data RAM, DATA_WORDS * 4 bytes, not initialised: .bss, stack at the top
//   elsewhere    reads 0, writes ignored, acked (a wild pointer never hangs the bus)
// One master (the CPU), so the interconnect is a decoder and a read multiplexer; every slave
// acks one or more cycles after the request and only while it is held.
// CPU: picorv32_wb from the PyPI package pythondata-cpu-picorv32 (not in this repository),
// RV32I without compressed instructions, multiplier or interrupts: the firmware polls the IRQ
// level in SYS (PicoRV32 interrupts need its own non-standard instructions).
// Parameters beyond RAM/UART (board builds, synth/targets.json; the defaults are the simulated
// SoC of the end-to-end tests): the hexstep_top configuration (NAXES, widths, RAM_STYLE; see
// hexstep_top) and four PicoRV32 options that trade speed for area without changing the
// instruction set. Axes k >= NAXES drive STEP/DIR low; the firmware reads NAXES from VERSION.
// Two RAMs rather than one: the data RAM needs no initial contents, so on the iCE40 UP5K it can
// be the single-port SPRAM (DATA_SPRAM 1), which leaves the block RAMs to the program and the
// core (30 SB_RAM40_4K: 8 for hexstep_top, 16 for an 8 KiB program RAM). One linker layout
// (firmware/soc.ld) serves every build.
module hexstep_soc #(
  parameter integer RAM_WORDS = 2048,  // program RAM, 8 KiB; any size >= the firmware image
  parameter integer DATA_WORDS = 2048, // data RAM, 8 KiB: .bss (move FIFOs) and the stack (sp =
                                       //   0x4000_0000 + DATA_WORDS * 4 at reset); any size >=
                                       //   .bss + 1 KiB
  parameter [0:0]   DATA_SPRAM = 0,    // 1: the data RAM in iCE40 UP5K SPRAM (hexstep_soc_ram)
  parameter         INIT_FILE = "",    // firmware image for $readmemh (built by soc/CMakeLists.txt)
  parameter integer UART_DIV  = 868,   // UART cycles per bit at reset (100 MHz / 115200)
  parameter integer NAXES     = 6,     // hexstep_top parameters, 1..6 here (six STEP/DIR pins)
  parameter integer ACC_W     = 48,
  parameter integer STEP_W    = 32,
  parameter integer DFRAC_W   = 32,
  parameter integer PULSE_W   = 12,
  parameter integer POS_W     = 32,
  parameter         RAM_STYLE = "DELAY",  // hexstep_top's memory: "DELAY" (iCE40, simulation),
                                          //   "ECP5" (DP16KD)
  parameter [0:0]   CPU_BARREL_SHIFTER  = 1,  // 0: shifts one bit (or four) per cycle
  parameter [0:0]   CPU_TWO_STAGE_SHIFT = 1,  // with CPU_BARREL_SHIFTER 0: 4-bit steps first
  parameter [0:0]   CPU_CATCH_MISALIGN  = 1,  // 0: no trap on a misaligned access
  parameter [0:0]   CPU_CATCH_ILLINSN   = 1   // 0: no trap on an illegal instruction
) (
  input  wire       clk_i,
  input  wire       rst_i,     // synchronous, active high
  input  wire       uart_rx_i,
  output wire       uart_tx_o,
  input  wire       estop_i,   // asynchronous, active high (hexstep_top synchronises it)
  output wire       irq_o,     // hexstep_top's interrupt line, also readable by the firmware
  output wire [5:0] step_o,
  output wire [5:0] dir_o,
  output wire       trap_o     // CPU trapped (illegal instruction, misaligned access)
);
  wire [31:0] adr, dat_w;
  wire [3:0]  sel;
  wire        cyc, stb, we;
  reg  [31:0] dat_r;
  reg         ack;

  picorv32_wb #(
    .ENABLE_COUNTERS (1), .ENABLE_COUNTERS64 (0), .COMPRESSED_ISA (0), .ENABLE_MUL (0),
    .ENABLE_DIV (0), .ENABLE_IRQ (0), .BARREL_SHIFTER (CPU_BARREL_SHIFTER),
    .TWO_STAGE_SHIFT (CPU_TWO_STAGE_SHIFT), .CATCH_MISALIGN (CPU_CATCH_MISALIGN),
    .CATCH_ILLINSN (CPU_CATCH_ILLINSN), .PROGADDR_RESET (32'h0),
    .STACKADDR (32'h4000_0000 + DATA_WORDS * 4)
  ) u_cpu (
    .trap (trap_o), .wb_rst_i (rst_i), .wb_clk_i (clk_i),
    .wbm_adr_o (adr), .wbm_dat_o (dat_w), .wbm_dat_i (dat_r), .wbm_we_o (we),
    .wbm_sel_o (sel), .wbm_stb_o (stb), .wbm_ack_i (ack), .wbm_cyc_o (cyc),
    .pcpi_valid (), .pcpi_insn (), .pcpi_rs1 (), .pcpi_rs2 (), .pcpi_wr (1'b0),
    .pcpi_rd (32'd0), .pcpi_wait (1'b0), .pcpi_ready (1'b0),
    .irq (32'd0), .eoi (), .trace_valid (), .trace_data (), .mem_instr ()
  );

  // ---- decoder ----
  wire s_ram = (adr[31:28] == 4'h0);
  wire s_uart = (adr[31:28] == 4'h1);
  wire s_hs = (adr[31:28] == 4'h2);
  wire s_sys = (adr[31:28] == 4'h3);
  wire s_data = (adr[31:28] == 4'h4);
  wire s_none = ~(s_ram | s_uart | s_hs | s_sys | s_data);

  wire [31:0] ram_dat, data_dat, uart_dat, hs_dat;
  wire        ram_ack, data_ack, uart_ack, hs_ack;
  reg  [31:0] sys_dat_q;
  reg         sys_ack_q;

  hexstep_soc_ram #(.WORDS (RAM_WORDS), .INIT_FILE (INIT_FILE)) u_ram (
    .clk_i (clk_i), .rst_i (rst_i), .wb_cyc_i (cyc), .wb_stb_i (stb & s_ram), .wb_we_i (we),
    .wb_adr_i (adr), .wb_dat_i (dat_w), .wb_sel_i (sel), .wb_dat_o (ram_dat), .wb_ack_o (ram_ack)
  );

  hexstep_soc_ram #(.WORDS (DATA_WORDS), .SPRAM (DATA_SPRAM)) u_data (
    .clk_i (clk_i), .rst_i (rst_i), .wb_cyc_i (cyc), .wb_stb_i (stb & s_data), .wb_we_i (we),
    .wb_adr_i (adr), .wb_dat_i (dat_w), .wb_sel_i (sel), .wb_dat_o (data_dat), .wb_ack_o (data_ack)
  );

  hexstep_soc_uart #(.DIV_RESET (UART_DIV)) u_uart (
    .clk_i (clk_i), .rst_i (rst_i), .wb_cyc_i (cyc), .wb_stb_i (stb & s_uart), .wb_we_i (we),
    .wb_adr_i (adr[3:2]), .wb_dat_i (dat_w), .wb_dat_o (uart_dat), .wb_ack_o (uart_ack),
    .rx_i (uart_rx_i), .tx_o (uart_tx_o)
  );

  wire [NAXES-1:0] hs_step, hs_dir;
  hexstep_top #(
    .NAXES (NAXES), .ACC_W (ACC_W), .STEP_W (STEP_W), .DFRAC_W (DFRAC_W),
    .PULSE_W (PULSE_W), .POS_W (POS_W), .RAM_STYLE (RAM_STYLE)
  ) u_hexstep (
    .clk_i (clk_i), .rst_i (rst_i), .wb_cyc_i (cyc), .wb_stb_i (stb & s_hs), .wb_we_i (we),
    .wb_adr_i (adr[11:0]), .wb_dat_i (dat_w), .wb_sel_i (sel), .wb_dat_o (hs_dat),
    .wb_ack_o (hs_ack), .estop_i (estop_i), .irq_o (irq_o), .step_o (hs_step), .dir_o (hs_dir)
  );
  generate
    if (NAXES < 6) begin : g_pad
      assign step_o = {{(6-NAXES){1'b0}}, hs_step};
      assign dir_o  = {{(6-NAXES){1'b0}}, hs_dir};
    end else begin : g_all
      assign step_o = hs_step;
      assign dir_o  = hs_dir;
    end
  endgenerate

  // ---- SYS register and the default slave ----
  reg [1:0] estop_sync_q;
  always @(posedge clk_i) begin
    if (rst_i) begin
      estop_sync_q <= 2'b00;
      sys_ack_q    <= 1'b0;
      sys_dat_q    <= 32'd0;
    end else begin
      estop_sync_q <= {estop_sync_q[0], estop_i};
      sys_ack_q    <= cyc & stb & (s_sys | s_none) & ~sys_ack_q;
      sys_dat_q    <= s_sys ? {30'd0, estop_sync_q[1], irq_o} : 32'd0;
    end
  end

  always @* begin
    dat_r = sys_dat_q;
    ack   = sys_ack_q;
    if (s_ram)  begin dat_r = ram_dat;  ack = ram_ack;  end
    if (s_data) begin dat_r = data_dat; ack = data_ack; end
    if (s_uart) begin dat_r = uart_dat; ack = uart_ack; end
    if (s_hs)   begin dat_r = hs_dat;   ack = hs_ack;   end
  end

endmodule

`default_nettype wire
