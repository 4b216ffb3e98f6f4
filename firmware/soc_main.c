/* SPDX-License-Identifier: Apache-2.0
 * hexstep SoC firmware: the UART protocol of docs/PROTOCOL.md (firmware/hexstep_proto.h) on top
 * of the hexstep driver (hexstep_drv.h). Freestanding C99, no libc, no interrupts: one loop
 * that keeps every running axis's 2-deep hardware queue full from a per-axis move FIFO in RAM
 * and receives, checks and answers frames. Memory map: soc/hexstep_soc.v.
 *
 * One image serves every build of the SoC: the firmware reads the number of axes from the
 * core's VERSION register (1..6; a board build may have fewer, synth/targets.json) and the
 * widths of its move and pulse registers from INFO0/INFO1 (a reduced build may have narrower
 * ones). A request naming an axis the core lacks is refused with E_ARG, a value wider than its
 * register with E_RANGE: nothing is truncated.
 *
 * Build-time settings (soc/CMakeLists.txt passes them):
 *   HXFW_BYTE_TIMEOUT  cycles without a byte after which a started frame is dropped (E_TIMEOUT)
 *   HXFW_FIFO_DEPTH    moves buffered per axis (power of two)
 */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "hexstep_drv.h"
#include "hexstep_proto.h"
#include "hexstep_regs.h"

#ifndef HXFW_BYTE_TIMEOUT
#define HXFW_BYTE_TIMEOUT 1000000u /* 10 ms at 100 MHz */
#endif
#ifndef HXFW_FIFO_DEPTH
#define HXFW_FIFO_DEPTH 8u
#endif
typedef char hxfw_chk_depth[((HXFW_FIFO_DEPTH & (HXFW_FIFO_DEPTH - 1u)) == 0u && HXFW_FIFO_DEPTH <= 128u) ? 1 : -1];

/* ---- SoC peripherals (soc/hexstep_soc.v) ---- */
#define UART_DATA (*(volatile uint32_t *)0x10000000u)
#define UART_STATUS (*(volatile uint32_t *)0x10000004u)
#define UART_ST_TX_READY 0x2u
#define UART_DATA_EMPTY 0x80000000u
#define HEXSTEP_BASE 0x20000000u
#define SYS_STATUS (*(volatile uint32_t *)0x30000000u)
#define SYS_IRQ 0x1u

static inline uint32_t cycles(void) {
  uint32_t c;
  __asm__ volatile("rdcycle %0" : "=r"(c));
  return c;
}

/* ---- state ---- */
static hexstep_dev_t dev;
static hexstep_info_t info; /* the build of the core: widths, VERSION.naxes */
static unsigned naxes;      /* VERSION.naxes of the core, 1..HEXSTEP_NUM_AXES */
static uint32_t axes_mask;  /* its axes: (1 << naxes) - 1 */

typedef struct {
  hexstep_move_t m[HXFW_FIFO_DEPTH];
  uint8_t head, count;
} fifo_t;

static fifo_t fifo[HEXSTEP_NUM_AXES];
static uint32_t active;   /* axes started and streaming */
static uint32_t underrun; /* sticky: an active axis ended with moves still waiting */
static uint32_t err_replies;

/* ---- UART ---- */
static void tx(uint8_t b) {
  while ((UART_STATUS & UART_ST_TX_READY) == 0u) {
  }
  UART_DATA = b;
}

static uint8_t reply_buf[HXP_MAX_PAYLOAD + HXP_OVERHEAD];
static unsigned reply_len;
static int last_seq = -1; /* SEQ and CMD of the last frame executed (its reply is in reply_buf) */
static uint8_t last_cmd;

static void send_frame(uint8_t seq, uint8_t cmd, const uint8_t *pl, unsigned n, bool keep) {
  uint8_t buf[HXP_MAX_PAYLOAD + HXP_OVERHEAD];
  unsigned i;
  uint16_t crc;
  buf[0] = HXP_SOF;
  buf[1] = (uint8_t)n;
  buf[2] = seq;
  buf[3] = cmd;
  for (i = 0; i < n; ++i) buf[HXP_HEADER + i] = pl[i];
  crc = hxp_crc16(buf + 1, n + 3u);
  buf[HXP_HEADER + n] = (uint8_t)crc;
  buf[HXP_HEADER + n + 1u] = (uint8_t)(crc >> 8);
  for (i = 0; i < n + HXP_OVERHEAD; ++i) tx(buf[i]);
  if (keep) {
    for (i = 0; i < n + HXP_OVERHEAD; ++i) reply_buf[i] = buf[i];
    reply_len = n + HXP_OVERHEAD;
  }
}

static void send_error(uint8_t seq, uint8_t cmd, uint8_t code) {
  ++err_replies;
  send_frame(seq, (uint8_t)(cmd | HXP_REPLY), &code, 1u, false);
}

/* ---- little-endian fields ---- */
static uint32_t get32(const uint8_t *p) {
  return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}
static uint64_t get64(const uint8_t *p) { return (uint64_t)get32(p) | ((uint64_t)get32(p + 4) << 32); }
static unsigned get16(const uint8_t *p) { return (unsigned)p[0] | ((unsigned)p[1] << 8); }
static void put32(uint8_t *p, uint32_t v) {
  p[0] = (uint8_t)v;
  p[1] = (uint8_t)(v >> 8);
  p[2] = (uint8_t)(v >> 16);
  p[3] = (uint8_t)(v >> 24);
}

/* ---- the core: axes and register widths ---- */
#define HS_REG(off) (*(volatile uint32_t *)(HEXSTEP_BASE + (off)))

/* The driver's hexstep_init accepts only the six-axis core; a board build may have fewer axes
 * (their registers exist, the others read 0 and ignore writes). Waits for the core (ID and a
 * map of major version 1, whose units are those `hexstep plan` computes), then reads its
 * build: the widths decide which values fit (move_fits, cmd_pulse) and are what INFO reports. */
static void core_init(void) {
  dev.base = HEXSTEP_BASE;
  dev.read = NULL;
  dev.write = NULL;
  dev.ctx = NULL;
  for (;;) {
    const uint32_t ver = HS_REG(offsetof(hexstep_t, VERSION));
    naxes = (ver & HEXSTEP__VERSION__NAXES_bm) >> HEXSTEP__VERSION__NAXES_bp;
    if (HS_REG(offsetof(hexstep_t, ID)) == HEXSTEP_ID_MAGIC &&
        ((ver & HEXSTEP__VERSION__MAJOR_bm) >> HEXSTEP__VERSION__MAJOR_bp) == HEXSTEP__VERSION__MAJOR_reset &&
        naxes >= 1u && naxes <= HEXSTEP_NUM_AXES)
      break;
  }
  axes_mask = (1u << naxes) - 1u;
  (void)hexstep_read_info(&dev, &info);
}

/* v has no bit at or above bit w. */
static bool fits(uint64_t v, unsigned w) { return w >= 64u || (v >> w) == 0u; }

/* Every value of the move fits its register in this build (the core would drop the upper bits). */
static bool move_fits(const hexstep_move_t *m) {
  return fits(m->steps, info.step_w) && fits(m->acc_steps, info.step_w) && fits(m->dec_step, info.step_w) &&
         fits(m->v_start, info.speed_w) && fits(m->v_max, info.speed_w) && fits(m->v_end, info.speed_w) &&
         fits(m->v_dec, info.speed_w) && fits(m->acc, info.acc_w) && fits(m->dec, info.acc_w) &&
         fits(m->dec_frac, info.dfrac_w);
}

/* ---- motion ---- */
static bool estop_latched(void) {
  bool latched = false;
  (void)hexstep_estop_status(&dev, &latched, NULL);
  return latched;
}

static void flush(uint32_t mask) {
  unsigned k;
  for (k = 0; k < naxes; ++k)
    if (mask & (1u << k)) fifo[k].head = fifo[k].count = 0u;
  active &= ~mask;
}

/* Moves from the FIFO into the hardware queue while it has a free slot. */
static void refill(unsigned k) {
  unsigned free_slots = 0u;
  while (fifo[k].count != 0u && hexstep_queue_free(&dev, k, &free_slots) == HEXSTEP_OK && free_slots != 0u) {
    if (hexstep_queue_move(&dev, k, &fifo[k].m[fifo[k].head]) != HEXSTEP_OK) return;
    fifo[k].head = (uint8_t)((fifo[k].head + 1u) & (HXFW_FIFO_DEPTH - 1u));
    --fifo[k].count;
  }
}

static void service_axes(void) {
  unsigned k;
  if (active == 0u) return;
  if (estop_latched()) { /* the hardware aborted and flushed; drop what is buffered */
    flush(axes_mask);
    return;
  }
  for (k = 0; k < naxes; ++k) {
    hexstep_axis_status_t st;
    if ((active & (1u << k)) == 0u) continue;
    if (hexstep_axis_status(&dev, k, &st) != HEXSTEP_OK) continue;
    if (!st.busy && !st.run) {
      /* The axis ended. Anything still queued would wait for another START and run late. */
      if (st.free < 2u || fifo[k].count != 0u) {
        underrun |= 1u << k;
        (void)hexstep_abort(&dev, 1u << k);
        flush(1u << k);
      }
      active &= ~(1u << k);
      continue;
    }
    if (st.free != 0u && fifo[k].count != 0u) refill(k);
  }
}

/* ---- commands: each returns the reply payload length (status byte first) ---- */
static unsigned cmd_hello(uint8_t *r) {
  r[0] = HXP_OK;
  r[1] = HXP_VERSION;
  r[2] = (uint8_t)naxes;
  r[3] = HXFW_FIFO_DEPTH;
  r[4] = HXP_MAX_PAYLOAD;
  r[5] = 1u; /* controlled STOP (hexstep_stop) */
  put32(r + 6, *(volatile uint32_t *)(HEXSTEP_BASE + 0x0u));
  put32(r + 10, *(volatile uint32_t *)(HEXSTEP_BASE + 0x4u));
  return HXP_HELLO_REPLY_LEN;
}

static unsigned cmd_pulse(const uint8_t *p, uint8_t *r) {
  hexstep_pulse_t pc;
  unsigned k = p[0];
  hexstep_axis_status_t st;
  if (k >= naxes || (p[9] & ~3u) != 0u) return r[0] = HXP_E_ARG, 1u;
  pc.step_high = get16(p + 1);
  pc.step_low = get16(p + 3);
  pc.dir_setup = get16(p + 5);
  pc.dir_hold = get16(p + 7);
  pc.step_invert = p[9] & 1u;
  pc.dir_invert = (p[9] >> 1) & 1u;
  if (!fits(pc.step_high, info.pulse_w) || !fits(pc.step_low, info.pulse_w) ||
      !fits(pc.dir_setup, info.pulse_w) || !fits(pc.dir_hold, info.pulse_w))
    return r[0] = HXP_E_RANGE, 1u;
  if (hexstep_axis_status(&dev, k, &st) != HEXSTEP_OK) return r[0] = HXP_E_ARG, 1u;
  if ((active & (1u << k)) || st.busy || st.run || fifo[k].count != 0u) return r[0] = HXP_E_BUSY, 1u;
  if (hexstep_set_pulse(&dev, k, &pc) != HEXSTEP_OK) return r[0] = HXP_E_RANGE, 1u;
  r[0] = HXP_OK;
  return 1u;
}

static unsigned cmd_move(const uint8_t *p, uint8_t *r) {
  unsigned k = p[0];
  hexstep_move_t m;
  fifo_t *f;
  if (k >= naxes || p[5] > (1u | HEXSTEP_MOVE_JOG)) return r[0] = HXP_E_ARG, 1u;
  m.steps = get32(p + 1);
  m.dir = p[5];
  m.v_start = get64(p + 6);
  m.v_max = get64(p + 14);
  m.v_end = get64(p + 22);
  m.acc = get64(p + 30);
  m.dec = get64(p + 38);
  m.v_dec = get64(p + 46);
  m.acc_steps = get32(p + 54);
  m.dec_step = get32(p + 58);
  m.dec_frac = get32(p + 62);
  if (!move_fits(&m)) return r[0] = HXP_E_RANGE, 1u;
  if (estop_latched()) return r[0] = HXP_E_ESTOP, 1u;
  f = &fifo[k];
  if (f->count >= HXFW_FIFO_DEPTH) {
    r[0] = HXP_E_FULL;
    r[1] = 0u;
    return 2u;
  }
  f->m[(f->head + f->count) & (HXFW_FIFO_DEPTH - 1u)] = m;
  ++f->count;
  if (active & (1u << k)) refill(k);
  r[0] = HXP_OK;
  r[1] = (uint8_t)(HXFW_FIFO_DEPTH - f->count);
  return 2u;
}

static unsigned cmd_start(const uint8_t *p, uint8_t *r) {
  uint32_t mask = p[0], go = 0u;
  unsigned k;
  if ((mask & ~axes_mask) != 0u) return r[0] = HXP_E_ARG, 1u;
  if (estop_latched()) return r[0] = HXP_E_ESTOP, 1u;
  for (k = 0; k < naxes; ++k) {
    if ((mask & (1u << k)) == 0u || (active & (1u << k)) || fifo[k].count == 0u) continue;
    refill(k);
    go |= 1u << k;
  }
  underrun &= ~go;
  if (go != 0u && hexstep_start(&dev, go) != HEXSTEP_OK) {
    flush(go);
    return r[0] = HXP_E_ESTOP, 1u;
  }
  active |= go;
  r[0] = HXP_OK;
  r[1] = (uint8_t)go;
  return 2u;
}

static unsigned cmd_abort(const uint8_t *p, uint8_t *r) {
  uint32_t mask = p[0];
  if ((mask & ~axes_mask) != 0u) return r[0] = HXP_E_ARG, 1u;
  (void)hexstep_abort(&dev, mask);
  flush(mask);
  r[0] = HXP_OK;
  return 1u;
}

/* Controlled stop: the core decelerates each axis by its move's dec to rest and flushes its
 * queue; the firmware drops the axis's FIFO. The axis stays busy until it is at rest. */
static unsigned cmd_stop(const uint8_t *p, uint8_t *r) {
  uint32_t mask = p[0];
  if ((mask & ~axes_mask) != 0u) return r[0] = HXP_E_ARG, 1u;
  flush(mask);
  (void)hexstep_stop(&dev, mask);
  r[0] = HXP_OK;
  return 1u;
}

static unsigned cmd_clear(uint8_t *r) {
  unsigned k;
  hexstep_rc_t rc = hexstep_estop_clear(&dev);
  for (k = 0; k < naxes; ++k) (void)hexstep_clear_errors(&dev, k, HEXSTEP_AXERR_ALL);
  underrun = 0u;
  r[0] = rc == HEXSTEP_OK ? HXP_OK : HXP_E_ESTOP;
  return 1u;
}

/* The widths of this build of the core (INFO0/INFO1): the host compares them with the widths
 * its job was planned for. */
static unsigned cmd_info(uint8_t *r) {
  r[0] = HXP_OK;
  r[1] = info.speed_w;
  r[2] = info.acc_w;
  r[3] = info.step_w;
  r[4] = info.dfrac_w;
  r[5] = info.pulse_w;
  return HXP_INFO_REPLY_LEN;
}

static unsigned cmd_status(uint8_t *r) {
  bool latched = false, pin = false;
  uint32_t busy = 0u;
  unsigned k;
  (void)hexstep_estop_status(&dev, &latched, &pin);
  (void)hexstep_busy(&dev, axes_mask, &busy);
  r[0] = HXP_OK;
  r[1] = (uint8_t)((latched ? HXP_G_ESTOP : 0u) | (pin ? HXP_G_ESTOP_PIN : 0u) |
                   ((SYS_STATUS & SYS_IRQ) ? HXP_G_IRQ : 0u));
  r[2] = (uint8_t)active;
  r[3] = (uint8_t)busy;
  r[4] = (uint8_t)underrun;
  put32(r + 5, err_replies);
  for (k = 0; k < HEXSTEP_NUM_AXES; ++k) {
    uint8_t *a = r + 9 + k * HXP_STATUS_AXIS_LEN;
    hexstep_axis_status_t st;
    uint32_t err = 0u;
    int64_t pos = 0;
    (void)hexstep_axis_status(&dev, k, &st);
    (void)hexstep_read_errors(&dev, k, &err);
    (void)hexstep_read_position(&dev, k, &pos);
    a[0] = fifo[k].count;
    a[1] = st.free;
    a[2] = (uint8_t)err;
    a[3] = (uint8_t)(((active >> k) & 1u ? HXP_A_ACTIVE : 0u) | ((busy >> k) & 1u ? HXP_A_BUSY : 0u) |
                     ((underrun >> k) & 1u ? HXP_A_UNDERRUN : 0u));
    put32(a + 4, (uint32_t)(uint64_t)pos);
    put32(a + 8, (uint32_t)((uint64_t)pos >> 32));
  }
  return HXP_STATUS_REPLY_LEN;
}

/* Length each command's request payload must have. */
static int request_len(uint8_t cmd) {
  switch (cmd) {
    case HXP_HELLO: case HXP_CLEAR: case HXP_STATUS: case HXP_INFO: return 0;
    case HXP_PULSE: return HXP_PULSE_LEN;
    case HXP_MOVE: return HXP_MOVE_LEN;
    case HXP_START: case HXP_STOP: case HXP_ABORT: return HXP_MASK_LEN;
    default: return -1;
  }
}

static void execute(uint8_t seq, uint8_t cmd, const uint8_t *p, unsigned n) {
  uint8_t r[HXP_MAX_PAYLOAD];
  unsigned len;
  int want = request_len(cmd);
  if (want < 0) return send_error(seq, cmd, HXP_E_COMMAND);
  if ((unsigned)want != n) return send_error(seq, cmd, HXP_E_LENGTH);
  if ((int)seq == last_seq && cmd == last_cmd) { /* a retransmission: answer again, do not execute twice */
    unsigned i;
    for (i = 0; i < reply_len; ++i) tx(reply_buf[i]);
    return;
  }
  switch (cmd) {
    case HXP_HELLO: len = cmd_hello(r); break;
    case HXP_PULSE: len = cmd_pulse(p, r); break;
    case HXP_MOVE: len = cmd_move(p, r); break;
    case HXP_START: len = cmd_start(p, r); break;
    case HXP_STOP: len = cmd_stop(p, r); break;
    case HXP_ABORT: len = cmd_abort(p, r); break;
    case HXP_CLEAR: len = cmd_clear(r); break;
    case HXP_INFO: len = cmd_info(r); break;
    default: len = cmd_status(r); break;
  }
  /* Refused requests change nothing and may be sent again with the same SEQ. */
  if (r[0] != HXP_OK) {
    ++err_replies;
    send_frame(seq, (uint8_t)(cmd | HXP_REPLY), r, len, false);
    return;
  }
  last_seq = seq;
  last_cmd = cmd;
  send_frame(seq, (uint8_t)(cmd | HXP_REPLY), r, len, true);
}

/* ---- frame receiver ---- */
enum { RX_SOF, RX_LEN, RX_SEQ, RX_CMD, RX_PAYLOAD, RX_CRC0, RX_CRC1 };

int main(void) {
  uint8_t payload[HXP_MAX_PAYLOAD];
  unsigned state = RX_SOF, len = 0u, got = 0u;
  uint8_t seq = 0u, cmd = 0u, crc_lo = 0u;
  uint16_t crc = 0xFFFFu;
  uint32_t last_byte = 0u;

  core_init();
  (void)hexstep_reset(&dev);
  /* The IRQ line (SYS_STATUS) says when a queue slot freed, a move ended or an error appeared:
   * the loop services the axes only then, or when it has just changed them itself. */
  (void)hexstep_irq_enable(&dev, HEXSTEP_IRQ_ALL);

  for (;;) {
    uint32_t v;
    if (SYS_STATUS & SYS_IRQ) {
      uint32_t pend = 0u;
      (void)hexstep_irq_pending(&dev, &pend);
      (void)hexstep_irq_clear(&dev, pend);
      service_axes();
    }
    v = UART_DATA;
    if (v & UART_DATA_EMPTY) {
      if (state != RX_SOF && (uint32_t)(cycles() - last_byte) > HXFW_BYTE_TIMEOUT) {
        send_error(seq, cmd, HXP_E_TIMEOUT);
        state = RX_SOF;
      }
      continue;
    }
    last_byte = cycles();
    {
      const uint8_t b = (uint8_t)v;
      if (state != RX_SOF && state < RX_CRC0) crc = hxp_crc16_byte(crc, b);
      switch (state) {
        case RX_SOF:
          if (b == HXP_SOF) {
            state = RX_LEN;
            crc = 0xFFFFu;
            seq = cmd = 0u;
          }
          break;
        case RX_LEN:
          len = b;
          got = 0u;
          state = RX_SEQ;
          break;
        case RX_SEQ:
          seq = b;
          state = RX_CMD;
          break;
        case RX_CMD:
          cmd = b;
          if (len > HXP_MAX_PAYLOAD) { /* cannot be a frame: resynchronise on the next SOF */
            send_error(seq, cmd, HXP_E_LENGTH);
            state = RX_SOF;
          } else {
            state = len ? RX_PAYLOAD : RX_CRC0;
          }
          break;
        case RX_PAYLOAD:
          payload[got++] = b;
          if (got == len) state = RX_CRC0;
          break;
        case RX_CRC0:
          crc_lo = b;
          state = RX_CRC1;
          break;
        default:
          state = RX_SOF;
          if ((uint16_t)(crc_lo | ((uint16_t)b << 8)) != crc) {
            send_error(seq, cmd, HXP_E_CRC);
            break;
          }
          execute(seq, cmd, payload, len);
          service_axes();
          break;
      }
    }
  }
}
