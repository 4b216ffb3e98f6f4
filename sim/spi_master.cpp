// SPDX-License-Identifier: Apache-2.0
// hexstep: SPI master bus-functional model (see spi_master.hpp).
#include "spi_master.hpp"

#include <stdexcept>

namespace hexstep {
namespace spi {

uint8_t crc8(const uint8_t* p, size_t n) {
  uint8_t c = 0;
  for (size_t i = 0; i < n; ++i)
    for (int b = 7; b >= 0; --b) {
      const bool in = (p[i] >> b) & 1u;
      const bool top = (c >> 7) & 1u;
      c = static_cast<uint8_t>(c << 1);
      if (top != in) c ^= 0x07;
    }
  return c;
}

std::vector<uint8_t> write_frame(uint32_t adr, uint32_t dat, unsigned sel) {
  std::vector<uint8_t> f = {static_cast<uint8_t>(kCmdWrite | (sel & 0xFu)),
                            static_cast<uint8_t>(adr >> 8), static_cast<uint8_t>(adr),
                            static_cast<uint8_t>(dat >> 24), static_cast<uint8_t>(dat >> 16),
                            static_cast<uint8_t>(dat >> 8), static_cast<uint8_t>(dat)};
  f.push_back(crc8(f.data(), f.size()));
  return f;
}

std::vector<uint8_t> read_frame(uint32_t adr) {
  std::vector<uint8_t> f = {kCmdRead, static_cast<uint8_t>(adr >> 8), static_cast<uint8_t>(adr)};
  f.push_back(crc8(f.data(), f.size()));
  f.resize(kReadBytes, 0x00);
  return f;
}

}  // namespace spi

SpiMaster::SpiMaster(SpiPins& dut, uint32_t seed, unsigned min_half, unsigned max_half)
    : dut_(dut), rng_(seed), min_half_(min_half), max_half_(max_half) {
  dut_.set_pins(false, true, false);
}

void SpiMaster::set_timing(unsigned min_half, unsigned max_half) {
  min_half_ = min_half;
  max_half_ = max_half;
}

void SpiMaster::wait_half() {
  const unsigned n = std::uniform_int_distribution<unsigned>(min_half_, max_half_)(rng_);
  for (unsigned i = 0; i < n; ++i) dut_.tick();
}

std::vector<uint8_t> SpiMaster::transfer(const std::vector<uint8_t>& mosi, long bits) {
  const size_t n = bits < 0 ? mosi.size() * 8 : static_cast<size_t>(bits);
  std::vector<uint8_t> in((n + 7) / 8, 0);
  auto bit = [&](size_t i) { return i / 8 < mosi.size() && ((mosi[i / 8] >> (7 - i % 8)) & 1u); };
  // Mode 0: CS_N falls with the first MOSI bit set up, the slave samples on the rising SCK edge
  // and changes MISO after the falling one; the master samples MISO at its rising edge.
  dut_.set_pins(false, false, bit(0));
  wait_half();
  for (size_t i = 0; i < n; ++i) {
    if (dut_.miso()) in[i / 8] |= static_cast<uint8_t>(0x80u >> (i % 8));
    dut_.set_pins(true, false, bit(i));
    wait_half();
    dut_.set_pins(false, false, i + 1 < n ? bit(i + 1) : false);
    wait_half();
  }
  dut_.set_pins(false, true, false);
  wait_half();
  ++frames_;
  return in;
}

void SpiMaster::cs_pulse() { transfer({}, 0); }

uint8_t SpiMaster::write(uint32_t adr, uint32_t dat, unsigned sel) {
  const auto in = transfer(spi::write_frame(adr, dat, sel));
  last_status_ = in[0];
  return in[0];
}

bool SpiMaster::read(uint32_t adr, uint32_t& dat) {
  const auto f = spi::read_frame(adr);
  const auto in = transfer(f);
  last_status_ = in[0];
  last_rstat_ = in[4];
  dat = (uint32_t{in[5]} << 24) | (uint32_t{in[6]} << 16) | (uint32_t{in[7]} << 8) | in[8];
  const uint8_t msg[7] = {f[0], f[1], f[2], in[5], in[6], in[7], in[8]};
  return in[4] == spi::kStatusOk && in[9] == spi::crc8(msg, sizeof msg);
}

uint32_t SpiMaster::read(uint32_t adr) {
  uint32_t d = 0;
  if (!read(adr, d)) throw std::runtime_error("spi read failed");
  return d;
}

uint8_t SpiMaster::status() {
  const auto in = transfer({0x00}, 8);
  last_status_ = in[0];
  return in[0];
}

}  // namespace hexstep
