// SPDX-License-Identifier: Apache-2.0
// hexstep: tests of the job file reader/writer (cpp_model/src/job_io.cpp).
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "hexstep/job_io.hpp"

using hexstep::AxisMove;
using hexstep::Job;
using hexstep::JobError;
using hexstep::PulseConfig;
using json = nlohmann::json;

namespace {

const hexstep::Widths kW{};
std::string range(uint64_t lo, uint64_t hi) {
  return "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}
const std::string kU64 = "18446744073709551615";
// The accepted ranges follow the register widths (SPEED_W = 64, ACC_W = 48, ... by default).
const std::string kSpeedRange = range(0, kW.speed_mask());
const std::string kAccRange = range(0, kW.acc_mask());
const std::string kStepRange = range(0, kW.steps_mask());
const std::string kFracRange = range(0, kW.dec_frac_mask());
const std::string kPulseRange = range(0, kW.pulse_mask());
const std::string kAxisRange = "must be an integer in [0, 5]";
const std::string kClockRange = "must be an integer in [1, 10000000000]";

json valid_move() {
  return json{{"steps", 1000}, {"dir", 1},         {"v_start", 0},        {"v_max", 1ull << 60},
              {"v_end", 1ull << 56}, {"acc", 1ull << 42}, {"dec", 1ull << 42},
              {"v_dec", (1ull << 60) - (1ull << 42)},
              {"acc_steps", 500}, {"dec_step", 600}, {"dec_frac", 0}};
}

json valid_job() {
  json j = {{"format", "hexstep-job"}, {"version", 1}, {"clock_hz", 100000000}};
  json a0 = {{"axis", 0},
             {"pulse",
              {{"step_high", 4}, {"step_low", 4}, {"dir_setup", 2}, {"dir_hold", 2},
               {"step_invert", false}, {"dir_invert", true}}},
             {"moves", json::array({valid_move(), valid_move()})}};
  a0["moves"][1]["dir"] = 0;
  json a3 = {{"axis", 3}, {"moves", json::array({valid_move()})}};
  j["axes"] = json::array({a0, a3});
  return j;
}

// The JobError message for `text`, or "" (and a test failure) if parse_job accepts it.
std::string error_of(const std::string& text, const hexstep::Widths& w = hexstep::Widths{}) {
  try {
    hexstep::parse_job(text, w);
  } catch (const JobError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "message not one line: " << m;
    return m;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a JobError: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return "";
}

std::string error_of(const json& j) { return error_of(j.dump()); }

json with(std::function<void(json&)> f) {
  json j = valid_job();
  f(j);
  return j;
}

#define EXPECT_HAS(msg, sub) EXPECT_NE((msg).find(sub), std::string::npos) << "message: " << (msg)

}  // namespace

// ---------------------------------------------------------------- reading and writing

TEST(JobIo, ParsesAValidJob) {
  const Job j = hexstep::parse_job(valid_job().dump());
  EXPECT_EQ(j.clock_hz, 100000000u);
  ASSERT_EQ(j.axes[0].moves.size(), 2u);
  ASSERT_EQ(j.axes[3].moves.size(), 1u);
  for (unsigned i : {1u, 2u, 4u, 5u}) EXPECT_TRUE(j.axes[i].moves.empty());
  EXPECT_EQ(j.axes[0].moves[0].v_max, 1ull << 60);
  EXPECT_TRUE(j.axes[0].moves[0].dir);
  EXPECT_FALSE(j.axes[0].moves[1].dir);
  EXPECT_EQ(j.axes[0].pulse.step_high, 4u);
  EXPECT_TRUE(j.axes[0].pulse.dir_invert);
  EXPECT_TRUE(hexstep::same_pulse(j.axes[3].pulse, PulseConfig{}));  // pulse omitted: defaults
}

TEST(JobIo, RoundTripIsExactAndCanonical) {
  Job j;
  j.clock_hz = 12345678901ull / 2;
  AxisMove m;
  m.steps = 0xFFFFFFFFu;
  m.dir = false;
  m.v_start = ~0ull - 1;
  m.v_max = ~0ull;  // all 64 bits, beyond double precision
  m.v_end = (1ull << 53) + 1;
  m.acc = kW.acc_mask();  // all ACC_W bits
  m.dec = 1;
  m.v_dec = ~0ull - 2;
  m.acc_steps = 0xFFFFFFFFu;
  m.dec_step = 0xFFFFFFFEu;
  m.dec_frac = static_cast<uint32_t>(kW.dec_frac_mask());
  j.axes[5].moves = {m, m};
  j.axes[5].moves[1].dir = true;
  j.axes[2].pulse = PulseConfig{4095, 0, 4095, 7, true, true};  // no moves, non-default pulse
  j.axes[1].moves.push_back(AxisMove{});                         // steps == 0: accepted
  const std::string text = hexstep::write_job(j);
  const Job back = hexstep::parse_job(text);
  EXPECT_TRUE(hexstep::same_job(back, j)) << text;
  EXPECT_EQ(hexstep::write_job(back), text);
  EXPECT_NE(text.find("18446744073709551615"), std::string::npos);  // plain integer
  // Axes 0, 3 and 4 are default and empty: left out. Axis order is by index.
  const json parsed = json::parse(text);
  ASSERT_EQ(parsed["axes"].size(), 3u);
  EXPECT_EQ(parsed["axes"][0]["axis"], 1);
  EXPECT_EQ(parsed["axes"][1]["axis"], 2);
  EXPECT_EQ(parsed["axes"][2]["axis"], 5);
  EXPECT_EQ(parsed["axes"][2]["moves"][0]["dir"], 0);  // dir written as 0/1
  EXPECT_EQ(text.back(), '\n');
}

TEST(JobIo, RoundTripOfValidJobAndExamples) {
  const Job j = hexstep::parse_job(valid_job().dump());
  EXPECT_TRUE(hexstep::same_job(hexstep::parse_job(hexstep::write_job(j)), j));
  for (const char* name : {"six_axis.json", "single_move.json"}) {
    std::ifstream f(std::string(HEXSTEP_EXAMPLES_DIR) + "/" + name);
    ASSERT_TRUE(f) << name;
    std::stringstream ss;
    ss << f.rdbuf();
    const Job e = hexstep::parse_job(ss.str());
    EXPECT_TRUE(hexstep::same_job(hexstep::parse_job(hexstep::write_job(e)), e)) << name;
  }
}

TEST(JobIo, SameJobSeesEveryField) {
  const Job a = hexstep::parse_job(valid_job().dump());
  std::vector<std::function<void(Job&)>> changes = {
      [](Job& j) { j.clock_hz += 1; },
      [](Job& j) { j.axes[0].moves[0].steps += 1; },
      [](Job& j) { j.axes[0].moves[0].dir = !j.axes[0].moves[0].dir; },
      [](Job& j) { j.axes[0].moves[0].v_start += 1; },
      [](Job& j) { j.axes[0].moves[0].v_max += 1; },
      [](Job& j) { j.axes[0].moves[0].v_end += 1; },
      [](Job& j) { j.axes[0].moves[0].acc += 1; },
      [](Job& j) { j.axes[0].moves[0].dec += 1; },
      [](Job& j) { j.axes[0].moves[0].v_dec += 1; },
      [](Job& j) { j.axes[0].moves[0].acc_steps += 1; },
      [](Job& j) { j.axes[0].moves[0].dec_step += 1; },
      [](Job& j) { j.axes[0].moves[0].dec_frac += 1; },
      [](Job& j) { j.axes[0].moves.pop_back(); },
      [](Job& j) { j.axes[4].pulse.step_high += 1; },
      [](Job& j) { j.axes[4].pulse.step_low += 1; },
      [](Job& j) { j.axes[4].pulse.dir_setup += 1; },
      [](Job& j) { j.axes[4].pulse.dir_hold += 1; },
      [](Job& j) { j.axes[4].pulse.step_invert = true; },
      [](Job& j) { j.axes[4].pulse.dir_invert = true; },
  };
  for (size_t i = 0; i < changes.size(); ++i) {
    Job b = a;
    changes[i](b);
    EXPECT_FALSE(hexstep::same_job(a, b)) << "change " << i;
    // ...and write_job carries the change through.
    EXPECT_TRUE(hexstep::same_job(hexstep::parse_job(hexstep::write_job(b)), b)) << "change " << i;
  }
}

TEST(JobIo, IntegersAsStrings) {
  json j = valid_job();
  j["clock_hz"] = "0x5F5E100";
  j["axes"][0]["moves"][0]["v_max"] = kU64;
  j["axes"][0]["moves"][0]["v_end"] = "0xffffffffffffffff";
  j["axes"][0]["moves"][0]["steps"] = "0X3e8";
  j["axes"][0]["pulse"]["step_high"] = "17";
  const Job p = hexstep::parse_job(j.dump());
  EXPECT_EQ(p.clock_hz, 100000000u);
  EXPECT_EQ(p.axes[0].moves[0].v_max, ~0ull);
  EXPECT_EQ(p.axes[0].moves[0].v_end, ~0ull);
  EXPECT_EQ(p.axes[0].moves[0].steps, 1000u);
  EXPECT_EQ(p.axes[0].pulse.step_high, 17u);
  for (const char* bad : {"", "0x", "-1", "+1", " 1", "1 ", "1.0", "1e3", "0x1g", "12abc", "0b1"}) {
    json k = valid_job();
    k["axes"][0]["moves"][0]["v_start"] = bad;
    const std::string m = error_of(k);
    EXPECT_HAS(m, "axes[0].moves[0].v_start: ");
    EXPECT_HAS(m, kSpeedRange);
  }
  json k = valid_job();
  k["axes"][0]["moves"][0]["v_start"] = "18446744073709551616";
  EXPECT_HAS(error_of(k), kSpeedRange);
  k["axes"][0]["moves"][0]["v_start"] = "0x10000000000000000";
  EXPECT_HAS(error_of(k), kSpeedRange);
}

TEST(JobIo, DirAndFlagsAcceptBooleans) {
  json j = valid_job();
  j["axes"][0]["moves"][0]["dir"] = false;
  j["axes"][0]["moves"][1]["dir"] = true;
  j["axes"][0]["pulse"]["step_invert"] = 1;
  j["axes"][0]["pulse"]["dir_invert"] = 0;
  const Job p = hexstep::parse_job(j.dump());
  EXPECT_FALSE(p.axes[0].moves[0].dir);
  EXPECT_TRUE(p.axes[0].moves[1].dir);
  EXPECT_TRUE(p.axes[0].pulse.step_invert);
  EXPECT_FALSE(p.axes[0].pulse.dir_invert);
}

TEST(JobIo, PulseFieldsAreOptional) {
  json j = valid_job();
  j["axes"][0]["pulse"] = json{{"step_low", 9}};
  const Job p = hexstep::parse_job(j.dump());
  PulseConfig want;
  want.step_low = 9;
  EXPECT_TRUE(hexstep::same_pulse(p.axes[0].pulse, want));
}

TEST(JobIo, EmptyAxesAndMoves) {
  json j = valid_job();
  j["axes"] = json::array();
  Job p = hexstep::parse_job(j.dump());
  for (const auto& a : p.axes) EXPECT_TRUE(a.moves.empty());
  j["axes"] = json::array({json{{"axis", 2}, {"moves", json::array()}}});
  p = hexstep::parse_job(j.dump());
  EXPECT_TRUE(p.axes[2].moves.empty());
}

// ---------------------------------------------------------------- errors

TEST(JobIoErrors, MalformedJson) {
  for (const char* text : {"", "{", "{\"format\": \"hexstep-job\",}", "[1, 2", "{} x", "nul"}) {
    const std::string m = error_of(std::string(text));
    EXPECT_HAS(m, "malformed JSON at byte ");
  }
  EXPECT_HAS(error_of(std::string("{\"a\":\n\n  ]")), "line 3");
}

TEST(JobIoErrors, TopLevel) {
  EXPECT_HAS(error_of(json::array()), "must be a JSON object");
  EXPECT_HAS(error_of(with([](json& j) { j.erase("format"); })),
             "format: required field is missing; it must be the string \"hexstep-job\"");
  EXPECT_HAS(error_of(with([](json& j) { j["format"] = "hexstep-plan"; })),
             "format: must be the string \"hexstep-job\"");
  EXPECT_HAS(error_of(with([](json& j) { j.erase("version"); })),
             "version: required field is missing; it must be an integer in [1, 1]");
  EXPECT_HAS(error_of(with([](json& j) { j["version"] = 2; })), "version: must be an integer in [1, 1]");
  EXPECT_HAS(error_of(with([](json& j) { j.erase("clock_hz"); })), std::string("clock_hz: required field is missing; it ") + kClockRange);
  EXPECT_HAS(error_of(with([](json& j) { j["clock_hz"] = 0; })), std::string("clock_hz: ") + kClockRange);
  EXPECT_HAS(error_of(with([](json& j) { j["clock_hz"] = 10000000001ull; })), std::string("clock_hz: ") + kClockRange);
  EXPECT_HAS(error_of(with([](json& j) { j["clock_hz"] = 1e8; })), std::string("clock_hz: ") + kClockRange);
  EXPECT_HAS(error_of(with([](json& j) { j.erase("axes"); })), "axes: required field is missing; it must be an array");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"] = json::object(); })), "axes: must be an array");
  EXPECT_HAS(error_of(with([](json& j) {
               json a = j["axes"][1];
               for (int i = 0; i < 6; ++i) j["axes"].push_back(a);
             })),
             "axes: must be an array of axis objects (at most 6)");
}

TEST(JobIoErrors, UnknownFields) {
  EXPECT_HAS(error_of(with([](json& j) { j["clockhz"] = 1; })), "clockhz: unknown field (accepted here: format, version, clock_hz, widths, axes)");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1]["pluse"] = json::object(); })), "axes[1].pluse: unknown field");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][0]["pulse"]["step_hi"] = 3; })), "axes[0].pulse.step_hi: unknown field (accepted here: step_high,");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][0]["moves"][1]["vmax"] = 3; })), "axes[0].moves[1].vmax: unknown field (accepted here: steps, dir, v_start, v_max,");
}

TEST(JobIoErrors, DuplicateFields) {
  const std::string t =
      R"({"format":"hexstep-job","version":1,"clock_hz":100,"axes":[{"axis":0,"moves":[]},)"
      R"({"axis":1,"moves":[{"steps":1,"steps":2}]}]})";
  EXPECT_HAS(error_of(t), "axes[1].moves[0].steps: duplicate field");
  EXPECT_HAS(error_of(std::string(R"({"format":"hexstep-job","format":"hexstep-job"})")), "format: duplicate field");
  // A key with an escaped control character (found by fuzz_job): the message stays one line.
  const std::string m = error_of(std::string(R"({"format":"hexstep-job","ve\nr":1,"ve\nr":1})"));
  EXPECT_HAS(m, "ve?r: duplicate field");
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST(JobIoErrors, AxisIndex) {
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1].erase("axis"); })), std::string("axes[1].axis: required field is missing; it ") + kAxisRange);
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1]["axis"] = 6; })), std::string("axes[1].axis: ") + kAxisRange);
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1]["axis"] = -1; })), std::string("axes[1].axis: ") + kAxisRange);
  const std::string m = error_of(with([](json& j) { j["axes"][1]["axis"] = 0; }));
  EXPECT_HAS(m, std::string("axes[1].axis: ") + kAxisRange + " and unique");
  EXPECT_HAS(m, "axes[0]");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1].erase("moves"); })), "axes[1].moves: required field is missing; it must be an array of move objects");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1]["moves"] = valid_move(); })), "axes[1].moves: must be an array of move objects");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1] = 3; })), "axes[1]: must be an axis object");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1]["pulse"] = json::array(); })), "axes[1].pulse: must be a pulse object");
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][1]["moves"][0] = "move"; })), "axes[1].moves[0]: must be a move object");
}

struct FieldCase {
  const char* field;
  std::string range;   // accepted range as printed
  json too_big;        // smallest value out of range (nullptr: none besides 64-bit overflow)
};

TEST(JobIoErrors, EveryMoveFieldMissingWrongTypeAndOutOfRange) {
  const std::vector<FieldCase> cases = {
      {"steps", kStepRange, 4294967296ull},
      {"v_start", kSpeedRange, "18446744073709551616"},
      {"v_max", kSpeedRange, "0x10000000000000000"},
      {"v_end", kSpeedRange, 18446744073709551615.0 * 2},
      {"acc", kAccRange, kW.acc_mask() + 1},
      {"dec", kAccRange, kW.acc_mask() + 1},
      {"v_dec", kSpeedRange, "0x10000000000000000"},
      {"acc_steps", kStepRange, 4294967296ull},
      {"dec_step", kStepRange, "4294967296"},
      {"dec_frac", kFracRange, kW.dec_frac_mask() + 1}, // DFRAC_W = 32: one past uint32
  };
  for (const auto& c : cases) {
    const std::string path = std::string("axes[0].moves[1].") + c.field;
    SCOPED_TRACE(path);
    std::string m = error_of(with([&](json& j) { j["axes"][0]["moves"][1].erase(c.field); }));
    EXPECT_HAS(m, path + ": required field is missing; it " + c.range);
    for (const json& bad : {json(-1), json(1.5), json(true), json(nullptr), json::array(), json::object(),
                            json("abc"), c.too_big}) {
      m = error_of(with([&](json& j) { j["axes"][0]["moves"][1][c.field] = bad; }));
      EXPECT_HAS(m, path + ": " + c.range);
    }
  }
  const std::string dir_accepts = "must be 1 (positive), 0 (negative), true (positive) or false (negative)";
  EXPECT_HAS(error_of(with([](json& j) { j["axes"][0]["moves"][1].erase("dir"); })), "axes[0].moves[1].dir: required field is missing; it " + dir_accepts);
  for (const json& bad : {json(2), json(-1), json("up"), json(nullptr), json(0.5)})
    EXPECT_HAS(error_of(with([&](json& j) { j["axes"][0]["moves"][1]["dir"] = bad; })), "axes[0].moves[1].dir: " + dir_accepts);
}

TEST(JobIoErrors, PulseFields) {
  for (const char* f : {"step_high", "step_low", "dir_setup", "dir_hold"}) {
    const std::string path = std::string("axes[0].pulse.") + f + ": ";
    for (const json& bad : {json(4096), json(-1), json("x"), json(false), json(2.0)})
      EXPECT_HAS(error_of(with([&](json& j) { j["axes"][0]["pulse"][f] = bad; })), path + kPulseRange);
  }
  for (const char* f : {"step_invert", "dir_invert"})
    for (const json& bad : {json(2), json("true"), json(nullptr)})
      EXPECT_HAS(error_of(with([&](json& j) { j["axes"][0]["pulse"][f] = bad; })),
                 std::string("axes[0].pulse.") + f + ": must be true or false (or 1 or 0)");
}

TEST(JobIoErrors, RangesFollowTheWidths) {
  struct Case {
    std::function<void(hexstep::Widths&)> narrow;
    std::function<void(json&)> set;
    const char* message;
  };
  const std::vector<Case> cases = {
      {[](hexstep::Widths& w) { w.acc = 20; },
       [](json& j) { j["axes"][0]["moves"][0]["acc"] = 1ull << 20; },
       "axes[0].moves[0].acc: must be an integer in [0, 1048575] (ACC_W = 20 bits)"},
      {[](hexstep::Widths& w) { w.steps = 16; },
       [](json& j) { j["axes"][0]["moves"][0]["steps"] = 65536; },
       "axes[0].moves[0].steps: must be an integer in [0, 65535] (STEP_W = 16 bits)"},
      {[](hexstep::Widths& w) { w.dec_frac = 8; },
       [](json& j) { j["axes"][0]["moves"][0]["dec_frac"] = 256; },
       "axes[0].moves[0].dec_frac: must be an integer in [0, 255] (DFRAC_W = 8 bits)"},
      {[](hexstep::Widths& w) { w.pulse = 4; },
       [](json& j) { j["axes"][0]["pulse"]["dir_hold"] = 16; },
       "axes[0].pulse.dir_hold: must be an integer in [0, 15] cycles (PULSE_W = 4 bits)"},
  };
  for (const auto& c : cases) {
    hexstep::Widths w;
    c.narrow(w);
    json j = valid_job();  // with small values that fit every narrowed width
    const json small = {{"steps", 100}, {"dir", 1},  {"v_start", 1000}, {"v_max", 1000},
                        {"v_end", 1000}, {"acc", 0}, {"dec", 0},        {"v_dec", 1000},
                        {"acc_steps", 0}, {"dec_step", 100}, {"dec_frac", 0}};
    for (auto& a : j["axes"])
      for (auto& m : a["moves"]) m = small;
    EXPECT_NO_THROW(hexstep::parse_job(j.dump(), w));
    c.set(j);
    EXPECT_HAS(error_of(j.dump(), w), c.message);
  }
}

// The file's own widths object: the same narrowing as above, written in the job.
TEST(JobIoWidths, WidthsObjectSetsTheRangesAndRoundTrips) {
  const json small = {{"steps", 100}, {"dir", 1},  {"v_start", 1000}, {"v_max", 1000},
                      {"v_end", 1000}, {"acc", 0}, {"dec", 0},        {"v_dec", 1000},
                      {"acc_steps", 0}, {"dec_step", 100}, {"dec_frac", 0}};
  json j = valid_job();
  for (auto& a : j["axes"])
    for (auto& m : a["moves"]) m = small;
  // A narrow board build (SPEED_W is 64 in every build, so it may be left out).
  j["widths"] = {{"ACC_W", 40}, {"STEP_W", 16}, {"DFRAC_W", 8}, {"PULSE_W", 8}, {"POS_W", 16}};
  const Job job = hexstep::parse_job(j.dump());
  EXPECT_EQ(job.widths.speed_frac, 64u);
  EXPECT_EQ(job.widths.acc, 40u);
  EXPECT_EQ(job.widths.steps, 16u);
  EXPECT_EQ(job.widths.dec_frac, 8u);
  EXPECT_EQ(job.widths.pulse, 8u);
  EXPECT_EQ(job.widths.pos, 16u);
  // Written with all six fields, read back equal; a default job has no widths object.
  const std::string text = hexstep::write_job(job);
  const json back = json::parse(text);
  EXPECT_EQ(back["widths"], (json{{"SPEED_W", 64}, {"ACC_W", 40}, {"STEP_W", 16}, {"DFRAC_W", 8},
                                  {"PULSE_W", 8}, {"POS_W", 16}}));
  EXPECT_TRUE(hexstep::same_job(hexstep::parse_job(text), job));
  EXPECT_FALSE(json::parse(hexstep::write_job(hexstep::parse_job(valid_job().dump()))).contains("widths"));
  Job other = job;
  other.widths.pos = 17;
  EXPECT_FALSE(hexstep::same_job(job, other));
  // Values are checked against the file's widths, not the default ones.
  j["axes"][0]["moves"][0]["acc"] = 1ull << 40;
  EXPECT_HAS(error_of(j), "axes[0].moves[0].acc: must be an integer in [0, 1099511627775] (ACC_W = 40 bits)");
  j["axes"][0]["moves"][0]["acc"] = 0;
  j["axes"][0]["moves"][0]["steps"] = 65536;
  EXPECT_HAS(error_of(j), "axes[0].moves[0].steps: must be an integer in [0, 65535] (STEP_W = 16 bits)");
  j["axes"][0]["moves"][0]["steps"] = 100;
  j["axes"][0]["pulse"]["step_high"] = 256;
  EXPECT_HAS(error_of(j), "axes[0].pulse.step_high: must be an integer in [0, 255] cycles (PULSE_W = 8 bits)");
}

TEST(JobIoWidths, BadWidthsNameTheFieldAndRange) {
  auto err = [](const json& w) {
    json j = valid_job();
    j["widths"] = w;
    return error_of(j);
  };
  // SPEED_W is fixed at 64 (the frame engine's datapath is two 32-bit halves).
  EXPECT_HAS(err({{"SPEED_W", 65}}), "widths.SPEED_W: must be an integer in [64, 64] bits, got 65");
  EXPECT_HAS(err({{"SPEED_W", 48}}), "widths.SPEED_W: must be an integer in [64, 64] bits, got 48");
  EXPECT_HAS(err({{"ACC_W", 0}}), "widths.ACC_W: must be an integer in [1, 64] bits, got 0");
  EXPECT_HAS(err({{"ACC_W", 65}}), "widths.ACC_W: must be an integer in [1, 64] bits, got 65");
  EXPECT_HAS(err({{"STEP_W", 33}}), "widths.STEP_W: must be an integer in [1, 32] bits, got 33");
  EXPECT_HAS(err({{"DFRAC_W", 33}}), "widths.DFRAC_W: must be an integer in [1, 32] bits, got 33");
  EXPECT_HAS(err({{"PULSE_W", 0}}), "widths.PULSE_W: must be an integer in [1, 16] bits, got 0");
  EXPECT_HAS(err({{"PULSE_W", 17}}), "widths.PULSE_W: must be an integer in [1, 16] bits, got 17");
  EXPECT_HAS(err({{"POS_W", 1}}), "widths.POS_W: must be an integer in [2, 64] bits, got 1");
  // OWE_W is gone with the old output stage: an unknown field now.
  EXPECT_HAS(err({{"OWE_W", 2}}), "widths.OWE_W: unknown field");
  EXPECT_HAS(err({{"FOO_W", 3}}), "widths.FOO_W");
  EXPECT_HAS(err(json::array({24})), "widths: must be a widths object");
  // The caller's default widths (a file without a widths object) are checked the same way.
  hexstep::Widths w48;
  w48.speed_frac = 48;
  EXPECT_HAS(error_of(valid_job().dump(), w48), "widths: default SPEED_W: must be an integer in [64, 64], got 48");
}

TEST(JobIoErrors, MovesTheCoreWouldRefuse) {
  auto move_err = [](std::function<void(json&)> f) {
    return error_of(with([&](json& j) { f(j["axes"][1]["moves"][0]); }));
  };
  const std::string p = "axes[1].moves[0].";
  EXPECT_HAS(move_err([](json& m) { m["v_max"] = 0; m["v_end"] = 0; }),
             p + "v_max: must be an integer in [1, " + kU64 + "]");
  EXPECT_HAS(move_err([](json& m) { m["v_start"] = (1ull << 60) + 1; }),
             p + "v_start: must be <= v_max, i.e. an integer in [0, 1152921504606846976], got 1152921504606846977");
  EXPECT_HAS(move_err([](json& m) { m["v_end"] = (1ull << 60) + 1; }),
             p + "v_end: must be <= v_max, i.e. an integer in [0, 1152921504606846976]");
  EXPECT_HAS(move_err([](json& m) { m["v_dec"] = (1ull << 60) + 1; }),
             p + "v_dec: must be <= v_max, i.e. an integer in [0, 1152921504606846976], got 1152921504606846977");
  EXPECT_HAS(move_err([](json& m) { m["acc_steps"] = 1001; }), p + "acc_steps: must be <= steps, i.e. an integer in [0, 1000], got 1001");
  EXPECT_HAS(move_err([](json& m) { m["dec_step"] = 1001; }), p + "dec_step: must be <= steps, i.e. an integer in [0, 1000], got 1001");
  const std::string nf = move_err([](json& m) { m["v_end"] = 0; m["dec"] = 0; });
  EXPECT_HAS(nf, p + "v_end, " + p + "dec: must not both be 0");
  EXPECT_HAS(nf, "v_end to an integer in [1, v_max = 1152921504606846976]");
  EXPECT_HAS(nf, "dec to an integer in [1, " + std::to_string(kW.acc_mask()) + "]");
  const std::string ns = move_err([](json& m) { m["acc"] = 0; });
  EXPECT_HAS(ns, p + "v_start: must be an integer in [1, v_max = 1152921504606846976] when acc or acc_steps is 0");
  EXPECT_HAS(move_err([](json& m) { m["acc_steps"] = 0; }), p + "v_start: must be an integer in [1, v_max");
  // Several at once: all named on one line.
  const std::string all = move_err([](json& m) {
    m["v_start"] = 5; m["v_max"] = 4; m["v_end"] = 6; m["acc_steps"] = 2000;
  });
  EXPECT_HAS(all, p + "v_start: must be <= v_max");
  EXPECT_HAS(all, p + "v_end: must be <= v_max");
  EXPECT_HAS(all, p + "acc_steps: must be <= steps");
  // steps == 0 is a no-op the core accepts, whatever the rest says.
  json j = valid_job();
  j["axes"][1]["moves"][0] = json{{"steps", 0}, {"dir", 0}, {"v_start", 0}, {"v_max", 0}, {"v_end", 0},
                                  {"acc", 0},   {"dec", 0}, {"v_dec", 0}, {"acc_steps", 0}, {"dec_step", 0},
                                  {"dec_frac", 0}};
  EXPECT_NO_THROW(hexstep::parse_job(j.dump()));
  // Deceleration from the start (dec_step = dec_frac = 0) needs no start speed.
  j["axes"][1]["moves"][0] = valid_move();
  j["axes"][1]["moves"][0]["acc"] = 0;
  j["axes"][1]["moves"][0]["dec_step"] = 0;
  j["axes"][1]["moves"][0]["v_start"] = 0;
  EXPECT_NO_THROW(hexstep::parse_job(j.dump()));
}

TEST(JobIoErrors, DescribeMoveErrorOfUnknownBits) {
  AxisMove m;
  m.steps = 10;
  EXPECT_HAS(hexstep::describe_move_error(1u << 20, m, "axes[2].moves[3]"),
             "axes[2].moves[3]: the core refuses this move");
}
