// SPDX-License-Identifier: Apache-2.0
// hexstep: JSON reading for the project's input files (jobs, planning requests): nlohmann-json
// with duplicate keys refused, one-line errors that name the field's path, and an object reader
// that refuses unknown fields. Needs nlohmann_json.
#pragma once

#include <set>
#include <stdexcept>
#include <string>
#include <utility>
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

// A key as it may appear in a one-line message: control characters become '?', "" stands for
// the empty key.
inline std::string printable_key(std::string key) {
  if (key.empty()) return "\"\"";  // an empty key is named by its quotes
  for (char& c : key)
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  return key;
}

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
      else p += (p.empty() ? "" : ".") + printable_key(st[i].key);
    }
    return p + (p.empty() ? "" : ".") + printable_key(key);
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

// "got ..." text for a JSON value in an error message, kept short and on one line.
inline std::string json_got(const nlohmann::json& v) {
  using json = nlohmann::json;
  switch (v.type()) {
    case json::value_t::null: return "got null";
    case json::value_t::boolean: return v.get<bool>() ? "got true" : "got false";
    case json::value_t::object: return "got an object";
    case json::value_t::array: return "got an array";
    case json::value_t::number_float:
      return "got " + v.dump() + " (a floating-point number, not an integer literal)";
    case json::value_t::string: {
      std::string s = v.dump();  // quoted and escaped, so one line
      if (s.size() > 42) s = s.substr(0, 40) + "...\"";
      return "got the string " + s;
    }
    default: return "got " + v.dump();
  }
}

// Reports an error at a JSON path; must throw (each file format has its own error type).
using JsonFail = void (*)(const std::string& path, const std::string& msg);

// One JSON object being read: type check, unknown and missing fields, paths of its members.
class JsonObject {
 public:
  JsonObject(const nlohmann::json& j, std::string path, const char* what,
             std::vector<const char*> fields, JsonFail fail)
      : j_(j), path_(std::move(path)), fields_(std::move(fields)), fail_(fail) {
    if (!j_.is_object())
      error(path_.empty() ? "(top level)" : path_, std::string("must be ") + what + ", " + json_got(j_));
  }
  void reject_unknown() const {
    for (auto it = j_.begin(); it != j_.end(); ++it) {
      bool known = false;
      for (const char* f : fields_) known = known || it.key() == f;
      if (!known) {
        std::string list;
        for (const char* f : fields_) list += (list.empty() ? "" : ", ") + std::string(f);
        error(sub(printable_key(it.key())), "unknown field (accepted here: " + list + ")");
      }
    }
  }
  const nlohmann::json* opt(const char* key) const {
    auto it = j_.find(key);
    return it == j_.end() ? nullptr : &*it;
  }
  // `accepts` completes "it ..." in the message for a missing field.
  const nlohmann::json& req(const char* key, const std::string& accepts) const {
    const nlohmann::json* v = opt(key);
    if (!v) error(sub(key), "required field is missing; it " + accepts);
    return *v;
  }
  std::string sub(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  [[noreturn]] void error(const std::string& path, const std::string& msg) const {
    fail_(path, msg);
    throw std::logic_error("JsonFail returned");
  }
  const nlohmann::json& j_;
  std::string path_;
  std::vector<const char*> fields_;
  JsonFail fail_;
};

}  // namespace hexstep
