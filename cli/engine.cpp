// SPDX-License-Identifier: Apache-2.0
#include "engine.hpp"

#include "common.hpp"
#include "hexstep/job_io.hpp"

#ifdef HEXSTEP_HAVE_RTL
#include "rtl_top.hpp"
#endif

namespace hexstep::cli {

bool rtl_available() {
#ifdef HEXSTEP_HAVE_RTL
  return true;
#else
  return false;
#endif
}

Widths engine_widths(Engine e) {
#ifdef HEXSTEP_HAVE_RTL
  if (e == Engine::kRtl) return RtlTop::rtl_widths();
#else
  (void)e;
#endif
  return Widths{};
}

void check_engine(Engine e, const std::string& trace_path) {
  if (e == Engine::kModel && !trace_path.empty())
    throw CliError(kExitUsage, "--trace: waveforms need --engine rtl (the model has no signals)");
  if (e == Engine::kRtl && !rtl_available())
    throw CliError(kExitUsage,
                   "--engine rtl: this hexstep was built without the Verilated RTL "
                   "(configure with -DHEXSTEP_RTL=ON and Verilator installed)");
}

std::unique_ptr<TopSim> make_engine(Engine e, const std::string& trace_path, const Widths& w) {
  check_engine(e, trace_path);
#ifdef HEXSTEP_HAVE_RTL
  if (e == Engine::kRtl) {
    const Widths rw = RtlTop::rtl_widths();
    if (!same_widths(w, rw))
      throw CliError(kExitUsage, "widths: the job is for a core with " + widths_text(w) +
                                     "; the Verilated RTL of --engine rtl is built with " +
                                     widths_text(rw) + " (use --engine model)");
    return std::make_unique<RtlTop>(trace_path);
  }
#endif
  return std::make_unique<ModelSim>(kNumAxes, w);
}

}  // namespace hexstep::cli
