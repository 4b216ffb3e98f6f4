// SPDX-License-Identifier: Apache-2.0
// hexstep: SPI master bus-functional model (mode 0, MSB first) speaking the frame format of
// rtl/hexstep_spi_wb.v (documented there and in docs/SYNTH.md) to a design clocked by the
// simulation: every SPI pin change happens between two core clock edges, and each SCK half
// period lasts a (random, bounded) number of core cycles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace hexstep {

// The pins of the design under test, and one rising edge of its core clock.
class SpiPins {
 public:
  virtual ~SpiPins() = default;
  virtual void set_pins(bool sck, bool cs_n, bool mosi) = 0;
  virtual bool miso() const = 0;
  virtual void tick() = 0;
};

// set_pins() and miso() for a Verilated top with the bridge's pins spi_sck_i, spi_cs_n_i,
// spi_mosi_i, spi_miso_o (hexstep_spi_wb and the tops built on it).
template <class Top>
void set_spi_pins(Top& top, bool sck, bool cs_n, bool mosi) {
  top.spi_sck_i = sck;
  top.spi_cs_n_i = cs_n;
  top.spi_mosi_i = mosi;
}
template <class Top>
bool spi_miso(Top& top) {
  top.eval();
  return top.spi_miso_o;
}

// Frame constants of rtl/hexstep_spi_wb.v.
namespace spi {
constexpr uint8_t kCmdWrite = 0xA0;   // | byte enables in bits 3:0
constexpr uint8_t kCmdRead = 0x50;
constexpr uint8_t kStatusIdle = 0xA0;
constexpr uint8_t kStatusOk = 0xA1;
constexpr uint8_t kStatusRejected = 0xA2;
constexpr size_t kWriteBytes = 8;
constexpr size_t kReadBytes = 10;
// CRC-8/SMBUS: polynomial 0x07, initial value 0, MSB first, no final XOR. Written here from the
// definition (bit by bit), independently of the RTL.
uint8_t crc8(const uint8_t* p, size_t n);
std::vector<uint8_t> write_frame(uint32_t adr, uint32_t dat, unsigned sel);
std::vector<uint8_t> read_frame(uint32_t adr);
}  // namespace spi

class SpiMaster {
 public:
  // Each SCK half period, the CS_N setup/hold times and the gap between frames last a random
  // number of core cycles in [min_half, max_half] (the bridge needs >= 4 with 2 synchronizer
  // stages).
  explicit SpiMaster(SpiPins& dut, uint32_t seed = 1, unsigned min_half = 4, unsigned max_half = 4);
  void set_timing(unsigned min_half, unsigned max_half);

  // One raw frame: CS_N low, the first `bits` bits of `mosi` (all of them if bits < 0), CS_N
  // high. Returns the MISO bits, packed MSB first into bytes (a partial last byte left-aligned).
  std::vector<uint8_t> transfer(const std::vector<uint8_t>& mosi, long bits = -1);
  // CS_N low and high again with no clock.
  void cs_pulse();

  // Register access. write() returns the STATUS byte its frame received (the outcome of the
  // frame before it); read() returns false if the reply's RSTAT is not "accepted" or its CRC is
  // wrong, and stores the RSTAT byte in last_rstat().
  uint8_t write(uint32_t adr, uint32_t dat, unsigned sel = 0xF);
  bool read(uint32_t adr, uint32_t& dat);
  uint32_t read(uint32_t adr);  // throws std::runtime_error if the read fails
  // The outcome of the last frame: a 1-byte frame (rejected itself) whose MISO byte is STATUS.
  uint8_t status();
  uint8_t last_status() const { return last_status_; }
  uint8_t last_rstat() const { return last_rstat_; }
  uint64_t frames() const { return frames_; }

 private:
  SpiPins& dut_;
  std::mt19937 rng_;
  unsigned min_half_, max_half_;
  uint8_t last_status_ = 0, last_rstat_ = 0;
  uint64_t frames_ = 0;
  void wait_half();
};

}  // namespace hexstep
