/* SPDX-License-Identifier: MIT */
/* What the analysis tools share: reading a number from the command line,
 * block averages with their standard errors (and a series' error
 * corrected for its correlation), and Enskog's shear viscosity (the
 * reference of tools/transport and tools/rheology). */
#ifndef DS_ANALYSIS_UTIL_H
#define DS_ANALYSIS_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* s as a number in [lo, hi], or a message naming program and what, and
 * exit status 2. */
static inline double tool_number(const char *program, const char *s, double lo, double hi,
                                 const char *what)
{
    char *end;
    const double v = strtod(s, &end);
    if (end == s || *end || !(v >= lo && v <= hi)) {
        fprintf(stderr, "%s: %s must be a number in [%g, %g], got '%s'\n", program, what, lo, hi,
                s);
        exit(2);
    }
    return v;
}

/* Block values as they come: their mean and the standard error of that
 * mean, sqrt(var / (count - 1)), honest when the blocks are longer than
 * the time over which the quantity stays correlated. */
typedef struct stats {
    double sum, sum2;
    int count;
} stats;

static inline void add(stats *s, double v)
{
    s->sum += v;
    s->sum2 += v * v;
    ++s->count;
}

static inline double mean(const stats *s) { return s->count ? s->sum / s->count : 0.0; }

static inline double error(const stats *s)
{
    const double m = mean(s), var = s->sum2 / s->count - m * m;
    return s->count > 1 && var > 0.0 ? sqrt(var / (s->count - 1)) : 0.0;
}

/* The mean of n samples of a correlated series, and its standard error
 * corrected for the correlation (Flyvbjerg and Petersen 1989): the
 * samples averaged in pairs again and again, the naive error of each
 * level's blocks grows until the blocks are longer than the series'
 * memory, then stays; the largest over the levels that keep 32 blocks or
 * more (one level below that the estimate itself is uncertain by a
 * quarter). x is overwritten. */
static inline double blocked_mean(double *x, size_t n, double *err)
{
    double m = 0.0;
    for (size_t i = 0; i < n; ++i)
        m += x[i];
    m = n ? m / (double)n : 0.0;
    *err = 0.0;
    for (; n >= 32; n /= 2) {
        double v = 0.0;
        for (size_t i = 0; i < n; ++i)
            v += (x[i] - m) * (x[i] - m);
        *err = fmax(*err, sqrt(v / ((double)n * (double)(n - 1))));
        for (size_t i = 0; i < n / 2; ++i)
            x[i] = 0.5 * (x[2 * i] + x[2 * i + 1]);
    }
    return m;
}

/* Enskog's shear viscosity of disks of diameter sigma at area fraction
 * eta, contact value g and temperature kT (unit mass), with Gass's
 * second Sonine approximation's factor 1.022 (Gass 1971):
 *   eta_E = 1.022 eta_0 (1 / g + 2 eta + (1 + 8 / pi) eta^2 g),
 *   eta_0 = (1 / (2 sigma)) sqrt(kT / pi). */
static inline double tool_enskog_viscosity(double kt, double sigma, double eta, double g)
{
    const double pi = 3.14159265358979323846;
    const double eta_0 = sqrt(kt / pi) / (2.0 * sigma);
    return 1.022 * eta_0 * (1.0 / g + 2.0 * eta + (1.0 + 8.0 / pi) * eta * eta * g);
}

#endif
