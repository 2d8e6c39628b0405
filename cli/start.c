/* SPDX-License-Identifier: MIT */
/* The request checked before any work: what the library would refuse, in
 * the command's words, and what this machine cannot hold. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"

/* The library's sentence about a field, in the command's words: a
 * message begins with the ds_params member it is about ("radius = 600
 * ..."), which the command calls by its option or argument. */
static const char *in_command_words(const char *field, const char *message, char *out, size_t cap)
{
    static const char *const names[][2] = {
        {"n", "N"},
        {"radius", "R"},
        {"box_y", "--box-y"},
        {"broadphase", "--broadphase"},
        {"integrator", "--integrator"},
    };
    const size_t flen = strlen(field);
    for (size_t k = 0; *field && k < sizeof names / sizeof names[0]; ++k) {
        if (strcmp(field, names[k][0]) != 0 || strncmp(message, field, flen) != 0 ||
            strncmp(message + flen, " = ", 3) != 0)
            continue;
        /* An option takes its value as "--box-y 5", an argument as "R = 5". */
        snprintf(out, cap, "%s%s%s", names[k][1], names[k][1][0] == '-' ? " " : " = ",
                 message + flen + 3);
        return out;
    }
    return message;
}

/* Refuses, before any work, what the library would refuse (in its words)
 * or what this machine cannot hold, and passes on its warnings. */
void check_request(const ds_params *p)
{
    unsigned warnings = 0;
    ds_params_error why;
    char words[sizeof why.message + 16];
    ds_status st = ds_diagnose_params(p, &warnings, &why);
    if (st == DS_ERR_NOMEM)
        die(EXIT_USAGE, "%s", in_command_words(why.field, why.message, words, sizeof words));
    size_t bytes = 0;
    if (st != DS_ERR_ARG && ds_memory_needed(p, &bytes) != DS_OK)
        die(EXIT_USAGE, "N = %zu disks cannot be held in memory", p->n);
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0 && (double)bytes > 0.8 * (double)pages * (double)page)
        die(EXIT_USAGE, "N = %zu disks need %.1f GiB, more than this machine's %.1f GiB", p->n,
            (double)bytes / 1073741824.0, (double)pages * (double)page / 1073741824.0);
    if (st != DS_OK)
        die(st == DS_ERR_PLACEMENT ? EXIT_RUN : EXIT_USAGE, "%s",
            in_command_words(why.field, why.message, words, sizeof words));
    if (warnings)
        fprintf(stderr, "disks: warning: %s\n",
                in_command_words("radius", why.warning, words, sizeof words));
}
