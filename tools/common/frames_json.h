/* SPDX-License-Identifier: MIT */
/* frames.json, the description disks writes beside its frames
 * (docs/cli.md, "Frame files"), read by tools/render and tools/gr: the
 * box, the boundary and the time of each frame, which the frame's own
 * text does not say. Public API only. Every key may be absent (a file
 * written by hand may give just the box); keys this reader does not know
 * are skipped, so a later disks may add some. */
#ifndef TOOLS_FRAMES_JSON_H
#define TOOLS_FRAMES_JSON_H

#include <stddef.h>
#include <stdint.h>

#include "disk_sim.h"

typedef struct fj_run {
    double box_x, box_y;      /* the box's sides; 0 when not given */
    int boundary;             /* a ds_boundary; -1 when not given */
    long n;                   /* disks in every frame; -1 when not given */
    double radius, dt;        /* 0 when not given */
    uint64_t steps_per_frame; /* 0 when not given */
    int velocities;           /* frames of "x y R vx vy": 1, "x y R": 0; -1 when not given */
    long jammed_frame;        /* the frame at which growth jammed; -1: none */
    double jammed_time;       /* its time */
} fj_run;

#define FJ_NAME "frames.json"

/* Reads DIR/frames.json into run: 1 when read, 0 when DIR holds none
 * (run then says nothing is given), -1 with one line in err naming the
 * file and line ("run/frames.json:4: \"box\" must be two positive
 * numbers"). A "disksim_frames" other than 1 is a later format, refused. */
int fj_read(const char *dir, fj_run *run, char *err, size_t errlen);

/* The time of frame k, k steps_per_frame dt (the jammed frame's own
 * time), or NAN when the file gives no dt or frame spacing. */
double fj_frame_time(const fj_run *run, long k);

#endif
