/* Draws one frame with whatever GL context is current: the same code for
 * every backend. Disks are quads whose fragment shader computes the exact
 * distance to the centre, so edges are antialiased analytically (coverage
 * of a one-pixel-wide ramp) and disks are round at any size. */
#ifndef RENDER_DRAW_H
#define RENDER_DRAW_H

#include <stddef.h>

#include "disk_sim.h"

typedef struct rd_renderer rd_renderer;

typedef struct rd_options {
    int size;    /* image side in pixels */
    double box;  /* box side in frame units (1000) */
    double vmax; /* top of the speed scale for 5-column frames, 0 = automatic */
} rd_options;

/* Compiles the shaders and makes the buffers, once per context. */
rd_renderer *rd_create(const rd_options *opt, char *err, size_t errlen);
/* Draws the frame into the current context's framebuffer. */
int rd_draw(rd_renderer *r, const ds_frame *frame, char *err, size_t errlen);
void rd_destroy(rd_renderer *r); /* NULL is allowed */

/* "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (...)" of the current context. */
void rd_describe_gl(char *out, size_t len);

#endif
