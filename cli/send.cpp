// SPDX-License-Identifier: Apache-2.0
#include "send.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include "common.hpp"
#include "hexstep/job_io.hpp"
#include "hexstep_proto.h"

namespace hexstep::cli {

namespace {

const char* status_text(uint8_t s) {
  switch (s) {
    case HXP_OK: return "ok";
    case HXP_E_CRC: return "checksum error (frame corrupted on the line)";
    case HXP_E_LENGTH: return "frame length wrong for the command";
    case HXP_E_COMMAND: return "unknown command";
    case HXP_E_ARG: return "argument out of range (axis, mask, dir or flags)";
    case HXP_E_RANGE: return "value does not fit its register";
    case HXP_E_FULL: return "move FIFO full";
    case HXP_E_ESTOP: return "E-STOP latched";
    case HXP_E_BUSY: return "axis busy";
    case HXP_E_TIMEOUT: return "frame truncated (inter-byte timeout)";
    case HXP_E_UNSUPPORTED: return "not supported by this firmware";
    default: return "unknown error code";
  }
}

const char* cmd_name(uint8_t c) {
  switch (c) {
    case HXP_HELLO: return "HELLO";
    case HXP_PULSE: return "PULSE";
    case HXP_MOVE: return "MOVE";
    case HXP_START: return "START";
    case HXP_STOP: return "STOP";
    case HXP_ABORT: return "ABORT";
    case HXP_CLEAR: return "CLEAR";
    case HXP_STATUS: return "STATUS";
    case HXP_INFO: return "INFO";
    default: return "?";
  }
}

speed_t baud_constant(unsigned b) {
  switch (b) {
    case 9600: return B9600;
    case 19200: return B19200;
    case 38400: return B38400;
    case 57600: return B57600;
    case 115200: return B115200;
    case 230400: return B230400;
    case 460800: return B460800;
    case 921600: return B921600;
    case 1000000: return B1000000;
    case 2000000: return B2000000;
    case 3000000: return B3000000;
    default: return B0;
  }
}

void put_le(std::vector<uint8_t>& v, uint64_t x, unsigned n) {
  for (unsigned i = 0; i < n; ++i) v.push_back(static_cast<uint8_t>(x >> (8 * i)));
}
uint64_t get_le(const uint8_t* p, unsigned n) {
  uint64_t x = 0;
  for (unsigned i = 0; i < n; ++i) x |= static_cast<uint64_t>(p[i]) << (8 * i);
  return x;
}

struct Reply {
  uint8_t status = 0;
  std::vector<uint8_t> data;  // after the status byte
};

class Link {
 public:
  Link(const std::string& port, unsigned baud, unsigned timeout_ms, unsigned retries)
      : port_(port), timeout_ms_(timeout_ms), retries_(retries) {
    fd_ = ::open(port.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd_ < 0) throw CliError(kExitLink, "--port " + port + ": cannot open: " + std::strerror(errno));
    termios t{};
    if (tcgetattr(fd_, &t) != 0) {
      ::close(fd_);
      throw CliError(kExitLink, "--port " + port + ": not a serial port: " + std::strerror(errno));
    }
    cfmakeraw(&t);
    t.c_cflag |= CLOCAL | CREAD;
    t.c_cflag &= ~static_cast<tcflag_t>(CSTOPB | PARENB | CRTSCTS);
    cfsetispeed(&t, baud_constant(baud));
    cfsetospeed(&t, baud_constant(baud));
    t.c_cc[VMIN] = 0;
    t.c_cc[VTIME] = 0;
    if (tcsetattr(fd_, TCSANOW, &t) != 0) {
      ::close(fd_);
      throw CliError(kExitLink, "--port " + port + ": cannot configure: " + std::strerror(errno));
    }
    tcflush(fd_, TCIOFLUSH);
  }
  ~Link() { ::close(fd_); }
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;

  // One request, one reply: retransmitted with the same SEQ (the firmware answers a repeated
  // SEQ from its last reply without executing again) until a valid reply with that SEQ arrives.
  Reply request(uint8_t cmd, const std::vector<uint8_t>& payload) {
    seq_ = static_cast<uint8_t>(seq_ + 1);
    std::vector<uint8_t> f{static_cast<uint8_t>(HXP_SOF), static_cast<uint8_t>(payload.size()), seq_, cmd};
    f.insert(f.end(), payload.begin(), payload.end());
    const uint16_t crc = hxp_crc16(f.data() + 1, static_cast<unsigned>(f.size() - 1));
    put_le(f, crc, 2);
    std::string last_problem = "no reply";
    for (unsigned attempt = 0; attempt <= retries_; ++attempt) {
      write_all(f);
      Reply r;
      std::string problem;
      if (read_reply(cmd, r, problem)) {
        // A CRC or timeout error answer may belong to a frame corrupted on the way: send again.
        if (r.status == HXP_E_CRC || r.status == HXP_E_TIMEOUT) {
          last_problem = std::string("board answered: ") + status_text(r.status);
          continue;
        }
        return r;
      }
      last_problem = problem;
    }
    throw CliError(kExitLink, "--port " + port_ + ": " + cmd_name(cmd) + ": " + last_problem +
                                  " after " + std::to_string(retries_ + 1) + " attempts (is the board running the hexstep firmware at this baud rate?)");
  }

 private:
  void write_all(const std::vector<uint8_t>& f) {
    size_t off = 0;
    while (off < f.size()) {
      const ssize_t n = ::write(fd_, f.data() + off, f.size() - off);
      if (n > 0) {
        off += static_cast<size_t>(n);
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        throw CliError(kExitLink, "--port " + port_ + ": write failed: " + std::strerror(errno));
      } else {
        pollfd p{fd_, POLLOUT, 0};
        ::poll(&p, 1, 10);
      }
    }
  }

  // Reads bytes until a frame with our SEQ and the reply command arrives (true), or the timeout.
  bool read_reply(uint8_t cmd, Reply& r, std::string& problem) {
    using clock = std::chrono::steady_clock;
    const auto deadline = clock::now() + std::chrono::milliseconds(timeout_ms_);
    std::vector<uint8_t> buf;
    problem = "no reply within --timeout " + std::to_string(timeout_ms_) + " ms";
    for (;;) {
      // Parse what we have: hunt SOF, wait for the whole frame, check it.
      while (!buf.empty()) {
        if (buf[0] != HXP_SOF) {
          buf.erase(buf.begin());
          continue;
        }
        if (buf.size() < HXP_HEADER) break;
        const unsigned len = buf[1];
        if (len > HXP_MAX_PAYLOAD) {
          buf.erase(buf.begin());
          continue;
        }
        if (buf.size() < len + HXP_OVERHEAD) break;
        const uint16_t crc = hxp_crc16(buf.data() + 1, len + 3);
        const uint16_t got = static_cast<uint16_t>(get_le(buf.data() + HXP_HEADER + len, 2));
        if (crc != got || len == 0) {
          problem = "corrupted reply (checksum)";
          buf.erase(buf.begin());
          continue;
        }
        const bool ours = buf[2] == seq_ && buf[3] == (cmd | HXP_REPLY);
        if (ours) {
          r.status = buf[HXP_HEADER];
          r.data.assign(buf.begin() + HXP_HEADER + 1, buf.begin() + HXP_HEADER + len);
          return true;
        }
        // An answer to something else (e.g. an error for a corrupted earlier frame): skip it.
        buf.erase(buf.begin(), buf.begin() + HXP_OVERHEAD + len);
      }
      const auto now = clock::now();
      if (now >= deadline) return false;
      const int ms = static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count()) + 1;
      pollfd p{fd_, POLLIN, 0};
      const int pr = ::poll(&p, 1, ms);
      if (pr < 0 && errno != EINTR)
        throw CliError(kExitLink, "--port " + port_ + ": poll failed: " + std::strerror(errno));
      if (pr > 0) {
        if (p.revents & (POLLERR | POLLHUP | POLLNVAL))
          throw CliError(kExitLink, "--port " + port_ + ": the device went away");
        uint8_t tmp[256];
        const ssize_t n = ::read(fd_, tmp, sizeof tmp);
        if (n > 0) buf.insert(buf.end(), tmp, tmp + n);
      }
    }
  }

  std::string port_;
  int fd_ = -1;
  unsigned timeout_ms_, retries_;
  uint8_t seq_ = 0;
};

struct AxisState {
  uint8_t fifo = 0, hw_free = 0, err = 0, flags = 0;
  int64_t position = 0;
};
struct Status {
  uint8_t gflags = 0, active = 0, busy = 0, underrun = 0;
  uint32_t err_replies = 0;
  std::array<AxisState, kNumAxes> axes{};
};

Status get_status(Link& link) {
  const Reply r = link.request(HXP_STATUS, {});
  if (r.status != HXP_OK || r.data.size() + 1 != HXP_STATUS_REPLY_LEN)
    throw CliError(kExitBoard, std::string("board: STATUS: ") + status_text(r.status));
  Status s;
  const uint8_t* p = r.data.data();
  s.gflags = p[0];
  s.active = p[1];
  s.busy = p[2];
  s.underrun = p[3];
  s.err_replies = static_cast<uint32_t>(get_le(p + 4, 4));
  for (unsigned k = 0; k < kNumAxes; ++k) {
    const uint8_t* a = p + 8 + k * HXP_STATUS_AXIS_LEN;
    s.axes[k].fifo = a[0];
    s.axes[k].hw_free = a[1];
    s.axes[k].err = a[2];
    s.axes[k].flags = a[3];
    s.axes[k].position = static_cast<int64_t>(get_le(a + 4, 8));
  }
  return s;
}

std::string positions(const Status& s, uint32_t mask) {
  std::string out;
  for (unsigned k = 0; k < kNumAxes; ++k)
    if (mask & (1u << k)) out += (out.empty() ? "" : ", ") + std::to_string(k) + ": " + std::to_string(s.axes[k].position);
  return out;
}

// Faults the board reports in a status; throws CliError(kExitBoard).
void check_faults(const Status& s, uint32_t mask, const std::array<size_t, kNumAxes>& left) {
  if (s.gflags & HXP_G_ESTOP)
    throw CliError(kExitBoard, "board: E-STOP latched: every axis was stopped (positions " +
                                   positions(s, mask) + "); release the e-stop input and run again with --clear-estop");
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (!(mask & (1u << k))) continue;
    if (s.axes[k].err & 1u)
      throw CliError(kExitBoard, "board: axis " + std::to_string(k) + ": the core refused a move (AXIS_ERR.move)");
    if (s.axes[k].err & 2u)
      throw CliError(kExitBoard, "board: axis " + std::to_string(k) + ": move queue overrun (AXIS_ERR.overrun)");
    if ((s.underrun & (1u << k)) || (left[k] != 0 && !(s.active & (1u << k))))
      throw CliError(kExitBoard, "board: axis " + std::to_string(k) +
                                     ": stream underrun: the axis ran out of moves before the next arrived "
                                     "(moves too short for the link); it was stopped");
  }
}

std::vector<uint8_t> move_payload(unsigned axis, const AxisMove& m) {
  std::vector<uint8_t> p;
  put_le(p, axis, 1);
  put_le(p, m.steps, 4);
  put_le(p, m.dir ? 1 : 0, 1);
  put_le(p, m.v_start, 8);
  put_le(p, m.v_max, 8);
  put_le(p, m.v_end, 8);
  put_le(p, m.acc, 8);
  put_le(p, m.dec, 8);
  put_le(p, m.v_dec, 8);
  put_le(p, m.acc_steps, 4);
  put_le(p, m.dec_step, 4);
  put_le(p, m.dec_frac, 4);
  return p;
}

void expect_ok(const Reply& r, const std::string& what) {
  if (r.status != HXP_OK) throw CliError(kExitBoard, "board refused " + what + ": " + status_text(r.status));
}

Status stream_job(Link& link, const Job& job, uint32_t mask, std::array<size_t, kNumAxes>& left,
                  unsigned depth);

}  // namespace

CLI::App* add_send(CLI::App& app, SendOptions& o) {
  CLI::App* sub = app.add_subcommand(
      "send",
      "Stream a job to a board running the hexstep SoC firmware over a serial port (protocol: "
      "docs/PROTOCOL.md), start all its axes with one START, wait until they finish and print the "
      "final positions.");
  sub->add_option("job", o.job, "Job file (docs/FORMATS.md), e.g. from `hexstep plan --format job`; '-' reads stdin")
      ->required()
      ->option_text("JOB.json");
  sub->add_option("--port", o.port, "Serial device of the board (or the simulator's pseudo-terminal)")
      ->required()
      ->option_text("PATH");
  sub->add_option("--baud", o.baud, "Line speed in baud, one of 9600, 19200, 38400, 57600, 115200, 230400, "
                                    "460800, 921600, 1000000, 2000000, 3000000. Default: 115200")
      ->check(CLI::IsMember({9600u, 19200u, 38400u, 57600u, 115200u, 230400u, 460800u, 921600u, 1000000u,
                             2000000u, 3000000u}))
      ->option_text("B");
  sub->add_option("--timeout", o.timeout_ms, "Milliseconds to wait for each reply, 1..600000. Default: 2000")
      ->check(CLI::Range(1u, 600000u))
      ->option_text("MS");
  sub->add_option("--retries", o.retries, "Retransmissions of a request without a valid reply, 0..100. Default: 3")
      ->check(CLI::Range(0u, 100u))
      ->option_text("N");
  sub->add_flag("--clear-estop", o.clear_estop,
                "Clear a latched E-STOP before sending (fails if the e-stop input is still active)");
  sub->footer(
      "Output (stdout, only on success): 'axis,position' and one line per axis of the job with its\n"
      "final position in steps (signed). Exit status: 0 success; 2 bad command line or job;\n"
      "6 link error (port unusable, no valid reply after the retries); 7 the board refused a\n"
      "request or reported a fault (E-STOP, a move refused by the core, stream underrun).");
  return sub;
}

int run_send(const SendOptions& o) {
  const std::string name = input_name(o.job);
  const std::string text = read_input(o.job);
  Job job;
  try {
    job = parse_job(text);
  } catch (const JobError& e) {
    throw CliError(kExitUsage, name + ": " + e.what());
  }
  uint32_t mask = 0;
  std::array<size_t, kNumAxes> left{};
  for (unsigned k = 0; k < kNumAxes; ++k) {
    for (size_t i = 0; i < job.axes[k].moves.size(); ++i)
      if (job.axes[k].moves[i].jog)
        throw CliError(kExitUsage, name + ": axes[" + std::to_string(k) + "].moves[" + std::to_string(i) +
                                       "].jog: jog moves cannot be sent (protocol version 1 has no jog)");
    left[k] = job.axes[k].moves.size();
    if (left[k] != 0) mask |= 1u << k;
  }
  if (mask == 0) throw CliError(kExitUsage, name + ": the job has no moves");

  Link link(o.port, o.baud, o.timeout_ms, o.retries);
  const Reply hello = link.request(HXP_HELLO, {});
  expect_ok(hello, "HELLO");
  if (hello.data.size() + 1 != HXP_HELLO_REPLY_LEN || hello.data[0] != HXP_VERSION)
    throw CliError(kExitBoard, "board: HELLO: protocol version " +
                                   std::to_string(hello.data.empty() ? 0 : hello.data[0]) + ", expected " +
                                   std::to_string(HXP_VERSION));
  // A board build may have fewer axes than six (synth/targets.json): the job must fit them.
  const unsigned board_axes = hello.data[1];
  if (board_axes < 1 || board_axes > kNumAxes)
    throw CliError(kExitBoard, "board: HELLO: axis count " + std::to_string(board_axes) + ", expected 1.." +
                                   std::to_string(kNumAxes));
  for (unsigned k = board_axes; k < kNumAxes; ++k)
    if (mask & (1u << k))
      throw CliError(kExitBoard, "board: the job moves axis " + std::to_string(k) + ", the board has " +
                                     std::to_string(board_axes) + (board_axes == 1 ? " axis (0)" : " axes (0.." +
                                     std::to_string(board_axes - 1) + ")") + "; nothing was sent");
  const unsigned depth = hello.data[2];
  // The widths of the board's core: a job's values must fit its registers (ACC_W, STEP_W,
  // DFRAC_W, PULSE_W), or the board would truncate them; SPEED_W is 64 in every build, so a
  // reply with another value is not a hexstep frame-engine core.
  const Reply info = link.request(HXP_INFO, {});
  expect_ok(info, "INFO");
  if (info.data.size() + 1 != HXP_INFO_REPLY_LEN)
    throw CliError(kExitBoard, "board: INFO: reply of " + std::to_string(info.data.size() + 1) +
                                   " bytes, expected " + std::to_string(HXP_INFO_REPLY_LEN));
  Widths board_w = job.widths;  // POS_W is not reported (INFO keeps its five-byte format)
  board_w.speed_frac = info.data[0];
  board_w.acc = info.data[1];
  board_w.steps = info.data[2];
  board_w.dec_frac = info.data[3];
  board_w.pulse = info.data[4];
  if (!same_widths(board_w, job.widths))
    throw CliError(kExitBoard, name + ": planned for a core with " + widths_text(job.widths) +
                                   ", the board's core has SPEED_W " + std::to_string(board_w.speed_frac) +
                                   ", ACC_W " + std::to_string(board_w.acc) + ", STEP_W " +
                                   std::to_string(board_w.steps) + ", DFRAC_W " + std::to_string(board_w.dec_frac) +
                                   ", PULSE_W " + std::to_string(board_w.pulse) +
                                   " (plan it with hexstep plan --widths); nothing was sent");

  Status st = get_status(link);
  if (st.gflags & HXP_G_ESTOP) {
    if (!o.clear_estop)
      throw CliError(kExitBoard, "board: E-STOP latched before the job; release the e-stop input and use --clear-estop");
  }
  if (st.active != 0 || st.busy != 0)
    throw CliError(kExitBoard, "board: axes busy (mask 0x" + std::to_string(st.active | st.busy) + ") before the job");
  // CLEAR: error flags of an earlier job (and, with --clear-estop, the latch).
  expect_ok(link.request(HXP_CLEAR, {}), "CLEAR (the e-stop input is still active?)");
  // ABORT the job's axes while they are idle: drops moves a refused earlier run left in the
  // board's FIFOs, so that START runs this job's moves only.
  expect_ok(link.request(HXP_ABORT, {static_cast<uint8_t>(mask)}), "ABORT (flush of the job's axes)");

  // From here on the board holds state of this job: a refusal or fault ends it with a
  // controlled STOP of the job's axes (flushes their FIFOs and queues, decelerates a running
  // axis to rest), so that nothing of it runs on after `send` has exited. A link error does
  // not try: the link is what failed.
  try {
    st = stream_job(link, job, mask, left, depth);
  } catch (const CliError& e) {
    if (e.code() == kExitBoard) {
      try {
        (void)link.request(HXP_STOP, {static_cast<uint8_t>(mask)});
      } catch (const CliError&) {
      }
    }
    throw;
  }
  std::string out = "axis,position\n";
  for (unsigned k = 0; k < kNumAxes; ++k)
    if (mask & (1u << k)) out += std::to_string(k) + "," + std::to_string(st.axes[k].position) + "\n";
  write_stdout(out);
  return kExitOk;
}

namespace {

// PULSE, MOVE, START, then STATUS and further MOVEs until every axis of the job is at rest.
Status stream_job(Link& link, const Job& job, uint32_t mask, std::array<size_t, kNumAxes>& left,
                  unsigned depth) {
  Status st;
  for (unsigned k = 0; k < kNumAxes; ++k) {
    if (!(mask & (1u << k))) continue;
    const PulseConfig& pc = job.axes[k].pulse;
    std::vector<uint8_t> p;
    put_le(p, k, 1);
    put_le(p, pc.step_high, 2);
    put_le(p, pc.step_low, 2);
    put_le(p, pc.dir_setup, 2);
    put_le(p, pc.dir_hold, 2);
    put_le(p, (pc.step_invert ? 1u : 0u) | (pc.dir_invert ? 2u : 0u), 1);
    expect_ok(link.request(HXP_PULSE, p), "PULSE for axis " + std::to_string(k));
  }

  // Moves: round robin over the axes, an axis waits while its FIFO is full.
  std::array<size_t, kNumAxes> next{};
  std::array<unsigned, kNumAxes> room{};
  room.fill(depth);
  auto send_some = [&]() {
    bool any = true;
    while (any) {
      any = false;
      for (unsigned k = 0; k < kNumAxes; ++k) {
        if (left[k] == 0 || room[k] == 0) continue;
        const Reply r = link.request(HXP_MOVE, move_payload(k, job.axes[k].moves[next[k]]));
        if (r.status == HXP_E_FULL) {
          room[k] = 0;
          continue;
        }
        expect_ok(r, "MOVE " + std::to_string(next[k]) + " of axis " + std::to_string(k));
        room[k] = r.data.empty() ? 0 : r.data[0];
        ++next[k];
        --left[k];
        any = true;
      }
    }
  };
  send_some();
  const Reply started = link.request(HXP_START, {static_cast<uint8_t>(mask)});
  expect_ok(started, "START");
  if (started.data.empty() || started.data[0] != mask)
    throw CliError(kExitBoard, "board: START started mask " +
                                   std::to_string(started.data.empty() ? 0 : started.data[0]) + ", not " + std::to_string(mask));
  for (;;) {
    st = get_status(link);
    check_faults(st, mask, left);
    bool pending = false;
    for (unsigned k = 0; k < kNumAxes; ++k) {
      room[k] = depth - st.axes[k].fifo;
      pending |= left[k] != 0;
    }
    if (pending) {
      send_some();
      continue;
    }
    if (st.active == 0 && st.busy == 0) break;
  }
  return st;
}

}  // namespace

}  // namespace hexstep::cli
