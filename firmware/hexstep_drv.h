/* SPDX-License-Identifier: Apache-2.0
 * hexstep firmware driver: freestanding C99 (no libc, no heap) over the Wishbone register block
 * of rtl/hexstep_wb.v, register map firmware/hexstep_regs.h (generated from rdl/hexstep.rdl).
 *
 * Build: C99 or later, -ffreestanding; put firmware/compat on the include path first
 * (-I firmware/compat -I firmware): hexstep_regs.h includes <assert.h> for a C11 static_assert,
 * which bare-metal toolchains without a C library do not have (see firmware/compat/assert.h).
 *
 * Register access: every access goes through the handle. With read/write left NULL the driver
 * does volatile 32-bit MMIO at base + offset; a host test (or a system with a bridge) plugs in
 * its own accessors, called with the byte offset inside the 0x400-byte block.
 *
 * Moves: hexstep_move_t is field for field the `hexstep_plan_move_t` that
 * `hexstep plan --format c` writes (order of hexstep::AxisMove: steps, dir, v_start, v_max,
 * v_end, acc, dec, v_dec, acc_steps, dec_step, dec_frac; same types), and hexstep_pulse_t is
 * `hexstep_plan_pulse_t`. tests/rtl/test_fw_driver.cpp compiles a generated plan header with
 * this one and checks sizes and every field offset, so a plan's table can be passed directly:
 *   hexstep_queue_move(&dev, 0, (const hexstep_move_t *)&hexstep_plan_moves[0]);
 *
 * Register map v1.0 (the frame engine, docs/ARCHITECTURE.md): speeds and accelerations count
 * ticks (one tick of every axis per frame of 32 clock cycles); START and STOP act at the next
 * frame boundary, ABORT on the next edge. Staging and pulse-configuration accesses wait for the
 * core's memory (a few cycles) and CMD.push is acked only when the move is in the queue (about
 * 106 cycles): the bus stalls meanwhile, no call needs to poll for it.
 *
 * Concurrency: the driver keeps no state but the handle; calls on one device must not race
 * (e.g. from an interrupt handler and the main loop) unless the caller serialises them.
 */
#ifndef HEXSTEP_DRV_H
#define HEXSTEP_DRV_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HEXSTEP_NUM_AXES 6u
#define HEXSTEP_ALL_AXES 0x3Fu
#define HEXSTEP_ID_MAGIC 0x48585354u /* "HXST" */

/* Return codes: 0 is success, every error is negative. */
typedef enum {
  HEXSTEP_OK = 0,
  HEXSTEP_ERR_ARG = -1,        /* NULL pointer, axis >= 6, mask outside 0x3F, ... */
  HEXSTEP_ERR_RANGE = -2,      /* a value does not fit its register (acc/dec > 48 bits, pulse > 4095) */
  HEXSTEP_ERR_NODEV = -3,      /* ID/VERSION do not identify a six-axis hexstep of map version 1 */
  HEXSTEP_ERR_QUEUE_FULL = -4, /* the axis's 2-deep move queue has no free slot; nothing pushed */
  HEXSTEP_ERR_ESTOP = -5,      /* e-stop latched (pushes and starts are dropped by the hardware) */
  HEXSTEP_ERR_TIMEOUT = -6,    /* hexstep_wait: still busy after max_polls polls */
  HEXSTEP_ERR_MOVE = -7        /* hexstep_wait: a waited axis has AXIS_ERR.move set (refused move) */
} hexstep_rc_t;

/* Register accessors: offset is the byte offset inside the register block (0x000..0x3FC). */
typedef uint32_t (*hexstep_read_fn)(void *ctx, uint32_t offset);
typedef void (*hexstep_write_fn)(void *ctx, uint32_t offset, uint32_t value);

typedef struct {
  uintptr_t base;         /* MMIO base address (used only when read/write are NULL) */
  hexstep_read_fn read;   /* NULL: volatile 32-bit load from base + offset */
  hexstep_write_fn write; /* NULL: volatile 32-bit store to base + offset */
  void *ctx;              /* passed to read/write */
} hexstep_dev_t;

/* A jog move (set in hexstep_move_t.dir, written to DIR.jog): ramps from v_start by acc to
 * v_max and runs until hexstep_stop(); steps, acc_steps, dec_step, dec_frac, v_end and v_dec are
 * ignored. The core refuses it if v_max is 0, v_start > v_max, v_start and acc are both 0, or
 * dec is 0. */
#define HEXSTEP_MOVE_JOG 0x2u

/* One move in the core's register units: same layout as hexstep_plan_move_t. */
typedef struct {
  uint32_t steps;     /* exact number of steps */
  uint32_t dir;       /* bit 0: 1 positive direction, 0 negative; bit 1: HEXSTEP_MOVE_JOG */
  uint64_t v_start;   /* 2^-64 step/tick */
  uint64_t v_max;     /* 2^-64 step/tick */
  uint64_t v_end;     /* 2^-64 step/tick */
  uint64_t acc;       /* 2^-64 step/tick^2, at most 48 bits */
  uint64_t dec;       /* 2^-64 step/tick^2, at most 48 bits */
  uint64_t v_dec;     /* 2^-64 step/tick */
  uint32_t acc_steps; /* steps */
  uint32_t dec_step;  /* steps */
  uint32_t dec_frac;  /* 2^-32 step */
} hexstep_move_t;

/* STEP/DIR timing (clock cycles, 0..4095) and polarity: same layout as hexstep_plan_pulse_t. */
typedef struct {
  uint32_t step_high;
  uint32_t step_low;
  uint32_t dir_setup;
  uint32_t dir_hold;
  uint32_t step_invert; /* nonzero: STEP active low */
  uint32_t dir_invert;  /* nonzero: DIR low for positive motion */
} hexstep_pulse_t;

/* AXIS_ERR flags (sticky, write 1 to clear). */
#define HEXSTEP_AXERR_MOVE 0x1u    /* the core refused a move */
#define HEXSTEP_AXERR_OVERRUN 0x2u /* push to a full queue (the driver checks first; see hexstep_push) */
#define HEXSTEP_AXERR_ESTOP 0x4u   /* e-stop latched */
#define HEXSTEP_AXERR_ALL 0x7u

/* IRQ_ENABLE / IRQ_PENDING layout: one bit per axis in each group. */
#define HEXSTEP_IRQ_DONE(mask) ((uint32_t)((mask)&0x3Fu))
#define HEXSTEP_IRQ_SLOT(mask) ((uint32_t)((mask)&0x3Fu) << 8)
#define HEXSTEP_IRQ_ERR(mask) ((uint32_t)((mask)&0x3Fu) << 16)
#define HEXSTEP_IRQ_ALL 0x003F3F3Fu

/* AXIS_STATUS decoded. */
typedef struct {
  bool busy;     /* core busy */
  uint8_t phase; /* 0 idle, 1 accelerate, 2 cruise, 3 decelerate */
  bool run;      /* queued moves start back to back */
  uint8_t free;  /* free queue slots, 0..2 */
} hexstep_axis_status_t;

/* The build of the core (VERSION, INFO0, INFO1): its register widths and frame schedule. A
 * move's values must fit these widths; the rest of the driver checks the default build's. */
typedef struct {
  uint8_t naxes;      /* VERSION.naxes */
  uint8_t speed_w;    /* speed and position fraction bits (64) */
  uint8_t acc_w;      /* ACC/DEC bits */
  uint8_t step_w;     /* STEPS, ACC_STEPS, DEC_STEP bits */
  uint8_t dfrac_w;    /* DEC_FRAC bits */
  uint8_t pulse_w;    /* pulse timing bits */
  uint8_t pos_w;      /* position counter bits */
  uint8_t frame_log2; /* a tick is 2^frame_log2 clock cycles */
  uint8_t slots;      /* slots per frame */
} hexstep_info_t;

/* Fills the handle (read/write may be NULL for MMIO) and checks ID, VERSION.major (1) and
 * VERSION.naxes (6). */
hexstep_rc_t hexstep_init(hexstep_dev_t *dev, uintptr_t base, hexstep_read_fn read, hexstep_write_fn write,
                          void *ctx);
/* Reads VERSION, INFO0 and INFO1 (any build, any number of axes; no check). */
hexstep_rc_t hexstep_read_info(hexstep_dev_t *dev, hexstep_info_t *info);

/* Known state: aborts every axis (queues flushed), disables and clears interrupts, clears
 * every axis's error flags and restores the reset pulse timing and polarity. Does not clear a
 * latched e-stop (hexstep_estop_clear does that, deliberately). Positions are not reset (the
 * hardware has no way to). */
hexstep_rc_t hexstep_reset(hexstep_dev_t *dev);

/* Pulse timing and polarity of one axis (used live by the hardware). */
hexstep_rc_t hexstep_set_pulse(hexstep_dev_t *dev, unsigned axis, const hexstep_pulse_t *pulse);

/* Writes a move into the axis's staging registers (no push). */
hexstep_rc_t hexstep_load_move(hexstep_dev_t *dev, unsigned axis, const hexstep_move_t *move);
/* Pushes the staged move into the axis's queue (the core checks it and acks the write once it
 * is queued). HEXSTEP_ERR_QUEUE_FULL (nothing written) if the queue has no free slot,
 * HEXSTEP_ERR_ESTOP if the e-stop is latched. */
hexstep_rc_t hexstep_push(hexstep_dev_t *dev, unsigned axis);
/* Checks for a free slot and the e-stop first, then load + push. */
hexstep_rc_t hexstep_queue_move(hexstep_dev_t *dev, unsigned axis, const hexstep_move_t *move);
/* Free queue slots of an axis (0..2) into *free_slots. */
hexstep_rc_t hexstep_queue_free(hexstep_dev_t *dev, unsigned axis, unsigned *free_slots);

/* Starts the queue heads of the axes in mask in one frame (the next frame boundary, at most
 * 32 cycles after the write): their motions share one time zero. A pending start counts as
 * running (STATUS.run), so a poll right after the call sees the axes running. */
hexstep_rc_t hexstep_start(hexstep_dev_t *dev, uint32_t mask);
/* Aborts the axes in mask on the edge after the write (no new STEP edge) and flushes their
 * queues. */
hexstep_rc_t hexstep_abort(hexstep_dev_t *dev, uint32_t mask);
/* Controlled stop of the axes in mask from the next frame boundary: each decelerates by its
 * move's dec from the speed it has and comes to rest (docs/REGISTERS.md, STOP); their queues are
 * flushed. Poll hexstep_done() or hexstep_wait() for rest. */
hexstep_rc_t hexstep_stop(hexstep_dev_t *dev, uint32_t mask);

hexstep_rc_t hexstep_axis_status(hexstep_dev_t *dev, unsigned axis, hexstep_axis_status_t *st);
/* Axes in mask that are busy or running (queued moves still to come) into *busy_mask. */
hexstep_rc_t hexstep_busy(hexstep_dev_t *dev, uint32_t mask, uint32_t *busy_mask);
/* true when no axis in mask is busy or running. */
bool hexstep_done(hexstep_dev_t *dev, uint32_t mask);
/* Polls until no axis in mask is busy or running, at most max_polls polls (0: no limit).
 * HEXSTEP_ERR_TIMEOUT if still busy, HEXSTEP_ERR_ESTOP if the e-stop is latched at the end,
 * HEXSTEP_ERR_MOVE if a waited axis has AXIS_ERR.move set, else HEXSTEP_OK. */
hexstep_rc_t hexstep_wait(hexstep_dev_t *dev, uint32_t mask, uint32_t max_polls);

/* Signed position in steps, read atomically (POS_LO latches POS_HI). */
hexstep_rc_t hexstep_read_position(hexstep_dev_t *dev, unsigned axis, int64_t *pos);

/* AXIS_ERR flags (HEXSTEP_AXERR_*) of one axis; clear writes 1 to the given flags. */
hexstep_rc_t hexstep_read_errors(hexstep_dev_t *dev, unsigned axis, uint32_t *flags);
hexstep_rc_t hexstep_clear_errors(hexstep_dev_t *dev, unsigned axis, uint32_t flags);

/* E-stop: latched state and the synchronised pin. Either pointer may be NULL. */
hexstep_rc_t hexstep_estop_status(hexstep_dev_t *dev, bool *latched, bool *pin);
/* Clears the latch; HEXSTEP_ERR_ESTOP if it is set again (pin still high). Axis ERR.estop
 * flags are left for hexstep_clear_errors. */
hexstep_rc_t hexstep_estop_clear(hexstep_dev_t *dev);

/* Interrupts: bits as HEXSTEP_IRQ_DONE/SLOT/ERR. irq_o = OR(pending & enable). */
hexstep_rc_t hexstep_irq_enable(hexstep_dev_t *dev, uint32_t bits);
hexstep_rc_t hexstep_irq_enabled(hexstep_dev_t *dev, uint32_t *bits);
hexstep_rc_t hexstep_irq_pending(hexstep_dev_t *dev, uint32_t *bits);
hexstep_rc_t hexstep_irq_clear(hexstep_dev_t *dev, uint32_t bits);

#ifdef __cplusplus
}
#endif

#endif /* HEXSTEP_DRV_H */
