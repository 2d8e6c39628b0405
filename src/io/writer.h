/* SPDX-License-Identifier: MIT */
/* The writers' interface (io/): one table an output format fills, which
 * the public ds_writer_open, ds_writer_write and ds_writer_close
 * (writer.c) dispatch through. sim/tables.c lists the tables by their
 * ds_format. Not installed. */
#ifndef DS_WRITER_H
#define DS_WRITER_H

#include <stdio.h>

#include "core/core.h"

/* One output format (docs/architecture.md, "An output format"). Every
 * hook gets the writer's own state, self, which open made (NULL if the
 * format keeps none); open and close may be NULL. */
typedef struct ds_writer_ops {
    const char *name; /* ds_format_name */
    unsigned flags;   /* the DS_WRITE_* bits it takes */
    /* Starts a file on out (a header, if the format has one). */
    ds_status (*open)(FILE *out, unsigned flags, void **self, ds_error *err);
    /* sim at ds_sim_get_time as one frame, flushed: DS_ERR_IO if the
     * write fails. */
    ds_status (*frame)(void *self, FILE *out, unsigned flags, const ds_sim *sim, ds_error *err);
    /* Finishes the file (an index, a footer) and frees self. */
    ds_status (*close)(void *self, FILE *out, ds_error *err);
} ds_writer_ops;

/* The writers: text frames (frame_io.c), extended XYZ (xyz.c) and GSD
 * (gsd.c). */
extern const ds_writer_ops ds_frame_writer;
extern const ds_writer_ops ds_xyz_writer;
extern const ds_writer_ops ds_gsd_writer;

/* The table of format, NULL if it is none: sim/tables.c, the list. */
const ds_writer_ops *ds_writer_ops_of(ds_format format);

#endif
