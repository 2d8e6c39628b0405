/* SPDX-License-Identifier: MIT */
/* The command line's values read and held to what they must be: whole
 * numbers, decimal numbers, names the library parses, file names
 * (options.c reads the command line with them; cli.h declares them). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

/* strtod also reads hexadecimal ("0x10"), "nan" and "infinity": a number
 * on our command line is decimal, so anything else is refused up front. */
int is_decimal_text(const char *s) { return *s && strspn(s, "0123456789.eE+-") == strlen(s); }

/* A non-negative integer: digits only, or an exact integer in decimal
 * scientific notation (1e5), no sign, no trailing text. */
static int parse_count(const char *s, uint64_t max, uint64_t *out)
{
    if (!is_decimal_text(s) || *s == '-' || *s == '+')
        return 0;
    char *end;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (*end == '\0' && end != s) {
        if (errno == ERANGE || v > max)
            return -1;
        *out = v;
        return 1;
    }
    double d = strtod(s, &end);
    if (*end != '\0' || end == s || !isfinite(d) || d != floor(d) || d < 0.0)
        return errno == ERANGE ? -1 : 0;
    /* (double)UINT64_MAX rounds up to 2^64, and converting 2^64 to uint64_t
     * is undefined: test against 2^64 itself, then compare as integers. */
    if (!(d < 18446744073709551616.0) || (uint64_t)d > max)
        return -1;
    *out = (uint64_t)d;
    return 1;
}

uint64_t count_arg(const char *name, const char *s, uint64_t min, uint64_t max)
{
    uint64_t v = 0;
    int ok = parse_count(s, max, &v);
    if (ok == 0)
        die(EXIT_USAGE, "%s must be a whole number, got '%s'", name, s);
    if (ok < 0 || v < min)
        die(EXIT_USAGE, "%s must be between %llu and %llu, got '%s'", name, (unsigned long long)min,
            (unsigned long long)max, s);
    return v;
}

double radius_arg(const char *s)
{
    char *end;
    errno = 0;
    double r = strtod(s, &end);
    if (end == s || *end != '\0')
        die(EXIT_USAGE, "R must be a number, got '%s'", s);
    /* ERANGE on underflow (1e-400) leaves r tiny: the range check below
     * names it better than "not finite". */
    if (!isfinite(r) || (errno == ERANGE && fabs(r) > 1.0))
        die(EXIT_USAGE, "R must be a finite number, got '%s'", s);
    if (!is_decimal_text(s))
        die(EXIT_USAGE, "R must be a decimal number, got '%s'", s);
    if (!(r > 0.0))
        die(EXIT_USAGE, "R must be a number > 0, got '%s'", s);
    return r;
}

/* A side of the box (--box, --box-y). */
double side_arg(const char *option, const char *s)
{
    char *end;
    double h = strtod(s, &end);
    if (!is_decimal_text(s) || end == s || *end != '\0' || !isfinite(h) || !(h > 0.0 && h <= 1e9))
        die(EXIT_USAGE, "%s must be a number > 0 and <= 1e9, got '%s'", option, s);
    return h;
}

/* A decimal number > 0 (and below a bound, when one is given). */
double positive_arg(const char *option, const char *s, double most)
{
    char *end;
    double v = strtod(s, &end);
    const int number = is_decimal_text(s) && end != s && *end == '\0' && isfinite(v);
    if (!number || !(v > 0.0))
        die(EXIT_USAGE, "%s must be a number > 0, got '%s'", option, s);
    if (most > 0.0 && !(v <= most))
        die(EXIT_USAGE, "%s must be a number > 0 and <= %g, got '%s'", option, most, s);
    return v;
}

/* --mixture RATIO:FRACTION: two decimal numbers, RATIO > 0 (the library
 * holds the large disks to the box), 0 < FRACTION < 1. */
void mixture_arg(const char *s, options *o)
{
    const char *colon = strchr(s, ':');
    char ratio[64];
    if (!colon || (size_t)(colon - s) >= sizeof ratio)
        die(EXIT_USAGE, "--mixture must be RATIO:FRACTION (e.g. 1.4:0.5), got '%s'", s);
    memcpy(ratio, s, (size_t)(colon - s));
    ratio[colon - s] = '\0';
    char *end;
    const double r = strtod(ratio, &end), f = strtod(colon + 1, &end);
    if (!is_decimal_text(ratio) || !is_decimal_text(colon + 1) || *end != '\0' ||
        !(isfinite(r) && r > 0.0) || !(f > 0.0 && f < 1.0))
        die(EXIT_USAGE,
            "--mixture must be RATIO:FRACTION, a radius ratio > 0 and a fraction between 0 "
            "and 1 (e.g. 1.4:0.5), got '%s'",
            s);
    o->mix_ratio = r;
    o->mix_fraction = f;
    o->mixture_text = s;
}

/* A name the library does not know, in the command's words
 * ("--integrator 'exact' is not one of 'step', 'event'"). */
void refuse_name(ds_status st, const ds_error *err)
{
    if (st != DS_OK) {
        char words[sizeof err->message + 16];
        die(EXIT_USAGE, "%s", in_command_words(err, words, sizeof words));
    }
}

/* A file name given to an option. */
const char *file_arg(const char *option, const char *value)
{
    if (!*value)
        die(EXIT_USAGE, "%s needs a file name", option);
    return value;
}
