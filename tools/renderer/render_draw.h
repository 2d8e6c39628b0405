/* SPDX-License-Identifier: MIT */
/* Draws one frame with whatever GL context is current: the same code for
 * every backend. Disks are quads whose fragment shader computes the exact
 * distance to the centre, so edges are antialiased analytically (coverage
 * of a one-pixel-wide ramp) and disks are round at any size. */
#ifndef RENDER_DRAW_H
#define RENDER_DRAW_H

#include <stddef.h>

#include "disk_sim.h"

typedef struct rd_renderer rd_renderer;

/* What a disk's colour shows. */
typedef enum rd_colour {
    RD_COLOUR_AUTO = 0, /* speed for "x y R vx vy" frames, one colour otherwise */
    RD_COLOUR_SPEED,    /* speed (viridis); the frame must have velocities */
    RD_COLOUR_PSI6,     /* bond orientation arg(psi6) / 6, darkened where |psi6| is small */
    RD_COLOUR_SIZE      /* radius, the frame's smallest to its largest on viridis */
} rd_colour;

typedef struct rd_options {
    int size;         /* image side in pixels */
    rd_colour colour; /* what the colours show */
    double vmax;      /* top of the speed scale for 5-column frames, 0 = automatic */
    int label;        /* a line above the box holds each frame's label (rd_view) */
} rd_options;

/* What one frame is drawn in, besides its disks. */
typedef struct rd_view {
    double box_x, box_y; /* the box's sides, in frame units */
    /* Walls: disks are drawn where they are. Periodic (channel: along x
     * only): a disk across an edge is drawn on both sides, clipped to the
     * box, and psi6 counts neighbours across the edges. */
    ds_boundary boundary;
    const char *label; /* text above the box's top-left corner ("t = 2.5"); NULL: none */
} rd_view;

/* Compiles the shaders and makes the buffers, once per context. */
rd_renderer *rd_create(const rd_options *opt, char *err, size_t errlen);
/* Draws the frame into the current context's framebuffer. */
int rd_draw(rd_renderer *r, const ds_frame *frame, const rd_view *view, char *err, size_t errlen);
void rd_destroy(rd_renderer *r); /* NULL is allowed */

/* "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (...)" of the current context. */
void rd_describe_gl(char *out, size_t len);

#endif
