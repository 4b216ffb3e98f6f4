// SPDX-License-Identifier: Apache-2.0
#include "common.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace hexstep::cli {

std::string input_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::string read_input(const std::string& path) {
  std::ostringstream ss;
  if (path == "-") {
    ss << std::cin.rdbuf();
    if (std::cin.bad()) throw CliError(kExitUsage, "cannot read <stdin>");
    return ss.str();
  }
  std::ifstream f(path, std::ios::binary);
  if (!f) throw CliError(kExitUsage, "cannot open " + path + ": " + std::strerror(errno));
  ss << f.rdbuf();
  if (f.bad()) throw CliError(kExitUsage, "cannot read " + path + ": " + std::strerror(errno));
  return ss.str();
}

void write_stdout(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    throw CliError(kExitInternal, std::string("cannot write to stdout: ") + std::strerror(errno));
}

void write_output(const std::string& path, const std::string& text, const std::string& flag) {
  if (path.empty() || path == "-") return write_stdout(text);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw CliError(kExitUsage, flag + ": cannot open " + path + " for writing: " + std::strerror(errno));
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const int err = errno;
  if (std::fclose(f) != 0 || !ok) {
    std::remove(path.c_str());
    throw CliError(kExitInternal, flag + ": cannot write " + path + ": " + std::strerror(ok ? errno : err));
  }
}

std::string format_seconds(uint64_t cycle, uint64_t clock_hz) {
  using u128 = unsigned __int128;
  unsigned d = 0;
  uint64_t scale = 1;  // 10^d
  while (scale < clock_hz) {
    scale *= 10;
    ++d;
  }
  uint64_t whole = cycle / clock_hz;
  const uint64_t rem = cycle % clock_hz;
  // frac = round(rem * 10^d / clock_hz); rem < clock_hz <= 10^d <= 10^10 fits easily in 128 bits.
  uint64_t frac = static_cast<uint64_t>((u128(rem) * scale * 2 + clock_hz) / (u128(clock_hz) * 2));
  if (frac >= scale) {
    frac -= scale;
    ++whole;
  }
  char buf[64];
  if (d == 0)
    std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(whole));
  else
    std::snprintf(buf, sizeof buf, "%llu.%0*llu", static_cast<unsigned long long>(whole),
                  static_cast<int>(d), static_cast<unsigned long long>(frac));
  return buf;
}

}  // namespace hexstep::cli
