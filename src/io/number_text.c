/* SPDX-License-Identifier: MIT */
/* Numbers as text for the text formats (frames, trajectories): fixed six
 * decimals, formatted by hand because fprintf("%.6f") dominated the cost of
 * `disks 400 5` (the same digits as printf, ties to even, from integer
 * arithmetic and one fma), and the shortest form that reads back exactly. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/number_text.h"

/* Below this magnitude fixed six decimals are formatted by hand: at most
 * 15 integer digits, plus sign, point and 6 decimals. */
#define FAST_LIMIT 1e15

size_t ds_format_fixed6(char *out, double v)
{
    if (!(fabs(v) < FAST_LIMIT)) {
        /* Unreachable for positions inside a box <= 1e9; kept exact and
         * bounded for anything else (NaN, inf, huge velocities). */
        int len = snprintf(out, DS_FIELD_MAX, "%.6f", v);
        if (len < 0 || len >= DS_FIELD_MAX)
            len = snprintf(out, DS_FIELD_MAX, "%.9e", v);
        return (size_t)len;
    }
    char *p = out;
    double a = fabs(v);
    double ip = floor(a);
    double frac = a - ip;                        /* exact */
    double scaled = frac * 1e6;                  /* rounded product... */
    double err = fma(frac, 1e6, -scaled);        /* ...and its exact error */
    double q = floor(scaled), rest = scaled - q; /* rest exact */
    uint64_t micro = (uint64_t)q;
    /* Round the exact value frac*1e6 = q + rest + err to nearest, ties to
     * even: rest and err never straddle 0.5 unless rest is exactly 0.5. */
    if (rest > 0.5 || (rest == 0.5 && (err > 0.0 || (err == 0.0 && (micro & 1u)))))
        ++micro;
    uint64_t whole = (uint64_t)ip;
    if (micro == 1000000u) {
        micro = 0;
        ++whole;
    }
    if (signbit(v))
        *p++ = '-'; /* like printf, tiny negatives print as -0.000000 */
    char digits[24];
    int nd = 0;
    do {
        digits[nd++] = (char)('0' + whole % 10);
        whole /= 10;
    } while (whole);
    while (nd)
        *p++ = digits[--nd];
    *p++ = '.';
    for (int k = 5; k >= 0; --k) {
        p[k] = (char)('0' + micro % 10);
        micro /= 10;
    }
    p += 6;
    return (size_t)(p - out);
}

void ds_format_shortest(char *out, size_t cap, double v)
{
    /* The shortest %.Ng text that reads back as the same double: 5 -> "5".
     * Not simply the fewest digits: %.1g writes 10 as "1e+01", %.2g "10".
     * 17 digits always read back, so the loop always ends with an answer. */
    char best[32] = "", text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        int len = snprintf(text, sizeof text, "%.*g", digits, v);
        if (len > 0 && strtod(text, NULL) == v && (!best[0] || (size_t)len < strlen(best)))
            memcpy(best, text, (size_t)len + 1);
    }
    snprintf(out, cap, "%s", best);
}
