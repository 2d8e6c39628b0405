/* SPDX-License-Identifier: MIT */
/* Output and input: frame files (frame_io.c), extended XYZ trajectories
 * (xyz.c), GSD trajectories (gsd.c), the writers over them (writer.h,
 * writer.c) and the number formatting the text formats use
 * (number_text.c). Not installed. */
#ifndef DS_IO_H
#define DS_IO_H

#include "core/core.h"
#include "io/number_text.h"
#include "io/writer.h"

/* Room for the radius as the text formats write it. */
#define DS_RADIUS_TEXT_MAX 32

/* The radius as frames write it: the shortest text that reads back as the
 * same double; returns its length. For a mixture, the longest such text
 * a radius can take (24 characters). */
size_t ds_radius_text(const ds_sim *sim, char out[DS_RADIUS_TEXT_MAX]);

/* The radius of the disk in slot k as text, written again only when it
 * differs from the last one asked for (a mixture's kinds repeat; one kind
 * is written once). Start with ds_radius_cache_init. */
typedef struct ds_radius_cache {
    double value;
    size_t len;
    char text[DS_RADIUS_TEXT_MAX];
} ds_radius_cache;

void ds_radius_cache_init(ds_radius_cache *c, const ds_sim *sim);
const char *ds_radius_at(const ds_sim *sim, size_t k, ds_radius_cache *c, size_t *len);

/* Formats the state with format into a buffer of cap bytes and writes it
 * to out, flushed and checked (DS_ERR_IO, field "out"); the frame writers
 * and the trajectory writer share it. */
typedef ds_status (*ds_format_fn)(const ds_sim *sim, int velocities, char *buf, size_t cap,
                                  size_t *len, ds_error *err);
ds_status ds_write_formatted(const ds_sim *sim, int velocities, FILE *out, size_t cap,
                             ds_format_fn format, ds_error *err);
/* A buffer of cap bytes too small for the need bytes of a text: the
 * refusal of ds_frame_format and ds_xyz_format. */
ds_status ds_refuse_cap(ds_error *err, size_t cap, size_t need);

/* The rest of stream in after the len bytes of head (copied first), up
 * to want bytes in all, into *out (malloc'd; *got bytes): the buffer
 * grows by doubling as bytes arrive, so a length a forged header
 * announces costs what the stream holds, not what it says. DS_ERR_NOMEM
 * if memory runs out (nothing allocated is left); a read error is the
 * caller's to see in ferror(in). */
ds_status ds_read_up_to(FILE *in, const uint8_t *head, size_t len, size_t want, uint8_t **out,
                        size_t *got);

#endif
