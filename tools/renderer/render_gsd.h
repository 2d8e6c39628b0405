/* SPDX-License-Identifier: MIT */
/* GSD trajectories, as disks --gsd, disksim.Writer and HOOMD-blue write
 * them, read from the published specification of the GSD file layer 2.x
 * (a 256-byte header, a list of chunk names, an index of 32-byte entries)
 * and of the HOOMD schema (configuration/box, particles/N, position,
 * diameter, velocity; log/disksim/time, disksim's). A frame that leaves a
 * chunk out takes frame 0's, as the schema says. HOOMD's box is centred
 * on the origin: a centre is drawn at its position plus half the box,
 * where disksim's [0, L) puts it. A file is scanned once, its index and
 * the small chunks of every frame checked; each frame's disks are then
 * read on their own, by any thread. GSD says nothing of walls: the
 * boundary is the options' (render_inputs.c). */
#ifndef RENDER_GSD_H
#define RENDER_GSD_H

#include <stddef.h>
#include <stdint.h>

#include "disk_sim.h"

/* Where one chunk's rows x cols elements are; location 0: none. */
typedef struct rg_chunk {
    uint64_t location, rows;
    uint32_t cols;
    uint8_t type;
} rg_chunk;

typedef struct rg_frame {
    size_t count;                          /* particles/N */
    double box_x, box_y;                   /* configuration/box's Lx and Ly */
    double time;                           /* log/disksim/time; NAN without */
    rg_chunk position, diameter, velocity; /* this frame's, or frame 0's */
} rg_frame;

/* Every frame of the GSD file at path into *frames (malloc'd, *count of
 * them). 0, or -1 with one line in err naming the file (and the frame). */
int rg_scan(const char *path, rg_frame **frames, size_t *count, char *err, size_t errlen);

/* The disks of one scanned frame into frame (columns 5 with velocities,
 * else 3; free with ds_frame_free). 0, or -1 with a message naming the
 * file. */
int rg_read(const char *path, const rg_frame *fr, size_t number, ds_frame *frame, char *err,
            size_t errlen);

/* Whether a path names a GSD file: it ends in .gsd. */
int rg_is_gsd(const char *path);

#endif
