/* SPDX-License-Identifier: MIT */
/* What the renderer draws: every frame the command line names, in its
 * order, with what the drawing needs besides the disks: the box and its
 * boundary (the options', else the run's frames.json beside a frame file,
 * the XYZ frame's header or the GSD frame's box, else 1000 x 1000 with
 * walls; a GSD file's boundary is periodic, as HOOMD's), the frame's
 * number and time (for --label) and its PNG's name. The list is built
 * before anything is drawn, so that every refusal comes first; ri_read
 * then reads one frame's disks, from any thread. */
#ifndef RENDER_INPUTS_H
#define RENDER_INPUTS_H

#include <stddef.h>

#include "disk_sim.h"
#include "frames_json.h"
#include "render_gsd.h"
#include "render_xyz.h"

/* The box the options give: 0 (sides) and -1 (boundary) when not given. */
typedef struct ri_box {
    double box, box_y;
    int boundary;
} ri_box;

typedef struct ri_frame {
    char *path;          /* the file it is in */
    size_t source;       /* its run's frames.json, or its XYZ or GSD file (ri_list.sources) */
    const rx_frame *xyz; /* its place in an extended XYZ file; NULL for another */
    const rg_frame *gsd; /* its chunks in a GSD file; NULL for another */
    char *output;        /* its PNG; NULL until ri_name_outputs */
    long number;         /* frame_0012.txt: 12; an XYZ or GSD file's frames 0, 1, ...; -1: none */
    double time;         /* NAN when neither frames.json, Time= nor log/disksim/time gives it */
    double box_x, box_y;
    ds_boundary boundary;
} ri_frame;

typedef struct ri_source ri_source; /* private to render_inputs.c */

typedef struct ri_list {
    ri_frame *frames;
    size_t count, cap;
    ri_source *sources;
    size_t nsources, source_cap;
} ri_list;

/* Each adds frames to the list, or prints why not ("render: ...") and
 * returns -1. ri_add_file: an extended XYZ file's frames (rx_is_xyz), a
 * GSD file's (rg_is_gsd), or one frame file; ri_add_dir: DIR/frame_*.txt in name order. A box or
 * boundary the options give that contradicts the file's is said once per
 * file or directory, on stderr. */
int ri_add_file(ri_list *l, const char *path, const ri_box *given);
int ri_add_dir(ri_list *l, const char *dir, const ri_box *given);

/* Names every frame's PNG: frame_0012.txt -> frame_0012.png and frame
 * 12 of run.xyz (or run.gsd) -> run_0012.png, in out_dir if given, else beside the
 * file; out_file (the list's one frame) names it outright. -1 without
 * memory. */
int ri_name_outputs(ri_list *l, const char *out_dir, const char *out_file);

/* The disks of frame i, checked against its run's frames.json (its N,
 * whether it has velocities). 0, or -1 with a message naming the file. */
int ri_read(const ri_list *l, size_t i, ds_frame *frame, char *err, size_t errlen);

void ri_free(ri_list *l);

#endif
