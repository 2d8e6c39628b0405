/* SPDX-License-Identifier: MIT */
/* A movie from rendered images: raw RGB frames piped to ffmpeg (found on
 * PATH), encoded as H.264 in yuv420p, the combination every browser and
 * phone plays, in an MP4 with its index at the front (+faststart) so it
 * starts playing before it has fully downloaded; or as an animated GIF,
 * each frame with its own palette of 256 colours. The file is written to a
 * temporary name beside the destination and renamed only when ffmpeg has
 * finished without error, so a failed or interrupted run leaves no
 * half-written movie. */
#ifndef RENDER_MOVIE_H
#define RENDER_MOVIE_H

#include <stddef.h>
#include <sys/types.h>

typedef struct rm_movie rm_movie;

typedef enum rm_format { RM_MP4, RM_GIF } rm_format;

/* The format a movie's name asks for: .mp4 or .gif, in any case; -1 for
 * any other name. */
int rm_format_of(const char *path);

/* Where ffmpeg is on PATH, into found; 0, or -1 when it is not there. */
int rm_find_ffmpeg(char *found, size_t cap);

/* Starts ffmpeg writing path in format at fps frames per second from
 * width x height images. yuv420p (MP4) stores colour at half resolution,
 * so an odd width or height is padded to even by repeating the last
 * column or row. mode: permissions of the finished file. NULL with a
 * message on failure. */
rm_movie *rm_open(const char *path, rm_format format, int width, int height, int fps, mode_t mode,
                  char *err, size_t errlen);

/* Converts an image (width * height RGBA bytes, bottom row first, as the
 * backends return it) into the next frame's RGB bytes in rgb, which holds
 * rm_frame_bytes(); safe to call from any thread. */
size_t rm_frame_bytes(const rm_movie *m);
void rm_convert(const rm_movie *m, const unsigned char *rgba, unsigned char *rgb);

/* Sends one converted frame to ffmpeg; frames must come in order. 0, or -1
 * with a message (ffmpeg has stopped, or the pipe failed). */
int rm_write(rm_movie *m, const unsigned char *rgb, char *err, size_t errlen);

/* Ends the input, waits for ffmpeg and renames the movie into place.
 * 0, or -1 with a message; either way m is freed and no temporary is left. */
int rm_finish(rm_movie *m, char *err, size_t errlen);

/* Stops ffmpeg and removes the temporary, after an error elsewhere. */
void rm_abort(rm_movie *m); /* NULL is allowed */

#endif
