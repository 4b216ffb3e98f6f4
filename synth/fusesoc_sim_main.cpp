// SPDX-License-Identifier: Apache-2.0
// hexstep: the C++ main of the FuseSoC `sim` target (hexstep.core): a smoke test of the
// Verilated spi_tb_top (tests/spi/spi_tb_top.v: hexstep_spi_wb in front of hexstep_top). It
// reads ID and VERSION with the project's SPI master model (sim/spi_master: frames, RSTAT and
// CRC checks) and compares them with the register map's reset values (regs.hpp, generated
// from rdl/hexstep.rdl). Exit status 0 when every check passes. The real tests are tests/spi
// (ctest Spi*), which compare the RTL with the C++ model; this main only shows that the
// FuseSoC file list simulates.
#include <cstdint>
#include <cstdio>
#include <memory>

#include "Vspi_tb_top.h"
#include "hexstep/regs.hpp"
#include "spi_master.hpp"
#include "verilated.h"

namespace {

class Bench : public hexstep::SpiPins {
 public:
  Bench() : top_(new Vspi_tb_top(&ctx_, "spi_tb_top")) {
    top_->rst_i = 1;
    set_pins(false, true, false);
    top_->estop_i = 0;
    for (int i = 0; i < 4; ++i) tick();
    top_->rst_i = 0;
    for (int i = 0; i < 1000; ++i) tick();  // hexstep_wb initializes its memories (32 * NAXES cycles)
  }
  ~Bench() override { top_->final(); }
  void set_pins(bool sck, bool cs_n, bool mosi) override {
    hexstep::set_spi_pins(*top_, sck, cs_n, mosi);
  }
  bool miso() const override { return hexstep::spi_miso(*top_); }
  void tick() override {
    top_->clk_i = 0;
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
  }

 private:
  VerilatedContext ctx_;
  std::unique_ptr<Vspi_tb_top> top_;
};

}  // namespace

int main(int argc, char** argv) {
  namespace regs = hexstep::regs;
  Verilated::commandArgs(argc, argv);
  Bench b;
  hexstep::SpiMaster spi(b, 1, 8, 8);
  uint32_t id = 0, version = 0;
  bool ok = spi.read(regs::ID, id) && spi.read(regs::VERSION, version);
  if (!ok) std::printf("SPI read failed: RSTAT 0x%02x\n", spi.last_rstat());
  if (ok && id != regs::ID_RESET) {
    std::printf("ID 0x%08x, expected 0x%08x\n", id, regs::ID_RESET);
    ok = false;
  }
  if (ok && (version & regs::VERSION_RMASK) != regs::VERSION_RESET) {
    std::printf("VERSION 0x%08x, expected 0x%08x\n", version, regs::VERSION_RESET);
    ok = false;
  }
  std::printf("%s: ID 0x%08x, VERSION 0x%08x through the SPI bridge\n", ok ? "PASS" : "FAIL", id,
              version);
  return ok ? 0 : 1;
}
