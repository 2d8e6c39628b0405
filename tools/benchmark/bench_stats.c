/* SPDX-License-Identifier: MIT */
/* What the sections of tools/bench share: medians over rounds, and the
 * peak memory of the process (bench.h). */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <sys/resource.h>

#include "bench.h"

static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double median(double *v, int count)
{
    qsort(v, (size_t)count, sizeof *v, compare_doubles);
    return v[count / 2];
}

double median_ratio(const double *a, const double *b)
{
    double r[ROUNDS];
    for (int k = 0; k < ROUNDS; ++k)
        r[k] = a[k] / b[k];
    return median(r, ROUNDS);
}

long peak_rss_kb(void)
{
    struct rusage u;
    return getrusage(RUSAGE_SELF, &u) == 0 ? u.ru_maxrss : -1; /* KB on Linux */
}
