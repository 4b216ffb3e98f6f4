// SPDX-License-Identifier: Apache-2.0
// hexstep: JSON parsing for the project's input files (jobs, planning requests): nlohmann-json
// with duplicate keys refused and errors reduced to one line. Needs nlohmann_json.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace hexstep {

// path(): JSON path of the offending field ("axes[1].moves[0].steps"), empty for malformed JSON.
class StrictJsonError : public std::runtime_error {
 public:
  StrictJsonError(std::string path, const std::string& msg)
      : std::runtime_error(msg), path_(std::move(path)) {}
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Parses `text`; a key repeated within one object is an error naming its path.
inline nlohmann::json parse_strict_json(const std::string& text) {
  using json = nlohmann::json;
  struct Frame {
    bool array = false;
    size_t index = 0;  // arrays: elements completed so far
    std::string key;   // objects: the last key read
    std::set<std::string> keys;
  };
  std::vector<Frame> st;
  auto path_of = [&st](const std::string& key) {
    std::string p;
    for (size_t i = 0; i + 1 < st.size(); ++i) {
      if (st[i].array) p += "[" + std::to_string(st[i].index) + "]";
      else p += (p.empty() ? "" : ".") + st[i].key;
    }
    return p + (p.empty() ? "" : ".") + key;
  };
  auto cb = [&](int, json::parse_event_t ev, json& parsed) -> bool {
    switch (ev) {
      case json::parse_event_t::object_start: st.push_back(Frame{}); break;
      case json::parse_event_t::array_start: st.push_back(Frame{true, 0, {}, {}}); break;
      case json::parse_event_t::key: {
        Frame& f = st.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second)
          throw StrictJsonError(path_of(f.key), "duplicate field (each field may appear only once)");
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        st.pop_back();
        if (!st.empty() && st.back().array) ++st.back().index;
        break;
      case json::parse_event_t::value:
        if (!st.empty() && st.back().array) ++st.back().index;
        break;
    }
    return true;
  };
  try {
    return json::parse(text, cb);
  } catch (const json::exception& e) {
    // "[json.exception.parse_error.101] parse error at line 1, column 2: ..." -> drop the tag.
    std::string what = e.what();
    const size_t tag = what.find("] ");
    if (what.rfind("[json.exception.", 0) == 0 && tag != std::string::npos) what = what.substr(tag + 2);
    for (char& c : what)
      if (c == '\n' || c == '\r') c = ' ';
    const auto* pe = dynamic_cast<const json::parse_error*>(&e);
    throw StrictJsonError("", "malformed JSON" +
                                  (pe ? " at byte " + std::to_string(pe->byte) : std::string()) + ": " + what);
  }
}

}  // namespace hexstep
