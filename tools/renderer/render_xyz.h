/* SPDX-License-Identifier: MIT */
/* Extended XYZ trajectories, as disks --trajectory and ASE write them:
 * each frame a disk count, a comment line of key=value pairs and a line
 * per disk. The columns are found by the comment's Properties= (never by
 * position: pos, radius and velo may come in any order, among columns the
 * renderer does not draw); Lattice= gives the box, pbc= its boundary
 * (Lattice without pbc is periodic, as ASE reads it) and Time= the time.
 * A file is scanned once for where each frame starts and what its
 * comment says; each frame is then read on its own, by any thread. */
#ifndef RENDER_XYZ_H
#define RENDER_XYZ_H

#include <stddef.h>

#include "disk_sim.h"

typedef struct rx_frame {
    long offset;         /* of its count line, in bytes */
    long line;           /* its count line's number, from 1 */
    size_t count;        /* disks */
    double box_x, box_y; /* the cell's sides in the plane; 0 without Lattice= */
    int boundary;        /* a ds_boundary from pbc= (or Lattice= alone); -1 without either */
    double time;         /* Time=; NAN without */
    int columns;         /* numbers and words on each disk's line */
    int pos, radius;     /* the first column of each */
    int velocity;        /* of velo (or vel, velocities); -1 without */
} rx_frame;

/* Every frame of the file at path into *frames (malloc'd, *count of
 * them). 0, or -1 with one line in err naming the file and line. */
int rx_scan(const char *path, rx_frame **frames, size_t *count, char *err, size_t errlen);

/* The disks of one scanned frame into frame (columns 5 with velocities,
 * else 3; free with ds_frame_free). 0, or -1 with a message naming the
 * file and line. */
int rx_read(const char *path, const rx_frame *fr, ds_frame *frame, char *err, size_t errlen);

/* Whether a path names an extended XYZ file: it ends in .xyz or .extxyz. */
int rx_is_xyz(const char *path);

#endif
