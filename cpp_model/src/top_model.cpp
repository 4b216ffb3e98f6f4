// SPDX-License-Identifier: Apache-2.0
// hexstep: cycle-exact model of rtl/hexstep_top.v. Each block names the part of rtl/ it
// mirrors: hexstep_wb.v (bus decode, registers, memory operations), hexstep_loader.v (CMD.push),
// hexstep_engine.v (frames, slots, queues) and hexstep_pulse.v (through PulseStage).
//
// Every edge is computed from the state before it: decisions first, then the new state.
#include "hexstep/top_model.hpp"

#include <algorithm>
#include <limits>

namespace hexstep {

namespace {
// Word indexes (byte offset / 4) of rdl/hexstep.rdl.
enum : unsigned { G_ID = 0, G_VERSION = 1, G_START = 2, G_ABORT = 3, G_GSTATUS = 4,
                  G_IRQ_EN = 5, G_IRQ_PEND = 6, G_STOP = 7, G_INFO0 = 8, G_INFO1 = 9 };
enum : unsigned { W_STEPS = 0, W_DIR = 1, W_V_START = 2, W_V_MAX = 4, W_V_END = 6, W_V_DEC = 8,
                  W_ACC = 10, W_DEC = 12, W_ACC_STEPS = 14, W_DEC_STEP = 15, W_DEC_FRAC = 16,
                  W_CMD = 17, W_STATUS = 18, W_ERR = 19, W_POS_LO = 20, W_POS_HI = 21,
                  W_CFG = 22 };
constexpr unsigned kAddrBits = 12;
constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();

uint32_t lo_mask(unsigned w) { return w >= 32 ? 0xFFFFFFFFu : ((1u << w) - 1u); }
uint32_t hi_mask(unsigned w) { return w >= 64 ? 0xFFFFFFFFu : (w <= 32 ? 0u : ((1u << (w - 32)) - 1u)); }
uint64_t pair(const std::array<uint32_t, TopModel::kNw>& wd, unsigned i) {
  return uint64_t(wd[i]) | (uint64_t(wd[i + 1]) << 32);
}
}  // namespace

TopModel::TopModel(unsigned naxes, const Widths& w) : naxes_(naxes), w_(w) {
  if (naxes_ < 1) naxes_ = 1;
  if (naxes_ > kSlots) naxes_ = kSlots;
  reset();
}

void TopModel::reset() {
  n_ = 0;
  ack_q_ = irq_q_ = cap_q_ = false;
  dat_q_ = 0;
  es1_ = es2_ = estop_ = false;
  abort_cmd_ = start_pend_ = stop_pend_ = frame_start_ = frame_stop_ = 0;
  irq_en_ = pend_ = 0;
  for (auto& a : ax_) {
    a = Axis{};
    a.pulse = PulseStage(w_);
    a.cfg = {1, 1, 0, 0, 0};  // STEP_HIGH = STEP_LOW = 1
  }
  // hexstep_wb.v "init": after reset the bus engine clears the staging words and writes the
  // configuration mirror, 8 words of every axis in each bank, one bus cycle each.
  op_ = Op{};
  op_.kind = Op::kInit;
  op_.done = 3 + 4ull * (8ull * naxes_ - 1);
}

// Implemented bits of each word (hexstep_wb.v stg_mask/cfg_mask).
uint32_t TopModel::stg_mask(unsigned i) const {
  switch (i) {
    case W_STEPS: case W_ACC_STEPS: case W_DEC_STEP: return lo_mask(w_.steps);
    case W_DIR: return 0x3u;
    case W_V_START: case W_V_MAX: case W_V_END: case W_V_DEC:
    case W_V_START + 1: case W_V_MAX + 1: case W_V_END + 1: case W_V_DEC + 1:
      return 0xFFFFFFFFu;
    case W_ACC: case W_DEC: return lo_mask(w_.acc);
    case W_ACC + 1: case W_DEC + 1: return hi_mask(w_.acc);
    case W_DEC_FRAC: return lo_mask(w_.dec_frac);
    default: return 0;
  }
}
uint32_t TopModel::cfg_mask(unsigned i) const { return i == kNc - 1 ? 0x3u : lo_mask(w_.pulse); }

AxisMove TopModel::staged_move(unsigned k) const {
  const auto& wd = ax_[k].stg;
  AxisMove m;
  m.steps = wd[W_STEPS];
  m.dir = wd[W_DIR] & 1u;
  m.jog = (wd[W_DIR] >> 1) & 1u;
  m.v_start = pair(wd, W_V_START);
  m.v_max = pair(wd, W_V_MAX);
  m.v_end = pair(wd, W_V_END);
  m.v_dec = pair(wd, W_V_DEC);
  m.acc = pair(wd, W_ACC);
  m.dec = pair(wd, W_DEC);
  m.acc_steps = wd[W_ACC_STEPS];
  m.dec_step = wd[W_DEC_STEP];
  m.dec_frac = wd[W_DEC_FRAC];
  return m;
}

PulseConfig TopModel::pulse_config(unsigned k) const {
  const auto& c = ax_[k].cfg;
  PulseConfig p;
  p.step_high = c[0];
  p.step_low = c[1];
  p.dir_setup = c[2];
  p.dir_hold = c[3];
  p.step_invert = c[4] & 1u;
  p.dir_invert = (c[4] >> 1) & 1u;
  return p;
}

// hexstep_engine.v busy_o: the axis is not at rest.
bool TopModel::busy_core(const Axis& a) const {
  return a.gen.run() || a.chain || a.starting || a.pulse.pending();
}
bool TopModel::busy(unsigned k) const { return busy_core(ax_[k]); }

uint32_t TopModel::status_word(unsigned k) const {
  const Axis& a = ax_[k];
  const uint32_t b = 1u << k;
  const bool run_bit = a.running || (start_pend_ & b) || (frame_start_ & b);
  return ((2u - a.qn) << 4) | (run_bit ? 8u : 0u) | (static_cast<uint32_t>(a.gen.phase()) << 1) |
         (busy_core(a) ? 1u : 0u);
}

void TopModel::tick(const WbPins& in) {
  const uint64_t c = n_;
  const unsigned f = static_cast<unsigned>(c % kFrameCycles);
  const uint32_t all = all_mask();
  const uint32_t abort_w = (abort_cmd_ | (estop_ ? all : 0u)) & all;

  std::array<bool, kSlots> busy0{};
  for (unsigned k = 0; k < naxes_; ++k) busy0[k] = busy_core(ax_[k]);

  // ================= decisions, from the state before this edge =================

  // ---- hexstep_wb.v: request decode ----
  // A request seen in one cycle (while idle and not acking) is taken at its edge and acted on
  // at the next (hexstep_wb.v: cap_q, the decodes registered a cycle ahead); the master holds
  // it until the ack.
  const bool take = in.cyc && in.stb && !ack_q_ && op_.kind == Op::kNone && !cap_q_;
  const bool req = cap_q_ && in.cyc && in.stb;
  const bool wr = req && in.we;
  const bool rd = req && !in.we;
  uint32_t bmask = 0;
  for (unsigned b = 0; b < 4; ++b)
    if ((in.sel >> b) & 1u) bmask |= 0xFFu << (8 * b);
  const uint32_t wdat = in.dat & bmask;
  const uint32_t adr = in.adr & ((1u << kAddrBits) - 1u);
  const uint32_t blk = adr >> 7;
  const uint32_t widx = (adr >> 2) & 31u;
  const bool g_hit = blk == 0;
  const bool a_hit = blk >= 2 && blk - 2 < naxes_;
  const unsigned ak = a_hit ? blk - 2 : 0;
  const uint32_t irq_mask = all | (all << 8) | (all << 16);

  bool ack_n = false;
  uint32_t dat_n = 0;
  uint32_t start_w = 0, stop_w = 0, abort_cmd_n = 0, irq_en_n = irq_en_, pend_w1c = 0;
  bool estop_clear = false;
  std::array<uint32_t, kSlots> err_w1c{}, eset{};
  std::array<bool, kSlots> poshi_latch{};
  std::array<uint32_t, kSlots> poshi_val{};
  std::array<int, kSlots> cfg_write{};  // config word written at this edge, + 1 (0: none)
  uint32_t cfg_value = 0;
  Op op_n = op_;
  bool push_now = false;  // a loader starts at this edge

  if (req) {
    ack_n = true;  // immediate registers; a memory operation clears this below
    if (g_hit) {
      uint32_t rdata = 0;
      switch (widx) {
        case G_ID: rdata = kId; break;
        case G_VERSION: rdata = (uint32_t(naxes_) << 16) | (kVersionMajor << 8) | kVersionMinor; break;
        case G_GSTATUS: rdata = (es2_ ? 2u : 0u) | (estop_ ? 1u : 0u); break;
        case G_IRQ_EN: rdata = irq_en_; break;
        case G_IRQ_PEND: rdata = pend_; break;
        case G_INFO0: rdata = w_.speed_frac | (w_.acc << 8) | (w_.steps << 16) | (w_.dec_frac << 24); break;
        case G_INFO1: rdata = w_.pulse | (w_.pos << 8) | (kFrameLog2 << 16) | (kSlots << 24); break;
        default: rdata = 0; break;
      }
      if (rd) dat_n = rdata;
      if (wr) {
        if (widx == G_START) start_w = wdat & all;
        if (widx == G_ABORT) abort_cmd_n = wdat & all;
        if (widx == G_STOP) stop_w = wdat & all;
        if (widx == G_IRQ_EN) irq_en_n = ((irq_en_ & ~bmask) | wdat) & irq_mask;
        if (widx == G_IRQ_PEND) pend_w1c = wdat;
        if (widx == G_GSTATUS && (wdat & 1u)) estop_clear = true;
      }
    } else if (a_hit) {
      Axis& a = ax_[ak];
      // hexstep_wb.v drives the memory port from registers set in the cycle before a bus cycle:
      // an operation accepted at this edge starts at the first bus cycle after the next cycle.
      const uint64_t b0 = next_bus_cycle(c + 1);
      // A memory-backed word: a read acks at b0 + 2 with the word, a write is a read-modify-
      // write (byte enables, implemented bits) that acks at b0 + 4.
      auto mem_op = [&](Op::Kind read, Op::Kind write, unsigned word) {
        ack_n = false;
        op_n = Op{};
        op_n.axis = ak;
        op_n.word = word;
        op_n.kind = rd ? read : write;
        op_n.done = b0 + (rd ? 2 : 4);
        if (!rd) {
          op_n.wdat = wdat;
          op_n.bmask = bmask;
        }
      };
      if (widx < kNw) {
        // Staging words live in the memory.
        mem_op(Op::kStgRead, Op::kStgWrite, widx);
      } else if (widx >= W_CFG && widx < W_CFG + kNc) {
        // Configuration: read from its memory mirror; a write is a read-modify-write of the
        // mirror like a staging write, and the live register takes the merged word at the
        // mirror's write.
        mem_op(Op::kCfgRead, Op::kCfgWrite, widx - W_CFG);
      } else {
        const uint64_t pos64 = static_cast<uint64_t>(a.pulse.position());
        uint32_t rdata = 0;
        switch (widx) {
          case W_STATUS: rdata = status_word(ak); break;
          case W_ERR: rdata = a.errf; break;
          case W_POS_LO: rdata = static_cast<uint32_t>(pos64); break;
          case W_POS_HI: rdata = a.poshi; break;
          default: break;
        }
        if (rd) dat_n = rdata;
        if (rd && widx == W_POS_LO) {
          poshi_latch[ak] = true;
          poshi_val[ak] = static_cast<uint32_t>(pos64 >> 32);
        }
        if (wr && widx == W_ERR) err_w1c[ak] = wdat & 7u;
        if (wr && widx == W_CMD && (wdat & 1u)) {
          const bool drop = estop_ || ((abort_w >> ak) & 1u);
          if (!drop && a.qn == 2) {
            eset[ak] |= 2u;  // overrun
          } else if (!drop) {
            // hexstep_loader.v: copy the staging words into the tail slot, checking them.
            ack_n = false;
            push_now = true;
            op_n = Op{};
            op_n.kind = Op::kPush;
            op_n.axis = ak;
            op_n.done = b0 + 4ull * kLoaderSteps;
            op_n.tail = (a.act + 1 + a.qn) % 3;
            op_n.sm = make_slot(staged_move(ak), w_);
          }
        }
      }
    } else if (rd) {
      dat_n = 0;  // unmapped
    }
  }

  // ---- hexstep_wb.v: completion of the bus engine's operation ----
  bool op_done = op_.kind != Op::kNone && c == op_.done;
  bool push_commit = false;
  unsigned stg_write_axis = kSlots, stg_write_word = 0;
  uint32_t stg_write_value = 0;
  if (op_done) {
    Axis& a = ax_[op_.axis];
    switch (op_.kind) {
      case Op::kStgRead: ack_n = true; dat_n = a.stg[op_.word]; break;
      case Op::kStgWrite:
        ack_n = true;
        stg_write_axis = op_.axis;
        stg_write_word = op_.word;
        stg_write_value = ((a.stg[op_.word] & ~op_.bmask) | op_.wdat) & stg_mask(op_.word);
        break;
      case Op::kCfgRead: ack_n = true; dat_n = a.cfg[op_.word]; break;
      case Op::kCfgWrite:
        ack_n = true;
        cfg_write[op_.axis] = static_cast<int>(op_.word) + 1;
        cfg_value = ((a.cfg[op_.word] & ~op_.bmask) | op_.wdat) & cfg_mask(op_.word);
        break;
      case Op::kPush: ack_n = true; push_commit = !op_.cancelled; break;
      default: break;  // kInit: no acknowledge
    }
    op_n.kind = Op::kNone;
  }

  // ---- hexstep_engine.v: frame boundary, samples, commits ----
  const bool boundary = f == kBoundaryCycle;
  std::array<bool, kSlots> flush{};  // queue flushed at this edge (abort or STOP)
  std::array<int, kSlots> pop{};
  std::array<bool, kSlots> consumed{};  // a refused or empty move was consumed (done)
  std::array<int, kSlots> tgt{};
  std::array<uint64_t, kSlots> req_due{};
  for (unsigned k = 0; k < kSlots; ++k) tgt[k] = -1;

  // Sample: the slot of axis i is decided at the edge that ends frame cycle 4i - 1.
  int sample_axis = -1;
  Flight sample_fl;
  const unsigned fs1 = (f + 1) % kFrameCycles;  // frame cycle after this edge
  if (fs1 % kSlotCycles == 0 && fs1 / kSlotCycles < naxes_) {
    const unsigned i = fs1 / kSlotCycles;
    const Axis& a = ax_[i];
    const uint32_t b = 1u << i;
    if (!(abort_w & b)) {
      sample_axis = static_cast<int>(i);
      const bool fs = frame_start_ & b, fp = frame_stop_ & b;
      const SlotMove& head = a.slot[(a.act + 1) % 3];
      const bool dir_ok = head.bad || head.empty || head.m.dir == a.pulse.dir_target() || !a.pulse.pending();
      sample_fl.valid = true;
      sample_fl.commit = c + kCommitDelay;
      sample_fl.frame = c + 1 - kSlotCycles * i;
      sample_fl.stop = fp;
      sample_fl.gen_ok = a.pulse.accepts();
      sample_fl.start_new = fs && !fp && !a.running && !busy_core(a) && a.qn > 0;
      const bool start_chain = a.chain && !fp && a.pulse.accepts() && dir_ok;
      sample_fl.start = sample_fl.start_new || start_chain;
      if (fp) flush[i] = true;
      else if (sample_fl.start) pop[i] = 1;
    }
  }

  // Commit: kCommitDelay edges after the sample.
  int commit_axis = -1;
  TickOut commit_out;
  for (unsigned k = 0; k < naxes_; ++k) {
    const Flight& fl = ax_[k].fl;
    if (fl.valid && fl.commit == c) commit_axis = static_cast<int>(k);
  }

  // ================= the new state =================

  // Commit of axis j's slot (its AxisGen is changed by nothing else at this edge).
  if (commit_axis >= 0) {
    const unsigned j = static_cast<unsigned>(commit_axis);
    Axis& a = ax_[j];
    Flight fl = a.fl;
    const bool aborted = fl.abort_seen || ((abort_w >> j) & 1u);
    if (!aborted) {
      bool ended = false, consumed_now = false;
      bool ticked = false;
      if (fl.start) {
        const SlotMove& s = a.slot[a.act];
        if (s.bad || s.empty) {
          consumed_now = true;
          if (s.bad) eset[j] |= 1u;  // ERR.move
        } else {
          a.gen.begin(s);
          a.t0 = fl.frame;
          tgt[j] = s.m.dir ? 1 : 0;
          commit_out = a.gen.tick();
          ticked = true;
        }
      } else if (a.gen.run() && fl.gen_ok) {
        commit_out = a.gen.tick();
        ticked = true;
      }
      if (ticked) {
        ended = commit_out.ended;
        if (commit_out.step) req_due[j] = fl.frame + kDueOffset - commit_out.q;
      }
      if (ended || consumed_now) {
        // The next queued move chains if the axis is running and one is queued.
        if (a.running && a.qn > 0) a.chain = true;
        else a.running = false;
      }
      if (consumed_now) consumed[j] = true;
      if (fl.stop && a.gen.run()) a.gen.enter_stop();
    }
    a.starting = false;
    a.fl.valid = false;
  }

  // Sample effects.
  if (sample_axis >= 0) {
    const unsigned i = static_cast<unsigned>(sample_axis);
    Axis& a = ax_[i];
    if (sample_fl.stop) {
      a.running = false;
      a.chain = false;
    } else if (sample_fl.start) {
      a.act = (a.act + 1) % 3;
      if (sample_fl.start_new) a.running = true;
      a.chain = false;
      a.starting = true;
    }
    a.fl = sample_fl;
  }

  // Abort (ABORT strobe, e-stop latch): everything of the axis stops at this edge.
  for (unsigned k = 0; k < naxes_; ++k) {
    if (!((abort_w >> k) & 1u)) continue;
    Axis& a = ax_[k];
    a.gen.halt();
    a.running = false;
    a.chain = false;
    a.starting = false;
    flush[k] = true;
    if (a.fl.valid) a.fl.abort_seen = true;
  }

  // Queue counts: flush, pop at a start, push at the loader's commit (a flush at the commit
  // edge cancels the push).
  std::array<bool, kSlots> freed{};  // a queue entry became free at this edge (IRQ slot)
  for (unsigned k = 0; k < naxes_; ++k) {
    Axis& a = ax_[k];
    const unsigned q0 = a.qn;
    const bool pushed = push_commit && op_.axis == k && !flush[k];
    if (pushed) a.slot[op_.tail] = op_.sm;
    if (flush[k]) a.qn = 0;
    else a.qn = a.qn - static_cast<unsigned>(pop[k]) + (pushed ? 1u : 0u);
    freed[k] = a.qn < q0;
  }
  // A flush while a push is loading (from the edge it starts on) cancels it: the loaded slot
  // is never counted.
  if (op_n.kind == Op::kPush && flush[op_n.axis]) op_n.cancelled = true;
  (void)push_now;

  // Frame masks and pending strobes (hexstep_engine.v: START/STOP act at frame boundaries).
  if (boundary) {
    frame_start_ = start_pend_;
    frame_stop_ = stop_pend_;
    start_pend_ = 0;
    stop_pend_ = 0;
  }
  if (sample_axis >= 0) {
    frame_start_ &= ~(1u << sample_axis);
    frame_stop_ &= ~(1u << sample_axis);
  }
  start_pend_ |= start_w;
  stop_pend_ |= stop_w;
  start_pend_ &= ~abort_w;
  stop_pend_ &= ~abort_w;
  frame_start_ &= ~abort_w;
  frame_stop_ &= ~abort_w;
  for (unsigned k = 0; k < naxes_; ++k)
    if (ax_[k].fl.valid && ((abort_w >> k) & 1u)) ax_[k].fl.abort_seen = true;

  // Output stages (the live configuration before this edge's write).
  for (unsigned k = 0; k < naxes_; ++k) {
    Axis& a = ax_[k];
    a.pulse.edge(c, (abort_w >> k) & 1u, pulse_config(k), req_due[k], tgt[k]);
  }

  // Bus-side register updates.
  if (stg_write_axis < kSlots) ax_[stg_write_axis].stg[stg_write_word] = stg_write_value;
  for (unsigned k = 0; k < naxes_; ++k) {
    Axis& a = ax_[k];
    if (cfg_write[k]) a.cfg[cfg_write[k] - 1] = cfg_value;
    if (poshi_latch[k]) a.poshi = poshi_val[k];
  }

  // Errors and interrupts.
  const bool estop_rise = es2_ && !estop_;
  uint32_t pend_set = 0;
  for (unsigned k = 0; k < naxes_; ++k) {
    Axis& a = ax_[k];
    if (estop_rise) eset[k] |= 4u;
    a.errf = (a.errf & ~err_w1c[k]) | eset[k];
    // hexstep_engine.v: busy fell during the last cycle (busy_q && !busy), or a refused or
    // empty move was consumed at this edge.
    if ((a.busy_prev && !busy0[k]) || consumed[k]) pend_set |= 1u << k;
    a.busy_prev = busy0[k];
    if (freed[k]) pend_set |= 1u << (8 + k);
    if (eset[k]) pend_set |= 1u << (16 + k);
  }
  // hexstep_wb.v: irq_o is registered from IRQ_PENDING & IRQ_ENABLE as they were before this edge.
  irq_q_ = (pend_ & irq_en_) != 0;
  pend_ = ((pend_ & ~pend_w1c) | pend_set) & irq_mask;
  irq_en_ = irq_en_n;

  // E-stop synchronizer and latch.
  const bool estop_n = es2_ || (estop_ && !estop_clear);
  es2_ = es1_;
  es1_ = in.estop;
  estop_ = estop_n;
  abort_cmd_ = abort_cmd_n;

  op_ = op_n;
  ack_q_ = ack_n;
  dat_q_ = dat_n;
  cap_q_ = take;
  ++n_;
}

// ---- event mode ----
// A stretch is quiet when no bus request, bus operation, pending strobe or e-stop event can
// change anything, no axis starts, chains or stops, and every running axis's generator and every
// output stage are quiet: then each slot in the stretch is a plain tick that AxisGen::skip()
// applies in closed form, and the output stages only count their interval counters down.

namespace {
// Edges e in [from, to) with e % kFrameCycles == r.
uint64_t count_mod(uint64_t from, uint64_t to, uint64_t r) {
  if (to <= from) return 0;
  auto upto = [r](uint64_t x) {  // edges e < x with e % 32 == r
    return x / kFrameCycles + (x % kFrameCycles > r ? 1 : 0);
  };
  return upto(to) - upto(from);
}
}  // namespace

uint64_t TopModel::quiet_cycles(const WbPins& in) const {
  if (in.cyc && in.stb) return 0;
  if (op_.kind != Op::kNone || ack_q_ || cap_q_ || dat_q_ != 0) return 0;
  if (abort_cmd_ || estop_ || es1_ != in.estop || es2_ != in.estop) return 0;
  if (start_pend_ || stop_pend_ || frame_start_ || frame_stop_) return 0;
  if (irq_q_ != ((pend_ & irq_en_) != 0)) return 0;
  uint64_t q = std::numeric_limits<uint64_t>::max();
  for (unsigned k = 0; k < naxes_; ++k) {
    const Axis& a = ax_[k];
    if (a.chain || a.starting) return 0;
    if (a.fl.valid && (a.fl.start || a.fl.stop || !a.fl.gen_ok || a.fl.abort_seen)) return 0;
    if (a.busy_prev != busy_core(a)) return 0;
    q = std::min(q, a.pulse.quiet_cycles(n_, pulse_config(k)));
    if (!a.gen.run()) continue;
    // The generator may run `t` more quiet ticks: its (t+1)-th commit from now must lie beyond.
    const uint64_t t = a.gen.quiet_ticks();
    if (t == std::numeric_limits<uint64_t>::max()) continue;
    const uint64_t r = (kSlotCycles * k + kFrameCycles - 1 + kCommitDelay) % kFrameCycles;  // commits
    uint64_t first = n_ + ((r + kFrameCycles - n_ % kFrameCycles) % kFrameCycles);  // first >= n_
    const uint64_t next_event = first + t * kFrameCycles;  // the (t+1)-th commit
    q = std::min(q, next_event - n_);
  }
  return q == std::numeric_limits<uint64_t>::max() ? (1ull << 40) : q;
}

void TopModel::skip(uint64_t k) {
  if (k == 0) return;
  const uint64_t from = n_, to = n_ + k;
  for (unsigned i = 0; i < naxes_; ++i) {
    Axis& a = ax_[i];
    const uint64_t rs = (kSlotCycles * i + kFrameCycles - 1) % kFrameCycles;  // sample edges
    const uint64_t rc = (rs + kCommitDelay) % kFrameCycles;                   // commit edges
    const uint64_t ticks = count_mod(from, to, rc);
    if (a.gen.run() && ticks) a.gen.skip(ticks);
    a.pulse.skip(k);
    // A slot sampled before the stretch keeps its flight if it commits after it; a slot sampled
    // in the stretch that commits after it is in flight afterwards (a plain tick).
    if (a.fl.valid && a.fl.commit < to) a.fl.valid = false;
    for (uint64_t s = (to > kCommitDelay ? to - kCommitDelay : 0); s < to; ++s) {
      if (s % kFrameCycles != rs || s < from) continue;
      Flight fl;
      fl.valid = true;
      fl.commit = s + kCommitDelay;
      fl.frame = s + 1 - kSlotCycles * i;
      fl.gen_ok = a.pulse.accepts();
      a.fl = fl;
    }
  }
  n_ = to;
}

}  // namespace hexstep
