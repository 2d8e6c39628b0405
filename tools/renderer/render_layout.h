/* SPDX-License-Identifier: MIT */
/* Where things go in the image, in pixels with the origin at the
 * bottom-left corner and y up (GL window coordinates; the PNG writer flips
 * the rows). GL-free, so the tests compute the same positions. */
#ifndef RENDER_LAYOUT_H
#define RENDER_LAYOUT_H

typedef struct rl_layout {
    int size;                          /* the image is size x size pixels */
    double box;                        /* width of the simulation box in frame units */
    double box_y;                      /* its height */
    double scale;                      /* pixels per frame unit */
    double x0, y0;                     /* pixel position of the box corner (0, 0) */
    double outline;                    /* width of the box outline, centred on the box edge */
    int legend;                        /* a speed legend is drawn right of the box */
    double bar_x, bar_y, bar_w, bar_h; /* the legend's colour bar */
    double text_px;                    /* size of one font pixel */
    int label;                         /* a line of text is drawn above the box */
    double label_x, label_y;           /* its bottom-left corner */
} rl_layout;

/* size >= RL_MIN_SIZE. The box keeps a margin on every side so its outline
 * is always visible; a legend takes a strip on the right. rl_make lays out
 * a square box of side box, filling the width left of the legend;
 * rl_make_rect a box_x by box_y box, as large as fits in the same space,
 * centred in it (a square box is laid out exactly as by rl_make). */
#define RL_MIN_SIZE 32
#define RL_MAX_SIZE 16384
void rl_make(rl_layout *l, int size, double box, int legend);
void rl_make_rect(rl_layout *l, int size, double box_x, double box_y, int legend);
/* rl_make_rect with, if label, a line of text above the box: the box is
 * then as large as fits below it. */
void rl_make_view(rl_layout *l, int size, double box_x, double box_y, int legend, int label);

/* Frame coordinates to pixels. */
static inline double rl_px(const rl_layout *l, double x) { return l->x0 + x * l->scale; }
static inline double rl_py(const rl_layout *l, double y) { return l->y0 + y * l->scale; }

#endif
