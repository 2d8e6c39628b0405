/* SPDX-License-Identifier: MIT */
/* What the command says when it cannot go on: one line on stderr, then
 * the exit status (docs/cli.md, "Exit status"). */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

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
