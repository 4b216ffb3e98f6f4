// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the job file reader (hexstep::parse_job, cpp_model/src/job_io.cpp).
// Oracles: a refusal is a JobError with a one-line message (any other exception is a crash);
// an accepted job has only moves the core's start logic accepts (validate_move), survives
// write_job -> parse_job unchanged (the documented round trip), and none of its moves is refused
// by the model when they start.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "hexstep/job_io.hpp"
#include "hexstep/top_sim.hpp"

using namespace hexstep;
using hexstep::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Job job;
  try {
    job = parse_job(text);
  } catch (const JobError& e) {
    fuzz::check_one_line(e.what(), "parse_job");
    return 0;
  }
  for (unsigned a = 0; a < kNumAxes; ++a)
    for (size_t i = 0; i < job.axes[a].moves.size(); ++i)
      check(validate_move(job.axes[a].moves[i]) == 0,
            "parse_job accepted axes[" + std::to_string(a) + "].moves[" + std::to_string(i) +
                "], which validate_move refuses");
  const std::string canon = write_job(job);
  Job again;
  try {
    again = parse_job(canon);
  } catch (const JobError& e) {
    fuzz::fail(std::string("write_job output of an accepted job is refused: ") + e.what());
  }
  check(same_job(job, again), "parse_job(write_job(j)) != j");
  check(write_job(again) == canon, "write_job is not canonical");
  // The runner pushes the first two moves of every axis, starts them on one START and refills
  // the queues as moves end: a bounded run shows whether the core's loader refuses a move that
  // the reader let through (reported at the move's start as ERR.move).
  ModelSim model;
  RunOptions ro;
  ro.event_mode = true;
  ro.max_cycles = 20000;
  const RunResult r = run_job(model, job, [](const StepEvent&) {}, ro);
  for (unsigned a = 0; a < kNumAxes; ++a)
    check(r.refused[a] == 0, "the model refused a move of axis " + std::to_string(a) + " that parse_job accepted");
  return 0;
}
