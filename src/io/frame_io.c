/* SPDX-License-Identifier: MIT */
/* Frame files: one line per disk, "x y R" or "x y R vx vy". The numbers
 * are formatted by number_text.c (fixed six decimals by hand, exactly as
 * printf would: fprintf("%.6f") dominated the cost of `disks 400 5`). */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"

size_t ds_radius_text(const ds_sim *sim, char out[DS_RADIUS_TEXT_MAX])
{
    ds_format_shortest(out, DS_RADIUS_TEXT_MAX, sim->world.radius);
    /* The longest shortest form: a sign, 17 digits, a point, "e-308". */
    return sim->disks.r ? 24 : strlen(out);
}

void ds_radius_cache_init(ds_radius_cache *c, const ds_sim *sim)
{
    c->value = sim->world.radius;
    ds_format_shortest(c->text, sizeof c->text, c->value);
    c->len = strlen(c->text);
}

const char *ds_radius_at(const ds_sim *sim, size_t k, ds_radius_cache *c, size_t *len)
{
    const double r = sim->disks.r ? sim->disks.r[k] : sim->world.radius;
    if (r != c->value) {
        c->value = r;
        ds_format_shortest(c->text, sizeof c->text, r);
        c->len = strlen(c->text);
    }
    *len = c->len;
    return c->text;
}

size_t ds_frame_get_size(const ds_sim *sim, int velocities)
{
    if (!sim)
        return 0;
    char radius[DS_RADIUS_TEXT_MAX];
    size_t fields = velocities ? 4 : 2;
    size_t line = fields * (DS_FIELD_MAX + 1) + ds_radius_text(sim, radius) + 2;
    return sim->world.n * line;
}

ds_status ds_refuse_cap(ds_error *err, size_t cap, size_t need)
{
    return ds_refuse(err, DS_ERR_ARG, "cap", (double)cap, (double)need,
                     "cap = %zu bytes is too small: the text needs %zu", cap, need);
}

ds_status ds_frame_format(const ds_sim *sim, int velocities, char *buf, size_t cap, size_t *len,
                          ds_error *err)
{
    ds_error_clear(err);
    if (len)
        *len = 0;
    /* buf NULL with cap 0 asks only for the size: the loop copies nothing. */
    if (!sim || (!buf && cap))
        return ds_refuse(err, DS_ERR_ARG, sim ? "buf" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "buf" : "sim");
    ds_radius_cache radius;
    ds_radius_cache_init(&radius, sim);
    const ds_disks *d = &sim->disks;
    char line[4 * (DS_FIELD_MAX + 1) + 40];
    size_t used = 0;
    for (size_t i = 0; i < d->n; ++i) {
        const size_t k = d->slot[i];
        size_t l = ds_format_fixed6(line, d->x[k]);
        line[l++] = ' ';
        l += ds_format_fixed6(line + l, d->y[k]);
        line[l++] = ' ';
        size_t rlen = 0;
        const char *r = ds_radius_at(sim, k, &radius, &rlen);
        memcpy(line + l, r, rlen);
        l += rlen;
        if (velocities) {
            line[l++] = ' ';
            l += ds_format_fixed6(line + l, d->vx[k]);
            line[l++] = ' ';
            l += ds_format_fixed6(line + l, d->vy[k]);
        }
        line[l++] = '\n';
        if (used + l <= cap)
            memcpy(buf + used, line, l);
        used += l;
    }
    if (len)
        *len = used;
    return used <= cap ? DS_OK : ds_refuse_cap(err, cap, used);
}

ds_status ds_write_formatted(const ds_sim *sim, int velocities, FILE *out, size_t cap,
                             ds_format_fn format, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !out)
        return ds_refuse(err, DS_ERR_ARG, sim ? "out" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "out" : "sim");
    size_t len = 0;
    char *buf = malloc(cap ? cap : 1);
    if (!buf)
        return ds_refuse(err, DS_ERR_NOMEM, "out", NAN, NAN,
                         "out: no memory for the %zu bytes of the text", cap);
    ds_status st = format(sim, velocities, buf, cap, &len, err);
    /* fwrite into stdio's buffer succeeds even on a full disk: only the
     * flush reaches the file, so its result (and the sticky error flag, set
     * by any earlier failed write on this stream) decides. */
    if (st == DS_OK && (fwrite(buf, 1, len, out) != len || fflush(out) != 0 || ferror(out)))
        st = ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: the write of %zu bytes failed", len);
    free(buf);
    return st;
}

ds_status ds_frame_write(const ds_sim *sim, int velocities, FILE *out, ds_error *err)
{
    return ds_write_formatted(sim, velocities != 0, out, ds_frame_get_size(sim, velocities != 0),
                              ds_frame_format, err);
}

/* The writer of frames: a text frame a write, one after another. */
static ds_status write_frame(void *self, FILE *out, unsigned flags, const ds_sim *sim,
                             ds_error *err)
{
    (void)self;
    return ds_frame_write(sim, (flags & DS_WRITE_VELOCITIES) != 0, out, err);
}

const ds_writer_ops ds_frame_writer = {
    .name = "frame",
    .flags = DS_WRITE_VELOCITIES,
    .open = NULL,
    .frame = write_frame,
    .close = NULL,
};

/* ------------------------------------------------------------------ */
/* Reading                                                             */
/* ------------------------------------------------------------------ */

/* Longest line accepted: five numbers of 17 significant digits with
 * exponents fit in well under this; anything longer is not a frame line. */
#define LINE_MAX_BYTES 512

/* A frame refused at a line (0: not about a line), the reason alone. */
static ds_status fail(ds_error *err, size_t line, const char *message)
{
    ds_error_index(err, line);
    return ds_refuse(err, DS_ERR_FORMAT, "frame", NAN, NAN, "%s", message);
}

void ds_frame_free(ds_frame *frame)
{
    if (!frame)
        return;
    free(frame->disks);
    frame->disks = NULL;
    frame->count = 0;
    frame->columns = 0;
}

/* Parses one line (NUL-terminated copy, no newline) into values. Returns
 * the number of numbers, or -1 with *why set. */
static int parse_numbers(const char *s, double values[5], const char **why)
{
    int count = 0;
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\r')
            ++s;
        if (*s == '\0')
            return count;
        if (count == 5) {
            *why = "expected 3 or 5 numbers";
            return -1;
        }
        char *end;
        errno = 0;
        double v = strtod(s, &end);
        if (end == s || (*end != '\0' && *end != ' ' && *end != '\t' && *end != '\r')) {
            *why = "not a number";
            return -1;
        }
        if (!isfinite(v) || errno == ERANGE) {
            *why = "number is not finite";
            return -1;
        }
        values[count++] = v;
        s = end;
    }
}

/* Every error leaves *frame empty, an argument error included, so a caller
 * may always ds_frame_free it. */
static void clear_frame(ds_frame *frame, ds_error *err)
{
    ds_error_clear(err);
    if (frame) {
        frame->disks = NULL;
        frame->count = 0;
        frame->columns = 0;
    }
}

/* d after the count disks of *disks (room for cap), which grows by
 * doubling. */
static ds_status add_disk(ds_frame_disk **disks, size_t *count, size_t *cap, ds_frame_disk d,
                          ds_error *err)
{
    if (*count == *cap) {
        const size_t ncap = *cap ? 2 * *cap : 256;
        ds_frame_disk *grown = realloc(*disks, ncap * sizeof *grown);
        if (!grown)
            return ds_refuse(err, DS_ERR_NOMEM, "frame", NAN, NAN, "frame: no memory for %zu disks",
                             ncap);
        *disks = grown;
        *cap = ncap;
    }
    (*disks)[(*count)++] = d;
    return DS_OK;
}

ds_status ds_frame_parse(const char *text, size_t len, ds_frame *frame, ds_error *err)
{
    clear_frame(frame, err);
    if (!frame || (!text && len))
        return ds_refuse(err, DS_ERR_ARG, frame ? "text" : "frame", NAN, NAN, "%s: NULL",
                         frame ? "text" : "frame");

    size_t cap = 0, count = 0, line_no = 0;
    int columns = 0;
    ds_frame_disk *disks = NULL;
    ds_status st = DS_OK;
    char line[LINE_MAX_BYTES + 1];

    size_t pos = 0;
    while (pos < len) {
        ++line_no;
        const char *start = text + pos;
        const char *nl = memchr(start, '\n', len - pos);
        size_t l = nl ? (size_t)(nl - start) : len - pos;
        pos += l + (nl ? 1 : 0);
        /* NUL first: binary input is named as such, not as a long line. */
        if (memchr(start, '\0', l)) {
            st = fail(err, line_no, "unexpected NUL byte");
            goto out;
        }
        if (l > LINE_MAX_BYTES) {
            st = fail(err, line_no, "line too long");
            goto out;
        }
        memcpy(line, start, l);
        line[l] = '\0';

        const char *first = line + strspn(line, " \t\r");
        if (*first == '\0' || *first == '#')
            continue;
        double v[5];
        const char *why = NULL;
        int got = parse_numbers(first, v, &why);
        if (got < 0) {
            st = fail(err, line_no, why);
            goto out;
        }
        if (got != 3 && got != 5) {
            st = fail(err, line_no, "expected 3 or 5 numbers");
            goto out;
        }
        if (columns == 0) {
            columns = got;
        } else if (got != columns) {
            st = fail(err, line_no,
                      columns == 3 ? "expected 3 numbers like the first line"
                                   : "expected 5 numbers like the first line");
            goto out;
        }
        if (!(v[2] > 0.0)) {
            st = fail(err, line_no, "radius must be positive");
            goto out;
        }
        ds_frame_disk d = {v[0], v[1], v[2], got == 5 ? v[3] : 0.0, got == 5 ? v[4] : 0.0};
        if ((st = add_disk(&disks, &count, &cap, d, err)) != DS_OK)
            goto out;
    }
    if (count == 0) {
        st = fail(err, 0, "empty frame: no disks");
        goto out;
    }
    frame->disks = disks;
    frame->count = count;
    frame->columns = columns;
    return DS_OK;
out:
    free(disks);
    return st;
}

ds_status ds_frame_read(const char *path, ds_frame *frame, ds_error *err)
{
    clear_frame(frame, err);
    if (!path || !frame)
        return ds_refuse(err, DS_ERR_ARG, path ? "frame" : "path", NAN, NAN, "%s: NULL",
                         path ? "frame" : "path");
    FILE *f = fopen(path, "rb");
    if (!f)
        return ds_refuse(err, DS_ERR_IO, "path", NAN, NAN, "cannot open: %s", strerror(errno));
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    ds_status st =
        buf ? DS_OK : ds_refuse(err, DS_ERR_NOMEM, "path", NAN, NAN, "no memory to read it");
    while (st == DS_OK) {
        if (len == cap) {
            char *grown = cap < ((size_t)1 << 40) ? realloc(buf, 2 * cap) : NULL;
            if (!grown) {
                st = ds_refuse(err, DS_ERR_NOMEM, "path", NAN, NAN,
                               "no memory to read more than %zu bytes", cap);
                break;
            }
            buf = grown;
            cap *= 2;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        /* A frame is text: at the first NUL byte stop reading and let the
         * parser name the line, so binary or endless input (/dev/zero, a
         * device, a wrong file) is refused at once instead of slurped. */
        int binary = got && memchr(buf + len, '\0', got) != NULL;
        len += got;
        if (binary)
            break;
        if (got == 0) {
            if (ferror(f))
                st = ds_refuse(err, DS_ERR_IO, "path", NAN, NAN, "read error: %s", strerror(errno));
            break;
        }
    }
    fclose(f);
    if (st == DS_OK)
        st = ds_frame_parse(buf, len, frame, err);
    free(buf);
    return st;
}
