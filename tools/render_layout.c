#include <math.h>

#include "render_font.h"
#include "render_layout.h"

void rl_make(rl_layout *l, int size, double box, int legend)
{
    const double s = size;
    const double margin = fmax(2.0, round(0.025 * s));
    const double text_px = fmax(1.0, floor(s / 400.0));
    /* A tenth of the image, or enough for the word "speed" in small images. */
    const double strip =
        legend ? fmax(round(0.1 * s), 5.0 * (RF_WIDTH + 1) * text_px + margin) : 0.0;
    const double side = s - 2.0 * margin - strip;
    l->size = size;
    l->box = box;
    l->scale = side / box;
    l->x0 = margin;
    l->y0 = round(0.5 * (s - side));
    /* 2 px at the default 800 px, never thinner than one pixel. */
    l->outline = fmax(1.0, round(s / 400.0));
    l->legend = legend;
    /* The colour bar spans the middle 60% of the box height; the labels
     * (5x7 font) go above and below it. */
    l->text_px = text_px;
    l->bar_x = margin + side + margin;
    l->bar_w = fmax(3.0, round(0.025 * s));
    l->bar_h = round(0.6 * side);
    l->bar_y = round(l->y0 + 0.5 * (side - l->bar_h));
}
