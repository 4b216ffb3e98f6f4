// SPDX-License-Identifier: Apache-2.0
// hexstep: black-box tests of `hexstep plan` (cli/plan.cpp). Runs the built binary and checks its
// JSON against values computed by hand here, its error messages and exit statuses, the
// planning request file and --out. The pipes into `hexstep simulate` and the C header compile
// test are in cli_test.sh (cases plan_*).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

using json = nlohmann::json;

namespace {

struct Result {
  int rc = -1;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

bool exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

class Plan : public ::testing::Test {
 protected:
  void SetUp() override {
    char tmpl[] = "/tmp/hexstep_plan_test.XXXXXX";
    ASSERT_NE(::mkdtemp(tmpl), nullptr);
    dir_ = tmpl;
  }
  void TearDown() override { std::system(("rm -rf " + quote(dir_)).c_str()); }

  std::string tmp(const std::string& name) const { return dir_ + "/" + name; }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(tmp(name), std::ios::binary) << text;
    return tmp(name);
  }

  // hexstep plan ARGS (stdin from `input`).
  Result plan(const std::vector<std::string>& args, const std::string& input = "") const {
    std::string cmd = quote(HEXSTEP_BIN) + " plan";
    for (const auto& a : args) cmd += " " + quote(a);
    cmd += " <" + quote(write("stdin", input)) + " >" + quote(tmp("out")) + " 2>" + quote(tmp("err"));
    const int st = std::system(cmd.c_str());
    Result r;
    r.rc = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = slurp(tmp("out"));
    r.err = slurp(tmp("err"));
    return r;
  }

  // The JSON of a successful run.
  json plan_json(const std::vector<std::string>& args, const std::string& input = "") const {
    const Result r = plan(args, input);
    EXPECT_EQ(r.rc, 0) << r.err;
    EXPECT_EQ(r.err, "");
    try {
      return json::parse(r.out);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not JSON: " << e.what() << "\n" << r.out;
      return json::object();
    }
  }

  // A failing run: exit status `rc`, nothing on stdout, one stderr line "hexstep: error: ..."
  // containing every text in `texts`, and no --out file.
  void expect_error(std::vector<std::string> args, int rc, const std::vector<std::string>& texts,
                    const std::string& input = "") const {
    const std::string out_file = tmp("must_not_exist.out");
    if (std::find(args.begin(), args.end(), "--out") == args.end()) {
      args.push_back("--out");
      args.push_back(out_file);
    }
    std::string what;
    for (const auto& a : args) what += " " + a;
    const Result r = plan(args, input);
    EXPECT_EQ(r.rc, rc) << what << "\n" << r.err;
    EXPECT_EQ(r.out, "") << what;
    EXPECT_FALSE(exists(out_file)) << what;
    EXPECT_EQ(r.err.rfind("hexstep: error: ", 0), 0u) << what << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << what << "\n" << r.err;
    for (const auto& t : texts) EXPECT_NE(r.err.find(t), std::string::npos) << what << "\n" << r.err << "lacks: " << t;
  }

  std::string dir_;
};

// |got - want| <= rel * |want| (or rel when want is 0).
void near_rel(double got, double want, double rel, const std::string& what) {
  const double tol = want == 0 ? rel : rel * std::fabs(want);
  EXPECT_NEAR(got, want, tol) << what;
}

const char* const kRegisterFields[] = {"steps",  "dir", "v_start",   "v_max",    "v_end",   "acc",
                                       "dec",    "v_dec", "acc_steps", "dec_step", "dec_frac"};

// The fields every axis object has, and the invariants between them.
void check_axis_shape(const json& a) {
  for (const char* k : {"axis", "profile", "unit", "steps_per_unit", "dir", "steps", "start_speed_steps_per_s",
                        "peak_speed_steps_per_s", "end_speed_steps_per_s", "end_speed_requested_steps_per_s",
                        "accel_steps_per_s2", "decel_steps_per_s2", "t_accel_s", "t_cruise_s", "t_decel_s",
                        "duration_s", "pulse", "registers", "executed"})
    EXPECT_TRUE(a.contains(k)) << k;
  const json& s = a["steps"];
  const int64_t n = s["accel"].get<int64_t>() + s["cruise"].get<int64_t>() + s["decel"].get<int64_t>();
  const int64_t total = s["total"].get<int64_t>();
  EXPECT_EQ(n, total < 0 ? -total : total) << "counts sum to |total|";
  const json& r = a["registers"];
  EXPECT_EQ(r.size(), std::size(kRegisterFields));
  for (const char* k : kRegisterFields) {
    ASSERT_TRUE(r.contains(k)) << k;
    EXPECT_TRUE(r[k].is_number_unsigned()) << k << " must be a JSON integer, is " << r[k].dump();
  }
  EXPECT_EQ(r["steps"].get<int64_t>(), total < 0 ? -total : total);
  EXPECT_EQ(r["dir"].get<int>(), total < 0 ? 0 : 1);
  EXPECT_EQ(a["dir"].get<int>(), r["dir"].get<int>());
  near_rel(a["duration_s"].get<double>(),
           a["t_accel_s"].get<double>() + a["t_cruise_s"].get<double>() + a["t_decel_s"].get<double>(), 1e-12,
           "duration = sum of phases");
  for (const char* k : {"start_speed_steps_per_s", "peak_speed_steps_per_s", "end_speed_steps_per_s",
                        "accel_steps_per_s2", "decel_steps_per_s2", "t_accel_s", "t_cruise_s", "t_decel_s",
                        "duration_s"})
    EXPECT_TRUE(a["executed"].contains(k)) << "executed." << k;
}

// Plan and executed profile agree (the accelerations here are >= 10^6 register LSBs).
void check_executed(const json& a) {
  near_rel(a["executed"]["peak_speed_steps_per_s"].get<double>(), a["peak_speed_steps_per_s"].get<double>(), 1e-6,
           "executed peak");
  near_rel(a["executed"]["duration_s"].get<double>(), a["duration_s"].get<double>(), 1e-6, "executed duration");
}

TEST_F(Plan, TriangularFromRestByHand) {
  // N = 1000, a = d = 1000 steps/s^2, v_max = 2000: the triangle's peak is sqrt(a N) = 1000
  // (< 2000), reached after t = v/a = 1 s and 500 steps; 2 s in all.
  const json j = plan_json({"--steps", "1000", "--max-speed", "2000", "--accel", "1000"});
  EXPECT_EQ(j["format"], "hexstep-plan");
  EXPECT_EQ(j["clock_hz"].get<uint64_t>(), 100000000u);
  ASSERT_EQ(j["axes"].size(), 1u);
  const json& a = j["axes"][0];
  check_axis_shape(a);
  check_executed(a);
  EXPECT_EQ(a["axis"], 0);
  EXPECT_EQ(a["profile"], "triangular");
  EXPECT_EQ(a["steps"], (json{{"accel", 500}, {"cruise", 0}, {"decel", 500}, {"total", 1000}}));
  near_rel(a["peak_speed_steps_per_s"].get<double>(), 1000, 1e-9, "peak");
  near_rel(a["duration_s"].get<double>(), 2.0, 1e-9, "duration");
  near_rel(j["duration_s"].get<double>(), 2.0, 1e-9, "top-level duration");
  near_rel(a["t_accel_s"].get<double>(), 1.0, 1e-9, "t_accel");
  EXPECT_EQ(a["t_cruise_s"].get<double>(), 0.0);
  EXPECT_FALSE(a.contains("warning"));
  // Registers at 100 MHz count ticks of 32 cycles, tick_rate ft = f / 32 = 3.125 MHz:
  // acceleration register = floor(a / ft^2 * 2^64) = floor(1000 * 1024 / 10^16 * 2^64)
  // = floor(1888946593.07...).
  EXPECT_EQ(a["registers"]["acc"].get<uint64_t>(), 1888946593u);
  EXPECT_EQ(a["registers"]["dec"].get<uint64_t>(), 1888946593u);
  // Peak speed register: floor(vp / ft * 2^64) of the peak the quantized ramps reach, at most
  // 1000 / 3.125e6 * 2^64 = 5902958103587056.5.
  EXPECT_LE(a["registers"]["v_max"].get<uint64_t>(), 5902958103587056u);
  EXPECT_GE(a["registers"]["v_max"].get<uint64_t>(), 5902958103587056u - 5902958103587056u / 1000000);
}

TEST_F(Plan, TrapezoidalWithRatioByHand) {
  // d = a / 2 = 500: accelerate 1000^2 / 2000 = 500 steps in 1 s, decelerate 1000^2 / 1000 =
  // 1000 steps in 2 s, cruise 1500 steps at 1000 steps/s = 1.5 s: 4.5 s.
  const json j = plan_json({"--steps", "3000", "--max-speed", "1000", "--accel", "1000", "--ratio", "2"});
  const json& a = j["axes"][0];
  check_axis_shape(a);
  check_executed(a);
  EXPECT_EQ(a["profile"], "trapezoidal");
  EXPECT_EQ(a["steps"], (json{{"accel", 500}, {"cruise", 1500}, {"decel", 1000}, {"total", 3000}}));
  near_rel(a["decel_steps_per_s2"].get<double>(), 500, 1e-12, "decel");
  near_rel(a["t_accel_s"].get<double>(), 1.0, 1e-9, "t_accel");
  near_rel(a["t_cruise_s"].get<double>(), 1.5, 1e-9, "t_cruise");
  near_rel(a["t_decel_s"].get<double>(), 2.0, 1e-9, "t_decel");
  near_rel(a["duration_s"].get<double>(), 4.5, 1e-9, "duration");
  // --decel 500 is the same move.
  const json k = plan_json({"--steps", "3000", "--max-speed", "1000", "--accel", "1000", "--decel", "500"});
  EXPECT_EQ(k["axes"][0]["registers"], a["registers"]);
}

TEST_F(Plan, StartAndEndSpeedsByHand) {
  // 200 -> 1000 at 1000: (10^6 - 4*10^4) / 2000 = 480 steps in 0.8 s; 1000 -> 400: 420 steps in
  // 0.6 s; cruise 3000 - 900 = 2100 steps in 2.1 s: 3.5 s.
  const json j = plan_json({"--steps", "3000", "--max-speed", "1000", "--accel", "1000", "--start-speed", "200",
                            "--end-speed", "400"});
  const json& a = j["axes"][0];
  check_axis_shape(a);
  check_executed(a);
  EXPECT_EQ(a["profile"], "trapezoidal");
  EXPECT_EQ(a["steps"], (json{{"accel", 480}, {"cruise", 2100}, {"decel", 420}, {"total", 3000}}));
  near_rel(a["start_speed_steps_per_s"].get<double>(), 200, 1e-12, "start");
  near_rel(a["end_speed_steps_per_s"].get<double>(), 400, 1e-12, "end");
  near_rel(a["duration_s"].get<double>(), 3.5, 1e-9, "duration");
}

TEST_F(Plan, ConstantSpeed) {
  const json j = plan_json({"--steps", "500", "--start-speed", "1000", "--max-speed", "1000", "--accel", "1"});
  const json& a = j["axes"][0];
  check_axis_shape(a);
  EXPECT_EQ(a["profile"], "constant");
  EXPECT_EQ(a["steps"], (json{{"accel", 0}, {"cruise", 500}, {"decel", 0}, {"total", 500}}));
  near_rel(a["duration_s"].get<double>(), 0.5, 1e-9, "duration");
  EXPECT_EQ(a["registers"]["acc"].get<uint64_t>(), 0u);
  EXPECT_EQ(a["registers"]["dec"].get<uint64_t>(), 0u);
}

TEST_F(Plan, ShortMoveWarns) {
  // 10 steps from 100 at 1000 steps/s^2 reach sqrt(100^2 + 2*1000*10) = sqrt(30000) < 1000.
  const json j = plan_json({"--steps", "10", "--start-speed", "100", "--end-speed", "1000", "--max-speed", "1000",
                            "--accel", "1000"});
  const json& a = j["axes"][0];
  check_axis_shape(a);
  EXPECT_EQ(a["profile"], "accel-only");
  ASSERT_TRUE(a.contains("warning"));
  EXPECT_NE(a["warning"].get<std::string>().find("--end-speed"), std::string::npos);
  near_rel(a["end_speed_steps_per_s"].get<double>(), std::sqrt(30000.0), 1e-12, "end speed reached");
  near_rel(a["end_speed_requested_steps_per_s"].get<double>(), 1000, 1e-12, "end speed requested");
}

TEST_F(Plan, EmptyMove) {
  const json j = plan_json({"--steps", "0", "--max-speed", "1000", "--accel", "1000"});
  const json& a = j["axes"][0];
  check_axis_shape(a);
  EXPECT_EQ(a["profile"], "empty");
  EXPECT_EQ(a["steps"]["total"], 0);
  EXPECT_EQ(j["duration_s"].get<double>(), 0.0);
}

TEST_F(Plan, TimeBudgetRanade) {
  // Triangle: peak 2N/T = 500 at T/2 = 2 s, acceleration 500 / 2 = 250.
  json j = plan_json({"--steps", "1000", "--time", "4", "--max-speed", "1000", "--accel", "1000"});
  json a = j["axes"][0];
  check_axis_shape(a);
  check_executed(a);
  EXPECT_EQ(a["profile"], "triangular");
  near_rel(a["peak_speed_steps_per_s"].get<double>(), 500, 1e-9, "peak");
  near_rel(a["accel_steps_per_s2"].get<double>(), 250, 1e-9, "accel");
  near_rel(a["duration_s"].get<double>(), 4, 1e-9, "duration");
  near_rel(a["time_budget_s"].get<double>(), 4, 0, "time budget");
  // Trapezoid: t_r = (v T - N) / v = (5000 - 3000) / 1000 = 2 s, acceleration 500, cruise 1 s.
  j = plan_json({"--steps", "3000", "--time", "5", "--max-speed", "1000", "--accel", "1000"});
  a = j["axes"][0];
  check_axis_shape(a);
  check_executed(a);
  EXPECT_EQ(a["profile"], "trapezoidal");
  near_rel(a["accel_steps_per_s2"].get<double>(), 500, 1e-9, "accel");
  near_rel(a["t_accel_s"].get<double>(), 2, 1e-9, "t_accel");
  near_rel(a["t_cruise_s"].get<double>(), 1, 1e-9, "t_cruise");
  near_rel(a["duration_s"].get<double>(), 5, 1e-9, "duration");
}

TEST_F(Plan, InfeasibleTimeExits3WithTheMinimum) {
  // The fastest 3000-step move at 1000 steps/s and 1000 steps/s^2 takes 1 + 2 + 1 = 4 s.
  expect_error({"--steps", "3000", "--time", "3.9", "--max-speed", "1000", "--accel", "1000"}, 3,
               {"--time", "minimum achievable time 4 s"});
  // In another unit (1 mm = 100 steps) the same.
  expect_error({"--distance", "30", "--unit", "mm", "--steps-per-mm", "100", "--time", "3.9", "--max-speed", "10",
                "--accel", "10"},
               3, {"--time", "minimum achievable time 4 s"});
}

TEST_F(Plan, Units) {
  auto total = [&](const std::vector<std::string>& args) {
    std::vector<std::string> all = args;
    for (const char* s : {"--max-speed", "1", "--accel", "1"}) all.push_back(s);
    const json j = plan_json(all);
    return j["axes"][0]["steps"]["total"].get<int64_t>();
  };
  EXPECT_EQ(total({"--distance", "1", "--unit", "rev", "--steps-per-rev", "200"}), 200);
  EXPECT_EQ(total({"--distance", "8", "--unit", "mm", "--pitch-mm", "8", "--steps-per-rev", "400"}), 400);
  EXPECT_EQ(total({"--distance", "2.5", "--unit", "mm", "--steps-per-mm", "80"}), 200);
  EXPECT_EQ(total({"--distance", "90", "--unit", "deg", "--steps-per-rev", "400"}), 100);
  EXPECT_EQ(total({"--distance", "3.14159265358979", "--unit", "rad", "--steps-per-rev", "200"}), 100);
  EXPECT_EQ(total({"--distance", "2.5", "--unit", "steps"}), 3);  // halves away from zero
  EXPECT_EQ(total({"--distance", "-2.5"}), -3);
  // Speeds and accelerations are in the unit too: 5 rev/s = 1000 steps/s, 5 rev/s^2 = 1000
  // steps/s^2; 10 rev = 2000 steps: 500 up in 1 s, 1000 cruising in 1 s, 500 down in 1 s.
  const json j = plan_json({"--distance", "10", "--unit", "rev", "--steps-per-rev", "200", "--max-speed", "5",
                            "--accel", "5"});
  const json& a = j["axes"][0];
  check_axis_shape(a);
  EXPECT_EQ(a["unit"], "rev");
  near_rel(a["steps_per_unit"].get<double>(), 200, 0, "steps per unit");
  near_rel(a["peak_speed_steps_per_s"].get<double>(), 1000, 1e-12, "peak");
  near_rel(a["accel_steps_per_s2"].get<double>(), 1000, 1e-12, "accel");
  EXPECT_EQ(a["steps"], (json{{"accel", 500}, {"cruise", 1000}, {"decel", 500}, {"total", 2000}}));
  near_rel(a["duration_s"].get<double>(), 3, 1e-9, "duration");
}

TEST_F(Plan, NegativeDistance) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"--distance", "-1", "--unit", "rev", "--steps-per-rev", "200"}, {"--steps", "-200"}, {"--steps=-200"}}) {
    std::vector<std::string> all = args;
    for (const char* s : {"--max-speed", "1000", "--accel", "10000"}) all.push_back(s);
    const json j = plan_json(all);
    const json& a = j["axes"][0];
    check_axis_shape(a);
    EXPECT_EQ(a["dir"], 0);
    EXPECT_EQ(a["registers"]["dir"], 0);
    EXPECT_EQ(a["registers"]["steps"], 200);
    EXPECT_EQ(a["steps"]["total"], -200);
  }
}

TEST_F(Plan, AxisClockAndPulse) {
  const json j = plan_json({"--steps", "1000", "--max-speed", "1000", "--accel", "10000", "--axis", "4",
                            "--clock-hz", "1e6", "--step-high", "3", "--step-low", "5", "--dir-setup", "7",
                            "--dir-hold", "9"});
  EXPECT_EQ(j["clock_hz"].get<uint64_t>(), 1000000u);
  const json& a = j["axes"][0];
  EXPECT_EQ(a["axis"], 4);
  EXPECT_EQ(a["pulse"]["step_high"], 3);
  EXPECT_EQ(a["pulse"]["step_low"], 5);
  EXPECT_EQ(a["pulse"]["dir_setup"], 7);
  EXPECT_EQ(a["pulse"]["dir_hold"], 9);
  // 10^4 steps/s^2 at 1 MHz, ft = 31250 ticks/s: floor(10^4 / 31250^2 * 2^64)
  // = floor(1.024e-5 * 2^64) = floor(188894659314785.8...).
  EXPECT_EQ(a["registers"]["acc"].get<uint64_t>(), 188894659314785u);
  // The pulse rate bound F / (high + low) binds below one step per tick (F / 32) only when
  // high + low > 32: with 20 + 20 cycles it is 25000 steps/s at 1 MHz; 25000 passes, more fails.
  const Result ok = plan({"--steps", "1000", "--start-speed", "25000", "--max-speed", "25000", "--accel", "1",
                       "--clock-hz", "1000000", "--step-high", "20", "--step-low", "20"});
  EXPECT_EQ(ok.rc, 0) << ok.err;
  expect_error({"--steps", "1000", "--start-speed", "25001", "--max-speed", "25001", "--accel", "1",
                "--clock-hz", "1000000", "--step-high", "20", "--step-low", "20"},
               2, {"--max-speed", "pulse stage", "[0, 25000] steps/s"});
  // With 3 + 5 cycles (125000 steps/s) the tick is the bound: a speed register holds less than
  // one step per tick, 31250 steps/s at 1 MHz.
  const Result tick_ok = plan({"--steps", "1000", "--start-speed", "31249", "--max-speed", "31249", "--accel", "1",
                               "--clock-hz", "1000000", "--step-high", "3", "--step-low", "5"});
  EXPECT_EQ(tick_ok.rc, 0) << tick_ok.err;
  expect_error({"--steps", "1000", "--start-speed", "31250", "--max-speed", "31250", "--accel", "1",
                "--clock-hz", "1000000", "--step-high", "3", "--step-low", "5"},
               2, {"--start-speed", "cannot be represented", "[0, 31250) steps/s"});
}

// --widths: registers for a narrower core build, computed by hand at 12 MHz (ft = 375000
// ticks/s): speed = floor(v / ft * 2^64), acceleration = floor(a / ft^2 * 2^64). SPEED_W is 64
// in every build; ACC_W = 40 holds accelerations up to (2^40 - 1) ft^2 / 2^64 = 8381.9 steps/s^2.
TEST_F(Plan, WidthsOfAReducedBuild) {
  const std::string wid = "ACC_W=40,STEP_W=16,DFRAC_W=8,PULSE_W=8,POS_W=16";
  const std::vector<std::string> base = {"--steps", "5000", "--start-speed", "20000", "--max-speed", "1e5",
                                         "--accel", "5000", "--decel", "2500", "--clock-hz", "12e6"};
  std::vector<std::string> args = base;
  args.insert(args.end(), {"--widths", wid});
  const json j = plan_json(args);
  EXPECT_EQ(j["widths"], (json{{"SPEED_W", 64}, {"ACC_W", 40}, {"STEP_W", 16}, {"DFRAC_W", 8}, {"PULSE_W", 8},
                               {"POS_W", 16}}));
  const json& r = j["axes"][0]["registers"];
  // 5000 steps from and to 2e4 steps/s, up at a = 5000 and down at d = 2500, stay below 1e5: the
  // triangle peaks at sqrt((2 a d N + (a + d) v0^2) / (a + d)) = 20412.41 steps/s, register
  // 20412.41 / 375000 * 2^64 = 1.0041135644e18 (the quantized ramps lower it by a few 1e-9).
  const double vmax = r["v_max"].get<uint64_t>();
  EXPECT_LE(vmax, 1004113564362176128.0);
  EXPECT_GE(vmax, 1004113564362176128.0 * (1 - 1e-7));
  EXPECT_EQ(r["v_end"].get<uint64_t>(), 983826350597842752u);     // 2e4 / 375000 * 2^64 (exact)
  EXPECT_EQ(r["acc"].get<uint64_t>(), 655884233731u);             // 5000 / 375000^2 * 2^64 = 655884233731.4
  EXPECT_EQ(r["dec"].get<uint64_t>(), 327942116865u);             // 2500 / 375000^2 * 2^64 = 327942116865.7
  EXPECT_LE(r["dec_frac"].get<uint64_t>(), 255u);
  // The default build: no widths object.
  EXPECT_FALSE(plan_json(base).contains("widths"));
  // The job and the C header record them.
  args.insert(args.end(), {"--format", "job"});
  const Result job = plan(args);
  ASSERT_EQ(job.rc, 0) << job.err;
  EXPECT_EQ(json::parse(job.out)["widths"]["ACC_W"], 40);
  args.back() = "c";
  const Result c = plan(args);
  ASSERT_EQ(c.rc, 0) << c.err;
  EXPECT_NE(c.out.find("#define HEXSTEP_PLAN_SPEED_W 64\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("#define HEXSTEP_PLAN_ACC_W 40\n"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("#define HEXSTEP_PLAN_DFRAC_W 8\n"), std::string::npos) << c.out;
  EXPECT_EQ(c.out.find("OWE_W"), std::string::npos) << c.out;
  // Ranges follow the widths; each error names the flag and the range.
  auto with = [&](std::vector<std::string> more, const std::string& w) {
    std::vector<std::string> a = base;
    for (size_t i = 0; i + 1 < a.size(); i += 2)
      for (size_t k = 0; k + 1 < more.size(); k += 2)
        if (a[i] == more[k]) {
          a[i + 1] = more[k + 1];
          more[k].clear();
        }
    for (size_t k = 0; k + 1 < more.size(); k += 2)
      if (!more[k].empty()) a.insert(a.end(), {more[k], more[k + 1]});
    a.insert(a.end(), {"--widths", w});
    return a;
  };
  expect_error(with({"--step-high", "256"}, wid), 2, {"--step-high", "[0, 255] clock cycles (PULSE_W = 8 bits"});
  expect_error(with({"--steps", "65536"}, wid), 2, {"--steps", "[0, 65535]"});
  // 10^4 steps/s^2 is above the largest ACC value (8381.9 steps/s^2) at ACC_W 40 and 12 MHz; the
  // default ACC_W 48 takes it.
  expect_error(with({"--accel", "1e4"}, wid), 2, {"--accel", "cannot be represented", "8381.9"});
  EXPECT_EQ(plan(with({"--accel", "1e4"}, "STEP_W=16")).rc, 0);
  // SPEED_W is fixed at 64: any other value names the field and its only value.
  expect_error(with({}, "SPEED_W=24"), 2, {"--widths SPEED_W", "[64, 64]", "got 24"});
  expect_error(with({}, "SPEED_W=65"), 2, {"--widths SPEED_W", "[64, 64]", "got 65"});
  EXPECT_EQ(plan(with({}, "SPEED_W=64")).rc, 0);
  expect_error(with({}, "ACC_W=65"), 2, {"--widths ACC_W", "[1, 64]", "got 65"});
  expect_error(with({}, "PULSE_W=17"), 2, {"--widths PULSE_W", "[1, 16]", "got 17"});
  expect_error(with({}, "ACC_W=30,ACC_W=31"), 2, {"--widths", "each at most once", "'ACC_W=31'"});
  expect_error(with({}, "FOO_W=3"), 2, {"--widths", "NAME one of SPEED_W", "'FOO_W=3'"});
  // OWE_W was a width of the old output stage; it is not accepted any more.
  expect_error(with({}, "OWE_W=2"), 2, {"--widths", "NAME one of SPEED_W", "'OWE_W=2'"});
  expect_error(with({}, "SPEED_W=x"), 2, {"--widths SPEED_W", "got 'x'"});
}

TEST_F(Plan, OutFileAndFormats) {
  const std::vector<std::string> move = {"--steps", "-700", "--max-speed", "5000", "--accel", "100000"};
  for (const char* fmt : {"json", "c", "csv", "job"}) {
    std::vector<std::string> args = move;
    args.push_back("--format");
    args.push_back(fmt);
    const Result to_stdout = plan(args);
    EXPECT_EQ(to_stdout.rc, 0) << to_stdout.err;
    args.push_back("--out");
    args.push_back(tmp(std::string("plan.") + fmt));
    const Result to_file = plan(args);
    EXPECT_EQ(to_file.rc, 0) << to_file.err;
    EXPECT_EQ(to_file.out, "") << fmt;
    EXPECT_EQ(slurp(tmp(std::string("plan.") + fmt)), to_stdout.out) << fmt;
  }
  // The job's move is the JSON's registers.
  const json plan_j = json::parse(slurp(tmp("plan.json")));
  const json job = json::parse(slurp(tmp("plan.job")));
  EXPECT_EQ(job["format"], "hexstep-job");
  EXPECT_EQ(job["axes"][0]["moves"][0], plan_j["axes"][0]["registers"]);
  // CSV: the documented header and one line per axis.
  const std::string csv = slurp(tmp("plan.csv"));
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "axis,profile,dir,total_steps,accel_steps,cruise_steps,decel_steps,start_speed_steps_per_s,"
            "peak_speed_steps_per_s,end_speed_steps_per_s,accel_steps_per_s2,decel_steps_per_s2,t_accel_s,"
            "t_cruise_s,t_decel_s,duration_s,executed_peak_speed_steps_per_s,executed_duration_s,warning");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2);
  EXPECT_EQ(csv.find("\n0,trapezoidal,0,-700,"), csv.find('\n'));
  // C header: include guard, stdint, the register values.
  const std::string c = slurp(tmp("plan.c"));
  EXPECT_NE(c.find("#ifndef HEXSTEP_PLAN_H"), std::string::npos);
  EXPECT_NE(c.find("#include <stdint.h>"), std::string::npos);
  EXPECT_NE(c.find("#define HEXSTEP_PLAN_CLOCK_HZ UINT64_C(100000000)"), std::string::npos);
  EXPECT_NE(c.find("UINT64_C(" + std::to_string(plan_j["axes"][0]["registers"]["v_max"].get<uint64_t>()) + ")"),
            std::string::npos);
}

const char* const kRequest = R"({
  "format": "hexstep-plan-request", "version": 1, "clock_hz": 10000000, "mode": "MODE",
  "axes": [
    {"axis": 3, "steps": -300, "max_speed": 2000, "accel": 20000},
    {"axis": 0, "distance": 10, "unit": "mm", "steps_per_rev": 200, "pitch_mm": 2,
     "max_speed": 20, "accel": 200, "pulse": {"step_high": 2, "step_low": 2, "dir_setup": 1, "dir_hold": 1}},
    {"axis": 5, "distance": 90, "unit": "deg", "steps_per_rev": 400, "max_speed": 360, "accel": 3600,
     "ratio": 2}
  ]
})";

std::string request(const std::string& mode) {
  std::string r = kRequest;
  r.replace(r.find("MODE"), 4, mode);
  return r;
}

TEST_F(Plan, RequestIndependent) {
  const json j = plan_json({"--job", write("req.json", request("independent"))});
  EXPECT_EQ(j["mode"], "independent");
  EXPECT_EQ(j["clock_hz"].get<uint64_t>(), 10000000u);
  ASSERT_EQ(j["axes"].size(), 3u);
  // Sorted by axis; each as if planned alone on the command line.
  EXPECT_EQ(j["axes"][0]["axis"], 0);
  EXPECT_EQ(j["axes"][1]["axis"], 3);
  EXPECT_EQ(j["axes"][2]["axis"], 5);
  EXPECT_EQ(j["axes"][0]["steps"]["total"], 1000);  // 10 mm * 200 / 2
  EXPECT_EQ(j["axes"][1]["steps"]["total"], -300);
  EXPECT_EQ(j["axes"][2]["steps"]["total"], 100);  // 90 deg * 400 / 360
  EXPECT_EQ(j["axes"][0]["pulse"]["step_high"], 2);
  const json alone = plan_json({"--steps", "-300", "--max-speed", "2000", "--accel", "20000", "--axis", "3",
                                "--clock-hz", "10000000"});
  EXPECT_EQ(j["axes"][1]["registers"], alone["axes"][0]["registers"]);
  double longest = 0;
  for (const json& a : j["axes"]) {
    check_axis_shape(a);
    longest = std::max(longest, a["duration_s"].get<double>());
  }
  EXPECT_EQ(j["duration_s"].get<double>(), longest);
  // A time budget per axis.
  std::string r = request("independent");
  r.replace(r.find("\"accel\": 20000"), 14, "\"accel\": 20000, \"time\": 2");
  const json t = plan_json({"--job", write("req_t.json", r)});
  near_rel(t["axes"][1]["duration_s"].get<double>(), 2, 1e-9, "timed axis");
}

TEST_F(Plan, RequestLine) {
  const json j = plan_json({"--job", write("req.json", request("line"))});
  EXPECT_EQ(j["mode"], "line");
  ASSERT_EQ(j["axes"].size(), 3u);
  // Every axis takes the same time, and its speeds are proportional to its distance.
  const json& lead = j["axes"][0];  // axis 0, 1000 steps: the longest
  for (const json& a : j["axes"]) {
    check_axis_shape(a);
    near_rel(a["duration_s"].get<double>(), j["duration_s"].get<double>(), 1e-12, "same duration");
    const double r = std::fabs(a["steps"]["total"].get<double>()) / 1000.0;
    near_rel(a["peak_speed_steps_per_s"].get<double>(), lead["peak_speed_steps_per_s"].get<double>() * r, 1e-9,
             "proportional peak");
  }
  EXPECT_EQ(j["path"]["steps"], 1000);
  // In steps: axis 0 1000 steps, 2000 steps/s, 20000 steps/s^2 each way (1 mm = 100 steps);
  // axis 3 300 steps, 2000, 20000; axis 5 100 steps, 400 steps/s, 4000 up and 2000 down (1 deg =
  // 10/9 steps). Path limits (L = 1000): speed min(2000, 2000/0.3, 400/0.1) = 2000, accel
  // min(20000, 20000/0.3, 4000/0.1) = 20000, decel min(20000, 20000/0.3, 2000/0.1) = 20000:
  // 100 steps up in 0.1 s, 800 cruising in 0.4 s, 100 down in 0.1 s.
  near_rel(lead["peak_speed_steps_per_s"].get<double>(), 2000, 1e-12, "path peak");
  near_rel(lead["duration_s"].get<double>(), 0.6, 1e-9, "line duration");
  EXPECT_EQ(lead["steps"], (json{{"accel", 100}, {"cruise", 800}, {"decel", 100}, {"total", 1000}}));
  // No time budget on a line.
  std::string r = request("line");
  r.replace(r.find("\"accel\": 20000"), 14, "\"accel\": 20000, \"time\": 2");
  expect_error({"--job", write("req_t.json", r)}, 2, {"axes[0].time", "\"line\""});
}

TEST_F(Plan, RequestErrors) {
  auto with = [&](const std::string& from, const std::string& to) {
    std::string r = request("independent");
    r.replace(r.find(from), from.size(), to);
    return write("bad.json", r);
  };
  expect_error({"--job", with("\"max_speed\": 2000", "\"max_sped\": 2000")}, 2,
               {"bad.json: axes[0].max_sped: unknown field (accepted here:"});
  expect_error({"--job", with("\"dir_hold\": 1", "\"dir_hold\": 1, \"dir_hld\": 1")}, 2, {"axes[1].pulse.dir_hld: unknown field"});
  expect_error({"--job", with("\"mode\"", "\"mood\"")}, 2, {"mood: unknown field"});
  expect_error({"--job", with("\"max_speed\": 2000", "\"max_speed\": -2000")}, 2, {"axes[0].max_speed", "> 0"});
  expect_error({"--job", with("\"max_speed\": 2000", "\"max_speed\": 2000, \"start_speed\": 2500")}, 2,
               {"axes[0].start_speed: must be in [0, max_speed = 2000]"});
  expect_error({"--job", with("\"max_speed\": 2000", "\"max_speed\": \"fast\"")}, 2, {"axes[0].max_speed", "number"});
  expect_error({"--job", with("\"steps\": -300", "\"steps\": -300, \"distance\": 3")}, 2,
               {"axes[0].distance", "not both"});
  expect_error({"--job", with("\"ratio\": 2", "\"ratio\": 2, \"decel\": 5")}, 2, {"axes[2].ratio", "not both"});
  expect_error({"--job", with("\"unit\": \"deg\"", "\"unit\": \"grad\"")}, 2, {"axes[2].unit", "steps, rev, deg, rad, mm"});
  expect_error({"--job", with("\"pitch_mm\": 2", "\"pitch_mm\": 0")}, 2, {"axes[1].pitch_mm", "> 0"});
  expect_error({"--job", with("\"steps_per_rev\": 200, \"pitch_mm\": 2", "\"pitch_mm\": 2")}, 2,
               {"axes[1].steps_per_rev: is required for unit mm with pitch_mm"});
  expect_error({"--job", with("\"axis\": 5", "\"axis\": 3")}, 2, {"axes[2].axis", "unique"});
  expect_error({"--job", with("\"axis\": 5", "\"axis\": 6")}, 2, {"axes[2].axis: must be an integer in [0, 5]"});
  expect_error({"--job", with("\"accel\": 20000", "\"accel\": 20000, \"accel\": 1")}, 2, {"axes[0].accel: duplicate field"});
  expect_error({"--job", with("\"accel\": 20000", "\"accel\": 1e-9")}, 2,
               {"axes[0].accel", "cannot be represented at clock_hz 10000000"});
  expect_error({"--job", with("\"accel\": 20000", "\"accel\": 20000, \"time\": 0.01")}, 3,
               {"axes[0].time", "minimum achievable time"});
  expect_error({"--job", with("\"max_speed\": 2000", "\"max_speed\": 6000000, \"start_speed\": 6000000")}, 2,
               {"axes[0].max_speed", "pulse stage", "[0, 5000000] steps/s"});
  expect_error({"--job", with("\"version\": 1", "\"version\": 2")}, 2, {"version: must be an integer in [1, 1]"});
  expect_error({"--job", with("hexstep-plan-request", "hexstep-job")}, 2, {"format: must be the string"});
  expect_error({"--job", with("\"mode\": \"independent\"", "\"mode\": \"circle\"")}, 2, {"mode: must be"});
  expect_error({"--job", with("\"clock_hz\": 10000000", "\"clock_hz\": 0")}, 2, {"clock_hz: must be an integer in [1, 10000000000]"});
  expect_error({"--job", write("trunc.json", "{\"format\": ")}, 2, {"malformed JSON"});
  expect_error({"--job", tmp("does_not_exist.json")}, 2, {"cannot open"});
  expect_error({"--job", "-"}, 2, {"<stdin>: axes: must be an array of 1 to 6"},
               R"({"format": "hexstep-plan-request", "version": 1, "axes": []})");
  // Command-line flags that belong in the file.
  const std::string good = write("good.json", request("independent"));
  expect_error({"--job", good, "--max-speed", "5"}, 2, {"--max-speed: cannot be combined with --job"});
  expect_error({"--job", good, "--step-low", "5"}, 2, {"--step-low: cannot be combined with --job"});
  expect_error({"--job", good, "--clock-hz", "1000"}, 2, {"--clock-hz", "contradicts clock_hz 10000000"});
  EXPECT_EQ(plan({"--job", good, "--clock-hz", "10000000"}).rc, 0);
}

struct ErrorCase {
  std::vector<std::string> args;
  int rc;
  std::vector<std::string> texts;
};

TEST_F(Plan, CommandLineErrors) {
  const std::vector<std::string> ok = {"--steps", "1000", "--max-speed", "1000", "--accel", "1000"};
  auto but = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = ok;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const std::vector<ErrorCase> cases = {
      // Negative, zero, NaN, infinite, not a number.
      {{"--steps", "1000", "--max-speed", "-1", "--accel", "1000"}, 2, {"--max-speed: must be a finite number > 0"}},
      {{"--steps", "1000", "--max-speed", "0", "--accel", "1000"}, 2, {"--max-speed: must be a finite number > 0"}},
      {{"--steps", "1000", "--max-speed", "1000", "--accel", "0"}, 2, {"--accel: must be a finite number > 0"}},
      {{"--steps", "1000", "--max-speed", "1000", "--accel", "nan"}, 2, {"--accel: must be a finite number > 0"}},
      {{"--steps", "1000", "--max-speed", "inf", "--accel", "1000"}, 2, {"--max-speed: must be a finite number > 0"}},
      {{"--steps", "1000", "--max-speed", "1000", "--accel", "fast"}, 2, {"--accel: must be a number"}},
      {but({"--decel", "-5"}), 2, {"--decel: must be a finite number > 0"}},
      {but({"--ratio", "0"}), 2, {"--ratio: must be a finite number > 0"}},
      {but({"--start-speed", "-1"}), 2, {"--start-speed: must be a finite number >= 0"}},
      {but({"--end-speed", "nan"}), 2, {"--end-speed: must be a finite number >= 0"}},
      {but({"--time", "0"}), 2, {"--time: must be a finite number > 0"}},
      {but({"--time=-inf"}), 2, {"--time: must be a finite number > 0"}},
      {{"--distance", "nan", "--max-speed", "1000", "--accel", "1000"}, 2, {"--distance: must be a finite number"}},
      // Start or end speed above the maximum speed.
      {but({"--start-speed", "1000.5"}), 2, {"--start-speed: must be in [0, --max-speed = 1000]"}},
      {but({"--end-speed", "2000"}), 2, {"--end-speed: must be in [0, --max-speed = 1000]"}},
      // Units and scale factors.
      {{"--distance", "1", "--unit", "furlong", "--max-speed", "1", "--accel", "1"}, 2, {"--unit: must be one of steps, rev, deg, rad, mm"}},
      {{"--distance", "1", "--unit", "rev", "--max-speed", "1", "--accel", "1"}, 2, {"--steps-per-rev: is required for --unit rev"}},
      {{"--distance", "1", "--unit", "deg", "--max-speed", "1", "--accel", "1"}, 2, {"--steps-per-rev: is required for --unit deg"}},
      {{"--distance", "1", "--unit", "mm", "--max-speed", "1", "--accel", "1"}, 2, {"--steps-per-mm: is required for --unit mm"}},
      {{"--distance", "1", "--unit", "mm", "--steps-per-rev", "200", "--max-speed", "1", "--accel", "1"}, 2, {"--pitch-mm: is required"}},
      {{"--distance", "1", "--unit", "rev", "--steps-per-rev", "-200", "--max-speed", "1", "--accel", "1"}, 2, {"--steps-per-rev: must be a finite number > 0"}},
      {{"--distance", "1", "--unit", "mm", "--steps-per-mm", "10", "--steps-per-rev", "200", "--pitch-mm", "2", "--max-speed", "1", "--accel", "1"}, 2, {"--steps-per-mm", "disagrees"}},
      // Contradictions and missing values.
      {but({"--distance", "5"}), 2, {"--distance: give either --steps N or --distance D, not both"}},
      {but({"--decel", "5", "--ratio", "2"}), 2, {"--ratio: give either --decel or --ratio"}},
      {but({"--time", "5", "--decel", "500"}), 2, {"--decel: a move with --time decelerates at its acceleration"}},
      {but({"--time", "5", "--ratio", "2"}), 2, {"--ratio: a move with --time"}},
      {but({"--time", "5", "--end-speed", "10"}), 2, {"--end-speed: a move with --time ends at --start-speed"}},
      {{"--max-speed", "1000", "--accel", "1000"}, 2, {"--steps: the move needs --steps N or --distance D"}},
      {{"--steps", "10", "--accel", "1000"}, 2, {"--max-speed: is required"}},
      {{"--steps", "10", "--max-speed", "1000"}, 2, {"--accel: is required"}},
      // Integers and their ranges.
      {{"--steps", "4294967296", "--max-speed", "1", "--accel", "1"}, 2, {"--steps: must be an integer in [-4294967295, 4294967295]"}},
      {{"--steps", "1.5", "--max-speed", "1", "--accel", "1"}, 2, {"--steps: must be an integer"}},
      {{"--distance", "1e10", "--max-speed", "1", "--accel", "1"}, 2, {"--distance:", "at most 4294967295 steps"}},
      {but({"--axis", "6"}), 2, {"--axis: must be an integer in [0, 5]"}},
      {but({"--axis", "-1"}), 2, {"--axis: must be an integer in [0, 5]"}},
      {but({"--clock-hz", "0"}), 2, {"--clock-hz: must be an integer in [1, 10000000000]"}},
      {but({"--clock-hz", "1.5"}), 2, {"--clock-hz: must be an integer in [1, 10000000000]"}},
      {but({"--step-high", "4096"}), 2, {"--step-high: must be an integer in [0, 4095]"}},
      {but({"--step-low", "-1"}), 2, {"--step-low: must be an integer in [0, 4095]"}},
      {but({"--dir-setup", "x"}), 2, {"--dir-setup: must be an integer in [0, 4095]"}},
      {but({"--dir-hold", "5000"}), 2, {"--dir-hold: must be an integer in [0, 4095]"}},
      {but({"--format", "xml"}), 2, {"--format"}},
      // Out of range for the registers at this clock.
      // At 100 MHz (ft = 3.125e6 ticks/s) accelerations hold [ft^2 / 2^64, (2^48 - 1) ft^2 / 2^64]
      // = [5.29395592e-07, 1.49011612e8] steps/s^2 and speeds [ft / 2^64 = 1.69e-13, ft).
      {{"--steps", "1000", "--max-speed", "1000", "--accel", "1e-7"}, 2,
       {"--accel: 1e-07 steps/s^2 cannot be represented at --clock-hz 100000000: must be in [5.29395592e-07, 149011612] steps/s^2"}},
      {{"--steps", "1000", "--max-speed", "1000", "--accel", "1.5e8"}, 2, {"--accel:", "cannot be represented", "149011612]"}},
      {{"--steps", "1000", "--max-speed", "1000", "--accel", "1000", "--ratio", "1e10"}, 2, {"--decel:", "cannot be represented"}},
      {{"--steps", "1000", "--max-speed", "1e-13", "--accel", "1"}, 2, {"--max-speed:", "cannot be represented", "[1.69406589e-13, "}},
      {{"--steps", "1000", "--start-speed", "3.2e6", "--max-speed", "3.2e6", "--accel", "1"}, 2,
       {"--start-speed:", "cannot be represented", "[0, 3125000) steps/s"}},
      {{"--steps", "1000", "--max-speed", "10", "--accel", "1e8", "--clock-hz", "1000"}, 2, {"--accel:", "--clock-hz 1000"}},
      // Pulse rate: at most F / (high + low) = 50 MHz with the default 1 + 1 cycles.
      {{"--steps", "1000", "--start-speed", "6e7", "--max-speed", "6e7", "--accel", "1"}, 2,
       {"--max-speed:", "pulse stage", "[0, 50000000] steps/s"}},
      {{"--steps", "1000", "--start-speed", "3e7", "--max-speed", "3e7", "--accel", "1", "--step-high", "2", "--step-low", "2"}, 2,
       {"--max-speed:", "[0, 25000000] steps/s"}},
      // Output file that cannot be created.
      {but({"--out", "/nonexistent-dir/x/plan.json"}), 2, {"--out: cannot open"}},
  };
  for (const ErrorCase& c : cases) expect_error(c.args, c.rc, c.texts);
}

TEST_F(Plan, HelpExplainsEveryFlag) {
  const Result r = plan({"--help"});
  EXPECT_EQ(r.rc, 0);
  for (const char* f : {"--steps", "--distance", "--unit", "--steps-per-rev", "--steps-per-mm", "--pitch-mm",
                        "--start-speed", "--end-speed", "--max-speed", "--accel", "--decel", "--ratio", "--time",
                        "--clock-hz", "--axis", "--job", "--format", "--out", "--step-high", "--step-low",
                        "--dir-setup", "--dir-hold", "--widths", "UNIT/s", "UNIT/s^2", "clock cycles", "Exit status"})
    EXPECT_NE(r.out.find(f), std::string::npos) << f;
}

}  // namespace
