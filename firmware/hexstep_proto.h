/* SPDX-License-Identifier: Apache-2.0
 * hexstep host link: frame layout, commands and error codes of the UART protocol between
 * `hexstep send` (cli/send.cpp) and the SoC firmware (firmware/soc_main.c). docs/PROTOCOL.md
 * describes it; both sides include this header so the numbers exist once.
 *
 * Frame: SOF, LEN, SEQ, CMD, LEN payload bytes, CRC16 (low byte first).
 * CRC-16/CCITT-FALSE (poly 0x1021, init 0xFFFF, no reflection, no final xor) over LEN, SEQ,
 * CMD and the payload. Multi-byte payload fields are little-endian.
 */
#ifndef HEXSTEP_PROTO_H
#define HEXSTEP_PROTO_H

#include <stdint.h>

#define HXP_SOF 0xA5u
#define HXP_VERSION 1u
#define HXP_MAX_PAYLOAD 96u   /* bytes; a longer LEN is answered HXP_E_LENGTH */
#define HXP_HEADER 4u         /* SOF LEN SEQ CMD */
#define HXP_OVERHEAD 6u       /* header + CRC */
#define HXP_REPLY 0x80u       /* reply CMD = request CMD | HXP_REPLY */

/* Commands (request payload -> reply payload after the status byte; docs/PROTOCOL.md). */
#define HXP_HELLO 0x01u  /* - -> version, naxes, fifo depth, max payload, stop, ID, VERSION */
#define HXP_PULSE 0x02u  /* axis, 4 x u16 timing, flags -> - */
#define HXP_MOVE 0x03u   /* axis + hexstep_move_t fields (dir bit 1: jog) -> free FIFO slots of the axis */
#define HXP_START 0x04u  /* mask -> mask of axes started */
#define HXP_STOP 0x05u   /* mask -> - (controlled stop, hexstep_stop) */
#define HXP_ABORT 0x06u  /* mask -> - */
#define HXP_CLEAR 0x07u  /* - -> - (clears the e-stop latch and every axis's error flags) */
#define HXP_STATUS 0x08u /* - -> status block */
#define HXP_INFO 0x09u   /* - -> SPEED_W, ACC_W, STEP_W, DFRAC_W, PULSE_W of the core (u8 each) */

#define HXP_PULSE_LEN 10u
#define HXP_MOVE_LEN 66u
#define HXP_MASK_LEN 1u
#define HXP_HELLO_REPLY_LEN 14u  /* including the status byte */
#define HXP_INFO_REPLY_LEN 6u    /* including the status byte */
#define HXP_STATUS_AXIS_LEN 12u  /* fifo, hw free, err, flags, position (i64) */
#define HXP_STATUS_REPLY_LEN (1u + 4u + 4u + 6u * HXP_STATUS_AXIS_LEN)

/* STATUS global flags. */
#define HXP_G_ESTOP 0x01u     /* e-stop latched */
#define HXP_G_ESTOP_PIN 0x02u /* e-stop pin high now */
#define HXP_G_IRQ 0x04u       /* hexstep irq line high */
/* STATUS per-axis flags. */
#define HXP_A_ACTIVE 0x01u   /* started and still streaming (firmware) */
#define HXP_A_BUSY 0x02u     /* core busy or queued moves running (hardware) */
#define HXP_A_UNDERRUN 0x04u /* the move FIFO ran dry while the axis was running (sticky until START) */

/* Status byte of a reply. */
#define HXP_OK 0u
#define HXP_E_CRC 1u       /* checksum mismatch: the frame is dropped */
#define HXP_E_LENGTH 2u    /* LEN above HXP_MAX_PAYLOAD or wrong for the command */
#define HXP_E_COMMAND 3u   /* unknown command */
#define HXP_E_ARG 4u       /* axis >= 6, mask outside 0x3F, dir > 1, unknown flag bits */
#define HXP_E_RANGE 5u     /* a value does not fit its register (acc/dec > 48 bits, pulse > 4095) */
#define HXP_E_FULL 6u      /* the axis's move FIFO is full: nothing stored, send again later */
#define HXP_E_ESTOP 7u     /* e-stop latched: motion commands refused */
#define HXP_E_BUSY 8u      /* PULSE on an axis that is moving or has moves waiting */
#define HXP_E_TIMEOUT 9u   /* frame truncated: no byte within the inter-byte timeout */
#define HXP_E_UNSUPPORTED 10u /* reserved: a request this firmware cannot serve */

static inline uint16_t hxp_crc16_byte(uint16_t crc, uint8_t b) {
  unsigned i;
  crc = (uint16_t)(crc ^ ((uint16_t)b << 8));
  for (i = 0; i < 8u; ++i) crc = (uint16_t)((crc & 0x8000u) ? (((unsigned)crc << 1) ^ 0x1021u) : ((unsigned)crc << 1));
  return crc;
}

static inline uint16_t hxp_crc16(const uint8_t *p, unsigned n) {
  uint16_t crc = 0xFFFFu;
  while (n--) crc = hxp_crc16_byte(crc, *p++);
  return crc;
}

#endif /* HEXSTEP_PROTO_H */
