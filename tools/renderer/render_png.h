/* SPDX-License-Identifier: MIT */
/* Writes an image as an 8-bit RGB PNG, atomically: into a temporary file
 * in the destination's directory, renamed over the destination only once
 * libpng has written and the file has been closed without error. A reader
 * (or a crash) never sees a half-written PNG. */
#ifndef RENDER_PNG_H
#define RENDER_PNG_H

#include <stddef.h>
#include <sys/types.h>

/* rgba: width * height RGBA bytes, bottom row first (alpha ignored).
 * mode: permissions of the new file. Returns 0, or -1 with a message. */
int rp_write(const char *path, const unsigned char *rgba, int width, int height, mode_t mode,
             char *err, size_t errlen);

#endif
