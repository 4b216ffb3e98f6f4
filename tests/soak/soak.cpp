// SPDX-License-Identifier: Apache-2.0
// hexstep_soak: long random co-simulation, RTL (Verilated hexstep_top) against the golden
// model (TopModel), every bus output and every STEP/DIR pin compared after every clock edge
// (lockstep.hpp). Jobs come from tests/common/vectors.* (random_job: planned ramps at 12..100
// MHz and raw register values, valid or not, random pulse timing and polarity), played through
// the Wishbone bus by run_job the way firmware does (two moves queued per axis, one START,
// refills from the slot interrupt) with random idle and wait cycles before every request. Job j
// of a run with --seed S uses its own seed S*1000003+j, written to the log with the command
// that replays it alone:
//   hexstep_soak --moves N --seed S [--log FILE] [--moves-per-axis K]
//   hexstep_soak --replay JOBSEED [--moves-per-axis K]      (TRACE=1: FST trace of the replay)
// Besides RTL == model, every job must finish without a bus protocol error, and each axis must
// end with exactly the steps and position of its moves that validate_move() accepts (an oracle
// independent of both), having reported a refusal (ERR.move) if one of its moves was refused.
// Exit status: 0 all jobs passed, 1 a job failed (the log names it), 2 bad command line.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "lockstep.hpp"
#include "vectors.hpp"

using namespace hexstep;
using namespace hexstep::test;

namespace {

struct Args {
  uint64_t moves = 0, seed = 0, replay = 0, per_axis = 28;
  bool has_seed = false, has_replay = false;
  std::string log;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "hexstep_soak: error: %s\n"
               "usage: hexstep_soak --moves N --seed S [--log FILE] [--moves-per-axis K]\n"
               "       hexstep_soak --replay JOBSEED [--moves-per-axis K]\n",
               why.c_str());
  std::exit(2);
}

uint64_t number(const char* flag, const char* v) {
  if (!v || !*v || std::strspn(v, "0123456789") != std::strlen(v) || std::strlen(v) > 19)
    usage(std::string(flag) + " must be a decimal integer in [0, 10^19), got '" + (v ? v : "") + "'");
  return std::strtoull(v, nullptr, 10);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string f = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : nullptr;
    if (f == "--moves") a.moves = number("--moves", v);
    else if (f == "--seed") a.seed = number("--seed", v), a.has_seed = true;
    else if (f == "--replay") a.replay = number("--replay", v), a.has_replay = true;
    else if (f == "--moves-per-axis") a.per_axis = number("--moves-per-axis", v);
    else if (f == "--log") {
      if (!v) usage("--log needs a file name");
      a.log = v;
    } else usage("unknown argument '" + f + "'");
    ++i;
  }
  if (a.per_axis == 0 || a.per_axis > 1000) usage("--moves-per-axis must be in [1, 1000]");
  if (a.has_replay == (a.has_seed || a.moves != 0)) usage("give either --moves and --seed, or --replay");
  if (!a.has_replay && (a.moves == 0 || !a.has_seed)) usage("--moves N (N >= 1) and --seed S are required");
  return a;
}

struct JobResult {
  bool ok = true;
  uint64_t moves = 0, cycles = 0, refused = 0;
  std::string why;
};

// Long enough for every job random_job makes (moves of at most a few thousand ticks, raw ones
// a step within ~128 ticks), short enough that a hang ends the run in minutes.
constexpr uint64_t kMaxJobCycles = 200000000;

JobResult run_one(uint64_t job_seed, unsigned per_axis) {
  std::mt19937_64 rng(job_seed);
  const NamedJob nj = random_job(rng, per_axis, true);
  RunOptions opt;
  opt.max_cycles = kMaxJobCycles;
  opt.bus_seed = static_cast<uint32_t>(rng());
  opt.bus_idle = static_cast<unsigned>(rng() % 4);
  opt.bus_wait = static_cast<unsigned>(rng() % 3);
  LockstepPair ls;
  ls.context() = "job seed " + std::to_string(job_seed);
  const RunResult r = run_job(ls, nj.job, [](const StepEvent&) {}, opt);
  JobResult out;
  out.moves = uint64_t(per_axis) * kNumAxes;
  out.cycles = ls.edges();
  if (ls.mismatches() != 0) {
    out.ok = false;
    out.why = std::to_string(ls.mismatches()) + " RTL/model mismatches, first:\n" + ls.report();
  }
  if (r.timed_out) {
    out.ok = false;
    out.why += "the job did not finish within " + std::to_string(kMaxJobCycles) + " cycles of its START\n";
  }
  if (r.protocol_errors != 0) {
    out.ok = false;
    out.why += std::to_string(r.protocol_errors) + " Wishbone protocol errors\n";
  }
  for (unsigned a = 0; a < kNumAxes; ++a) {
    uint64_t steps = 0, refused = 0;
    int64_t pos = 0;
    for (const AxisMove& m : nj.job.axes[a].moves) {
      if (validate_move(m, nj.job.widths) != 0) {
        ++refused;
        continue;
      }
      steps += m.steps;
      pos += m.dir ? int64_t(m.steps) : -int64_t(m.steps);
    }
    out.refused += refused;
    // ERR.move is one sticky flag: refusals consumed in consecutive frames while the runner
    // serves another axis read as one. At least one, at most all of them are seen.
    const bool refusals_seen = refused == 0 ? r.refused[a] == 0 : r.refused[a] >= 1 && r.refused[a] <= refused;
    if (r.steps[a] != steps || r.position[a] != pos || !refusals_seen) {
      out.ok = false;
      out.why += "axis " + std::to_string(a) + ": " + std::to_string(r.steps[a]) + " steps, position " +
                 std::to_string(r.position[a]) + ", " + std::to_string(r.refused[a]) +
                 " refusals seen; the accepted moves give " + std::to_string(steps) + ", " + std::to_string(pos) +
                 ", and " + std::to_string(refused) + " are refused\n";
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  if (a.has_replay) {
    const JobResult r = run_one(a.replay, static_cast<unsigned>(a.per_axis));
    std::printf("job seed %llu: %llu moves, %llu cycles, %llu refused: %s\n%s",
                static_cast<unsigned long long>(a.replay), static_cast<unsigned long long>(r.moves),
                static_cast<unsigned long long>(r.cycles), static_cast<unsigned long long>(r.refused),
                r.ok ? "ok" : "FAILED", r.why.c_str());
    return r.ok ? 0 : 1;
  }
  std::FILE* log = a.log.empty() ? stdout : std::fopen(a.log.c_str(), "w");
  if (!log) usage("--log: cannot open " + a.log + " for writing");
  const auto t0 = std::chrono::steady_clock::now();
  std::fprintf(log, "soak: --moves %llu --seed %llu --moves-per-axis %llu\n",
               static_cast<unsigned long long>(a.moves), static_cast<unsigned long long>(a.seed),
               static_cast<unsigned long long>(a.per_axis));
  uint64_t moves = 0, cycles = 0, refused = 0, jobs = 0;
  bool ok = true;
  for (uint64_t j = 0; moves < a.moves; ++j) {
    const uint64_t js = a.seed * 1000003ull + j;
    const JobResult r = run_one(js, static_cast<unsigned>(a.per_axis));
    moves += r.moves;
    cycles += r.cycles;
    refused += r.refused;
    ++jobs;
    std::fprintf(log, "job %llu seed %llu: %llu moves, %llu cycles: %s (replay: hexstep_soak --replay %llu --moves-per-axis %llu)\n",
                 static_cast<unsigned long long>(j), static_cast<unsigned long long>(js),
                 static_cast<unsigned long long>(r.moves), static_cast<unsigned long long>(r.cycles),
                 r.ok ? "ok" : "FAILED", static_cast<unsigned long long>(js),
                 static_cast<unsigned long long>(a.per_axis));
    if (!r.ok) {
      std::fprintf(log, "%s", r.why.c_str());
      ok = false;
      break;
    }
    std::fflush(log);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fprintf(log, "soak: seed %llu: %llu jobs, %llu moves (%llu refused as expected), %llu cycles, %.1f s: %s\n",
               static_cast<unsigned long long>(a.seed), static_cast<unsigned long long>(jobs),
               static_cast<unsigned long long>(moves), static_cast<unsigned long long>(refused),
               static_cast<unsigned long long>(cycles), s, ok ? "PASS" : "FAIL");
  if (log != stdout) {
    std::fclose(log);
    std::printf("soak: seed %llu: %llu moves, %.1f s: %s\n", static_cast<unsigned long long>(a.seed),
                static_cast<unsigned long long>(moves), s, ok ? "PASS" : "FAIL");
  }
  return ok ? 0 : 1;
}
