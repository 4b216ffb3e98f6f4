// SPDX-License-Identifier: Apache-2.0
// hexstep CLI: `hexstep send`, stream a job to a board (or the simulated SoC) over a serial port
// with the framed protocol of docs/PROTOCOL.md, wait for the end and print the positions.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace hexstep::cli {

// Exit statuses of `hexstep send` beyond those of common.hpp.
enum SendExit : int {
  kExitLink = 6,   // the port cannot be used, or the board does not answer with valid frames
  kExitBoard = 7,  // the board refused a request or reported a fault (e-stop, refused move,
                   // stream underrun)
};

struct SendOptions {
  std::string job;   // path, or "-" for stdin
  std::string port;  // serial device, e.g. /dev/ttyUSB1 or a pseudo-terminal
  unsigned baud = 115200;
  unsigned timeout_ms = 2000;  // per reply
  unsigned retries = 3;        // retransmissions of a request without a valid reply
  bool clear_estop = false;
};

CLI::App* add_send(CLI::App& app, SendOptions& o);
int run_send(const SendOptions& o);

}  // namespace hexstep::cli
