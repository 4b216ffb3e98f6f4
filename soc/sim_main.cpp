// SPDX-License-Identifier: Apache-2.0
// hexstep-soc-sim: the Verilated SoC (soc/hexstep_soc.v running firmware/soc_main.c) with its
// UART on a pseudo-terminal, so that an unmodified host program (`hexstep send`) talks to it as
// to a board. Runs COMMAND (with {port} replaced by the terminal's path) next to the simulation,
// until it exits; exits with its status. Optionally records every STEP edge as the CSV of
// `hexstep simulate` (numbered with the moves of --job) and raises the e-stop pin mid-run.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <verilated.h>
#include <verilated_fst_c.h>

#include "Vhexstep_soc.h"
#include "Vhexstep_soc___024root.h"
#include "hexstep/job.hpp"
#include "hexstep/job_io.hpp"
#include "simulate.hpp"

extern char** environ;

namespace {

constexpr unsigned kAxes = 6;

[[noreturn]] void die(const std::string& msg, int code = 2) {
  std::fprintf(stderr, "hexstep-soc-sim: error: %s\n", msg.c_str());
  std::exit(code);
}

struct Options {
  std::string job, csv, trace;
  uint64_t max_cycles = 2000000000ull;
  long estop_after_steps = -1;  // raise the e-stop pin after this many STEP edges in total
  std::vector<std::string> cmd;
};

uint64_t parse_u64(const std::string& flag, const std::string& v) {
  if (v.empty() || v.size() > 19 || v.find_first_not_of("0123456789") != std::string::npos)
    die(flag + " must be a decimal integer in [0, 10^19), got '" + v + "'");
  return std::stoull(v);
}

Options parse(int argc, char** argv) {
  Options o;
  int i = 1;
  for (; i < argc; ++i) {
    const std::string a = argv[i];
    auto val = [&]() -> std::string {
      if (i + 1 >= argc) die(a + " needs a value");
      return argv[++i];
    };
    if (a == "--") {
      ++i;
      break;
    } else if (a == "--job") {
      o.job = val();
    } else if (a == "--csv") {
      o.csv = val();
    } else if (a == "--trace") {
      o.trace = val();
    } else if (a == "--max-cycles") {
      o.max_cycles = parse_u64(a, val());
    } else if (a == "--estop-after-steps") {
      o.estop_after_steps = static_cast<long>(parse_u64(a, val()));
    } else if (a == "--help" || a == "-h") {
      std::printf(
          "usage: hexstep-soc-sim [--job JOB.json --csv OUT.csv] [--estop-after-steps N]\n"
          "                       [--max-cycles N] [--trace F.fst] -- COMMAND ARGS...\n"
          "Runs the Verilated SoC with its UART on a pseudo-terminal and COMMAND beside it;\n"
          "{port} in ARGS is replaced by the terminal's path. Exit status: COMMAND's, or 124 if\n"
          "--max-cycles ran out, 125 if the CPU trapped, 2 for a bad command line.\n"
          "--csv writes every STEP edge as `hexstep simulate` does; cycle 0 is the first cycle\n"
          "with a START write at the core (the motion begins at the next frame boundary);\n"
          "--job numbers the steps within moves and gives the clock and polarities.\n");
      std::exit(0);
    } else {
      die("unknown option '" + a + "' (see --help)");
    }
  }
  for (; i < argc; ++i) o.cmd.push_back(argv[i]);
  if (o.cmd.empty()) die("no COMMAND after '--' (see --help)");
  if (!o.csv.empty() && o.job.empty()) die("--csv needs --job (to number steps within moves)");
  return o;
}

// The pseudo-terminal: master side here, slave path for COMMAND. The slave stays open here
// too, in raw mode, so the master never sees a hang-up between the client's open and close.
struct Pty {
  int master = -1, slave = -1;
  std::string path;
  Pty() {
    master = posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0) die("posix_openpt failed");
    const char* p = ptsname(master);
    if (!p) die("ptsname failed");
    path = p;
    slave = open(p, O_RDWR | O_NOCTTY);
    if (slave < 0) die("cannot open " + path);
    termios t{};
    tcgetattr(slave, &t);
    cfmakeraw(&t);
    tcsetattr(slave, TCSANOW, &t);
    fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
  }
};

// Serial line at the UART's bit time: bytes from the host shifted onto rx, bytes from tx
// collected.
struct Line {
  unsigned div;
  std::deque<uint8_t> to_board;
  // rx driver
  int tx_bit = -1;  // -1 idle; 0 start; 1..8 data; 9 stop
  unsigned tx_cnt = 0;
  uint8_t tx_byte = 0;
  bool rx_level = true;
  // tx sampler
  bool in_byte = false;
  unsigned rx_cnt = 0, rx_bit = 0;
  uint8_t rx_byte = 0;
  bool prev_tx = true;
  std::vector<uint8_t> from_board;

  explicit Line(unsigned d) : div(d) {}
  void step(bool tx_pin) {  // once per clock cycle
    if (tx_bit < 0 && !to_board.empty()) {
      tx_byte = to_board.front();
      to_board.pop_front();
      tx_bit = 0;
      tx_cnt = 0;
    }
    if (tx_bit >= 0) {
      rx_level = tx_bit == 0 ? false : tx_bit == 9 ? true : ((tx_byte >> (tx_bit - 1)) & 1u);
      if (++tx_cnt == div) {
        tx_cnt = 0;
        if (++tx_bit == 10) tx_bit = -1;
      }
    } else {
      rx_level = true;
    }
    if (!in_byte) {
      if (prev_tx && !tx_pin) {
        in_byte = true;
        rx_cnt = div + div / 2;  // middle of data bit 0
        rx_bit = 0;
        rx_byte = 0;
      }
    } else if (--rx_cnt == 0) {
      if (rx_bit < 8) {
        rx_byte |= static_cast<uint8_t>((tx_pin ? 1u : 0u) << rx_bit);
        ++rx_bit;
        rx_cnt = div;
      } else {
        if (tx_pin) from_board.push_back(rx_byte);  // a missing stop bit drops the byte
        in_byte = false;
      }
    }
    prev_tx = tx_pin;
  }
};

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  signal(SIGPIPE, SIG_IGN);

  hexstep::Job job;
  if (!o.job.empty()) {
    std::ifstream f(o.job);
    if (!f) die("cannot read --job " + o.job);
    std::stringstream ss;
    ss << f.rdbuf();
    try {
      job = hexstep::parse_job(ss.str());
    } catch (const hexstep::JobError& e) {
      die(o.job + ": " + e.what());
    }
  }

  Pty pty;
  std::vector<std::string> args = o.cmd;
  for (std::string& a : args)
    for (size_t p; (p = a.find("{port}")) != std::string::npos;) a.replace(p, 6, pty.path);
  std::vector<char*> cargv;
  for (std::string& a : args) cargv.push_back(a.data());
  cargv.push_back(nullptr);

  auto ctx = std::make_unique<VerilatedContext>();
  ctx->traceEverOn(!o.trace.empty());
  auto top = std::make_unique<Vhexstep_soc>(ctx.get());
  std::unique_ptr<VerilatedFstC> tfp;
  if (!o.trace.empty()) {
    tfp = std::make_unique<VerilatedFstC>();
    top->trace(tfp.get(), 99);
    tfp->open(o.trace.c_str());
  }
  Line line(HEXSTEP_SOC_UART_DIV);
  uint64_t t = 0;
  auto tick = [&]() {
    top->clk_i = 0;
    top->eval();
    if (tfp) tfp->dump(2 * t);
    top->clk_i = 1;
    top->eval();
    if (tfp) tfp->dump(2 * t + 1);
    ++t;
  };
  top->rst_i = 1;
  top->uart_rx_i = 1;
  top->estop_i = 0;
  for (int i = 0; i < 8; ++i) tick();
  top->rst_i = 0;

  pid_t pid;
  if (posix_spawnp(&pid, cargv[0], nullptr, nullptr, cargv.data(), environ) != 0)
    die("cannot run '" + args[0] + "': " + std::strerror(errno));

  // STEP edges: cycle counted from the first cycle with a START write at the core (its start_w
  // strobe, the cycle the write is acted on). The core starts the axes at the next frame
  // boundary, so the first STEP edge is 1 to 32 cycles later than from a START written at
  // another phase of the frame: `hexstep simulate` and this differ by that constant.
  struct Ev {
    unsigned axis;
    uint64_t edge;
    bool dir;
  };
  std::vector<Ev> evs;
  int64_t edge0 = -1;
  uint8_t prev_step = 0;
  long nsteps = 0;
  std::array<bool, kAxes> step_inv{}, dir_inv{};
  for (unsigned k = 0; k < kAxes; ++k) {
    step_inv[k] = job.axes[k].pulse.step_invert;
    dir_inv[k] = job.axes[k].pulse.dir_invert;
  }
  for (unsigned k = 0; k < kAxes; ++k) prev_step |= static_cast<uint8_t>((step_inv[k] ? 1u : 0u) << k);

  int status = -1;
  uint64_t cycle = 0;
  int rc = 0;
  for (;; ++cycle) {
    if (cycle >= o.max_cycles) {
      std::fprintf(stderr, "hexstep-soc-sim: --max-cycles %llu reached; stopping '%s'\n",
                   static_cast<unsigned long long>(o.max_cycles), args[0].c_str());
      kill(pid, SIGTERM);
      waitpid(pid, &status, 0);
      rc = 124;
      break;
    }
    line.step(top->uart_tx_o);
    top->uart_rx_i = line.rx_level;
    const bool started = top->rootp->hexstep_soc__DOT__u_hexstep__DOT__start_w != 0;
    tick();
    if (edge0 < 0 && started) edge0 = static_cast<int64_t>(cycle);
    const uint8_t step = top->step_o, dir = top->dir_o;
    if (step != prev_step) {
      for (unsigned k = 0; k < kAxes; ++k) {
        const bool now = (step >> k) & 1u, was = (prev_step >> k) & 1u;
        if (now != was && now != step_inv[k]) {  // start of a STEP pulse
          evs.push_back({k, cycle, (((dir >> k) & 1u) != 0) != dir_inv[k]});
          ++nsteps;
        }
      }
      prev_step = step;
      if (o.estop_after_steps >= 0 && nsteps >= o.estop_after_steps) top->estop_i = 1;
    }
    if (top->trap_o) {
      std::fprintf(stderr, "hexstep-soc-sim: the CPU trapped at cycle %llu\n",
                   static_cast<unsigned long long>(cycle));
      kill(pid, SIGTERM);
      waitpid(pid, &status, 0);
      rc = 125;
      break;
    }
    if ((cycle & 63u) == 0) {
      if (!line.from_board.empty()) {
        const ssize_t n = write(pty.master, line.from_board.data(), line.from_board.size());
        if (n > 0) line.from_board.erase(line.from_board.begin(), line.from_board.begin() + n);
      }
      uint8_t buf[256];
      const ssize_t n = read(pty.master, buf, sizeof buf);
      for (ssize_t i = 0; i < n; ++i) line.to_board.push_back(buf[i]);
    }
    if ((cycle & 4095u) == 0 && waitpid(pid, &status, WNOHANG) == pid) {
      rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      break;
    }
  }
  if (tfp) tfp->close();
  top->final();

  if (!o.csv.empty()) {
    // Number the steps within the moves of the job (moves of zero steps make no edge).
    std::array<size_t, kAxes> move{};
    std::array<uint32_t, kAxes> in_move{};
    std::vector<hexstep::StepEvent> out;
    for (const Ev& e : evs) {
      const auto& moves = job.axes[e.axis].moves;
      hexstep::StepEvent s;
      s.axis = e.axis;
      while (move[e.axis] < moves.size() && in_move[e.axis] >= moves[move[e.axis]].steps) {
        ++move[e.axis];
        in_move[e.axis] = 0;
      }
      s.move = static_cast<unsigned>(move[e.axis]);
      s.step = ++in_move[e.axis];
      s.cycle = edge0 < 0 ? e.edge : e.edge - static_cast<uint64_t>(edge0);
      s.dir = e.dir;
      out.push_back(s);
    }
    std::stable_sort(out.begin(), out.end(), [](const hexstep::StepEvent& a, const hexstep::StepEvent& b) {
      return a.cycle != b.cycle ? a.cycle < b.cycle : a.axis < b.axis;
    });
    std::ofstream f(o.csv);
    f << hexstep::cli::format_csv(out, job.clock_hz);
    if (!f) die("cannot write --csv " + o.csv);
  }
  std::fprintf(stderr, "hexstep-soc-sim: %llu cycles, %ld STEP edges, command exit status %d\n",
               static_cast<unsigned long long>(cycle), nsteps, rc);
  return rc;
}
