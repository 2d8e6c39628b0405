/* SPDX-License-Identifier: MIT */
/* Numbers as text, shared by the text formats (frame_io.c, xyz.c) and the
 * radius a simulation prints (sim.c). Internal, not installed. */
#ifndef DS_NUMBER_TEXT_H
#define DS_NUMBER_TEXT_H

#include <stddef.h>

/* Room one ds_format_fixed6 field may take (with a NUL to spare). */
#define DS_FIELD_MAX 40

/* Writes v with exactly 6 decimals, as printf("%.6f") would, without a
 * NUL; returns the length (at most DS_FIELD_MAX - 1). */
size_t ds_format_fixed6(char *out, double v);

/* Writes the shortest %g form of v that reads back as the same double
 * (5 -> "5", 0.1 -> "0.1"), NUL-terminated, into out[cap]. */
void ds_format_shortest(char *out, size_t cap, double v);

#endif
