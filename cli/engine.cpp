// SPDX-License-Identifier: Apache-2.0
#include "engine.hpp"

#include "common.hpp"

#ifdef HEXSTEP_HAVE_RTL
#include "rtl_core.hpp"
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
  if (e == Engine::kRtl) return RtlCore::rtl_widths();
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

std::unique_ptr<CoreSim> make_engine(Engine e, const std::string& trace_path) {
  check_engine(e, trace_path);
#ifdef HEXSTEP_HAVE_RTL
  if (e == Engine::kRtl) return std::make_unique<RtlCore>(trace_path);
#endif
  return std::make_unique<CoreModel>(engine_widths(e));
}

}  // namespace hexstep::cli
