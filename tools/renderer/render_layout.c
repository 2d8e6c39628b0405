/* SPDX-License-Identifier: MIT */
#include <math.h>

#include "render_font.h"
#include "render_layout.h"

void rl_make(rl_layout *l, int size, double box, int legend)
{
    rl_make_rect(l, size, box, box, legend);
}

void rl_make_rect(rl_layout *l, int size, double box_x, double box_y, int legend)
{
    rl_make_view(l, size, box_x, box_y, legend, 0);
}

void rl_make_view(rl_layout *l, int size, double box_x, double box_y, int legend, int label)
{
    const double s = size;
    const double margin = fmax(2.0, round(0.025 * s));
    const double text_px = fmax(1.0, floor(s / 400.0));
    /* A tenth of the image, or enough for the word "speed" in small images. */
    const double strip =
        legend ? fmax(round(0.1 * s), 5.0 * (RF_WIDTH + 1) * text_px + margin) : 0.0;
    /* A label: a line of text and three font pixels of gap above the box. */
    const double label_h = label ? (RF_HEIGHT + 3) * text_px : 0.0;
    /* The space for the box: the width left of the legend, the full height
     * less the margins (and the label). A square box with no label fills
     * the width (the narrower side). */
    const double side = s - 2.0 * margin - strip, height = s - 2.0 * margin - label_h;
    l->size = size;
    l->box = box_x;
    l->box_y = box_y;
    const int square = box_x == box_y && !label;
    l->scale = square ? side / box_x : fmin(side / box_x, height / box_y);
    /* side itself for a square, not box * (side / box), which may be off
     * by a rounding and move a half-pixel centring by a whole pixel. */
    const double w = square ? side : box_x * l->scale, h = square ? side : box_y * l->scale;
    l->x0 = margin + round(0.5 * (side - w));
    l->y0 = label ? margin + round(0.5 * (height - h)) : round(0.5 * (s - h));
    /* 2 px at the default 800 px, never thinner than one pixel. */
    l->outline = fmax(1.0, round(s / 400.0));
    l->legend = legend;
    /* The colour bar spans 60% of the space's width, centred on the box's
     * height; the labels (5x7 font) go above and below it. */
    l->text_px = text_px;
    l->bar_x = margin + side + margin;
    l->bar_w = fmax(3.0, round(0.025 * s));
    l->bar_h = round(0.6 * side);
    l->bar_y = round(l->y0 + 0.5 * (h - l->bar_h));
    /* The label's bottom-left corner: above the box's top-left corner,
     * clear of the outline (which is at most 2 text_px wide). */
    l->label = label;
    l->label_x = l->x0;
    l->label_y = round(l->y0 + h + fmax(l->outline, text_px) + text_px);
}
