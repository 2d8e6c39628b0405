/* SPDX-License-Identifier: MIT */
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

/* sRGB transfer function: linear light to the encoded value in [0, 1]. */
static double srgb_encode(double c)
{
    c = c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

rc_rgb rc_cyclic(double t)
{
    if (!isfinite(t))
        t = 0.0;
    const double h = 2.0 * 3.14159265358979323846 * (t - floor(t));
    const double lightness = 0.74, chroma = 0.12;
    const double a = chroma * cos(h), b = chroma * sin(h);
    /* OKLab to linear sRGB (Ottosson 2020): to the cone responses l, m, s
     * (cube roots), cube them, then to red, green, blue. */
    const double l_ = lightness + 0.3963377774 * a + 0.2158037573 * b;
    const double m_ = lightness - 0.1055613458 * a - 0.0638541728 * b;
    const double s_ = lightness - 0.0894841775 * a - 1.2914855480 * b;
    const double l = l_ * l_ * l_, m = m_ * m_ * m_, s = s_ * s_ * s_;
    const double r = 4.0767416621 * l - 3.3077115913 * m + 0.2309699292 * s;
    const double g = -1.2684380046 * l + 2.6097574011 * m - 0.3413193965 * s;
    const double bl = -0.0041960863 * l - 0.7034186147 * m + 1.7076147010 * s;
    rc_rgb out = {(float)srgb_encode(r), (float)srgb_encode(g), (float)srgb_encode(bl)};
    return out;
}

rc_rgb rc_psi6(double re, double im)
{
    const double order = fmin(hypot(re, im), 1.0);
    const double t = atan2(im, re) / (2.0 * 3.14159265358979323846) + 0.5;
    const float k = (float)(0.3 + 0.7 * (order >= 0.0 ? order : 0.0));
    rc_rgb c = rc_cyclic(t);
    c.r *= k;
    c.g *= k;
    c.b *= k;
    return c;
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
