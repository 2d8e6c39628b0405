/* SPDX-License-Identifier: MIT */
/* Writers: every trajectory format behind one interface (writer.h). A
 * writer is its format's table, the stream it writes to and the
 * format's own state; each call dispatches through the table. */
#include <math.h>
#include <stdlib.h>

#include "io/io.h"

struct ds_writer {
    const ds_writer_ops *ops;
    FILE *out;
    unsigned flags;
    void *self; /* the format's own, from its open */
};

const char *ds_format_name(ds_format format)
{
    const ds_writer_ops *ops = ds_writer_ops_of(format);
    return ops ? ops->name : "unknown";
}

static const char *format_name_of(int v) { return ds_format_name((ds_format)v); }

ds_status ds_format_parse(const char *name, ds_format *out, ds_error *err)
{
    int v = 0;
    const ds_status st =
        ds_parse_name("format", name, DS_FORMAT_COUNT, format_name_of, out ? &v : NULL, err);
    if (st == DS_OK)
        *out = (ds_format)v;
    return st;
}

ds_status ds_writer_open(ds_format format, FILE *out, unsigned flags, ds_writer **writer,
                         ds_error *err)
{
    ds_error_clear(err);
    if (writer)
        *writer = NULL;
    const ds_writer_ops *ops = ds_writer_ops_of(format);
    if (!ops)
        return ds_refuse(err, DS_ERR_ARG, "format", (double)format, (double)DS_FORMAT_COUNT,
                         "format = %d is not a ds_format", (int)format);
    if (!out || !writer)
        return ds_refuse(err, DS_ERR_ARG, out ? "writer" : "out", NAN, NAN, "%s: no %s (NULL)",
                         out ? "writer" : "out",
                         out ? "place for the writer" : "stream to write to");
    if (flags & ~ops->flags)
        return ds_refuse(err, DS_ERR_ARG, "flags", (double)flags, (double)ops->flags,
                         "flags = 0x%x: the %s writer takes 0x%x at most", flags, ops->name,
                         ops->flags);
    ds_writer *w = calloc(1, sizeof *w);
    if (!w)
        return ds_refuse(err, DS_ERR_NOMEM, "writer", NAN, NAN, "writer: no memory for it");
    w->ops = ops;
    w->out = out;
    w->flags = flags;
    const ds_status st = ops->open ? ops->open(out, flags, &w->self, err) : DS_OK;
    if (st != DS_OK) {
        free(w);
        return ds_error_done(err, st);
    }
    *writer = w;
    return DS_OK;
}

ds_status ds_writer_write(ds_writer *writer, const ds_sim *sim, ds_error *err)
{
    ds_error_clear(err);
    if (!writer || !sim)
        return ds_refuse(err, DS_ERR_ARG, writer ? "sim" : "writer", NAN, NAN, "%s: NULL",
                         writer ? "sim" : "writer");
    return ds_error_done(err,
                         writer->ops->frame(writer->self, writer->out, writer->flags, sim, err));
}

ds_status ds_writer_close(ds_writer *writer, ds_error *err)
{
    ds_error_clear(err);
    if (!writer)
        return DS_OK;
    const ds_status st =
        writer->ops->close ? writer->ops->close(writer->self, writer->out, err) : DS_OK;
    free(writer);
    return ds_error_done(err, st);
}
