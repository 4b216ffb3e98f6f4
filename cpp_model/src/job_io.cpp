// SPDX-License-Identifier: Apache-2.0
// hexstep: the job file (JSON) to and from hexstep::Job. docs/FORMATS.md is the user's view.
#include "hexstep/job_io.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hexstep/strict_json.hpp"

namespace hexstep {

namespace {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

constexpr const char* kFormat = "hexstep-job";
constexpr uint64_t kVersion = 1;
constexpr uint64_t kClockMax = 10000000000ull;  // 10 GHz
constexpr uint64_t kU32Max = std::numeric_limits<uint32_t>::max();

[[noreturn]] void fail(const std::string& path, const std::string& msg) {
  throw JobError(path + ": " + msg);
}

std::string range_text(uint64_t lo, uint64_t hi) {
  return "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

std::string bits_note(const char* reg, unsigned bits) {
  return std::string(" (") + reg + " = " + std::to_string(bits) + " bits)";
}

enum class IntParse { kOk, kNotInt, kOverflow };

// A JSON unsigned integer, or a string holding a decimal or 0x-hex unsigned integer.
IntParse to_u64(const json& v, uint64_t& out) {
  if (v.is_number_unsigned()) {
    out = v.get<uint64_t>();
    return IntParse::kOk;
  }
  if (v.is_number_integer()) {  // negative (non-negative integers parse as unsigned)
    const int64_t s = v.get<int64_t>();
    if (s < 0) return IntParse::kNotInt;
    out = static_cast<uint64_t>(s);
    return IntParse::kOk;
  }
  if (!v.is_string()) return IntParse::kNotInt;
  const std::string& s = v.get_ref<const std::string&>();
  unsigned base = 10;
  size_t i = 0;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    base = 16;
    i = 2;
  }
  if (i >= s.size()) return IntParse::kNotInt;
  uint64_t x = 0;
  bool overflow = false;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    unsigned d;
    if (c >= '0' && c <= '9') d = static_cast<unsigned>(c - '0');
    else if (base == 16 && c >= 'a' && c <= 'f') d = static_cast<unsigned>(c - 'a' + 10);
    else if (base == 16 && c >= 'A' && c <= 'F') d = static_cast<unsigned>(c - 'A' + 10);
    else return IntParse::kNotInt;
    if (x > (std::numeric_limits<uint64_t>::max() - d) / base) overflow = true;
    x = x * base + d;
  }
  if (overflow) return IntParse::kOverflow;
  out = x;
  return IntParse::kOk;
}

// An integer field in [lo, hi]; `note` follows the range in messages (e.g. the register width).
uint64_t get_uint(const json& v, const std::string& path, uint64_t lo, uint64_t hi,
                  const std::string& note = "") {
  uint64_t x = 0;
  switch (to_u64(v, x)) {
    case IntParse::kNotInt: fail(path, range_text(lo, hi) + note + ", " + json_got(v));
    case IntParse::kOverflow:
      fail(path, range_text(lo, hi) + note + ", " + json_got(v) + " (beyond 64 bits)");
    case IntParse::kOk: break;
  }
  if (x < lo || x > hi) fail(path, range_text(lo, hi) + note + ", got " + std::to_string(x));
  return x;
}

const char* const kBoolAccepts = "must be true or false (or 1 or 0)";

bool get_bool(const json& v, const std::string& path, const char* accepts = kBoolAccepts) {
  if (v.is_boolean()) return v.get<bool>();
  uint64_t x = 0;
  if (to_u64(v, x) == IntParse::kOk && x <= 1) return x == 1;
  fail(path, std::string(accepts) + ", " + json_got(v));
}

// One JSON object of a job file; errors are JobErrors.
class Obj : public JsonObject {
 public:
  Obj(const json& j, std::string path, const char* what, std::vector<const char*> fields)
      : JsonObject(j, std::move(path), what, std::move(fields), &fail) {}
};

struct UField {
  const char* name;
  uint64_t lo, hi;
  std::string note;
  std::string accepts() const { return range_text(lo, hi) + note; }
};

uint64_t read_uint(const Obj& o, const UField& f) {
  return get_uint(o.req(f.name, f.accepts()), o.sub(f.name), f.lo, f.hi, f.note);
}
uint64_t read_uint_opt(const Obj& o, const UField& f, uint64_t dflt) {
  const json* v = o.opt(f.name);
  return v ? get_uint(*v, o.sub(f.name), f.lo, f.hi, f.note) : dflt;
}

const char* const kDirAccepts = "must be 1 (positive), 0 (negative), true (positive) or false (negative)";

AxisMove read_move(const json& j, const std::string& path, const Widths& w) {
  Obj o(j, path, "a move object",
        {"steps", "dir", "v_start", "v_max", "v_end", "acc", "dec", "v_dec", "acc_steps",
         "dec_step", "dec_frac"});
  o.reject_unknown();
  const std::string speed_note = bits_note("SPEED_W", w.speed_frac);
  const std::string acc_note = bits_note("ACC_W", w.acc);
  const std::string step_note = bits_note("STEP_W", w.steps);
  const uint64_t speed_max = w.speed_mask();
  const uint64_t acc_max = w.acc_mask();
  const uint64_t step_max = std::min<uint64_t>(w.steps_mask(), kU32Max);
  const uint64_t dfrac_max = std::min<uint64_t>(w.dec_frac_mask(), kU32Max);
  AxisMove m;
  m.steps = static_cast<uint32_t>(read_uint(o, {"steps", 0, step_max, step_note}));
  m.dir = get_bool(o.req("dir", kDirAccepts), o.sub("dir"), kDirAccepts);
  m.v_start = read_uint(o, {"v_start", 0, speed_max, speed_note});
  m.v_max = read_uint(o, {"v_max", 0, speed_max, speed_note});
  m.v_end = read_uint(o, {"v_end", 0, speed_max, speed_note});
  m.acc = read_uint(o, {"acc", 0, acc_max, acc_note});
  m.dec = read_uint(o, {"dec", 0, acc_max, acc_note});
  m.v_dec = read_uint(o, {"v_dec", 0, speed_max, speed_note});
  m.acc_steps = static_cast<uint32_t>(read_uint(o, {"acc_steps", 0, step_max, step_note}));
  m.dec_step = static_cast<uint32_t>(read_uint(o, {"dec_step", 0, step_max, step_note}));
  m.dec_frac = static_cast<uint32_t>(
      read_uint(o, {"dec_frac", 0, dfrac_max, bits_note("DFRAC_W", w.dec_frac)}));
  const uint32_t e = validate_move(m, w);
  if (e != kErrNone) throw JobError(describe_move_error(e, m, path, w));
  return m;
}

PulseConfig read_pulse(const json& j, const std::string& path, const Widths& w) {
  Obj o(j, path, "a pulse object",
        {"step_high", "step_low", "dir_setup", "dir_hold", "step_invert", "dir_invert"});
  o.reject_unknown();
  const std::string note = " cycles" + bits_note("PULSE_W", w.pulse);
  const uint64_t pmax = std::min<uint64_t>(w.pulse_mask(), kU32Max);
  PulseConfig p;
  p.step_high = static_cast<uint32_t>(read_uint_opt(o, {"step_high", 0, pmax, note}, p.step_high));
  p.step_low = static_cast<uint32_t>(read_uint_opt(o, {"step_low", 0, pmax, note}, p.step_low));
  p.dir_setup = static_cast<uint32_t>(read_uint_opt(o, {"dir_setup", 0, pmax, note}, p.dir_setup));
  p.dir_hold = static_cast<uint32_t>(read_uint_opt(o, {"dir_hold", 0, pmax, note}, p.dir_hold));
  if (const json* v = o.opt("step_invert")) p.step_invert = get_bool(*v, o.sub("step_invert"));
  if (const json* v = o.opt("dir_invert")) p.dir_invert = get_bool(*v, o.sub("dir_invert"));
  return p;
}

Widths read_widths(const json& j, const std::string& path, const Widths& dflt) {
  Obj o(j, path, "a widths object",
        std::vector<const char*>(kWidthNames, kWidthNames + kNumWidths));
  o.reject_unknown();
  Widths w = dflt;
  // SPEED_W first: the ranges of ACC_W and DFRAC_W depend on it.
  for (unsigned i = 0; i < kNumWidths; ++i) {
    unsigned lo = 0, hi = 0;
    width_range(w, i, lo, hi);
    if (const json* v = o.opt(kWidthNames[i]))
      width_ref(w, i) = static_cast<unsigned>(get_uint(*v, o.sub(kWidthNames[i]), lo, hi, " bits"));
  }
  const std::string e = widths_error(w);  // a default that the new SPEED_W no longer allows
  if (!e.empty())
    fail(path + "." + e.substr(0, e.find(':')), e.substr(e.find(':') + 2) + " (not given: its default)");
  return w;
}

json parse_json(const std::string& text) {
  try {
    return parse_strict_json(text);
  } catch (const StrictJsonError& e) {
    if (e.path().empty()) throw JobError(e.what());
    fail(e.path(), e.what());
  }
}

}  // namespace

const char* const kWidthNames[kNumWidths] = {"SPEED_W", "ACC_W", "STEP_W", "DFRAC_W", "PULSE_W", "POS_W"};

unsigned& width_ref(Widths& w, unsigned i) {
  switch (i) {
    case 0: return w.speed_frac;
    case 1: return w.acc;
    case 2: return w.steps;
    case 3: return w.dec_frac;
    case 4: return w.pulse;
    default: return w.pos;
  }
}

unsigned width_of(const Widths& w, unsigned i) {
  Widths c = w;
  return width_ref(c, i);
}

void width_range(const Widths& w, unsigned i, unsigned& lo, unsigned& hi) {
  // rtl/hexstep_top.v: SPEED_W is 64 (the frame engine's datapath), ACC_W 1..64, STEP_W and
  // DFRAC_W 1..32 (one memory word), PULSE_W 1..16, POS_W 2..64.
  (void)w;
  static const unsigned kLo[kNumWidths] = {64, 1, 1, 1, 1, 2};
  static const unsigned kHi[kNumWidths] = {64, 64, 32, 32, 16, 64};
  lo = kLo[i];
  hi = kHi[i];
}

std::string widths_error(const Widths& w) {
  for (unsigned i = 0; i < kNumWidths; ++i) {
    unsigned lo = 0, hi = 0;
    width_range(w, i, lo, hi);
    const unsigned v = width_of(w, i);
    if (v < lo || v > hi)
      return std::string(kWidthNames[i]) + ": " + range_text(lo, hi) +
             ", got " + std::to_string(v);
  }
  return "";
}

std::string widths_text(const Widths& w) {
  std::string s;
  for (unsigned i = 0; i < kNumWidths; ++i)
    s += (i ? ", " : "") + std::string(kWidthNames[i]) + " " + std::to_string(width_of(w, i));
  return s;
}

bool same_widths(const Widths& a, const Widths& b) {
  for (unsigned i = 0; i < kNumWidths; ++i)
    if (width_of(a, i) != width_of(b, i)) return false;
  return true;
}

std::string describe_move_error(uint32_t err, const AxisMove& m, const std::string& path,
                                const Widths& w) {
  const std::string p = path.empty() ? "" : path + ".";
  const std::string speed_max = std::to_string(w.speed_mask());
  const std::string acc_max = std::to_string(w.acc_mask());
  std::vector<std::string> parts;
  if (err & kErrVmaxZero)
    parts.push_back(p + "v_max: must be an integer in [1, " + speed_max +
                    "] when steps > 0 (the core refuses v_max = 0), got 0");
  if (err & kErrStartAboveMax)
    parts.push_back(p + "v_start: must be <= v_max, i.e. an integer in [0, " +
                    std::to_string(m.v_max) + "], got " + std::to_string(m.v_start));
  if (err & kErrEndAboveMax)
    parts.push_back(p + "v_end: must be <= v_max, i.e. an integer in [0, " +
                    std::to_string(m.v_max) + "], got " + std::to_string(m.v_end));
  if (err & kErrDecAboveMax)
    parts.push_back(p + "v_dec: must be <= v_max, i.e. an integer in [0, " +
                    std::to_string(m.v_max) + "], got " + std::to_string(m.v_dec));
  if (err & kErrCountPastN) {
    if (m.acc_steps > m.steps)
      parts.push_back(p + "acc_steps: must be <= steps, i.e. an integer in [0, " +
                      std::to_string(m.steps) + "], got " + std::to_string(m.acc_steps));
    if (m.dec_step > m.steps)
      parts.push_back(p + "dec_step: must be <= steps, i.e. an integer in [0, " +
                      std::to_string(m.steps) + "], got " + std::to_string(m.dec_step));
  }
  if (err & kErrNoFloor)
    parts.push_back(p + "v_end, " + p + "dec: must not both be 0 (deceleration could stall): "
                    "set v_end to an integer in [1, v_max = " + std::to_string(m.v_max) +
                    "] or dec to an integer in [1, " + acc_max + "]");
  if (err & kErrNoStart)
    parts.push_back(p + "v_start: must be an integer in [1, v_max = " + std::to_string(m.v_max) +
                    "] when acc or acc_steps is 0 and deceleration does not start at once "
                    "(dec_step or dec_frac nonzero), got 0: the move could never take a step");
  const uint32_t known = kErrVmaxZero | kErrStartAboveMax | kErrEndAboveMax | kErrDecAboveMax |
                         kErrCountPastN | kErrNoFloor | kErrNoStart;
  if ((err & ~known) != 0 || parts.empty())
    parts.push_back(path + ": the core refuses this move (error bits " + std::to_string(err) + ")");
  std::string s;
  for (const auto& x : parts) s += (s.empty() ? "" : "; ") + x;
  return s;
}

Job parse_job(const std::string& text, const Widths& w) {
  const json root = parse_json(text);
  if (!root.is_object()) fail("(top level)", "must be a JSON object, " + json_got(root));
  Obj o(root, "", "a JSON object", {"format", "version", "clock_hz", "widths", "axes"});
  {
    const std::string accepts = std::string("must be the string \"") + kFormat + "\"";
    const json& f = o.req("format", accepts);
    if (!f.is_string() || f.get_ref<const std::string&>() != kFormat)
      fail("format", accepts + " (this is not a hexstep job file?), " + json_got(f));
  }
  get_uint(o.req("version", range_text(kVersion, kVersion)), "version", kVersion, kVersion,
           " (the only version this hexstep reads)");
  o.reject_unknown();

  Job job;
  job.clock_hz = read_uint(o, {"clock_hz", 1, kClockMax, " Hz"});
  if (const std::string e = widths_error(w); !e.empty()) fail("widths", "default " + e);
  job.widths = w;
  if (const json* v = o.opt("widths")) job.widths = read_widths(*v, "widths", w);

  const char* const axes_accepts = "must be an array of axis objects (at most 6)";
  const json& axes = o.req("axes", axes_accepts);
  if (!axes.is_array()) fail("axes", std::string(axes_accepts) + ", " + json_got(axes));
  if (axes.size() > kNumAxes)
    fail("axes", std::string(axes_accepts) + ", got " + std::to_string(axes.size()) + " entries");
  std::array<int, kNumAxes> seen_at;
  seen_at.fill(-1);
  for (size_t i = 0; i < axes.size(); ++i) {
    const std::string ap = "axes[" + std::to_string(i) + "]";
    Obj a(axes[i], ap, "an axis object", {"axis", "pulse", "moves"});
    a.reject_unknown();
    const UField axis_f{"axis", 0, kNumAxes - 1, ""};
    const unsigned idx = static_cast<unsigned>(read_uint(a, axis_f));
    if (seen_at[idx] >= 0)
      fail(a.sub("axis"), axis_f.accepts() + " and unique, got " + std::to_string(idx) +
                              " again (also in axes[" + std::to_string(seen_at[idx]) + "])");
    seen_at[idx] = static_cast<int>(i);
    AxisJob& aj = job.axes[idx];
    if (const json* p = a.opt("pulse")) aj.pulse = read_pulse(*p, a.sub("pulse"), job.widths);
    const char* const moves_accepts = "must be an array of move objects (may be empty)";
    const json& moves = a.req("moves", moves_accepts);
    if (!moves.is_array()) fail(a.sub("moves"), std::string(moves_accepts) + ", " + json_got(moves));
    for (size_t k = 0; k < moves.size(); ++k)
      aj.moves.push_back(read_move(moves[k], a.sub("moves") + "[" + std::to_string(k) + "]", job.widths));
  }
  return job;
}

std::string write_job(const Job& job) {
  ojson root = ojson::object();
  root["format"] = kFormat;
  root["version"] = kVersion;
  root["clock_hz"] = job.clock_hz;
  if (!same_widths(job.widths, Widths{})) {
    ojson wj = ojson::object();
    for (unsigned i = 0; i < kNumWidths; ++i) wj[kWidthNames[i]] = width_of(job.widths, i);
    root["widths"] = std::move(wj);
  }
  ojson axes = ojson::array();
  for (unsigned i = 0; i < kNumAxes; ++i) {
    const AxisJob& aj = job.axes[i];
    if (aj.moves.empty() && same_pulse(aj.pulse, PulseConfig{})) continue;
    ojson a = ojson::object();
    a["axis"] = i;
    ojson p = ojson::object();
    p["step_high"] = aj.pulse.step_high;
    p["step_low"] = aj.pulse.step_low;
    p["dir_setup"] = aj.pulse.dir_setup;
    p["dir_hold"] = aj.pulse.dir_hold;
    p["step_invert"] = aj.pulse.step_invert;
    p["dir_invert"] = aj.pulse.dir_invert;
    a["pulse"] = std::move(p);
    ojson moves = ojson::array();
    for (const AxisMove& m : aj.moves) {
      ojson mj = ojson::object();
      mj["steps"] = m.steps;
      mj["dir"] = m.dir ? 1 : 0;
      mj["v_start"] = m.v_start;
      mj["v_max"] = m.v_max;
      mj["v_end"] = m.v_end;
      mj["acc"] = m.acc;
      mj["dec"] = m.dec;
      mj["v_dec"] = m.v_dec;
      mj["acc_steps"] = m.acc_steps;
      mj["dec_step"] = m.dec_step;
      mj["dec_frac"] = m.dec_frac;
      moves.push_back(std::move(mj));
    }
    a["moves"] = std::move(moves);
    axes.push_back(std::move(a));
  }
  root["axes"] = std::move(axes);
  return root.dump(2) + "\n";
}

bool same_move(const AxisMove& a, const AxisMove& b) {
  return a.steps == b.steps && a.dir == b.dir && a.v_start == b.v_start && a.v_max == b.v_max &&
         a.v_end == b.v_end && a.acc == b.acc && a.dec == b.dec && a.v_dec == b.v_dec &&
         a.acc_steps == b.acc_steps &&
         a.dec_step == b.dec_step && a.dec_frac == b.dec_frac;
}

bool same_pulse(const PulseConfig& a, const PulseConfig& b) {
  return a.step_high == b.step_high && a.step_low == b.step_low && a.dir_setup == b.dir_setup &&
         a.dir_hold == b.dir_hold && a.step_invert == b.step_invert && a.dir_invert == b.dir_invert;
}

bool same_job(const Job& a, const Job& b) {
  if (a.clock_hz != b.clock_hz || !same_widths(a.widths, b.widths)) return false;
  for (unsigned i = 0; i < kNumAxes; ++i) {
    const AxisJob& x = a.axes[i];
    const AxisJob& y = b.axes[i];
    if (!same_pulse(x.pulse, y.pulse) || x.moves.size() != y.moves.size()) return false;
    for (size_t k = 0; k < x.moves.size(); ++k)
      if (!same_move(x.moves[k], y.moves[k])) return false;
  }
  return true;
}

}  // namespace hexstep
