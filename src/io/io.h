/* SPDX-License-Identifier: MIT */
/* Text output and input: frame files (frame_io.c), extended XYZ
 * trajectories (xyz.c) and the number formatting both use
 * (number_text.c). Not installed. */
#ifndef DS_IO_H
#define DS_IO_H

#include "core/core.h"
#include "io/number_text.h"

/* Room for the radius as the text formats write it. */
#define DS_RADIUS_TEXT_MAX 32

/* The radius as frames write it: the shortest text that reads back as the
 * same double; returns its length. */
size_t ds_radius_text(const ds_sim *sim, char out[DS_RADIUS_TEXT_MAX]);

/* Formats the state with format into a buffer of cap bytes and writes it
 * to out, flushed and checked; the frame writers and the trajectory
 * writer share it. */
typedef ds_status (*ds_format_fn)(const ds_sim *sim, int velocities, char *buf, size_t cap,
                                  size_t *len);
ds_status ds_write_formatted(const ds_sim *sim, int velocities, FILE *out, size_t cap,
                             ds_format_fn format);

#endif
