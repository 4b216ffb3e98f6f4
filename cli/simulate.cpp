// SPDX-License-Identifier: Apache-2.0
#include "simulate.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

#include "common.hpp"
#include "engine.hpp"
#include "hexstep/job_io.hpp"

namespace hexstep::cli {

CLI::App* add_simulate(CLI::App& app, SimulateOptions& o) {
  CLI::App* sub = app.add_subcommand(
      "simulate",
      "Run a job file on the cycle-exact C++ model or on the Verilated RTL and print every STEP "
      "rising edge as CSV on stdout (or, with --summary, a per-axis table).");
  sub->add_option("job", o.job,
                  "Job file (JSON, format \"hexstep-job\" version 1, see docs/FORMATS.md); "
                  "'-' reads it from stdin")
      ->required()
      ->option_text("JOB.json");
  sub->add_option("--engine", o.engine,
                  "Simulator of the whole block (rtl/hexstep_top.v): 'model' = the cycle-exact C++ "
                  "golden model, 'rtl' = the Verilated RTL (only if this hexstep was built with "
                  "-DHEXSTEP_RTL=ON). Both are driven through the same Wishbone job runner and "
                  "give identical output for a valid job. Default: model")
      ->check(CLI::IsMember({"model", "rtl"}))
      ->option_text("model|rtl");
  sub->add_flag("--event-mode", o.event_mode,
                "Skip over stretches of clock cycles in which no output changes instead of "
                "simulating every cycle (much faster for slow moves; same output; the model "
                "supports it, the rtl engine ignores it)");
  sub->add_option("--max-cycles", o.max_cycles,
                  "Give up (exit status 4, nothing printed) if the job has not finished (every "
                  "axis seen at rest by the job runner: the 'run:' length of --summary) within N "
                  "clock cycles, counted from the START write (at 100 MHz, 10^8 cycles = 1 s of "
                  "machine time). Default: 10000000000 (100 s at 100 MHz)")
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            // Plain decimal only: strtoull would accept "-5" and wrap it around.
            const bool digits = !v.empty() && v.size() <= 20 &&
                                v.find_first_not_of("0123456789") == std::string::npos;
            if (!digits || v.find_first_not_of('0') == std::string::npos ||
                (v.size() == 20 && v > "18446744073709551615"))
              return "must be an integer in [1, 18446744073709551615], got '" + v + "'";
            return "";
          },
          "", "cycle count"))
      ->option_text("N");
  sub->add_flag("--summary", o.summary,
                "Print a human-readable table instead of the CSV: per axis the number of moves, "
                "steps taken, final position (steps, signed), clock cycle of the last STEP rising "
                "edge and its time in seconds; then the total run length in cycles and seconds");
  sub->add_option("--trace", o.trace,
                  "Write an FST waveform of the RTL run to FILE (--engine rtl only)")
      ->option_text("FILE.fst");
  sub->footer(
      "Output: nothing on stdout unless the whole run succeeded. The CSV has the header line\n"
      "  axis,step,cycle,time_s,dir\n"
      "and one line per step (the start of its STEP pulse: the rising edge, or the falling edge\n"
      "with step_invert), sorted by cycle, then axis:\n"
      "  axis    axis index, 0..5\n"
      "  step    index of the step within its move, counting from 1\n"
      "  cycle   first clock cycle of the pulse, counted from the cycle in which the runner\n"
      "          writes START (cycle 0), after the pulse configuration and the first moves\n"
      "  time_s  cycle / clock_hz in seconds, in fixed point with as many decimals as the\n"
      "          clock needs to be exact to the cycle (8 at 100 MHz)\n"
      "  dir     1 = positive motion, 0 = negative motion\n"
      "Errors go to stderr as one line starting 'hexstep: error:' (exit statuses: hexstep --help).");
  return sub;
}

std::string format_csv(const std::vector<StepEvent>& events, uint64_t clock_hz) {
  std::string out = "axis,step,cycle,time_s,dir\n";
  out.reserve(out.size() + events.size() * 40);
  char buf[128];
  for (const StepEvent& e : events) {
    const std::string t = format_seconds(e.cycle, clock_hz);
    std::snprintf(buf, sizeof buf, "%u,%u,%llu,%s,%d\n", e.axis, static_cast<unsigned>(e.step),
                  static_cast<unsigned long long>(e.cycle), t.c_str(), e.dir ? 1 : 0);
    out += buf;
  }
  return out;
}

std::string format_summary(const Job& job, const RunResult& r, const std::vector<StepEvent>& events,
                           const std::string& source, const std::string& engine) {
  std::array<uint64_t, kNumAxes> last{};
  std::array<bool, kNumAxes> any{};
  for (const StepEvent& e : events) {
    last[e.axis] = std::max(last[e.axis], e.cycle);
    any[e.axis] = true;
  }
  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf, "job %s, clock %llu Hz, engine %s\n", source.c_str(),
                static_cast<unsigned long long>(job.clock_hz), engine.c_str());
  out += buf;
  std::snprintf(buf, sizeof buf, "%4s %6s %12s %12s %16s %16s\n", "axis", "moves", "steps",
                "position", "last step cycle", "duration s");
  out += buf;
  for (unsigned i = 0; i < kNumAxes; ++i) {
    if (job.axes[i].moves.empty()) continue;
    const std::string cyc = any[i] ? std::to_string(last[i]) : "-";
    const std::string dur = any[i] ? format_seconds(last[i], job.clock_hz) : "-";
    std::snprintf(buf, sizeof buf, "%4u %6zu %12llu %12lld %16s %16s\n", i,
                  job.axes[i].moves.size(), static_cast<unsigned long long>(r.steps[i]),
                  static_cast<long long>(r.position[i]), cyc.c_str(), dur.c_str());
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "run: %llu cycles = %s s\n",
                static_cast<unsigned long long>(r.cycles),
                format_seconds(r.cycles, job.clock_hz).c_str());
  out += buf;
  return out;
}

int run_simulate(const SimulateOptions& o) {
  const Engine engine = o.engine == "rtl" ? Engine::kRtl : Engine::kModel;
  check_engine(engine, o.trace);
  const std::string name = input_name(o.job);
  const std::string text = read_input(o.job);
  Job job;
  try {
    job = parse_job(text, engine_widths(engine));
  } catch (const JobError& e) {
    throw CliError(kExitUsage, name + ": " + e.what());
  }
  std::unique_ptr<TopSim> core;
  try {
    core = make_engine(engine, o.trace, job.widths);
  } catch (const CliError& e) {
    throw CliError(e.code(), name + ": " + e.what());
  }

  for (unsigned k = core->naxes(); k < kNumAxes; ++k)
    if (!job.axes[k].moves.empty())
      throw CliError(kExitUsage, name + ": axis " + std::to_string(k) + " has moves; the " + o.engine +
                                     " core has " + std::to_string(core->naxes()) + " axes (0.." +
                                     std::to_string(core->naxes() - 1) + ")");

  std::vector<StepEvent> events;
  RunOptions ro;
  ro.event_mode = o.event_mode;
  ro.max_cycles = o.max_cycles;
  const RunResult r = run_job(*core, job, [&events](const StepEvent& e) { events.push_back(e); }, ro);
  // The runner checks its bound between bus transactions, so a run may end a few cycles past
  // it; the run length it reports is what --max-cycles bounds (docs/FORMATS.md).
  if (r.timed_out || r.cycles > o.max_cycles)
    throw CliError(kExitTimeout, name + ": the run did not finish within --max-cycles " +
                                     std::to_string(o.max_cycles) + " cycles (" +
                                     format_seconds(o.max_cycles, job.clock_hz) +
                                     " s at " + std::to_string(job.clock_hz) +
                                     " Hz); raise --max-cycles");
  for (unsigned i = 0; i < kNumAxes; ++i)
    if (r.refused[i] != 0)
      throw CliError(kExitRefused, name + ": the " + o.engine + " core refused " +
                                       std::to_string(r.refused[i]) + " move(s) of axis " +
                                       std::to_string(i) +
                                       " that the job reader accepted (a model/RTL mismatch?)");
  std::stable_sort(events.begin(), events.end(), [](const StepEvent& a, const StepEvent& b) {
    return a.cycle != b.cycle ? a.cycle < b.cycle : a.axis < b.axis;
  });
  write_stdout(o.summary ? format_summary(job, r, events, name, o.engine)
                         : format_csv(events, job.clock_hz));
  return kExitOk;
}

}  // namespace hexstep::cli
