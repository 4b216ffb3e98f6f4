// SPDX-License-Identifier: Apache-2.0
// hexstep: the C++ main of the FuseSoC `sim` target (hexstep.core): a smoke test of the
// Verilated spi_tb_top (tests/spi/spi_tb_top.v: hexstep_spi_wb in front of hexstep_top). It
// reads ID and VERSION through SPI read frames (rtl/hexstep_spi_wb.v, docs/SYNTH.md "SPI
// frame") and checks RSTAT, RCRC and the values of the register map (rdl/hexstep.rdl). Exit
// status 0 when every check passes. The real tests are tests/spi (ctest Spi*), which compare
// the RTL with the C++ model; this main only shows that the FuseSoC file list simulates.
#include <cstdint>
#include <cstdio>
#include <memory>

#include "Vspi_tb_top.h"
#include "verilated.h"

namespace {

constexpr int kHalf = 8;  // core cycles per SCK half period (the bridge needs >= 4)

uint8_t crc8(const uint8_t* p, int n) {  // CRC-8/SMBUS: poly 0x07, init 0
  uint8_t c = 0;
  for (int i = 0; i < n; ++i) {
    c ^= p[i];
    for (int b = 0; b < 8; ++b) c = static_cast<uint8_t>((c & 0x80) ? (c << 1) ^ 0x07 : c << 1);
  }
  return c;
}

class Bench {
 public:
  Bench() : top_(new Vspi_tb_top(&ctx_, "spi_tb_top")) {
    top_->clk_i = 0;
    top_->rst_i = 1;
    top_->spi_cs_n_i = 1;
    top_->spi_sck_i = 0;
    top_->spi_mosi_i = 0;
    top_->estop_i = 0;
    top_->eval();
    cycles(4);
    top_->rst_i = 0;
    cycles(1000);  // hexstep_wb initializes its memories after reset (32 * NAXES cycles)
  }
  ~Bench() { top_->final(); }

  void cycles(int n) {
    for (int i = 0; i < n; ++i) {
      top_->clk_i = 1;
      top_->eval();
      top_->clk_i = 0;
      top_->eval();
    }
  }

  // One full-duplex frame, mode 0, MSB first: MOSI set while SCK is low, both lines sampled
  // at the rising edge.
  void frame(const uint8_t* out, uint8_t* in, int n) {
    top_->spi_cs_n_i = 0;
    cycles(kHalf);
    for (int i = 0; i < n; ++i) {
      uint8_t r = 0;
      for (int b = 7; b >= 0; --b) {
        top_->spi_mosi_i = (out[i] >> b) & 1;
        cycles(kHalf);
        top_->spi_sck_i = 1;
        top_->eval();
        r = static_cast<uint8_t>((r << 1) | (top_->spi_miso_o & 1));
        cycles(kHalf);
        top_->spi_sck_i = 0;
      }
      in[i] = r;
    }
    cycles(kHalf);
    top_->spi_cs_n_i = 1;
    cycles(4 * kHalf);
  }

  // A read frame of register ADR; false if RSTAT or RCRC is wrong.
  bool read(uint16_t adr, uint32_t* data) {
    uint8_t out[10] = {0x50, static_cast<uint8_t>(adr >> 8), static_cast<uint8_t>(adr), 0};
    out[3] = crc8(out, 3);
    uint8_t in[10] = {};
    frame(out, in, 10);
    const uint8_t chk[7] = {out[0], out[1], out[2], in[5], in[6], in[7], in[8]};
    *data = (uint32_t(in[5]) << 24) | (uint32_t(in[6]) << 16) | (uint32_t(in[7]) << 8) | in[8];
    if (in[4] != 0xA1) {
      std::printf("read 0x%03x: RSTAT 0x%02x, expected 0xA1 (issued)\n", adr, in[4]);
      return false;
    }
    if (in[9] != crc8(chk, 7)) {
      std::printf("read 0x%03x: RCRC 0x%02x, expected 0x%02x\n", adr, in[9], crc8(chk, 7));
      return false;
    }
    return true;
  }

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vspi_tb_top> top_;
};

}  // namespace

int main(int argc, char** argv) {
  Verilated::commandArgs(argc, argv);
  Bench b;
  uint32_t id = 0, version = 0;
  bool ok = b.read(0x000, &id) && b.read(0x004, &version);
  if (ok && id != 0x48585354u) {
    std::printf("ID 0x%08x, expected 0x48585354 (\"HXST\")\n", id);
    ok = false;
  }
  if (ok && ((version >> 8) & 0xFF) != 1) {
    std::printf("VERSION 0x%08x: major %u, expected 1\n", version, (version >> 8) & 0xFF);
    ok = false;
  }
  if (ok && ((version >> 16) & 0xFF) != 6) {
    std::printf("VERSION 0x%08x: %u axes, expected 6\n", version, (version >> 16) & 0xFF);
    ok = false;
  }
  std::printf("%s: ID 0x%08x, VERSION 0x%08x through the SPI bridge\n", ok ? "PASS" : "FAIL", id,
              version);
  return ok ? 0 : 1;
}
