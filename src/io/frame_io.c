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
    return strlen(out);
}

size_t ds_frame_size(const ds_sim *sim, int velocities)
{
    if (!sim)
        return 0;
    char radius[DS_RADIUS_TEXT_MAX];
    size_t fields = velocities ? 4 : 2;
    size_t line = fields * (DS_FIELD_MAX + 1) + ds_radius_text(sim, radius) + 2;
    return sim->world.n * line;
}

ds_status ds_format_frame(const ds_sim *sim, int velocities, char *buf, size_t cap, size_t *len)
{
    if (len)
        *len = 0;
    /* buf NULL with cap 0 asks only for the size: the loop copies nothing. */
    if (!sim || (!buf && cap))
        return DS_ERR_ARG;
    char radius[DS_RADIUS_TEXT_MAX];
    const size_t rlen = ds_radius_text(sim, radius);
    const ds_disks *d = &sim->disks;
    char line[4 * (DS_FIELD_MAX + 1) + 40];
    size_t used = 0;
    for (size_t i = 0; i < d->n; ++i) {
        const size_t k = d->slot[i];
        size_t l = ds_format_fixed6(line, d->x[k]);
        line[l++] = ' ';
        l += ds_format_fixed6(line + l, d->y[k]);
        line[l++] = ' ';
        memcpy(line + l, radius, rlen);
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
    return used <= cap ? DS_OK : DS_ERR_ARG;
}

ds_status ds_write_formatted(const ds_sim *sim, int velocities, FILE *out, size_t cap,
                             ds_format_fn format)
{
    if (!sim || !out)
        return DS_ERR_ARG;
    size_t len = 0;
    char *buf = malloc(cap ? cap : 1);
    if (!buf)
        return DS_ERR_NOMEM;
    ds_status st = format(sim, velocities, buf, cap, &len);
    /* fwrite into stdio's buffer succeeds even on a full disk: only the
     * flush reaches the file, so its result (and the sticky error flag, set
     * by any earlier failed write on this stream) decides. */
    if (st == DS_OK && (fwrite(buf, 1, len, out) != len || fflush(out) != 0 || ferror(out)))
        st = DS_ERR_IO;
    free(buf);
    return st;
}

ds_status ds_write_frame(const ds_sim *sim, FILE *out)
{
    return ds_write_formatted(sim, 0, out, ds_frame_size(sim, 0), ds_format_frame);
}

ds_status ds_write_frame_velocities(const ds_sim *sim, FILE *out)
{
    return ds_write_formatted(sim, 1, out, ds_frame_size(sim, 1), ds_format_frame);
}

/* ------------------------------------------------------------------ */
/* Reading                                                             */
/* ------------------------------------------------------------------ */

/* Longest line accepted: five numbers of 17 significant digits with
 * exponents fit in well under this; anything longer is not a frame line. */
#define LINE_MAX_BYTES 512

static ds_status fail(ds_frame_error *err, size_t line, const char *message)
{
    if (err) {
        err->line = line;
        snprintf(err->message, sizeof err->message, "%s", message);
    }
    return DS_ERR_FORMAT;
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
static void clear_frame(ds_frame *frame, ds_frame_error *err)
{
    if (err) {
        err->line = 0;
        err->message[0] = '\0';
    }
    if (frame) {
        frame->disks = NULL;
        frame->count = 0;
        frame->columns = 0;
    }
}

ds_status ds_parse_frame(const char *text, size_t len, ds_frame *frame, ds_frame_error *err)
{
    clear_frame(frame, err);
    if (!frame || (!text && len))
        return DS_ERR_ARG;

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
        if (count == cap) {
            size_t ncap = cap ? 2 * cap : 256;
            ds_frame_disk *grown = realloc(disks, ncap * sizeof *grown);
            if (!grown) {
                st = DS_ERR_NOMEM;
                goto out;
            }
            disks = grown;
            cap = ncap;
        }
        ds_frame_disk d = {v[0], v[1], v[2], got == 5 ? v[3] : 0.0, got == 5 ? v[4] : 0.0};
        disks[count++] = d;
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

ds_status ds_read_frame(const char *path, ds_frame *frame, ds_frame_error *err)
{
    clear_frame(frame, err);
    if (!path || !frame)
        return DS_ERR_ARG;
    FILE *f = fopen(path, "rb");
    if (!f) {
        if (err)
            snprintf(err->message, sizeof err->message, "cannot open: %s", strerror(errno));
        return DS_ERR_IO;
    }
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    ds_status st = buf ? DS_OK : DS_ERR_NOMEM;
    while (st == DS_OK) {
        if (len == cap) {
            char *grown = cap < ((size_t)1 << 40) ? realloc(buf, 2 * cap) : NULL;
            if (!grown) {
                st = DS_ERR_NOMEM;
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
            if (ferror(f)) {
                if (err)
                    snprintf(err->message, sizeof err->message, "read error: %s", strerror(errno));
                st = DS_ERR_IO;
            }
            break;
        }
    }
    fclose(f);
    if (st == DS_OK)
        st = ds_parse_frame(buf, len, frame, err);
    free(buf);
    return st;
}
