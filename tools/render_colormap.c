#include <math.h>

#include "render_colormap.h"

rc_rgb rc_viridis(double t)
{
    /* Degree-6 polynomial fit of matplotlib's 256-entry viridis table
     * (Matt Zucker, shadertoy "Colormap fitting", CC0); it stays within
     * 0.015 of the table, under one 8-bit step in most of the range, and
     * needs no 768-number table here. */
    static const double c[7][3] = {
        {0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
        {0.1050930431085774, 1.404613529898575, 1.384590162594685},
        {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
        {-4.634230498983486, -5.799100973351585, -19.33244095627987},
        {6.228269936347081, 14.17993336680509, 56.69055260068105},
        {4.776384997670288, -13.74514537774601, -65.35303263337234},
        {-5.435455855934631, 4.645852612178535, 26.3124352495832},
    };
    if (!(t > 0.0))
        t = 0.0; /* NaN too */
    if (t > 1.0)
        t = 1.0;
    double v[3];
    for (int k = 0; k < 3; ++k) {
        double acc = c[6][k];
        for (int d = 5; d >= 0; --d)
            acc = acc * t + c[d][k];
        v[k] = acc < 0.0 ? 0.0 : acc > 1.0 ? 1.0 : acc;
    }
    rc_rgb out = {(float)v[0], (float)v[1], (float)v[2]};
    return out;
}

double rc_speed_scale(const ds_frame *frame)
{
    double sum = 0.0;
    for (size_t i = 0; i < frame->count; ++i)
        sum += frame->disks[i].vx * frame->disks[i].vx + frame->disks[i].vy * frame->disks[i].vy;
    double top = frame->count ? 2.5 * sqrt(sum / (double)frame->count) : 0.0;
    if (!(top > 0.0) || !isfinite(top))
        return 1.0;
    double unit = pow(10.0, floor(log10(top)) - 1.0); /* two significant digits */
    return round(top / unit) * unit;
}
