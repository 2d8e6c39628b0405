/* SPDX-License-Identifier: MIT */
/* What the command says when it cannot go on: one line on stderr, then
 * the exit status (docs/cli.md, "Exit status"). */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

void die(int code, const char *fmt, ...)
{
    va_list ap;
    fputs("disks: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(code);
}

/* The library's names for what it refuses, the command's for the same:
 * its arguments N and R, and its options. */
static const char *const command_names[][2] = {
    {"n", "N"},
    {"radius", "R"},
    {"box", "--box"},
    {"box_y", "--box-y"},
    {"dt", "--dt"},
    {"speed", "--speed"},
    {"broadphase", "--broadphase"},
    {"integrator", "--integrator"},
    {"mass_rule", "--mass"},
    {"mixture", "--mixture"},
    {"rate", "--grow"},
    {"until_eta", "--until-eta"},
    {"until_z", "--until-z"},
    {"restitution", "--restitution"},
    {"wall_restitution", "--wall-restitution"},
    {"contact_time", "--contact-time"},
    {"strength", "--drive"},
    {"thermostat", "--thermostat"},
    {"kt", "--temperature"},
    {"collision_rate", "--thermostat-rate"},
    {"pressure", "--pressure"},
    {"max_step", "--barostat-step"},
    {"barostat", "--pressure"},
};

const char *in_command_words(const ds_error *err, char *out, size_t cap)
{
    const char *field = err->field, *message = err->message;
    const size_t flen = strlen(field);
    for (size_t k = 0; *field && k < sizeof command_names / sizeof command_names[0]; ++k) {
        const char *name = command_names[k][1];
        if (strcmp(field, command_names[k][0]) != 0 || strncmp(message, field, flen) != 0)
            continue;
        const char *rest = message + flen;
        /* "radius = 5 ..." is "R = 5 ...", "rate = 5 ..." "--grow 5 ...";
         * "mixture: ..." is "--mixture: ...". */
        if (strncmp(rest, " = ", 3) == 0)
            snprintf(out, cap, "%s%s%s", name, name[0] == '-' ? " " : " = ", rest + 3);
        else if (rest[0] == ':')
            snprintf(out, cap, "%s%s", name, rest);
        else
            continue;
        return out;
    }
    return message;
}
