// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the strict JSON reader (cpp_model/include/hexstep/strict_json.hpp).
// Oracle: plain nlohmann::json::parse as the reference. Strict accepts => plain accepts the
// same value; plain refuses => strict refuses; strict refuses valid JSON only for a duplicate
// key; an error has a path exactly when it is a duplicate key. Every message
// is one line; only StrictJsonError may leave the reader. JsonObject's unknown-field check runs
// on accepted objects.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "hexstep/strict_json.hpp"

using namespace hexstep;
using hexstep::fuzz::check;
using json = nlohmann::json;

namespace {
struct ObjectError {
  std::string path, msg;
};
void object_fail(const std::string& path, const std::string& msg) { throw ObjectError{path, msg}; }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  json plain;
  bool plain_ok = true;
  try {
    plain = json::parse(text);
  } catch (const json::exception&) {
    plain_ok = false;
  }
  json strict;
  try {
    strict = parse_strict_json(text);
  } catch (const StrictJsonError& e) {
    fuzz::check_one_line(e.what(), "parse_strict_json");
    // A path only for a duplicate key (which may come before a syntax error later in the
    // text: the first error found is reported); valid JSON is refused only for a duplicate.
    const std::string msg = e.what();
    const bool dup = msg.rfind("duplicate field", 0) == 0;
    check(dup || msg.rfind("malformed JSON", 0) == 0, "unexpected error message: " + msg);
    check(e.path().empty() != dup, "error path and kind disagree: " + e.path() + ": " + msg);
    if (plain_ok) check(dup, std::string("valid JSON refused for something other than a duplicate key: ") + e.what());
    return 0;
  }
  check(plain_ok, "parse_strict_json accepted what nlohmann::json::parse refuses");
  check(strict == plain, "parse_strict_json and nlohmann::json::parse disagree on the value");
  fuzz::check_one_line(json_got(strict), "json_got");
  if (strict.is_object()) {
    try {
      JsonObject o(strict, "", "an object", {"format", "version", "axes"}, object_fail);
      o.reject_unknown();
      for (const char* f : {"format", "version", "axes"})
        check(o.opt(f) == nullptr ? !strict.contains(f) : strict.contains(f), "JsonObject::opt disagrees");
    } catch (const ObjectError& e) {
      check(!e.path.empty(), "JsonObject error without a path");
      fuzz::check_one_line(e.msg, "JsonObject");
    }
  }
  return 0;
}
