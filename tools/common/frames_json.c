/* SPDX-License-Identifier: MIT */
/* A JSON reader just large enough for frames.json: one object whose
 * values this reader checks by key, anything else (strings, numbers,
 * literals, arrays and objects nested up to MAX_DEPTH) skipped. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frames_json.h"

#define MAX_BYTES (1 << 20) /* disks writes under 1 kB */
#define MAX_DEPTH 32

typedef struct parser {
    const char *p, *end, *path;
    int line;
    char *err;
    size_t errlen;
    int failed;
} parser;

#if defined(__GNUC__)
#define FORMAT_2_3 __attribute__((format(printf, 2, 3)))
#else
#define FORMAT_2_3
#endif

static int fail(parser *ps, const char *fmt, ...) FORMAT_2_3;

/* Keeps the first failure: its line is where the reader stopped. */
static int fail(parser *ps, const char *fmt, ...)
{
    if (ps->failed)
        return -1;
    char why[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, sizeof why, fmt, ap);
    va_end(ap);
    snprintf(ps->err, ps->errlen, "%s:%d: %s", ps->path, ps->line, why);
    ps->failed = 1;
    return -1;
}

static void skip_space(parser *ps)
{
    for (; ps->p < ps->end && strchr(" \t\r\n", *ps->p); ++ps->p)
        ps->line += *ps->p == '\n';
}

/* Takes c if it comes next: 1, else 0. */
static int take(parser *ps, char c)
{
    skip_space(ps);
    if (ps->p < ps->end && *ps->p == c) {
        ++ps->p;
        return 1;
    }
    return 0;
}

static int expect(parser *ps, char c) { return take(ps, c) ? 0 : fail(ps, "expected '%c'", c); }

/* A string into out (cap bytes; longer ones cut, which no key or name of
 * disks's reaches); \uXXXX beyond ASCII becomes '?'. */
static int string(parser *ps, char *out, size_t cap)
{
    if (expect(ps, '"'))
        return -1;
    size_t n = 0;
    while (ps->p < ps->end && *ps->p != '"') {
        char c = *ps->p++;
        if ((unsigned char)c < 0x20)
            return fail(ps, "a control character inside a string");
        if (c == '\\') {
            if (ps->p >= ps->end)
                break;
            const char e = *ps->p++;
            static const char escapes[] = "\"\\/bfnrt", meant[] = "\"\\/\b\f\n\r\t";
            const char *plain = e ? strchr(escapes, e) : NULL;
            if (e == 'u') {
                if (ps->end - ps->p < 4 || strspn(ps->p, "0123456789abcdefABCDEF") < 4)
                    return fail(ps, "a bad \\u escape");
                const long code =
                    strtol((char[5]){ps->p[0], ps->p[1], ps->p[2], ps->p[3], 0}, NULL, 16);
                c = code < 0x80 ? (char)code : '?';
                ps->p += 4;
            } else if (plain) {
                c = meant[plain - escapes];
            } else {
                return fail(ps, "a bad escape '\\%c'", e);
            }
        }
        if (n + 1 < cap)
            out[n++] = c;
    }
    if (ps->p >= ps->end)
        return fail(ps, "a string that does not end");
    ++ps->p;
    if (cap)
        out[n] = '\0';
    return 0;
}

/* A JSON number (no nan, inf or hex: a digit or '-' first) if one comes
 * next: 0, else -1 with nothing said or taken. */
static int try_number(parser *ps, double *v)
{
    skip_space(ps);
    if (ps->p >= ps->end || !(*ps->p == '-' || (*ps->p >= '0' && *ps->p <= '9')))
        return -1;
    char *stop;
    errno = 0;
    const double got = strtod(ps->p, &stop);
    /* strtod reads more than JSON ("0x1p3"): it must stop where the
     * characters of a JSON number do. */
    if (stop != ps->p + strspn(ps->p, "0123456789+-.eE") || errno || !isfinite(got))
        return -1;
    *v = got;
    ps->p = stop;
    return 0;
}

static int number(parser *ps, double *v)
{
    return try_number(ps, v) == 0 ? 0 : fail(ps, "expected a finite number");
}

static int literal(parser *ps, const char *word)
{
    skip_space(ps);
    const size_t n = strlen(word);
    if ((size_t)(ps->end - ps->p) < n || strncmp(ps->p, word, n) != 0)
        return -1;
    ps->p += n;
    return 0;
}

static int skip_value(parser *ps, int depth);

/* The items of an array or the members of an object, after its opening
 * bracket, up to its closing one. */
static int skip_items(parser *ps, int depth, char close, int members)
{
    skip_space(ps);
    if (ps->p < ps->end && *ps->p == close) {
        ++ps->p;
        return 0;
    }
    for (;;) {
        char key[8];
        if (members && (string(ps, key, sizeof key) || expect(ps, ':')))
            return -1;
        if (skip_value(ps, depth + 1))
            return -1;
        skip_space(ps);
        if (ps->p < ps->end && *ps->p == ',') {
            ++ps->p;
            continue;
        }
        return expect(ps, close);
    }
}

static int skip_value(parser *ps, int depth)
{
    skip_space(ps);
    if (depth > MAX_DEPTH)
        return fail(ps, "nested deeper than %d", MAX_DEPTH);
    if (ps->p >= ps->end)
        return fail(ps, "expected a value");
    double v;
    char s[8];
    switch (*ps->p) {
    case '"':
        return string(ps, s, sizeof s);
    case '[':
        ++ps->p;
        return skip_items(ps, depth, ']', 0);
    case '{':
        ++ps->p;
        return skip_items(ps, depth, '}', 1);
    default:
        if (!literal(ps, "true") || !literal(ps, "false") || !literal(ps, "null"))
            return 0;
        return number(ps, &v);
    }
}

/* A whole number in [lo, hi]. */
static int whole(parser *ps, const char *key, double lo, double hi, double *v)
{
    if (number(ps, v) || !(*v >= lo && *v <= hi) || *v != floor(*v))
        return fail(ps, "\"%s\" must be a whole number from %.0f to %.0f", key, lo, hi);
    return 0;
}

static int positive(parser *ps, const char *key, double *v)
{
    if (number(ps, v) || !(*v > 0.0))
        return fail(ps, "\"%s\" must be a positive number", key);
    return 0;
}

/* The value of a key this reader knows, checked; others skipped. */
static int member(parser *ps, const char *key, fj_run *run)
{
    double v = 0.0, w = 0.0;
    char name[32];
    if (!strcmp(key, "disksim_frames")) {
        if (number(ps, &v) || v != 1.0)
            return fail(ps, "\"disksim_frames\" is %g: a later format than this reader's (1)", v);
    } else if (!strcmp(key, "box")) {
        if (!take(ps, '[') || try_number(ps, &v) || !take(ps, ',') || try_number(ps, &w) ||
            !take(ps, ']') || !(v > 0.0) || !(w > 0.0))
            return fail(ps, "\"box\" must be [width, height], two positive numbers");
        run->box_x = v;
        run->box_y = w;
    } else if (!strcmp(key, "boundary")) {
        ds_boundary b;
        if (string(ps, name, sizeof name) || ds_boundary_parse(name, &b, NULL) != DS_OK)
            return fail(ps, "\"boundary\" must be \"walls\", \"periodic\" or \"channel\"");
        run->boundary = (int)b;
    } else if (!strcmp(key, "n")) {
        if (whole(ps, key, 0, 1e15, &v))
            return -1;
        run->n = (long)v;
    } else if (!strcmp(key, "radius") || !strcmp(key, "dt")) {
        if (positive(ps, key, key[0] == 'r' ? &run->radius : &run->dt))
            return -1;
    } else if (!strcmp(key, "steps_per_frame")) {
        if (whole(ps, key, 1, 1e15, &v))
            return -1;
        run->steps_per_frame = (uint64_t)v;
    } else if (!strcmp(key, "velocities")) {
        run->velocities = !literal(ps, "true") ? 1 : !literal(ps, "false") ? 0 : -2;
        if (run->velocities == -2)
            return fail(ps, "\"velocities\" must be true or false");
    } else if (!strcmp(key, "jammed_frame")) {
        if (whole(ps, key, 0, 1e15, &v))
            return -1;
        run->jammed_frame = (long)v;
    } else if (!strcmp(key, "jammed_time")) {
        if (number(ps, &run->jammed_time) || !(run->jammed_time >= 0.0))
            return fail(ps, "\"jammed_time\" must be a number >= 0");
    } else {
        return skip_value(ps, 1);
    }
    return 0;
}

static int object(parser *ps, fj_run *run)
{
    if (expect(ps, '{'))
        return -1;
    skip_space(ps);
    if (ps->p < ps->end && *ps->p == '}')
        ++ps->p;
    else
        for (;;) {
            char key[64];
            if (string(ps, key, sizeof key) || expect(ps, ':') || member(ps, key, run))
                return -1;
            skip_space(ps);
            if (ps->p < ps->end && *ps->p == ',') {
                ++ps->p;
                continue;
            }
            if (expect(ps, '}'))
                return -1;
            break;
        }
    skip_space(ps);
    if (ps->p != ps->end)
        return fail(ps, "text after the object");
    return 0;
}

int fj_read(const char *dir, fj_run *run, char *err, size_t errlen)
{
    *run = (fj_run){0.0, 0.0, -1, -1, 0.0, 0.0, 0, -1, -1, 0.0};
    char path[4200];
    const size_t d = strlen(dir);
    snprintf(path, sizeof path, "%s%s%s", dir, d && dir[d - 1] == '/' ? "" : "/", FJ_NAME);
    FILE *f = fopen(path, "rb");
    if (!f && errno == ENOENT)
        return 0;
    if (!f) {
        snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    char *text = malloc(MAX_BYTES + 1);
    errno = 0;
    size_t len = text ? fread(text, 1, MAX_BYTES + 1, f) : 0;
    const int failed = !text || ferror(f), saved = errno ? errno : EIO;
    fclose(f);
    if (failed || len > MAX_BYTES) {
        snprintf(err, errlen, "%s: %s", path,
                 !text    ? "out of memory"
                 : failed ? strerror(saved)
                          : "larger than 1 MB: not a frames.json");
        free(text);
        return -1;
    }
    text[len] = '\0';
    if (memchr(text, '\0', len)) {
        snprintf(err, errlen, "%s: a NUL byte: not a frames.json", path);
        free(text);
        return -1;
    }
    parser ps = {text, text + len, path, 1, err, errlen, 0};
    const int rc = object(&ps, run);
    free(text);
    return rc == 0 ? 1 : -1;
}

double fj_frame_time(const fj_run *run, long k)
{
    if (run->jammed_frame >= 0 && k == run->jammed_frame)
        return run->jammed_time;
    if (!(run->dt > 0.0) || run->steps_per_frame == 0)
        return NAN;
    return (double)k * (double)run->steps_per_frame * run->dt;
}
