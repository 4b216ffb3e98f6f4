// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: `hexstep plan`. Reads one move from the command line or up to six from a
// planning request file (docs/FORMATS.md, "Planning request"), plans them with hexstep_planner
// (docs/PLANNER.md), encodes them into registers and prints JSON, a C header, CSV or a job file.
#include "plan.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "common.hpp"
#include "hexstep/job.hpp"
#include "hexstep/job_io.hpp"
#include "hexstep/planner.hpp"
#include "hexstep/strict_json.hpp"

namespace hexstep::cli {

namespace {

using plan::real;
using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

constexpr uint64_t kClockMax = 10000000000ull;  // the job file's limit (10 GHz)
constexpr const char* kRequestFormat = "hexstep-plan-request";
constexpr const char* kPlanFormat = "hexstep-plan";

// ---------------------------------------------------------------------------------------------
// One axis to plan, from the command line or from the request file. Speeds, accelerations and
// the distance are in `unit`; `steps` is always in steps.

struct AxisSpec {
  unsigned axis = 0;
  std::optional<int64_t> steps;  // signed step count
  std::optional<real> distance;  // signed distance in `unit`
  plan::Unit unit = plan::Unit::Steps;
  plan::Scale scale;
  plan::Limits limits;           // in unit/s and unit/s^2
  std::optional<real> time;      // time budget (s)
  PulseConfig pulse;
  // Messages: the request file's name and this axis's JSON path; both empty on the command line.
  std::string file, path;
};

struct AxisResult {
  AxisSpec spec;
  real steps_per_unit = 1;
  plan::PhasePlan plan;
  EncodedMove enc;
};

struct PlanResult {
  uint64_t clock_hz = kDefaultClockHz;
  Widths widths{};                  // the core build the registers are for (--widths)
  std::string mode = "single";      // "single", "independent" or "line"
  std::optional<plan::PhasePlan> path;  // line mode: the plan of the path
  std::vector<AxisResult> axes;     // sorted by axis index
};

// ---------------------------------------------------------------------------------------------
// Messages

// Flag -> field of an axis object of the request file (clock_hz is top level).
struct FlagField {
  const char* flag;
  const char* field;
};
constexpr FlagField kFlagFields[] = {
    {"--steps", "steps"},           {"--distance", "distance"},     {"--unit", "unit"},
    {"--steps-per-rev", "steps_per_rev"}, {"--steps-per-mm", "steps_per_mm"},
    {"--pitch-mm", "pitch_mm"},     {"--start-speed", "start_speed"}, {"--end-speed", "end_speed"},
    {"--max-speed", "max_speed"},   {"--accel", "accel"},           {"--decel", "decel"},
    {"--ratio", "ratio"},           {"--time", "time"},             {"--axis", "axis"},
    {"--clock-hz", "clock_hz"},     {"--step-high", "pulse.step_high"},
    {"--step-low", "pulse.step_low"}, {"--dir-setup", "pulse.dir_setup"},
    {"--dir-hold", "pulse.dir_hold"},
};

const char* field_of(const std::string& flag) {
  for (const FlagField& f : kFlagFields)
    if (flag == f.flag) return f.field;
  return nullptr;
}

// A planner message names command-line flags; for an axis of the request file, the leading
// flag becomes the field's JSON path ("axes[1].max_speed") and later ones the field names.
std::string rename_flags(const std::string& msg, const std::string& path) {
  std::string out;
  size_t i = 0;
  bool first = true;
  while (i < msg.size()) {
    if (msg.compare(i, 2, "--") == 0 && (i == 0 || msg[i - 1] == ' ' || msg[i - 1] == '(' ||
                                         msg[i - 1] == '[')) {
      size_t j = i + 2;
      while (j < msg.size() && ((msg[j] >= 'a' && msg[j] <= 'z') || msg[j] == '-')) ++j;
      const std::string flag = msg.substr(i, j - i);
      if (const char* f = field_of(flag)) {
        const std::string field = f;
        if (first && i == 0)
          out += field == "clock_hz" || path.empty() ? field : path + "." + field;
        else
          out += field;
        first = false;
        i = j;
        continue;
      }
    }
    out += msg[i++];
  }
  return out;
}

// Runs planner calls for one axis; turns their errors into CliErrors in the user's terms:
// exit 3 for an infeasible time budget, 2 for everything else. `note` is appended (units).
template <class F>
auto guarded(const AxisSpec& s, const std::string& note, F&& fn) -> decltype(fn()) {
  auto say = [&](const std::string& what) {
    std::string m = s.file.empty() ? what : s.file + ": " + rename_flags(what, s.path);
    return m + note;
  };
  try {
    return fn();
  } catch (const plan::InfeasibleTime& e) {
    throw CliError(kExitInfeasible, say(e.what()));
  } catch (const plan::PlanError& e) {
    throw CliError(kExitUsage, say(e.what()));
  }
}

// " (values in steps: 1 mm = 80 steps)" for messages about converted values; "" for steps.
std::string unit_note(const AxisSpec& s, real k) {
  if (s.unit == plan::Unit::Steps) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9Lg", k);
  return std::string(" (values in steps: 1 ") + plan::unit_name(s.unit) + " = " + buf + " steps)";
}

// ---------------------------------------------------------------------------------------------
// Numbers on the command line

bool parse_real_text(const std::string& text, real& out) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  const char* b = text.c_str();
  char* e = nullptr;
  errno = 0;
  const long double v = std::strtold(b, &e);
  if (e != b + text.size()) return false;
  out = v;  // out of range gives +-inf / 0; inf is refused by the planner, naming the flag
  return true;
}

real flag_real(const std::string& flag, const std::string& text, const std::string& unit) {
  real v = 0;
  if (!parse_real_text(text, v))
    throw CliError(kExitUsage, flag + ": must be a number" + (unit.empty() ? "" : " in " + unit) +
                                   ", got '" + text + "'");
  return v;
}

// A plain decimal integer in [lo, hi] (an optional leading '-' only if lo < 0).
bool parse_int_text(const std::string& text, int64_t lo, int64_t hi, int64_t& out) {
  size_t i = 0;
  bool neg = false;
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
    neg = text[0] == '-';
    i = 1;
  }
  if (i >= text.size() || text.size() - i > 19) return false;
  int64_t v = 0;
  for (; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
    v = v * 10 + (text[i] - '0');
  }
  if (neg) v = -v;
  if (v < lo || v > hi) return false;
  out = v;
  return true;
}

int64_t flag_int(const std::string& flag, const std::string& text, int64_t lo, int64_t hi,
                 const std::string& what) {
  int64_t v = 0;
  if (!parse_int_text(text, lo, hi, v))
    throw CliError(kExitUsage, flag + ": must be an integer in [" + std::to_string(lo) + ", " +
                                   std::to_string(hi) + "]" + what + ", got '" + text + "'");
  return v;
}

const int64_t kMaxSteps = static_cast<int64_t>(plan::kMaxSteps);
const int64_t kPulseMax = static_cast<int64_t>(Widths{}.pulse_mask());
const std::string kPulseNote = " clock cycles (PULSE_W = 12 bits)";

// --widths: NAME=BITS pairs, separated by commas; names left out keep their default.
Widths parse_widths_flag(const std::string& text) {
  Widths w;
  if (text.empty()) return w;
  const std::string accepts = "NAME=BITS pairs separated by commas, NAME one of SPEED_W, ACC_W, STEP_W, "
                              "DFRAC_W, PULSE_W, POS_W, each at most once (SPEED_W only as 64)";
  std::array<bool, kNumWidths> seen{};
  size_t pos = 0;
  while (pos <= text.size()) {
    const size_t end = std::min(text.find(',', pos), text.size());
    const std::string item = text.substr(pos, end - pos);
    const size_t eq = item.find('=');
    unsigned i = kNumWidths;
    if (eq != std::string::npos)
      for (unsigned k = 0; k < kNumWidths; ++k)
        if (item.compare(0, eq, kWidthNames[k]) == 0 && eq == std::string(kWidthNames[k]).size()) i = k;
    if (i == kNumWidths || seen[i])
      throw CliError(kExitUsage, "--widths: must be " + accepts + ", got '" + item + "' in '" + text + "'");
    seen[i] = true;
    width_ref(w, i) = static_cast<unsigned>(
        flag_int(std::string("--widths ") + kWidthNames[i], item.substr(eq + 1), 0, 1000, " bits"));
    pos = end + 1;
  }
  const std::string e = widths_error(w);
  if (!e.empty()) {
    const std::string n = e.substr(0, e.find(':'));
    bool named = false;
    for (unsigned k = 0; k < kNumWidths; ++k) named |= seen[k] && n == kWidthNames[k];
    throw CliError(kExitUsage, "--widths " + e + (named ? "" : " (not given: its default)"));
  }
  return w;
}

// ---------------------------------------------------------------------------------------------
// The command line

// Flags that describe one axis; none may be combined with --job.
const char* const kAxisFlags[] = {
    "--steps", "--distance", "--unit", "--steps-per-rev", "--steps-per-mm", "--pitch-mm",
    "--start-speed", "--end-speed", "--max-speed", "--accel", "--decel", "--ratio", "--time",
    "--axis", "--step-high", "--step-low", "--dir-setup", "--dir-hold"};

bool given(const PlanOptions& o, const std::string& flag) {
  return o.sub->get_option(flag)->count() > 0;
}

AxisSpec spec_from_flags(const PlanOptions& o) {
  AxisSpec s;
  const bool has_steps = given(o, "--steps"), has_dist = given(o, "--distance");
  if (has_steps && has_dist)
    throw CliError(kExitUsage, "--distance: give either --steps N or --distance D, not both");
  if (!has_steps && !has_dist)
    throw CliError(kExitUsage,
                   "--steps: the move needs --steps N or --distance D (with --unit), or --job FILE");
  if (given(o, "--decel") && given(o, "--ratio"))
    throw CliError(kExitUsage, "--ratio: give either --decel or --ratio (m = accel/decel), not both");
  s.unit = guarded(s, "", [&] { return plan::parse_unit(o.unit); });
  const std::string u = plan::unit_name(s.unit);
  if (!given(o, "--max-speed"))
    throw CliError(kExitUsage, "--max-speed: is required (the speed limit in " + u +
                                   "/s, a finite number > 0)");
  if (!given(o, "--accel"))
    throw CliError(kExitUsage, "--accel: is required (the acceleration limit in " + u +
                                   "/s^2, a finite number > 0)");
  s.axis = static_cast<unsigned>(flag_int("--axis", o.axis, 0, kNumAxes - 1, ""));
  if (has_steps)
    s.steps = flag_int("--steps", o.steps, -kMaxSteps, kMaxSteps,
                       " steps (the sign is the direction)");
  if (has_dist) s.distance = flag_real("--distance", o.distance, u);
  if (given(o, "--steps-per-rev")) s.scale.steps_per_rev = flag_real("--steps-per-rev", o.steps_per_rev, "steps/rev");
  if (given(o, "--steps-per-mm")) s.scale.steps_per_mm = flag_real("--steps-per-mm", o.steps_per_mm, "steps/mm");
  if (given(o, "--pitch-mm")) s.scale.pitch_mm = flag_real("--pitch-mm", o.pitch_mm, "mm/rev");
  s.limits.max_speed = flag_real("--max-speed", o.max_speed, u + "/s");
  s.limits.accel = flag_real("--accel", o.accel, u + "/s^2");
  if (given(o, "--decel")) s.limits.decel = flag_real("--decel", o.decel, u + "/s^2");
  if (given(o, "--ratio")) s.limits.ratio = flag_real("--ratio", o.ratio, "");
  if (given(o, "--start-speed")) s.limits.start_speed = flag_real("--start-speed", o.start_speed, u + "/s");
  if (given(o, "--end-speed")) s.limits.end_speed = flag_real("--end-speed", o.end_speed, u + "/s");
  if (given(o, "--time")) s.time = flag_real("--time", o.time, "s");
  s.pulse.step_high = static_cast<uint32_t>(flag_int("--step-high", o.step_high, 0, kPulseMax, kPulseNote));
  s.pulse.step_low = static_cast<uint32_t>(flag_int("--step-low", o.step_low, 0, kPulseMax, kPulseNote));
  s.pulse.dir_setup = static_cast<uint32_t>(flag_int("--dir-setup", o.dir_setup, 0, kPulseMax, kPulseNote));
  s.pulse.dir_hold = static_cast<uint32_t>(flag_int("--dir-hold", o.dir_hold, 0, kPulseMax, kPulseNote));
  return s;
}

// ---------------------------------------------------------------------------------------------
// The planning request file

struct Request {
  std::optional<uint64_t> clock_hz;
  bool line = false;
  std::vector<AxisSpec> axes;
};

class RequestError : public std::runtime_error {
 public:
  RequestError(const std::string& path, const std::string& msg)
      : std::runtime_error(path + ": " + msg) {}
};

[[noreturn]] void request_fail(const std::string& path, const std::string& msg) {
  throw RequestError(path, msg);
}

// One JSON object of the request: type check and unknown fields refused on construction.
class Obj : public hexstep::JsonObject {
 public:
  Obj(const json& j, std::string path, const char* what, std::vector<const char*> fields)
      : JsonObject(j, std::move(path), what, std::move(fields), &request_fail) {
    reject_unknown();
  }
};

real num_field(const json& v, const std::string& path, const std::string& unit) {
  if (!v.is_number())
    throw RequestError(path, "must be a number" + (unit.empty() ? "" : " in " + unit) + ", " + hexstep::json_got(v));
  return v.get<real>();
}

// A JSON integer (no fraction, no exponent) in [lo, hi].
int64_t int_field(const json& v, const std::string& path, int64_t lo, int64_t hi,
                  const std::string& what) {
  const std::string range = "must be an integer in [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + "]" + what;
  if (v.is_number_unsigned()) {
    const uint64_t x = v.get<uint64_t>();
    if (x > static_cast<uint64_t>(hi) || static_cast<int64_t>(x) < lo)
      throw RequestError(path, range + ", got " + v.dump());
    return static_cast<int64_t>(x);
  }
  if (v.is_number_integer()) {
    const int64_t x = v.get<int64_t>();
    if (x < lo || x > hi) throw RequestError(path, range + ", got " + v.dump());
    return x;
  }
  throw RequestError(path, range + ", " + hexstep::json_got(v));
}

bool bool_field(const json& v, const std::string& path) {
  if (v.is_boolean()) return v.get<bool>();
  if (v.is_number_integer() && (v.get<int64_t>() == 0 || v.get<int64_t>() == 1)) return v.get<int64_t>() == 1;
  throw RequestError(path, "must be true or false (or 1 or 0), " + hexstep::json_got(v));
}

// JSON with duplicate keys refused (the path of the second one named).
json parse_request_json(const std::string& text) {
  try {
    return hexstep::parse_strict_json(text);
  } catch (const hexstep::StrictJsonError& e) {
    if (e.path().empty()) throw std::runtime_error(e.what());
    throw RequestError(e.path(), e.what());
  }
}

PulseConfig read_pulse(const json& j, const std::string& path) {
  Obj o(j, path, "a pulse object",
        {"step_high", "step_low", "dir_setup", "dir_hold", "step_invert", "dir_invert"});
  PulseConfig p;
  auto cycles = [&](const char* k, uint32_t& dst) {
    if (const json* v = o.opt(k)) dst = static_cast<uint32_t>(int_field(*v, o.sub(k), 0, kPulseMax, kPulseNote));
  };
  cycles("step_high", p.step_high);
  cycles("step_low", p.step_low);
  cycles("dir_setup", p.dir_setup);
  cycles("dir_hold", p.dir_hold);
  if (const json* v = o.opt("step_invert")) p.step_invert = bool_field(*v, o.sub("step_invert"));
  if (const json* v = o.opt("dir_invert")) p.dir_invert = bool_field(*v, o.sub("dir_invert"));
  return p;
}

AxisSpec read_axis(const json& j, const std::string& path, const std::string& file, bool line) {
  Obj o(j, path, "an axis object",
        {"axis", "steps", "distance", "unit", "steps_per_rev", "steps_per_mm", "pitch_mm",
         "max_speed", "accel", "decel", "ratio", "start_speed", "end_speed", "time", "pulse"});
  AxisSpec s;
  s.file = file;
  s.path = path;
  s.axis = static_cast<unsigned>(
      int_field(o.req("axis", "must be an integer in [0, 5]"), o.sub("axis"), 0, kNumAxes - 1, ""));
  if (const json* v = o.opt("unit")) {
    if (!v->is_string()) throw RequestError(o.sub("unit"), "must be one of steps, rev, deg, rad, mm, " + hexstep::json_got(*v));
    s.unit = guarded(s, "", [&] { return plan::parse_unit(v->get<std::string>()); });
  }
  const std::string u = plan::unit_name(s.unit);
  const json* steps = o.opt("steps");
  const json* dist = o.opt("distance");
  if (steps && dist) throw RequestError(o.sub("distance"), "give either steps or distance, not both");
  if (!steps && !dist)
    throw RequestError(o.sub("steps"), "required field is missing; give steps (an integer, the sign "
                                       "is the direction) or distance (a number in unit)");
  if (steps)
    s.steps = int_field(*steps, o.sub("steps"), -kMaxSteps, kMaxSteps, " steps (the sign is the direction)");
  if (dist) s.distance = num_field(*dist, o.sub("distance"), u);
  auto opt_num = [&](const char* k, const std::string& unit) -> std::optional<real> {
    if (const json* v = o.opt(k)) return num_field(*v, o.sub(k), unit);
    return std::nullopt;
  };
  s.scale.steps_per_rev = opt_num("steps_per_rev", "steps/rev");
  s.scale.steps_per_mm = opt_num("steps_per_mm", "steps/mm");
  s.scale.pitch_mm = opt_num("pitch_mm", "mm/rev");
  s.limits.max_speed = num_field(o.req("max_speed", "must be a number > 0 in " + u + "/s"),
                                 o.sub("max_speed"), u + "/s");
  s.limits.accel = num_field(o.req("accel", "must be a number > 0 in " + u + "/s^2"), o.sub("accel"),
                             u + "/s^2");
  s.limits.decel = opt_num("decel", u + "/s^2");
  s.limits.ratio = opt_num("ratio", "");
  if (s.limits.decel && s.limits.ratio)
    throw RequestError(o.sub("ratio"), "give either decel or ratio (m = accel/decel), not both");
  if (auto v = opt_num("start_speed", u + "/s")) s.limits.start_speed = *v;
  s.limits.end_speed = opt_num("end_speed", u + "/s");
  s.time = opt_num("time", "s");
  if (s.time && line)
    throw RequestError(o.sub("time"), "not allowed with mode \"line\" (a line is always the fastest "
                                      "one within every axis's limits); leave it out or use mode "
                                      "\"independent\"");
  if (const json* p = o.opt("pulse")) s.pulse = read_pulse(*p, o.sub("pulse"));
  return s;
}

Request parse_request(const std::string& text, const std::string& file) {
  const json root = parse_request_json(text);
  Obj o(root, "", "a JSON object", {"format", "version", "clock_hz", "mode", "axes"});
  {
    const std::string accepts = std::string("must be the string \"") + kRequestFormat + "\"";
    const json& f = o.req("format", accepts);
    if (!f.is_string() || f.get_ref<const std::string&>() != kRequestFormat)
      throw RequestError("format", accepts + " (this is not a hexstep planning request?), " + hexstep::json_got(f));
  }
  int_field(o.req("version", "must be an integer in [1, 1]"), "version", 1, 1,
            " (the only version this hexstep reads)");
  Request r;
  if (const json* v = o.opt("clock_hz"))
    r.clock_hz = static_cast<uint64_t>(int_field(*v, "clock_hz", 1, static_cast<int64_t>(kClockMax), " Hz"));
  if (const json* v = o.opt("mode")) {
    if (!v->is_string() || (*v != "independent" && *v != "line"))
      throw RequestError("mode", "must be \"independent\" or \"line\", " + hexstep::json_got(*v));
    r.line = *v == "line";
  }
  const std::string accepts = "must be an array of 1 to 6 axis objects";
  const json& axes = o.req("axes", accepts);
  if (!axes.is_array()) throw RequestError("axes", accepts + ", " + hexstep::json_got(axes));
  if (axes.empty() || axes.size() > kNumAxes)
    throw RequestError("axes", accepts + ", got " + std::to_string(axes.size()) + " entries");
  std::array<int, kNumAxes> seen;
  seen.fill(-1);
  for (size_t i = 0; i < axes.size(); ++i) {
    const std::string path = "axes[" + std::to_string(i) + "]";
    AxisSpec s = read_axis(axes[i], path, file, r.line);
    if (seen[s.axis] >= 0)
      throw RequestError(path + ".axis", "must be an integer in [0, 5] and unique, got " +
                                             std::to_string(s.axis) + " again (also in axes[" +
                                             std::to_string(seen[s.axis]) + "])");
    seen[s.axis] = static_cast<int>(i);
    r.axes.push_back(std::move(s));
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// Planning

struct Prepared {
  plan::StepCount count;
  real k = 1;             // steps per unit
  plan::Limits limits;    // in steps/s, steps/s^2
};

Prepared prepare(const AxisSpec& s) {
  Prepared p;
  guarded(s, "", [&] {
    // Units and limits in the caller's unit first, so that the messages quote the given values.
    p.k = plan::steps_per_unit(s.unit, s.scale);
    plan::resolve(s.limits);
    if (s.steps) {
      const int64_t n = *s.steps;
      p.count.steps = static_cast<uint32_t>(n < 0 ? -n : n);
      p.count.dir = n >= 0;
      p.count.exact = static_cast<real>(p.count.steps);
    } else {
      p.count = plan::distance_to_steps(*s.distance, s.unit, s.scale);
    }
    p.limits = plan::limits_to_steps(s.limits, s.unit, s.scale);
  });
  return p;
}

// Pulse rate and registers of a decided plan.
EncodedMove finish_axis(const AxisSpec& s, real k, const plan::PhasePlan& p, uint64_t clock_hz,
                        const Widths& w) {
  return guarded(s, unit_note(s, k), [&] {
    // The pulse flags were read against the default PULSE_W; a narrower build takes less.
    const uint64_t pmax = w.pulse_mask();
    const std::pair<const char*, uint32_t> pulse[] = {{"--step-high", s.pulse.step_high},
                                                      {"--step-low", s.pulse.step_low},
                                                      {"--dir-setup", s.pulse.dir_setup},
                                                      {"--dir-hold", s.pulse.dir_hold}};
    for (const auto& [flag, v] : pulse)
      if (v > pmax)
        throw plan::PlanError(std::string(flag) + ": must be an integer in [0, " + std::to_string(pmax) +
                              "] clock cycles (PULSE_W = " + std::to_string(w.pulse) +
                              " bits, --widths), got " + std::to_string(v));
    const real f = static_cast<real>(clock_hz);
    plan::check_pulse_rate(p.v_peak, f, s.pulse.step_high, s.pulse.step_low);
    return plan::encode(p, f, w);
  });
}

PlanResult plan_all(std::vector<AxisSpec> specs, bool line, uint64_t clock_hz, const std::string& mode,
                    const Widths& w) {
  std::sort(specs.begin(), specs.end(), [](const AxisSpec& a, const AxisSpec& b) { return a.axis < b.axis; });
  PlanResult r;
  r.clock_hz = clock_hz;
  r.widths = w;
  r.mode = mode;
  std::vector<Prepared> prep;
  for (const AxisSpec& s : specs) prep.push_back(prepare(s));
  if (line) {
    std::vector<plan::AxisRequest> req;
    for (size_t i = 0; i < specs.size(); ++i) {
      plan::AxisRequest q;
      q.axis = specs[i].axis;
      q.steps = prep[i].count.dir ? static_cast<int64_t>(prep[i].count.steps)
                                  : -static_cast<int64_t>(prep[i].count.steps);
      q.limits = prep[i].limits;
      req.push_back(q);
    }
    plan::LinePlan lp;
    try {
      lp = plan::coordinated_line(req);
    } catch (const plan::PlanError& e) {
      // Every axis's values were checked above, so this is the path's own plan.
      throw CliError(kExitUsage, specs.front().file + ": the line: " + e.what());
    }
    r.path = lp.path;
    for (size_t i = 0; i < specs.size(); ++i) {
      AxisResult a;
      a.spec = specs[i];
      a.steps_per_unit = prep[i].k;
      a.plan = lp.axes[i].plan;
      a.enc = finish_axis(specs[i], prep[i].k, a.plan, clock_hz, w);
      r.axes.push_back(std::move(a));
    }
    return r;
  }
  for (size_t i = 0; i < specs.size(); ++i) {
    const AxisSpec& s = specs[i];
    AxisResult a;
    a.spec = s;
    a.steps_per_unit = prep[i].k;
    a.plan = guarded(s, unit_note(s, prep[i].k), [&] {
      return s.time ? plan::plan_timed(prep[i].count.steps, *s.time, prep[i].limits, prep[i].count.dir)
                    : plan::plan_min_time(prep[i].count.steps, prep[i].limits, prep[i].count.dir);
    });
    a.enc = finish_axis(s, prep[i].k, a.plan, clock_hz, w);
    r.axes.push_back(std::move(a));
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// Output

int64_t signed_total(const plan::PhasePlan& p) {
  return p.dir ? static_cast<int64_t>(p.steps) : -static_cast<int64_t>(p.steps);
}

// Shortest text that reads back as the same double (as in the JSON output).
std::string num(real x) { return ojson(static_cast<double>(x)).dump(); }

real plan_duration(const PlanResult& r) {
  real d = 0;
  for (const AxisResult& a : r.axes) d = std::max(d, a.plan.duration);
  return d;
}
real executed_duration(const PlanResult& r) {
  real d = 0;
  for (const AxisResult& a : r.axes) d = std::max(d, a.enc.ideal.duration());
  return d;
}

ojson registers_json(const AxisMove& m) {
  ojson j = ojson::object();
  j["steps"] = m.steps;
  j["dir"] = m.dir ? 1 : 0;
  j["v_start"] = m.v_start;
  j["v_max"] = m.v_max;
  j["v_end"] = m.v_end;
  j["acc"] = m.acc;
  j["dec"] = m.dec;
  j["v_dec"] = m.v_dec;
  j["acc_steps"] = m.acc_steps;
  j["dec_step"] = m.dec_step;
  j["dec_frac"] = m.dec_frac;
  return j;
}

ojson pulse_json(const PulseConfig& p) {
  ojson j = ojson::object();
  j["step_high"] = p.step_high;
  j["step_low"] = p.step_low;
  j["dir_setup"] = p.dir_setup;
  j["dir_hold"] = p.dir_hold;
  j["step_invert"] = p.step_invert;
  j["dir_invert"] = p.dir_invert;
  return j;
}

std::string format_json(const PlanResult& r) {
  auto d = [](real x) { return static_cast<double>(x); };
  ojson root = ojson::object();
  root["format"] = kPlanFormat;
  root["version"] = 1;
  root["clock_hz"] = r.clock_hz;
  if (!same_widths(r.widths, Widths{})) {
    ojson wj = ojson::object();
    for (unsigned i = 0; i < kNumWidths; ++i) wj[kWidthNames[i]] = width_of(r.widths, i);
    root["widths"] = std::move(wj);
  }
  root["mode"] = r.mode;
  root["duration_s"] = d(plan_duration(r));
  root["executed_duration_s"] = d(executed_duration(r));
  if (r.path) {
    ojson p = ojson::object();
    p["profile"] = plan::profile_name(r.path->profile);
    p["steps"] = r.path->steps;
    p["peak_speed_steps_per_s"] = d(r.path->v_peak);
    p["duration_s"] = d(r.path->duration);
    root["path"] = std::move(p);
  }
  ojson axes = ojson::array();
  for (const AxisResult& a : r.axes) {
    const plan::PhasePlan& p = a.plan;
    const IdealProfile& id = a.enc.ideal;
    ojson j = ojson::object();
    j["axis"] = a.spec.axis;
    j["profile"] = plan::profile_name(p.profile);
    if (!p.warning.empty()) j["warning"] = p.warning;
    j["unit"] = plan::unit_name(a.spec.unit);
    j["steps_per_unit"] = d(a.steps_per_unit);
    j["dir"] = p.dir ? 1 : 0;
    ojson st = ojson::object();
    st["accel"] = p.accel_steps;
    st["cruise"] = p.cruise_steps;
    st["decel"] = p.decel_steps;
    st["total"] = signed_total(p);
    j["steps"] = std::move(st);
    j["start_speed_steps_per_s"] = d(p.v_start);
    j["peak_speed_steps_per_s"] = d(p.v_peak);
    j["end_speed_steps_per_s"] = d(p.v_end);
    j["end_speed_requested_steps_per_s"] = d(p.end_speed_requested);
    j["accel_steps_per_s2"] = d(p.a);
    j["decel_steps_per_s2"] = d(p.d);
    j["t_accel_s"] = d(p.t_acc);
    j["t_cruise_s"] = d(p.t_cruise);
    j["t_decel_s"] = d(p.t_dec);
    j["duration_s"] = d(p.duration);
    if (a.spec.time) j["time_budget_s"] = d(*a.spec.time);
    j["pulse"] = pulse_json(a.spec.pulse);
    j["registers"] = registers_json(a.enc.regs);
    ojson ex = ojson::object();
    ex["start_speed_steps_per_s"] = d(p.steps ? id.v0 : 0);
    ex["peak_speed_steps_per_s"] = d(id.vp);
    ex["end_speed_steps_per_s"] = d(p.steps ? id.ve : 0);
    ex["accel_steps_per_s2"] = d(id.a);
    ex["decel_steps_per_s2"] = d(id.d);
    ex["accel_distance_steps"] = d(id.s_acc);
    ex["cruise_distance_steps"] = d(id.s_cruise);
    ex["decel_distance_steps"] = d(id.s_dec);
    ex["t_accel_s"] = d(id.t_acc);
    ex["t_cruise_s"] = d(id.t_cruise);
    ex["t_decel_s"] = d(id.t_dec);
    ex["duration_s"] = d(id.duration());
    j["executed"] = std::move(ex);
    axes.push_back(std::move(j));
  }
  root["axes"] = std::move(axes);
  return root.dump(2) + "\n";
}

const char* const kCsvHeader =
    "axis,profile,dir,total_steps,accel_steps,cruise_steps,decel_steps,start_speed_steps_per_s,"
    "peak_speed_steps_per_s,end_speed_steps_per_s,accel_steps_per_s2,decel_steps_per_s2,"
    "t_accel_s,t_cruise_s,t_decel_s,duration_s,executed_peak_speed_steps_per_s,"
    "executed_duration_s,warning";

std::string csv_quote(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string format_csv_plan(const PlanResult& r) {
  std::string out = std::string(kCsvHeader) + "\n";
  for (const AxisResult& a : r.axes) {
    const plan::PhasePlan& p = a.plan;
    const std::vector<std::string> cols = {
        std::to_string(a.spec.axis), plan::profile_name(p.profile), p.dir ? "1" : "0",
        std::to_string(signed_total(p)), std::to_string(p.accel_steps),
        std::to_string(p.cruise_steps), std::to_string(p.decel_steps), num(p.v_start),
        num(p.v_peak), num(p.v_end), num(p.a), num(p.d), num(p.t_acc), num(p.t_cruise),
        num(p.t_dec), num(p.duration), num(a.enc.ideal.vp), num(a.enc.ideal.duration()),
        csv_quote(p.warning)};
    for (size_t i = 0; i < cols.size(); ++i) out += (i ? "," : "") + cols[i];
    out += "\n";
  }
  return out;
}

// Text safe inside a C block comment.
std::string comment_safe(std::string s) {
  for (size_t i; (i = s.find("*/")) != std::string::npos;) s.replace(i, 2, "* /");
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

std::string format_c(const PlanResult& r) {
  std::string o;
  o += "/* Generated by `hexstep plan`: linear-ramp moves for the hexstep core. Do not edit.\n";
  o += " * Schema: docs/FORMATS.md, \"hexstep plan output\". Speeds in steps/s, accelerations in\n";
  o += " * steps/s^2, times in s; the registers are in the core's units (2^-64 step per tick of 32\n";
  o += " * clock cycles, ...).\n";
  o += " *\n";
  o += " * clock " + std::to_string(r.clock_hz) + " Hz, mode " + r.mode + ", duration " +
       num(plan_duration(r)) + " s (executed " + num(executed_duration(r)) + " s)\n";
  for (const AxisResult& a : r.axes) {
    const plan::PhasePlan& p = a.plan;
    o += " * axis " + std::to_string(a.spec.axis) + ": " + plan::profile_name(p.profile) + ", " +
         std::to_string(signed_total(p)) + " steps (accel " + std::to_string(p.accel_steps) +
         ", cruise " + std::to_string(p.cruise_steps) + ", decel " + std::to_string(p.decel_steps) + ")\n";
    o += " *   speed start " + num(p.v_start) + ", peak " + num(p.v_peak) + ", end " + num(p.v_end) +
         " steps/s; accel " + num(p.a) + ", decel " + num(p.d) + " steps/s^2\n";
    o += " *   t_accel " + num(p.t_acc) + ", t_cruise " + num(p.t_cruise) + ", t_decel " +
         num(p.t_dec) + ", duration " + num(p.duration) + " s; executed peak " +
         num(a.enc.ideal.vp) + " steps/s, duration " + num(a.enc.ideal.duration()) + " s\n";
    o += " *   pulse: step_high " + std::to_string(a.spec.pulse.step_high) + ", step_low " +
         std::to_string(a.spec.pulse.step_low) + ", dir_setup " + std::to_string(a.spec.pulse.dir_setup) +
         ", dir_hold " + std::to_string(a.spec.pulse.dir_hold) + " cycles\n";
    if (!p.warning.empty()) o += " *   warning: " + comment_safe(p.warning) + "\n";
  }
  o += " */\n";
  o += "#ifndef HEXSTEP_PLAN_H\n#define HEXSTEP_PLAN_H\n\n#include <stdint.h>\n\n";
  o += "#define HEXSTEP_PLAN_CLOCK_HZ UINT64_C(" + std::to_string(r.clock_hz) + ")\n";
  o += "#define HEXSTEP_PLAN_NUM_AXES " + std::to_string(kNumAxes) + "\n";
  if (!same_widths(r.widths, Widths{})) {
    o += "/* Registers for a core built with " + widths_text(r.widths) + " (--widths). */\n";
    for (unsigned i = 0; i < kNumWidths; ++i)
      o += "#define HEXSTEP_PLAN_" + std::string(kWidthNames[i]) + " " + std::to_string(width_of(r.widths, i)) + "\n";
  }
  unsigned mask = 0;
  for (const AxisResult& a : r.axes) mask |= 1u << a.spec.axis;
  char buf[64];
  std::snprintf(buf, sizeof buf, "0x%02Xu", mask);
  o += "/* Bit i set: axis i has a planned move; the other rows are all zero (no move). */\n";
  o += "#define HEXSTEP_PLAN_AXIS_MASK " + std::string(buf) + "\n\n";
  o += "/* The registers of one move, in the order of hexstep::AxisMove (docs/FORMATS.md, job file). */\n";
  o += "typedef struct hexstep_plan_move {\n"
       "  uint32_t steps;     /* exact number of steps */\n"
       "  uint32_t dir;       /* 1: positive direction, 0: negative */\n"
       "  uint64_t v_start;   /* 2^-64 step/tick (1 tick = 32 clock cycles) */\n"
       "  uint64_t v_max;     /* 2^-64 step/tick */\n"
       "  uint64_t v_end;     /* 2^-64 step/tick */\n"
       "  uint64_t acc;       /* 2^-64 step/tick^2 */\n"
       "  uint64_t dec;       /* 2^-64 step/tick^2 */\n"
       "  uint64_t v_dec;     /* 2^-64 step/tick */\n"
       "  uint32_t acc_steps; /* steps */\n"
       "  uint32_t dec_step;  /* steps */\n"
       "  uint32_t dec_frac;  /* 2^-32 step */\n"
       "} hexstep_plan_move_t;\n\n";
  o += "/* STEP/DIR output timing of one axis, in clock cycles. */\n";
  o += "typedef struct hexstep_plan_pulse {\n"
       "  uint32_t step_high;\n  uint32_t step_low;\n  uint32_t dir_setup;\n  uint32_t dir_hold;\n"
       "  uint32_t step_invert;\n  uint32_t dir_invert;\n"
       "} hexstep_plan_pulse_t;\n\n";
  std::array<const AxisResult*, kNumAxes> by_axis{};
  for (const AxisResult& a : r.axes) by_axis[a.spec.axis] = &a;
  auto u64 = [](uint64_t v) { return "UINT64_C(" + std::to_string(v) + ")"; };
  auto u32 = [](uint64_t v) { return std::to_string(v) + "u"; };
  o += "/* Indexed by axis. */\n";
  o += "static const hexstep_plan_move_t hexstep_plan_moves[HEXSTEP_PLAN_NUM_AXES] = {\n";
  for (unsigned i = 0; i < kNumAxes; ++i) {
    const AxisMove m = by_axis[i] ? by_axis[i]->enc.regs : AxisMove{0, false, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    o += "  /* axis " + std::to_string(i) + (by_axis[i] ? "" : ": no move") + " */\n";
    o += "  {" + u32(m.steps) + ", " + u32(m.dir ? 1 : 0) + ", " + u64(m.v_start) + ", " + u64(m.v_max) +
         ", " + u64(m.v_end) + ", " + u64(m.acc) + ", " + u64(m.dec) + ", " + u64(m.v_dec) + ", " +
         u32(m.acc_steps) + ", " + u32(m.dec_step) + ", " + u32(m.dec_frac) + "}" +
         (i + 1 < kNumAxes ? "," : "") + "\n";
  }
  o += "};\n\n";
  o += "static const hexstep_plan_pulse_t hexstep_plan_pulse[HEXSTEP_PLAN_NUM_AXES] = {\n";
  for (unsigned i = 0; i < kNumAxes; ++i) {
    const PulseConfig p = by_axis[i] ? by_axis[i]->spec.pulse : PulseConfig{};
    o += "  {" + u32(p.step_high) + ", " + u32(p.step_low) + ", " + u32(p.dir_setup) + ", " +
         u32(p.dir_hold) + ", " + u32(p.step_invert ? 1 : 0) + ", " + u32(p.dir_invert ? 1 : 0) + "}" +
         (i + 1 < kNumAxes ? "," : "") + " /* axis " + std::to_string(i) + " */\n";
  }
  o += "};\n\n#endif /* HEXSTEP_PLAN_H */\n";
  return o;
}

std::string format_job_plan(const PlanResult& r) {
  Job job;
  job.clock_hz = r.clock_hz;
  job.widths = r.widths;
  for (const AxisResult& a : r.axes) {
    job.axes[a.spec.axis].pulse = a.spec.pulse;
    job.axes[a.spec.axis].moves.push_back(a.enc.regs);
  }
  const std::string text = write_job(job);
  try {
    parse_job(text);  // what `hexstep simulate` will read; a failure here is a bug
  } catch (const JobError& e) {
    throw CliError(kExitInternal, std::string("the planned job does not read back: ") + e.what());
  }
  return text;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

CLI::App* add_plan(CLI::App& app, PlanOptions& o) {
  CLI::App* sub = app.add_subcommand(
      "plan",
      "Plan a linear-ramp move (accelerate, cruise, decelerate) within speed and acceleration "
      "limits, or in a given time, and print its profile and the core's registers. One axis from "
      "the flags, or up to six from a request file (--job). Method: docs/PLANNER.md; output "
      "formats: docs/FORMATS.md.");
  o.sub = sub;
  auto opt = [&](const char* name, std::string& dst, const char* text, const std::string& help) {
    return sub->add_option(name, dst, help)->option_text(text);
  };
  sub->option_defaults()->group("Move");
  opt("--steps", o.steps, "N",
      "Distance in steps: an integer in [-4294967295, 4294967295], negative = negative direction "
      "(write --steps=-N). Not with --distance");
  opt("--distance", o.distance, "D",
      "Distance in --unit, negative = negative direction; rounded to the nearest whole step "
      "(halves away from zero). Not with --steps");
  opt("--unit", o.unit, "UNIT",
      "Unit of --distance and of every speed (UNIT/s) and acceleration (UNIT/s^2): steps, rev "
      "(needs --steps-per-rev), deg, rad (both need --steps-per-rev), mm (needs --steps-per-mm, "
      "or --steps-per-rev and --pitch-mm). Default: steps");
  opt("--steps-per-rev", o.steps_per_rev, "K", "Steps per motor revolution (microsteps included), > 0");
  opt("--steps-per-mm", o.steps_per_mm, "S", "Steps per mm of a linear axis, > 0");
  opt("--pitch-mm", o.pitch_mm, "P",
      "Lead-screw pitch in mm per revolution, > 0: 1 mm = K / P steps with --steps-per-rev K");
  opt("--axis", o.axis, "I", "Axis (STEP/DIR output pair) of the move, 0..5. Default: 0");
  sub->option_defaults()->group("Limits");
  opt("--max-speed", o.max_speed, "V",
      "Speed limit in UNIT/s, > 0 (required). The plan cruises here if the move is long enough");
  opt("--accel", o.accel, "A", "Acceleration limit in UNIT/s^2, > 0 (required)");
  opt("--decel", o.decel, "D", "Deceleration limit in UNIT/s^2, > 0. Default: --accel / --ratio. Not with --ratio");
  opt("--ratio", o.ratio, "M", "Ratio M = accel / decel (no unit), > 0: decel = A / M. Default: 1. Not with --decel");
  opt("--start-speed", o.start_speed, "V",
      "Speed in UNIT/s the move starts at (the speed the motor can jump to from standstill), in "
      "[0, --max-speed]. Default: 0");
  opt("--end-speed", o.end_speed, "V",
      "Speed in UNIT/s the move ends at, in [0, --max-speed]. Default: --start-speed. If the move "
      "is too short to reach it, the plan says so in 'warning'");
  opt("--time", o.time, "T",
      "Time budget in s, > 0: the move takes exactly T s (Ranade), at most --max-speed and --accel, "
      "ending at --start-speed. Exit status 3 if T is below the minimum achievable time (which the "
      "message gives). Default: the fastest move");
  sub->option_defaults()->group("Core");
  opt("--clock-hz", o.clock_hz, "F",
      "Clock frequency of the core in Hz, an integer in [1, 10000000000]; the registers depend on "
      "it. Default: 100000000 (or the request file's clock_hz)");
  opt("--widths", o.widths, "LIST",
      "Register widths of the core build the registers are for, as NAME=BITS pairs separated by "
      "commas, names SPEED_W, ACC_W, STEP_W, DFRAC_W, PULSE_W, POS_W (the parameters of "
      "rtl/hexstep_top.v; a board's are in synth/targets.json and its top level), e.g. "
      "STEP_W=16,DFRAC_W=8,PULSE_W=8,POS_W=16. SPEED_W is fixed at 64 (the frame engine's "
      "datapath). Names left out keep their default. Default: the default build (SPEED_W 64, "
      "ACC_W 48, STEP_W 32, DFRAC_W 32, PULSE_W 12, POS_W 32)");
  const std::string pulse_range = "0.." + std::to_string(hexstep::Widths{}.pulse_mask());
  opt("--step-high", o.step_high, "C",
      "STEP pulse high time in clock cycles, " + pulse_range + " (0 acts as 1). Default: 1");
  opt("--step-low", o.step_low, "C",
      "Minimum STEP low time in clock cycles, " + pulse_range + " (0 acts as 1). Default: 1. The "
      "peak speed must not exceed F / (step-high + step-low) steps/s");
  opt("--dir-setup", o.dir_setup, "C",
      "DIR setup time before a STEP rising edge, clock cycles, " + pulse_range + ". Default: 0");
  opt("--dir-hold", o.dir_hold, "C",
      "DIR hold time after a STEP rising edge, clock cycles, " + pulse_range + ". Default: 0");
  sub->option_defaults()->group("Input and output");
  opt("--job", o.job, "FILE",
      "Plan up to six axes from a planning request file (JSON, format \"hexstep-plan-request\", "
      "docs/FORMATS.md), independently or along one straight line; '-' reads stdin. The move, "
      "limit and pulse flags then belong in the file");
  opt("--format", o.format, "FMT",
      "Output: json (the plan and registers per axis), c (a C99 header with the register table), "
      "csv (one line per axis), job (a job file for 'hexstep simulate'). Default: json")
      ->check(CLI::IsMember({"json", "c", "csv", "job"}));
  opt("--out", o.out, "FILE", "Write the output to FILE instead of stdout (only if planning succeeded)");
  sub->footer(
      "Units: distances in UNIT (--unit), speeds in UNIT/s, accelerations in UNIT/s^2, times in s,\n"
      "pulse times in clock cycles. The output is always in steps, steps/s, steps/s^2 and s.\n"
      "CSV header:\n  " + std::string(kCsvHeader) + "\n"
      "Errors go to stderr as one line starting 'hexstep: error:' naming the flag (or the request\n"
      "file's field) and the accepted range; then nothing is written. Exit status 2 for a bad\n"
      "value, a contradiction or a move the registers or the pulse timing cannot do; 3 if --time\n"
      "is shorter than the fastest possible move.\n"
      "Example: hexstep plan --distance 90 --unit deg --steps-per-rev 3200 --max-speed 360 \\\n"
      "           --accel 720 --format job | hexstep simulate - --summary --event-mode");
  return sub;
}

int run_plan(const PlanOptions& o) {
  uint64_t clock_hz = kDefaultClockHz;
  const bool clock_given = given(o, "--clock-hz");
  if (clock_given) {
    // An integer, also written as 1e8 or 100e6.
    real f = 0;
    if (!parse_real_text(o.clock_hz, f) || !(f >= 1) || !(f <= static_cast<real>(kClockMax)) || f != std::floor(f))
      throw CliError(kExitUsage, "--clock-hz: must be an integer in [1, " + std::to_string(kClockMax) +
                                     "] Hz, got '" + o.clock_hz + "'");
    clock_hz = static_cast<uint64_t>(f);
  }
  const Widths widths = parse_widths_flag(o.widths);
  PlanResult result;
  if (given(o, "--job")) {
    for (const char* f : kAxisFlags)
      if (given(o, f))
        throw CliError(kExitUsage, std::string(f) + ": cannot be combined with --job (give it in the "
                                   "request file, as axes[]." + field_of(f) + ")");
    const std::string name = input_name(o.job);
    const std::string text = read_input(o.job);
    Request req;
    try {
      req = parse_request(text, name);
    } catch (const CliError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw CliError(kExitUsage, name + ": " + e.what());
    }
    if (req.clock_hz) {
      if (clock_given && *req.clock_hz != clock_hz)
        throw CliError(kExitUsage, "--clock-hz: " + std::to_string(clock_hz) + " contradicts clock_hz " +
                                       std::to_string(*req.clock_hz) + " in " + name +
                                       " (give the clock in one place)");
      clock_hz = *req.clock_hz;
    }
    result = plan_all(req.axes, req.line, clock_hz, req.line ? "line" : "independent", widths);
  } else {
    result = plan_all({spec_from_flags(o)}, false, clock_hz, "single", widths);
  }
  std::string text;
  if (o.format == "c") text = format_c(result);
  else if (o.format == "csv") text = format_csv_plan(result);
  else if (o.format == "job") text = format_job_plan(result);
  else text = format_json(result);
  write_output(o.out, text, "--out");
  return kExitOk;
}

}  // namespace hexstep::cli
