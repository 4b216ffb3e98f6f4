// SPDX-License-Identifier: Apache-2.0
// Bad frames against the firmware on the simulated SoC (run under hexstep-soc-sim, which passes
// the pseudo-terminal as argv[1]): every malformed, corrupted or truncated frame is answered
// with the documented error (docs/PROTOCOL.md) and causes no motion; a repeated SEQ is answered
// again without executing twice. With the widths of a narrower build as arguments, checks
// instead that the firmware refuses every value one bit wider than that build's registers and
// accepts the widest that fits. Exit 0 if every check holds; prints each failure.
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "hexstep_proto.h"
#include "hexstep_regs.h"

namespace {

int fd = -1;
int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok  " : "FAIL", what.c_str());
  if (!ok) ++failures;
}

std::vector<uint8_t> frame(uint8_t seq, uint8_t cmd, const std::vector<uint8_t>& pl) {
  std::vector<uint8_t> f;
  f.reserve(HXP_OVERHEAD + pl.size());
  f.push_back(static_cast<uint8_t>(HXP_SOF));
  f.push_back(static_cast<uint8_t>(pl.size()));
  f.push_back(seq);
  f.push_back(cmd);
  f.insert(f.end(), pl.begin(), pl.end());
  const uint16_t crc = hxp_crc16(f.data() + 1, static_cast<unsigned>(f.size() - 1));
  f.push_back(static_cast<uint8_t>(crc));
  f.push_back(static_cast<uint8_t>(crc >> 8));
  return f;
}

void send_raw(const std::vector<uint8_t>& b) {
  size_t off = 0;
  while (off < b.size()) {
    const ssize_t n = write(fd, b.data() + off, b.size() - off);
    if (n > 0) off += static_cast<size_t>(n);
  }
}

struct Reply {
  bool got = false;
  uint8_t seq = 0, cmd = 0, status = 0xFF;
  std::vector<uint8_t> data;
};

// Next complete frame with a valid CRC within timeout_ms (wall clock; the simulation is slow).
Reply recv(int timeout_ms = 20000) {
  static std::vector<uint8_t> buf;
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    while (!buf.empty() && buf[0] != HXP_SOF) buf.erase(buf.begin());
    if (buf.size() >= HXP_HEADER && buf.size() >= buf[1] + HXP_OVERHEAD) {
      const unsigned len = buf[1];
      const uint16_t crc = hxp_crc16(buf.data() + 1, len + 3);
      const uint16_t got = static_cast<uint16_t>(buf[HXP_HEADER + len] | (buf[HXP_HEADER + len + 1] << 8));
      if (crc == got && len >= 1) {
        Reply r;
        r.got = true;
        r.seq = buf[2];
        r.cmd = buf[3];
        r.status = buf[4];
        r.data.assign(buf.begin() + 5, buf.begin() + HXP_HEADER + len);
        buf.erase(buf.begin(), buf.begin() + HXP_OVERHEAD + len);
        return r;
      }
      buf.erase(buf.begin());
      continue;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now >= end) return Reply{};
    pollfd p{fd, POLLIN, 0};
    poll(&p, 1, 50);
    uint8_t tmp[256];
    const ssize_t n = read(fd, tmp, sizeof tmp);
    if (n > 0) buf.insert(buf.end(), tmp, tmp + n);
  }
}

Reply transact(const std::vector<uint8_t>& f, int timeout_ms = 20000) {
  send_raw(f);
  return recv(timeout_ms);
}

// A constant-speed move of `steps` steps at 1/16 step per tick (v = 2^60 in 2^-64 step/tick: a
// step every 512 cycles); deceleration (only used by a STOP) 2^47, i.e. 2^-17 step/tick^2 (the
// register holds 48 bits): a STOP comes to rest after 2^13 ticks and about 256 steps.
std::vector<uint8_t> move_payload(uint8_t axis, uint64_t acc, uint32_t steps = 100) {
  std::vector<uint8_t> p{axis};
  auto le = [&p](uint64_t v, unsigned n) {
    for (unsigned i = 0; i < n; ++i) p.push_back(static_cast<uint8_t>(v >> (8 * i)));
  };
  const uint64_t v = 1ull << 60;
  le(steps, 4);
  le(1, 1);
  le(v, 8);         // v_start
  le(v, 8);         // v_max
  le(0, 8);         // v_end
  le(acc, 8);       // acc
  le(1ull << 47, 8);  // dec
  le(v, 8);         // v_dec
  le(0, 4);         // acc_steps
  le(steps, 4);     // dec_step (no planned deceleration)
  le(0, 4);         // dec_frac
  return p;
}

struct Status {
  uint8_t active = 0xFF, busy = 0xFF;
  uint8_t fifo[6] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  int64_t pos[6] = {};
};

Status status(uint8_t seq) {
  const Reply r = transact(frame(seq, HXP_STATUS, {}));
  Status s;
  if (!r.got || r.status != HXP_OK || r.data.size() + 1 != HXP_STATUS_REPLY_LEN) {
    check(false, "STATUS answered");
    return s;
  }
  s.active = r.data[1];
  s.busy = r.data[2];
  for (unsigned k = 0; k < 6; ++k) {
    const uint8_t* a = r.data.data() + 8 + k * HXP_STATUS_AXIS_LEN;
    s.fifo[k] = a[0];
    uint64_t p = 0;
    for (unsigned i = 0; i < 8; ++i) p |= static_cast<uint64_t>(a[4 + i]) << (8 * i);
    s.pos[k] = static_cast<int64_t>(p);
  }
  return s;
}

void put_le(std::vector<uint8_t>& p, size_t at, uint64_t v, unsigned n) {
  for (unsigned i = 0; i < n; ++i) p[at + i] = static_cast<uint8_t>(v >> (8 * i));
}

// A one-axis core of narrower widths (soc_e2e.sh case reduced passes them): INFO reports them,
// every move value and pulse time one bit wider than its register is refused with E_RANGE and
// the widest value that fits is accepted, axis 1 does not exist. Nothing runs (the accepted
// moves stay in the FIFO and are flushed).
void narrow(unsigned acc_w, unsigned step_w, unsigned dfrac_w, unsigned pulse_w) {
  Reply r = transact(frame(1, HXP_HELLO, {}));
  check(r.got && r.status == HXP_OK && r.data.size() == 13 && r.data[1] == 1, "HELLO: one axis");
  r = transact(frame(2, HXP_INFO, {}));
  check(r.got && r.status == HXP_OK && r.data.size() + 1 == HXP_INFO_REPLY_LEN && r.data[0] == 64 &&
            r.data[1] == acc_w && r.data[2] == step_w && r.data[3] == dfrac_w && r.data[4] == pulse_w,
        "INFO: SPEED_W 64, ACC_W " + std::to_string(acc_w) + ", STEP_W " + std::to_string(step_w) +
            ", DFRAC_W " + std::to_string(dfrac_w) + ", PULSE_W " + std::to_string(pulse_w));
  r = transact(frame(3, HXP_MOVE, move_payload(1, 0)));
  check(r.got && r.status == HXP_E_ARG, "MOVE to axis 1 -> E_ARG");
  struct Field {
    const char* name;
    size_t at;
    unsigned bytes, width;
  };
  // Offsets in the MOVE payload (docs/PROTOCOL.md): steps 1, acc 30, dec 38, acc_steps 54,
  // dec_step 58, dec_frac 62.
  const Field fields[] = {{"steps", 1, 4, step_w},      {"acc", 30, 8, acc_w},        {"dec", 38, 8, acc_w},
                          {"acc_steps", 54, 4, step_w}, {"dec_step", 58, 4, step_w}, {"dec_frac", 62, 4, dfrac_w}};
  // The base move's values all fit (its dec of 2^47 would not: a dec of 1 instead).
  auto base = [] {
    std::vector<uint8_t> p = move_payload(0, 0, 10);
    put_le(p, 38, 1, 8);
    return p;
  };
  uint8_t seq = 4;
  for (const Field& fd : fields) {
    std::vector<uint8_t> p = base();
    put_le(p, fd.at, 1ull << fd.width, fd.bytes);
    r = transact(frame(seq++, HXP_MOVE, p));
    check(r.got && r.status == HXP_E_RANGE, std::string("MOVE with ") + fd.name + " = 2^" +
                                                std::to_string(fd.width) + " -> E_RANGE");
    p = base();
    put_le(p, fd.at, (1ull << fd.width) - 1, fd.bytes);
    r = transact(frame(seq++, HXP_MOVE, p));
    check(r.got && r.status == HXP_OK, std::string("MOVE with ") + fd.name + " = 2^" + std::to_string(fd.width) +
                                           " - 1 -> OK (got " + (r.got ? std::to_string(r.status) : "no reply") +
                                           ")");
  }
  std::vector<uint8_t> pulse = {0, 2, 0, 2, 0, 0, 0, 0, 0, 0};
  put_le(pulse, 1, 1ull << pulse_w, 2);
  r = transact(frame(seq++, HXP_PULSE, pulse));
  check(r.got && r.status == HXP_E_RANGE, "PULSE with step_high = 2^" + std::to_string(pulse_w) + " -> E_RANGE");
  r = transact(frame(seq++, HXP_ABORT, {0x01}));
  check(r.got && r.status == HXP_OK, "ABORT axis 0 -> OK");
  const Status s = status(seq++);
  check(s.fifo[0] == 0 && s.active == 0 && s.busy == 0, "nothing queued, nothing moving");
  r = transact(frame(seq++, HXP_PULSE, {0, 2, 0, 2, 0, 0, 0, 0, 0, 0}));
  check(r.got && r.status == HXP_OK, "PULSE with step_high = 2 -> OK");
}

unsigned width_arg(const char* s) {
  char* end = nullptr;
  const unsigned long v = std::strtoul(s, &end, 10);
  if (*s == '\0' || *end != '\0' || v < 1 || v > 48) {
    std::fprintf(stderr, "soc_frames: width '%s' must be an integer in [1, 48]\n", s);
    std::exit(2);
  }
  return static_cast<unsigned>(v);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 6) {
    std::fprintf(stderr, "usage: soc_frames PORT [ACC_W STEP_W DFRAC_W PULSE_W]\n");
    return 2;
  }
  fd = open(argv[1], O_RDWR | O_NOCTTY);
  if (fd < 0) {
    std::perror(argv[1]);
    return 2;
  }
  termios t{};
  tcgetattr(fd, &t);
  cfmakeraw(&t);
  tcsetattr(fd, TCSANOW, &t);

  if (argc == 6) {
    narrow(width_arg(argv[2]), width_arg(argv[3]), width_arg(argv[4]), width_arg(argv[5]));
    std::printf("%d failure(s)\n", failures);
    return failures == 0 ? 0 : 1;
  }

  // The CRC is CRC-16/CCITT-FALSE: its published check value for "123456789" is 0x29B1.
  const uint8_t nine[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  check(hxp_crc16(nine, 9) == 0x29B1u, "CRC-16/CCITT-FALSE check value 0x29B1");

  Reply r = transact(frame(1, HXP_HELLO, {}));
  check(r.got && r.status == HXP_OK && r.cmd == (HXP_HELLO | HXP_REPLY) && r.seq == 1 && r.data.size() == 13 &&
            r.data[0] == HXP_VERSION && r.data[1] == 6,
        "HELLO: version 1, six axes");
  // INFO: the default core's widths (rtl/hexstep_top.v parameters, documented as the reset
  // values of INFO0/INFO1 in rdl/hexstep.rdl: SPEED_W 64, ACC_W 48, STEP_W 32, DFRAC_W 32,
  // PULSE_W 12).
  r = transact(frame(1, HXP_INFO, {}));
  check(r.got && r.status == HXP_OK && r.data.size() + 1 == HXP_INFO_REPLY_LEN &&
            r.data[0] == HEXSTEP__INFO0__SPEED_W_reset && r.data[1] == HEXSTEP__INFO0__ACC_W_reset &&
            r.data[2] == HEXSTEP__INFO0__STEP_W_reset && r.data[3] == HEXSTEP__INFO0__DFRAC_W_reset &&
            r.data[4] == HEXSTEP__INFO1__PULSE_W_reset,
        "INFO: SPEED_W 64, ACC_W 48, STEP_W 32, DFRAC_W 32, PULSE_W 12");

  // Corrupted: one payload bit of a valid MOVE flipped (CRC no longer matches).
  std::vector<uint8_t> f = frame(2, HXP_MOVE, move_payload(1, 0));
  f[HXP_HEADER + 7] ^= 0x10;
  r = transact(f);
  check(r.got && r.status == HXP_E_CRC && r.seq == 2, "MOVE with a flipped payload bit -> E_CRC");
  // Corrupted CRC byte.
  f = frame(3, HXP_MOVE, move_payload(1, 0));
  f.back() ^= 0x01;
  r = transact(f);
  check(r.got && r.status == HXP_E_CRC, "MOVE with a corrupted CRC -> E_CRC");
  // Length wrong for the command (one payload byte short, CRC right).
  std::vector<uint8_t> shortp = move_payload(1, 0);
  shortp.pop_back();
  r = transact(frame(4, HXP_MOVE, shortp));
  check(r.got && r.status == HXP_E_LENGTH && r.seq == 4, "MOVE with 65 payload bytes -> E_LENGTH");
  // LEN above the maximum: answered at once, the rest is skipped until the next SOF.
  r = transact(std::vector<uint8_t>{HXP_SOF, HXP_MAX_PAYLOAD + 1, 5, HXP_MOVE});
  check(r.got && r.status == HXP_E_LENGTH && r.seq == 5, "LEN 97 -> E_LENGTH");
  // Unknown command.
  r = transact(frame(6, 0x55, {}));
  check(r.got && r.status == HXP_E_COMMAND && r.cmd == (0x55 | HXP_REPLY), "command 0x55 -> E_COMMAND");
  // Arguments: axis 6, a 49-bit acceleration, a mask outside 0x3F.
  r = transact(frame(7, HXP_MOVE, move_payload(6, 0)));
  check(r.got && r.status == HXP_E_ARG, "MOVE to axis 6 -> E_ARG");
  r = transact(frame(8, HXP_MOVE, move_payload(1, 1ull << 48)));
  check(r.got && r.status == HXP_E_RANGE, "MOVE with acc = 2^48 -> E_RANGE");
  r = transact(frame(9, HXP_START, {0x40}));
  check(r.got && r.status == HXP_E_ARG, "START mask 0x40 -> E_ARG");
  // Truncated: a header and half a payload, then silence: E_TIMEOUT after the inter-byte timeout.
  f = frame(10, HXP_MOVE, move_payload(1, 0));
  f.resize(HXP_HEADER + 30);
  r = transact(f, 60000);
  check(r.got && r.status == HXP_E_TIMEOUT, "truncated MOVE -> E_TIMEOUT");

  Status s = status(11);
  check(s.fifo[1] == 0 && s.active == 0 && s.busy == 0, "after the bad frames: nothing queued, nothing moving");

  // A repeated SEQ is answered from the last reply, not executed again.
  const std::vector<uint8_t> good = frame(12, HXP_MOVE, move_payload(1, 0));
  r = transact(good);
  check(r.got && r.status == HXP_OK && r.data.size() == 1, "valid MOVE -> OK");
  const Reply again = transact(good);
  check(again.got && again.status == HXP_OK && again.data == r.data, "same MOVE, same SEQ -> the same reply");
  s = status(13);
  check(s.fifo[1] == 1, "the repeated MOVE was stored once");
  r = transact(frame(14, HXP_ABORT, {0x3F}));
  check(r.got && r.status == HXP_OK, "ABORT all -> OK");
  s = status(15);
  check(s.fifo[1] == 0 && s.active == 0 && s.busy == 0, "ABORT flushed the FIFO; nothing ran");

  // STOP in motion: a 100000-step move on axis 4 (51 million cycles at 1/16 step per tick),
  // stopped once it has moved: it comes to rest long before its end (soc_e2e.sh checks that
  // the last STEP intervals grow: a deceleration, not an abort).
  r = transact(frame(16, HXP_MOVE, move_payload(4, 0, 100000)));
  check(r.got && r.status == HXP_OK, "long MOVE on axis 4 -> OK");
  r = transact(frame(17, HXP_START, {0x10}));
  check(r.got && r.status == HXP_OK && r.data.size() == 1 && r.data[0] == 0x10, "START axis 4");
  uint8_t seq = 18;
  s = status(seq++);
  for (int i = 0; i < 50 && s.pos[4] < 50; ++i) s = status(seq++);
  check(s.pos[4] >= 50 && (s.busy & 0x10), "axis 4 moving");
  r = transact(frame(seq++, HXP_STOP, {0x10}));
  check(r.got && r.status == HXP_OK, "STOP axis 4 -> OK");
  for (int i = 0; i < 50 && (s.busy & 0x10); ++i) s = status(seq++);
  const int64_t rest = s.pos[4];
  s = status(seq++);
  check(!(s.busy & 0x10) && !(s.active & 0x10) && s.pos[4] == rest && rest > 0 && rest < 100000,
        "axis 4 at rest after STOP at position " + std::to_string(rest) + " (< 100000)");
  std::printf("%d failure(s)\n", failures);
  return failures == 0 ? 0 : 1;
}
