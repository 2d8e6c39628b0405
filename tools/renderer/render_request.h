/* SPDX-License-Identifier: MIT */
/* The renderer's command line: what it asks for, checked first on its
 * own (rq_check), then against the frames it names (rq_prepare, which
 * lists them with render_inputs.c), all before anything is made. */
#ifndef RENDER_REQUEST_H
#define RENDER_REQUEST_H

#include <stddef.h>

#include "render_draw.h"
#include "render_inputs.h"

#define RQ_MAX_WORKERS 256 /* -j's largest */

typedef enum rq_label { RQ_LABEL_NONE, RQ_LABEL_TIME, RQ_LABEL_FRAME } rq_label;

/* The command line: what it asks for, and its inputs in their order. */
typedef struct rq_request {
    const char *out, *movie;
    double size, vmax, jobs, fps;
    ri_box box;
    int quiet;
    rd_colour colour;
    rq_label label;
    const char **inputs; /* argv entries, in order */
    int *is_dir;         /* inputs[k] was given to --dir */
    size_t count;
} rq_request;

extern const char rq_usage[];

/* What rq_parse returns besides 0 (render) and 2 (a usage error, said). */
enum { RQ_HELP = -1, RQ_VERSION = -2 };

/* Reads the command line into q, whose inputs and is_dir hold argc
 * entries and whose other fields hold the defaults. */
int rq_parse(rq_request *q, int argc, char **argv);
/* The checks that need only the command line: 0, or 2 (said). */
int rq_check(const rq_request *q);
/* Lists every frame into list, checks what the request needs of them
 * (one frame for --out F.png, a time or a number for --label), names the
 * PNGs and makes --out's directory (*made: this call made it). 0, or the
 * exit status (said). */
int rq_prepare(const rq_request *q, ri_list *list, int *made);

#endif
