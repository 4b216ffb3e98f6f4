/* SPDX-License-Identifier: Apache-2.0
 * hexstep firmware driver (see hexstep_drv.h). Freestanding C99: no libc, no heap.
 * Register offsets and fields come from hexstep_regs.h (generated from rdl/hexstep.rdl).
 */
#include "hexstep_drv.h"

#include "hexstep_regs.h"

/* ---- register offsets from the generated map ---- */
#define G_OFF(reg) ((uint32_t)offsetof(hexstep_t, reg))
#define A_OFF(axis, reg)                                                          \
  ((uint32_t)(offsetof(hexstep_t, AXIS) + (axis) * sizeof(hexstep__axis_t__stride80_t) + \
              offsetof(hexstep__axis_t__stride80_t, reg)))

#define FIELD(val, reg_field) (((val)&reg_field##_bm) >> reg_field##_bp)

#define PULSE_MAX HEXSTEP__AXIS_T__STEP_HIGH__VAL_bm /* 12-bit timing registers */
#define ACC_HI_MASK HEXSTEP__AXIS_T__WORD16_R__VAL_bm /* ACC_HI/DEC_HI: bits 47:32 */

/* The driver's constants agree with the generated map. */
typedef char hexstep_chk_naxes[(sizeof(((hexstep_t *)0)->AXIS) / sizeof(((hexstep_t *)0)->AXIS[0]) ==
                                HEXSTEP_NUM_AXES)
                                   ? 1
                                   : -1];
typedef char hexstep_chk_mask[(HEXSTEP__START__MASK_bm == HEXSTEP_ALL_AXES) ? 1 : -1];
typedef char hexstep_chk_magic[(HEXSTEP__ID__MAGIC_reset == HEXSTEP_ID_MAGIC) ? 1 : -1];
typedef char hexstep_chk_err[((HEXSTEP__AXIS_T__ERR__MOVE_bm | HEXSTEP__AXIS_T__ERR__OVERRUN_bm |
                               HEXSTEP__AXIS_T__ERR__ESTOP_bm) == HEXSTEP_AXERR_ALL &&
                              HEXSTEP__AXIS_T__ERR__MOVE_bm == HEXSTEP_AXERR_MOVE &&
                              HEXSTEP__AXIS_T__ERR__OVERRUN_bm == HEXSTEP_AXERR_OVERRUN)
                                 ? 1
                                 : -1];
typedef char hexstep_chk_irq[((HEXSTEP__IRQ_ENABLE__DONE_bm | HEXSTEP__IRQ_ENABLE__SLOT_bm |
                               HEXSTEP__IRQ_ENABLE__ERR_bm) == HEXSTEP_IRQ_ALL &&
                              HEXSTEP__IRQ_ENABLE__SLOT_bp == 8 && HEXSTEP__IRQ_ENABLE__ERR_bp == 16)
                                 ? 1
                                 : -1];

/* ---- access ---- */
static uint32_t rd(const hexstep_dev_t *dev, uint32_t off) {
  if (dev->read) return dev->read(dev->ctx, off);
  return *(volatile const uint32_t *)(dev->base + off);
}

static void wr(const hexstep_dev_t *dev, uint32_t off, uint32_t val) {
  if (dev->write) {
    dev->write(dev->ctx, off, val);
    return;
  }
  *(volatile uint32_t *)(dev->base + off) = val;
}

static bool axis_ok(const hexstep_dev_t *dev, unsigned axis) { return dev && axis < HEXSTEP_NUM_AXES; }
static bool mask_ok(const hexstep_dev_t *dev, uint32_t mask) { return dev && (mask & ~HEXSTEP_ALL_AXES) == 0u; }

static bool estop_latched(const hexstep_dev_t *dev) {
  return (rd(dev, G_OFF(GSTATUS)) & HEXSTEP__GSTATUS__ESTOP_bm) != 0u;
}

/* ---- init / reset ---- */
hexstep_rc_t hexstep_init(hexstep_dev_t *dev, uintptr_t base, hexstep_read_fn read, hexstep_write_fn write,
                          void *ctx) {
  uint32_t ver;
  if (!dev) return HEXSTEP_ERR_ARG;
  dev->base = base;
  dev->read = read;
  dev->write = write;
  dev->ctx = ctx;
  if (rd(dev, G_OFF(ID)) != HEXSTEP_ID_MAGIC) return HEXSTEP_ERR_NODEV;
  ver = rd(dev, G_OFF(VERSION));
  /* Another major version has other register units (map 0.x counted clock cycles). */
  if (FIELD(ver, HEXSTEP__VERSION__MAJOR) != HEXSTEP__VERSION__MAJOR_reset) return HEXSTEP_ERR_NODEV;
  if (FIELD(ver, HEXSTEP__VERSION__NAXES) != HEXSTEP_NUM_AXES) return HEXSTEP_ERR_NODEV;
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_read_info(hexstep_dev_t *dev, hexstep_info_t *info) {
  uint32_t v, i0, i1;
  if (!dev || !info) return HEXSTEP_ERR_ARG;
  v = rd(dev, G_OFF(VERSION));
  i0 = rd(dev, G_OFF(INFO0));
  i1 = rd(dev, G_OFF(INFO1));
  info->naxes = (uint8_t)FIELD(v, HEXSTEP__VERSION__NAXES);
  info->speed_w = (uint8_t)FIELD(i0, HEXSTEP__INFO0__SPEED_W);
  info->acc_w = (uint8_t)FIELD(i0, HEXSTEP__INFO0__ACC_W);
  info->step_w = (uint8_t)FIELD(i0, HEXSTEP__INFO0__STEP_W);
  info->dfrac_w = (uint8_t)FIELD(i0, HEXSTEP__INFO0__DFRAC_W);
  info->pulse_w = (uint8_t)FIELD(i1, HEXSTEP__INFO1__PULSE_W);
  info->pos_w = (uint8_t)FIELD(i1, HEXSTEP__INFO1__POS_W);
  info->frame_log2 = (uint8_t)FIELD(i1, HEXSTEP__INFO1__FRAME_LOG2);
  info->slots = (uint8_t)FIELD(i1, HEXSTEP__INFO1__SLOTS);
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_reset(hexstep_dev_t *dev) {
  static const hexstep_pulse_t reset_pulse = {HEXSTEP__AXIS_T__STEP_HIGH__VAL_reset,
                                              HEXSTEP__AXIS_T__STEP_LOW__VAL_reset,
                                              HEXSTEP__AXIS_T__DIR_SETUP__VAL_reset,
                                              HEXSTEP__AXIS_T__DIR_HOLD__VAL_reset, 0u, 0u};
  unsigned k;
  hexstep_rc_t rc;
  if (!dev) return HEXSTEP_ERR_ARG;
  wr(dev, G_OFF(IRQ_ENABLE), 0u);
  rc = hexstep_abort(dev, HEXSTEP_ALL_AXES);
  if (rc != HEXSTEP_OK) return rc;
  for (k = 0; k < HEXSTEP_NUM_AXES; ++k) {
    rc = hexstep_set_pulse(dev, k, &reset_pulse);
    if (rc != HEXSTEP_OK) return rc;
    wr(dev, A_OFF(k, ERR), HEXSTEP_AXERR_ALL);
  }
  /* After the abort: its done and slot-free events are cleared too. */
  wr(dev, G_OFF(IRQ_PENDING), HEXSTEP_IRQ_ALL);
  return HEXSTEP_OK;
}

/* ---- pulse configuration ---- */
hexstep_rc_t hexstep_set_pulse(hexstep_dev_t *dev, unsigned axis, const hexstep_pulse_t *p) {
  uint32_t pol = 0u;
  if (!axis_ok(dev, axis) || !p) return HEXSTEP_ERR_ARG;
  if (p->step_high > PULSE_MAX || p->step_low > PULSE_MAX || p->dir_setup > PULSE_MAX ||
      p->dir_hold > PULSE_MAX)
    return HEXSTEP_ERR_RANGE;
  if (p->step_invert) pol |= HEXSTEP__AXIS_T__POLARITY__STEP_INV_bm;
  if (p->dir_invert) pol |= HEXSTEP__AXIS_T__POLARITY__DIR_INV_bm;
  wr(dev, A_OFF(axis, STEP_HIGH), p->step_high);
  wr(dev, A_OFF(axis, STEP_LOW), p->step_low);
  wr(dev, A_OFF(axis, DIR_SETUP), p->dir_setup);
  wr(dev, A_OFF(axis, DIR_HOLD), p->dir_hold);
  wr(dev, A_OFF(axis, POLARITY), pol);
  return HEXSTEP_OK;
}

/* ---- moves and queue ---- */
static void wr64(const hexstep_dev_t *dev, uint32_t lo_off, uint64_t v) {
  wr(dev, lo_off, (uint32_t)v);
  wr(dev, lo_off + 4u, (uint32_t)(v >> 32));
}

hexstep_rc_t hexstep_load_move(hexstep_dev_t *dev, unsigned axis, const hexstep_move_t *m) {
  if (!axis_ok(dev, axis) || !m) return HEXSTEP_ERR_ARG;
  if ((m->acc >> 32) > ACC_HI_MASK || (m->dec >> 32) > ACC_HI_MASK) return HEXSTEP_ERR_RANGE;
  if (m->dir > (HEXSTEP__AXIS_T__DIR__POSITIVE_bm | HEXSTEP__AXIS_T__DIR__JOG_bm))
    return HEXSTEP_ERR_RANGE;
  wr(dev, A_OFF(axis, STEPS), m->steps);
  wr(dev, A_OFF(axis, DIR), m->dir);
  wr64(dev, A_OFF(axis, V_START_LO), m->v_start);
  wr64(dev, A_OFF(axis, V_MAX_LO), m->v_max);
  wr64(dev, A_OFF(axis, V_END_LO), m->v_end);
  wr64(dev, A_OFF(axis, V_DEC_LO), m->v_dec);
  wr64(dev, A_OFF(axis, ACC_LO), m->acc);
  wr64(dev, A_OFF(axis, DEC_LO), m->dec);
  wr(dev, A_OFF(axis, ACC_STEPS), m->acc_steps);
  wr(dev, A_OFF(axis, DEC_STEP), m->dec_step);
  wr(dev, A_OFF(axis, DEC_FRAC), m->dec_frac);
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_queue_free(hexstep_dev_t *dev, unsigned axis, unsigned *free_slots) {
  if (!axis_ok(dev, axis) || !free_slots) return HEXSTEP_ERR_ARG;
  *free_slots = (unsigned)FIELD(rd(dev, A_OFF(axis, STATUS)), HEXSTEP__AXIS_T__STATUS__FREE);
  return HEXSTEP_OK;
}

/* Free slots only grow behind the driver's back (a pop), so free != 0 here means the push fits. */
static hexstep_rc_t check_push(hexstep_dev_t *dev, unsigned axis) {
  unsigned n = 0;
  hexstep_rc_t rc = hexstep_queue_free(dev, axis, &n);
  if (rc != HEXSTEP_OK) return rc;
  if (estop_latched(dev)) return HEXSTEP_ERR_ESTOP;
  if (n == 0u) return HEXSTEP_ERR_QUEUE_FULL;
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_push(hexstep_dev_t *dev, unsigned axis) {
  hexstep_rc_t rc = check_push(dev, axis);
  if (rc != HEXSTEP_OK) return rc;
  wr(dev, A_OFF(axis, CMD), HEXSTEP__AXIS_T__CMD__PUSH_bm);
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_queue_move(hexstep_dev_t *dev, unsigned axis, const hexstep_move_t *m) {
  hexstep_rc_t rc = check_push(dev, axis);
  if (rc != HEXSTEP_OK) return rc;
  rc = hexstep_load_move(dev, axis, m);
  if (rc != HEXSTEP_OK) return rc;
  wr(dev, A_OFF(axis, CMD), HEXSTEP__AXIS_T__CMD__PUSH_bm);
  return HEXSTEP_OK;
}

/* ---- start / abort ---- */
hexstep_rc_t hexstep_start(hexstep_dev_t *dev, uint32_t mask) {
  if (!mask_ok(dev, mask)) return HEXSTEP_ERR_ARG;
  if (estop_latched(dev)) return HEXSTEP_ERR_ESTOP;
  wr(dev, G_OFF(START), mask);
  /* A bridge may post the write; a read cannot pass it, so STATUS.run is 1 after this one. */
  (void)rd(dev, G_OFF(GSTATUS));
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_abort(hexstep_dev_t *dev, uint32_t mask) {
  if (!mask_ok(dev, mask)) return HEXSTEP_ERR_ARG;
  wr(dev, G_OFF(ABORT), mask);
  (void)rd(dev, G_OFF(GSTATUS));
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_stop(hexstep_dev_t *dev, uint32_t mask) {
  if (!mask_ok(dev, mask)) return HEXSTEP_ERR_ARG;
  wr(dev, G_OFF(STOP), mask);
  (void)rd(dev, G_OFF(GSTATUS));
  return HEXSTEP_OK;
}

/* ---- status ---- */
hexstep_rc_t hexstep_axis_status(hexstep_dev_t *dev, unsigned axis, hexstep_axis_status_t *st) {
  uint32_t s;
  if (!axis_ok(dev, axis) || !st) return HEXSTEP_ERR_ARG;
  s = rd(dev, A_OFF(axis, STATUS));
  st->busy = FIELD(s, HEXSTEP__AXIS_T__STATUS__BUSY) != 0u;
  st->phase = (uint8_t)FIELD(s, HEXSTEP__AXIS_T__STATUS__PHASE);
  st->run = FIELD(s, HEXSTEP__AXIS_T__STATUS__RUN) != 0u;
  st->free = (uint8_t)FIELD(s, HEXSTEP__AXIS_T__STATUS__FREE);
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_busy(hexstep_dev_t *dev, uint32_t mask, uint32_t *busy_mask) {
  unsigned k;
  uint32_t b = 0u;
  if (!mask_ok(dev, mask) || !busy_mask) return HEXSTEP_ERR_ARG;
  for (k = 0; k < HEXSTEP_NUM_AXES; ++k) {
    if (!((mask >> k) & 1u)) continue;
    if (rd(dev, A_OFF(k, STATUS)) & (HEXSTEP__AXIS_T__STATUS__BUSY_bm | HEXSTEP__AXIS_T__STATUS__RUN_bm))
      b |= 1u << k;
  }
  *busy_mask = b;
  return HEXSTEP_OK;
}

bool hexstep_done(hexstep_dev_t *dev, uint32_t mask) {
  uint32_t b = 0u;
  if (hexstep_busy(dev, mask, &b) != HEXSTEP_OK) return false;
  return b == 0u;
}

hexstep_rc_t hexstep_wait(hexstep_dev_t *dev, uint32_t mask, uint32_t max_polls) {
  uint32_t polls = 0u, b = 0u, k;
  hexstep_rc_t rc;
  if (!mask_ok(dev, mask)) return HEXSTEP_ERR_ARG;
  for (;;) {
    rc = hexstep_busy(dev, mask, &b);
    if (rc != HEXSTEP_OK) return rc;
    if (b == 0u) break;
    if (max_polls != 0u && ++polls >= max_polls) return HEXSTEP_ERR_TIMEOUT;
  }
  if (estop_latched(dev)) return HEXSTEP_ERR_ESTOP;
  for (k = 0; k < HEXSTEP_NUM_AXES; ++k)
    if (((mask >> k) & 1u) && (rd(dev, A_OFF(k, ERR)) & HEXSTEP_AXERR_MOVE)) return HEXSTEP_ERR_MOVE;
  return HEXSTEP_OK;
}

/* ---- position ---- */
hexstep_rc_t hexstep_read_position(hexstep_dev_t *dev, unsigned axis, int64_t *pos) {
  uint32_t lo, hi;
  uint64_t u;
  if (!axis_ok(dev, axis) || !pos) return HEXSTEP_ERR_ARG;
  lo = rd(dev, A_OFF(axis, POS_LO)); /* latches POS_HI */
  hi = rd(dev, A_OFF(axis, POS_HI));
  u = ((uint64_t)hi << 32) | lo;
  /* Two's complement without relying on an implementation-defined conversion. */
  *pos = (u >> 63) ? -(int64_t)(~u) - 1 : (int64_t)u;
  return HEXSTEP_OK;
}

/* ---- errors ---- */
hexstep_rc_t hexstep_read_errors(hexstep_dev_t *dev, unsigned axis, uint32_t *flags) {
  if (!axis_ok(dev, axis) || !flags) return HEXSTEP_ERR_ARG;
  *flags = rd(dev, A_OFF(axis, ERR)) & HEXSTEP_AXERR_ALL;
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_clear_errors(hexstep_dev_t *dev, unsigned axis, uint32_t flags) {
  if (!axis_ok(dev, axis) || (flags & ~HEXSTEP_AXERR_ALL)) return HEXSTEP_ERR_ARG;
  wr(dev, A_OFF(axis, ERR), flags);
  return HEXSTEP_OK;
}

/* ---- e-stop ---- */
hexstep_rc_t hexstep_estop_status(hexstep_dev_t *dev, bool *latched, bool *pin) {
  uint32_t g;
  if (!dev) return HEXSTEP_ERR_ARG;
  g = rd(dev, G_OFF(GSTATUS));
  if (latched) *latched = (g & HEXSTEP__GSTATUS__ESTOP_bm) != 0u;
  if (pin) *pin = (g & HEXSTEP__GSTATUS__ESTOP_PIN_bm) != 0u;
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_estop_clear(hexstep_dev_t *dev) {
  if (!dev) return HEXSTEP_ERR_ARG;
  wr(dev, G_OFF(GSTATUS), HEXSTEP__GSTATUS__ESTOP_bm);
  return estop_latched(dev) ? HEXSTEP_ERR_ESTOP : HEXSTEP_OK;
}

/* ---- interrupts ---- */
hexstep_rc_t hexstep_irq_enable(hexstep_dev_t *dev, uint32_t bits) {
  if (!dev || (bits & ~HEXSTEP_IRQ_ALL)) return HEXSTEP_ERR_ARG;
  wr(dev, G_OFF(IRQ_ENABLE), bits);
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_irq_enabled(hexstep_dev_t *dev, uint32_t *bits) {
  if (!dev || !bits) return HEXSTEP_ERR_ARG;
  *bits = rd(dev, G_OFF(IRQ_ENABLE)) & HEXSTEP_IRQ_ALL;
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_irq_pending(hexstep_dev_t *dev, uint32_t *bits) {
  if (!dev || !bits) return HEXSTEP_ERR_ARG;
  *bits = rd(dev, G_OFF(IRQ_PENDING)) & HEXSTEP_IRQ_ALL;
  return HEXSTEP_OK;
}

hexstep_rc_t hexstep_irq_clear(hexstep_dev_t *dev, uint32_t bits) {
  if (!dev || (bits & ~HEXSTEP_IRQ_ALL)) return HEXSTEP_ERR_ARG;
  wr(dev, G_OFF(IRQ_PENDING), bits);
  return HEXSTEP_OK;
}
