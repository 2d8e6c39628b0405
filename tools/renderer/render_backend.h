/* SPDX-License-Identifier: MIT */
/* The renderer's only contact with a GL implementation: a context that
 * draws into an off-screen W x H RGBA image, made current on the calling
 * thread, and a way to read the pixels back. Everything else (shaders,
 * geometry, colours) is in render_draw.c and is the same for every backend.
 *
 * Exactly one backend is linked into a renderer binary: OSMesa and libGL
 * both export the gl* entry points, so a binary linking both would call
 * whichever the dynamic linker found first. That is why `make` builds one
 * binary per backend rather than one binary with a runtime switch. */
#ifndef RENDER_BACKEND_H
#define RENDER_BACKEND_H

#include <stddef.h>

typedef struct rb_context rb_context;

/* "osmesa" or "egl". */
const char *rb_name(void);

/* Process-wide set-up, once, before any worker thread starts (EGL opens
 * its display here). Returns 0, or -1 with a message in err. */
int rb_open(char *err, size_t errlen);
/* Releases what rb_open set up, after the last rb_destroy. */
void rb_close(void);

/* A context drawing into a width x height image, current on the calling
 * thread from now on. NULL with a message in err on failure. */
rb_context *rb_create(int width, int height, char *err, size_t errlen);

/* Waits for drawing to finish and returns the image: width * height RGBA
 * bytes, bottom row first (GL's convention), owned by the context and
 * valid until the next draw. NULL with a message on failure. */
const unsigned char *rb_pixels(rb_context *ctx, char *err, size_t errlen);

void rb_destroy(rb_context *ctx); /* NULL is allowed */

#endif
