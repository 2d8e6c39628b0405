/* SPDX-License-Identifier: MIT */
/* "Did you mean ...?" for an option the command does not know: the known
 * name nearest to what was typed, by edit distance (insertions,
 * deletions, substitutions and swaps of two neighbours, as typos are
 * made), if it is near enough to be the one meant. */
#define _POSIX_C_SOURCE 200809L
#include <string.h>

#include "cli.h"

enum { LONGEST = 64 };

/* The optimal-string-alignment distance between a (la bytes) and b. */
static size_t distance(const char *a, size_t la, const char *b)
{
    const size_t lb = strlen(b);
    if (la >= LONGEST || lb >= LONGEST)
        return (size_t)-1;
    size_t d[LONGEST + 1][LONGEST + 1];
    for (size_t i = 0; i <= la; ++i)
        d[i][0] = i;
    for (size_t j = 0; j <= lb; ++j)
        d[0][j] = j;
    for (size_t i = 1; i <= la; ++i)
        for (size_t j = 1; j <= lb; ++j) {
            size_t best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[la][lb];
}

const char *closest_option(const char *typed, size_t len, const char *const *names, size_t count)
{
    const char *best = NULL;
    size_t best_d = (size_t)-1;
    for (size_t k = 0; k < count; ++k) {
        const size_t d = distance(typed, len, names[k]);
        if (d < best_d) {
            best_d = d;
            best = names[k];
        }
    }
    /* Two edits in a long name, one in a short one ("--perodic" is
     * "--periodic", "--bx" "--box"), none in a letter ("-x" is no "-h"). */
    const size_t allowed = len > 8 ? 2 : len > 3 ? 1 : 0;
    return best_d <= allowed ? best : NULL;
}
