// SPDX-License-Identifier: Apache-2.0
// soc-board-fw-sim: the firmware image on the Verilated iCEBreaker SoC board top
// (soc/boards/hexstep_soc_icebreaker.v with its defaults: one axis of the default widths, the
// small PicoRV32 options, 8 KiB program RAM, 64 KiB data RAM in SPRAM; soc/CMakeLists.txt). A
// bit-level UART on the board's UART_RX / UART_TX pins sends protocol frames (docs/PROTOCOL.md)
// and checks the replies against the protocol and the core's documented widths (the reset
// values of INFO0/INFO1 in the generated register header), not against this firmware's output:
//   HELLO reports one axis, INFO the widths; requests for an axis the core lacks are refused
//   with E_ARG; values wider than the core's registers are refused with E_RANGE (nothing is
//   truncated); a constant-speed move of N steps on axis 0 gives exactly N STEP rising edges
//   with DIR high and EN_N low, and STATUS reports position N; pins of absent axes stay low /
//   disabled.
// Exit status 0 when every check passes, 1 otherwise (each failure printed).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

#include <verilated.h>

#include "Vhexstep_soc_icebreaker.h"
#include "hexstep_proto.h"
#include "hexstep_regs.h"

namespace {

constexpr unsigned kDiv = HEXSTEP_BOARD_SIM_UART_DIV;  // cycles per bit, as the Verilated top
// The core widths of hexstep_soc_icebreaker's defaults (synth/targets.json soc_icebreaker): the
// default build's, as rdl/hexstep.rdl documents them.
constexpr unsigned kSpeedW = HEXSTEP__INFO0__SPEED_W_reset, kAccW = HEXSTEP__INFO0__ACC_W_reset,
                   kStepW = HEXSTEP__INFO0__STEP_W_reset, kDfracW = HEXSTEP__INFO0__DFRAC_W_reset,
                   kPulseW = HEXSTEP__INFO1__PULSE_W_reset;
static_assert(kSpeedW == 64 && kStepW == 32 && kDfracW == 32,
              "the checks below assume values of these widths cannot be too wide for their fields");

Vhexstep_soc_icebreaker* top;
uint64_t cycle = 0;
int failures = 0;

// Host side of the UART: a transmit queue of bits and a receiver sampling mid-bit.
std::deque<int> tx_bits;
unsigned tx_cnt = 0;
std::vector<uint8_t> rx_bytes;
int rx_state = -1;  // -1 idle, 0..9 bit index
unsigned rx_cnt = 0;
unsigned rx_sh = 0;

// Pin observation.
unsigned step0_edges = 0, other_step_edges = 0;
bool prev_step0 = false;
unsigned prev_steps = 0;
bool dir_low_at_step = false, en_high_at_step = false, absent_pin_active = false;

void check(bool ok, const std::string& what) {
  if (!ok) {
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
    ++failures;
  }
}

void tick() {
  // host -> board
  if (!tx_bits.empty()) {
    top->UART_RX = tx_bits.front() & 1;
    if (++tx_cnt == kDiv) {
      tx_cnt = 0;
      tx_bits.pop_front();
    }
  } else {
    top->UART_RX = 1;
  }
  top->CLK = 0;
  top->eval();
  top->CLK = 1;
  top->eval();
  ++cycle;
  // board -> host: start bit confirmed at half a bit, then one sample per bit
  const int line = top->UART_TX;
  if (rx_state < 0) {
    if (line == 0) {
      rx_state = 0;
      rx_cnt = kDiv / 2;
    }
  } else if (--rx_cnt == 0) {
    rx_cnt = kDiv;
    if (rx_state == 0) {
      if (line != 0) rx_state = -1;  // glitch
      else rx_state = 1;
    } else if (rx_state <= 8) {
      rx_sh = (rx_sh >> 1) | (line ? 0x80u : 0u);
      ++rx_state;
    } else {
      check(line == 1, "stop bit of a byte from the board");
      rx_bytes.push_back(static_cast<uint8_t>(rx_sh));
      rx_state = -1;
    }
  }
  // pins
  const unsigned steps = top->STEP;
  const bool s0 = steps & 1u;
  if (s0 && !prev_step0) {
    ++step0_edges;
    if (!(top->DIR & 1u)) dir_low_at_step = true;
    if (top->EN_N & 1u) en_high_at_step = true;
  }
  prev_step0 = s0;
  if ((steps & ~prev_steps & 0x3Eu) != 0u) ++other_step_edges;
  prev_steps = steps;
  if ((top->DIR & 0x3Eu) != 0u || (top->EN_N & 0x3Eu) != 0x3Eu) absent_pin_active = true;
}

void send_byte(uint8_t b) {
  tx_bits.push_back(0);
  for (int i = 0; i < 8; ++i) tx_bits.push_back((b >> i) & 1);
  tx_bits.push_back(1);
}

struct Reply {
  bool ok = false;
  uint8_t cmd = 0;
  std::vector<uint8_t> data;  // status byte first
};

// One request; waits for one complete reply frame (or a timeout of max_cycles).
Reply request(uint8_t seq, uint8_t cmd, const std::vector<uint8_t>& pl, uint64_t max_cycles = 3000000) {
  std::vector<uint8_t> f = {HXP_SOF, static_cast<uint8_t>(pl.size()), seq, cmd};
  f.insert(f.end(), pl.begin(), pl.end());
  const uint16_t crc = hxp_crc16(f.data() + 1, static_cast<unsigned>(f.size() - 1));
  f.push_back(static_cast<uint8_t>(crc));
  f.push_back(static_cast<uint8_t>(crc >> 8));
  rx_bytes.clear();
  for (uint8_t b : f) send_byte(b);
  Reply r;
  const uint64_t end = cycle + max_cycles;
  while (cycle < end) {
    tick();
    if (rx_bytes.size() >= HXP_OVERHEAD && rx_bytes[0] == HXP_SOF &&
        rx_bytes.size() == HXP_OVERHEAD + rx_bytes[1]) {
      const unsigned n = rx_bytes[1];
      const uint16_t c = hxp_crc16(rx_bytes.data() + 1, n + 3u);
      const uint16_t got = static_cast<uint16_t>(rx_bytes[4 + n] | (rx_bytes[5 + n] << 8));
      r.ok = c == got && rx_bytes[2] == seq;
      r.cmd = rx_bytes[3];
      r.data.assign(rx_bytes.begin() + 4, rx_bytes.begin() + 4 + n);
      check(r.ok, "reply CRC and SEQ to command " + std::to_string(cmd));
      check(r.cmd == (cmd | HXP_REPLY), "reply CMD to command " + std::to_string(cmd));
      return r;
    }
  }
  check(false, "no reply to command " + std::to_string(cmd) + " within " + std::to_string(max_cycles) +
                   " cycles");
  return r;
}

void put(std::vector<uint8_t>& v, uint64_t x, int bytes) {
  for (int i = 0; i < bytes; ++i) v.push_back(static_cast<uint8_t>(x >> (8 * i)));
}

struct Move {
  uint32_t steps = 0, dir = 1;
  uint64_t v_start = 0, v_max = 0, v_end = 0, acc = 0, dec = 0, v_dec = 0;
  uint32_t acc_steps = 0, dec_step = 0, dec_frac = 0;
};

std::vector<uint8_t> move_payload(unsigned axis, const Move& m) {
  std::vector<uint8_t> p = {static_cast<uint8_t>(axis)};
  put(p, m.steps, 4);
  p.push_back(static_cast<uint8_t>(m.dir));
  put(p, m.v_start, 8);
  put(p, m.v_max, 8);
  put(p, m.v_end, 8);
  put(p, m.acc, 8);
  put(p, m.dec, 8);
  put(p, m.v_dec, 8);
  put(p, m.acc_steps, 4);
  put(p, m.dec_step, 4);
  put(p, m.dec_frac, 4);
  return p;
}

// A constant-speed move of n steps at 1/8 step per tick (ARCHITECTURE.md "Registers of a move":
// v_start = v_max = v_end = v_dec, no acceleration phase, deceleration point at the end).
Move constant_move(uint32_t n) {
  Move m;
  m.steps = n;
  m.v_start = m.v_max = m.v_end = m.v_dec = 1ull << (kSpeedW - 3);
  m.dec_step = n;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  Verilated::commandArgs(argc, argv);
  top = new Vhexstep_soc_icebreaker;
  top->BTN_N = 0;  // reset pressed
  top->ESTOP = 0;
  top->UART_RX = 1;
  for (int i = 0; i < 20; ++i) tick();
  top->BTN_N = 1;
  for (int i = 0; i < 2000; ++i) tick();  // reset release, firmware start

  uint8_t seq = 1;
  // HELLO: protocol version, one axis, VERSION register with naxes 1.
  Reply r = request(seq++, HXP_HELLO, {});
  check(r.data.size() == HXP_HELLO_REPLY_LEN, "HELLO reply length");
  if (r.data.size() == HXP_HELLO_REPLY_LEN) {
    check(r.data[0] == HXP_OK, "HELLO status OK");
    check(r.data[1] == HXP_VERSION, "HELLO protocol version");
    check(r.data[2] == 1, "HELLO reports 1 axis, got " + std::to_string(r.data[2]));
    check(r.data[12] == 1, "HELLO VERSION register naxes field (bits 23:16) 1");
  }
  // INFO: the widths of this build, as the host compares them with its job's.
  r = request(seq++, HXP_INFO, {});
  check(r.data.size() == HXP_INFO_REPLY_LEN && r.data[0] == HXP_OK && r.data[1] == kSpeedW &&
            r.data[2] == kAccW && r.data[3] == kStepW && r.data[4] == kDfracW && r.data[5] == kPulseW,
        "INFO reports SPEED_W 64, ACC_W 48, STEP_W 32, DFRAC_W 32, PULSE_W 12");

  // An axis the core lacks: MOVE, PULSE, START, STOP, ABORT refused with E_ARG.
  r = request(seq++, HXP_MOVE, move_payload(1, constant_move(10)));
  check(r.data.size() >= 1 && r.data[0] == HXP_E_ARG, "MOVE on axis 1 refused with E_ARG");
  std::vector<uint8_t> pulse1 = {1, 2, 0, 2, 0, 2, 0, 2, 0, 0};
  r = request(seq++, HXP_PULSE, pulse1);
  check(r.data.size() >= 1 && r.data[0] == HXP_E_ARG, "PULSE on axis 1 refused with E_ARG");
  for (uint8_t c : {HXP_START, HXP_STOP, HXP_ABORT}) {
    r = request(seq++, c, {0x02});
    check(r.data.size() >= 1 && r.data[0] == HXP_E_ARG,
          "command " + std::to_string(c) + " with mask 0x02 refused with E_ARG");
  }

  // Values wider than the core's registers: E_RANGE, nothing stored. (Speeds, step counts and
  // DEC_FRAC fill their protocol fields in this build; the reduced-width SoC of
  // tests/soc/soc_e2e.sh case reduced covers those.)
  Move wide = constant_move(10);
  wide.acc = 1ull << kAccW;
  r = request(seq++, HXP_MOVE, move_payload(0, wide));
  check(r.data.size() >= 1 && r.data[0] == HXP_E_RANGE, "MOVE with acc of ACC_W+1 bits refused with E_RANGE");
  wide = constant_move(10);
  wide.dec = ~0ull;
  r = request(seq++, HXP_MOVE, move_payload(0, wide));
  check(r.data.size() >= 1 && r.data[0] == HXP_E_RANGE, "MOVE with dec of 64 bits refused with E_RANGE");
  std::vector<uint8_t> pulse_wide = {0, 0, static_cast<uint8_t>(1u << (kPulseW - 8)), 2, 0, 2, 0, 2, 0, 0};
  r = request(seq++, HXP_PULSE, pulse_wide);  // step_high = 2^PULSE_W
  check(r.data.size() >= 1 && r.data[0] == HXP_E_RANGE, "PULSE with step_high of PULSE_W+1 bits refused with E_RANGE");
  // The largest values that fit are accepted (and flushed again by ABORT).
  wide = constant_move(10);
  wide.acc = (1ull << kAccW) - 1;
  r = request(seq++, HXP_MOVE, move_payload(0, wide));
  check(r.data.size() == 2 && r.data[0] == HXP_OK, "MOVE with acc of ACC_W bits accepted");
  r = request(seq++, HXP_ABORT, {0x01});
  check(r.data.size() == 1 && r.data[0] == HXP_OK, "ABORT axis 0");

  // A move that fits: exactly N steps, positive direction, driver enabled.
  constexpr uint32_t kN = 37;
  r = request(seq++, HXP_MOVE, move_payload(0, constant_move(kN)));
  check(r.data.size() == 2 && r.data[0] == HXP_OK, "MOVE on axis 0 accepted");
  r = request(seq++, HXP_START, {0x01});
  check(r.data.size() == 2 && r.data[0] == HXP_OK && r.data[1] == 0x01, "START axis 0 accepted and started");
  for (int i = 0; i < 20000; ++i) tick();  // 37 steps at 8 ticks per step: far less
  check(step0_edges == kN, "axis 0 made " + std::to_string(step0_edges) + " steps, expected " + std::to_string(kN));
  check(!dir_low_at_step, "DIR high (positive) at every step");
  check(!en_high_at_step, "EN_N low (enabled) at every step");
  check(other_step_edges == 0 && !absent_pin_active, "pins of absent axes 1..5 stay STEP/DIR low, EN_N high");
  r = request(seq++, HXP_STATUS, {});
  check(r.data.size() == HXP_STATUS_REPLY_LEN, "STATUS reply length");
  if (r.data.size() == HXP_STATUS_REPLY_LEN) {
    check(r.data[0] == HXP_OK, "STATUS OK");
    const uint8_t* a = r.data.data() + 9;
    int64_t pos = 0;
    for (int i = 7; i >= 0; --i) pos = (pos << 8) | a[4 + i];
    check(pos == kN, "STATUS position of axis 0 is " + std::to_string(pos) + ", expected " + std::to_string(kN));
    check(a[2] == 0, "no error flags on axis 0");
  }
  check(top->LEDR_N == 1, "no CPU trap, no E-STOP (red LED off)");

  std::printf("%s: %d failure(s), %llu cycles\n", failures ? "FAIL" : "ok", failures,
              static_cast<unsigned long long>(cycle));
  top->final();
  delete top;
  return failures ? 1 : 0;
}
