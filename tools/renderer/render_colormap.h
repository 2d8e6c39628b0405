/* SPDX-License-Identifier: MIT */
/* Colours of the renderer: the perceptual map for speeds, the cyclic map
 * for the bond orientation, and the fixed
 * colours of 3-column frames. GL-free, so the tests link it directly. */
#ifndef RENDER_COLORMAP_H
#define RENDER_COLORMAP_H

#include <stddef.h>

#include "disk_sim.h"

typedef struct rc_rgb {
    float r, g, b; /* 0..1 */
} rc_rgb;

/* Viridis (van der Walt and Smith, matplotlib 2.0): dark blue at 0, green
 * at 0.5, yellow at 1, lightness increasing throughout, readable in grey
 * and by colour-blind viewers. t is clamped to [0, 1]. */
rc_rgb rc_viridis(double t);

/* A cyclic map: t and t + 1 give the same colour. A circle of hues at
 * constant lightness and chroma in Ottosson's OKLab space (L = 0.74,
 * C = 0.12, the widest circle sRGB holds at every hue at that lightness),
 * so equal steps of t look like equal steps of hue and no phase looks
 * brighter than another. t = 0 is pink, 1/4 ochre, 1/2 teal, 3/4
 * lavender blue. */
rc_rgb rc_cyclic(double t);

/* The colour of a disk with local bond order psi6 = re + i im: the cyclic
 * map at the bond orientation arg(psi6) / 6, t = arg(psi6) / (2 pi) + 1/2
 * (so t = 0 and 1 are an orientation of -30 = +30 degrees), darkened by
 * the order: brightness 0.3 + 0.7 |psi6| (|psi6| taken as at most 1), so a
 * disordered disk is dark whatever its phase. */
rc_rgb rc_psi6(double re, double im);

/* Plain frames: gnuplot's disk blue of animate_disk.plt on white. */
#define RC_DISK ((rc_rgb){0.165f, 0.435f, 0.690f})
#define RC_BACKGROUND ((rc_rgb){1.0f, 1.0f, 1.0f})
#define RC_OUTLINE ((rc_rgb){0.0f, 0.0f, 0.0f})

/* Top of the speed scale when the user gives none: 2.5 times the frame's
 * rms speed, rounded to two significant digits. Energy is conserved, so
 * the rms speed (and the scale) is the same in every frame of a run and
 * colours do not flicker; at equilibrium speeds follow the 2D Maxwell law,
 * where P(v > 2.5 v_rms) = exp(-6.25) = 0.2%, so almost no disk saturates.
 * Returns 1 for a frame where every disk is at rest. */
double rc_speed_scale(const ds_frame *frame);

#endif
