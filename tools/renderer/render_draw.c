/* SPDX-License-Identifier: MIT */
#define GL_GLEXT_PROTOTYPES 1
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/gl.h>
#include <GL/glext.h>

#include "render_colormap.h"
#include "render_draw.h"
#include "render_font.h"
#include "render_layout.h"

/* GLSL 1.20 (OpenGL 2.1) so any compatibility context will do: OSMesa's
 * default context and EGL's desktop GL context are both compatibility. */
static const char *vertex_src =
    "#version 120\n"
    "attribute vec2 a_pos;\n"    /* pixels, origin bottom-left */
    "attribute vec3 a_circle;\n" /* centre (px) and radius (px); radius < 0: solid */
    "attribute vec3 a_color;\n"
    "uniform vec2 u_size;\n"
    "varying vec3 v_circle;\n"
    "varying vec3 v_color;\n"
    "void main() {\n"
    "    v_circle = a_circle;\n"
    "    v_color = a_color;\n"
    "    gl_Position = vec4(a_pos / u_size * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

/* Coverage of a pixel by a disk, approximated by a ramp one pixel wide
 * centred on the edge: exact for a straight edge through the pixel, which
 * is what the edge looks like at the scale of one pixel once R >> 1 px. */
static const char *fragment_src =
    "#version 120\n"
    "varying vec3 v_circle;\n"
    "varying vec3 v_color;\n"
    "void main() {\n"
    "    float cover = 1.0;\n"
    "    if (v_circle.z > 0.0)\n"
    "        cover = clamp(v_circle.z - distance(gl_FragCoord.xy, v_circle.xy) + 0.5, 0.0, 1.0);\n"
    "    gl_FragColor = vec4(v_color, cover);\n"
    "}\n";

enum { ATTR_POS, ATTR_CIRCLE, ATTR_COLOR, FLOATS_PER_VERTEX = 8, VERTICES_PER_QUAD = 6 };

struct rd_renderer {
    rd_options opt;
    GLuint program, vbo;
    float *vertices;   /* FLOATS_PER_VERTEX per vertex, rebuilt per frame */
    size_t count, cap; /* vertices */
};

static int grow(rd_renderer *r, size_t extra)
{
    if (r->count + extra <= r->cap)
        return 0;
    size_t cap = r->cap ? r->cap : 4096;
    while (cap < r->count + extra)
        cap *= 2;
    float *v = realloc(r->vertices, cap * FLOATS_PER_VERTEX * sizeof *v);
    if (!v)
        return -1;
    r->vertices = v;
    r->cap = cap;
    return 0;
}

/* Two triangles covering [x0,x1] x [y0,y1]; capacity reserved by caller. */
static void quad(rd_renderer *r, double x0, double y0, double x1, double y1, double cx, double cy,
                 double radius, rc_rgb c)
{
    const double corner[VERTICES_PER_QUAD][2] = {{x0, y0}, {x1, y0}, {x1, y1},
                                                 {x0, y0}, {x1, y1}, {x0, y1}};
    float *v = r->vertices + r->count * FLOATS_PER_VERTEX;
    for (int k = 0; k < VERTICES_PER_QUAD; ++k, v += FLOATS_PER_VERTEX) {
        v[0] = (float)corner[k][0];
        v[1] = (float)corner[k][1];
        v[2] = (float)cx;
        v[3] = (float)cy;
        v[4] = (float)radius;
        v[5] = c.r;
        v[6] = c.g;
        v[7] = c.b;
    }
    r->count += VERTICES_PER_QUAD;
}

static int rect(rd_renderer *r, double x0, double y0, double x1, double y1, rc_rgb c)
{
    if (grow(r, VERTICES_PER_QUAD))
        return -1;
    quad(r, x0, y0, x1, y1, 0.0, 0.0, -1.0, c);
    return 0;
}

/* Text with its bottom-left corner at (x, y), one font pixel = px pixels. */
static int text(rd_renderer *r, double x, double y, double px, const char *s, rc_rgb c)
{
    for (; *s; ++s, x += (RF_WIDTH + 1) * px) {
        const unsigned char *rows = rf_glyph(*s);
        for (int row = 0; row < RF_HEIGHT; ++row)
            for (int col = 0; col < RF_WIDTH; ++col)
                if (rows[row] & (1u << (RF_WIDTH - 1 - col))) {
                    double gx = x + col * px, gy = y + (RF_HEIGHT - 1 - row) * px;
                    if (rect(r, gx, gy, gx + px, gy + px, c))
                        return -1;
                }
    }
    return 0;
}

/* The legend: a bar of the map from bottom to top, its two end labels and
 * a caption above. */
static int legend(rd_renderer *r, const rl_layout *l, rc_rgb (*map)(double), const char *bottom,
                  const char *top, const char *caption)
{
    /* The bar is a stack of thin solid slices, one per pixel row, each the
     * map's colour at its middle: what a disk of that value looks like. */
    const int rows = (int)l->bar_h;
    for (int k = 0; k < rows; ++k) {
        double y = l->bar_y + k;
        if (rect(r, l->bar_x, y, l->bar_x + l->bar_w, y + 1.0, map((k + 0.5) / rows)))
            return -1;
    }
    const double line = l->text_px, gap = 4.0 * l->text_px, h = RF_HEIGHT * l->text_px;
    if (rect(r, l->bar_x - line, l->bar_y - line, l->bar_x + l->bar_w + line, l->bar_y,
             RC_OUTLINE) ||
        rect(r, l->bar_x - line, l->bar_y + l->bar_h, l->bar_x + l->bar_w + line,
             l->bar_y + l->bar_h + line, RC_OUTLINE) ||
        text(r, l->bar_x, l->bar_y + l->bar_h + gap, l->text_px, top, RC_OUTLINE) ||
        text(r, l->bar_x, l->bar_y + l->bar_h + 2.0 * gap + h, l->text_px, caption, RC_OUTLINE) ||
        text(r, l->bar_x, l->bar_y - gap - h, l->text_px, bottom, RC_OUTLINE))
        return -1;
    return 0;
}

static int speed_legend(rd_renderer *r, const rl_layout *l, double vmax)
{
    char top[32];
    snprintf(top, sizeof top, vmax >= 10.0 ? "%.0f" : "%.2g", vmax);
    return legend(r, l, rc_viridis, "0", top, "speed");
}

static int size_legend(rd_renderer *r, const rl_layout *l, double rmin, double rmax)
{
    char bottom[32], top[32];
    snprintf(bottom, sizeof bottom, "%.3g", rmin);
    snprintf(top, sizeof top, "%.3g", rmax);
    return legend(r, l, rc_viridis, bottom, top, "radius");
}

/* A centre into the box along its periodic axes (an XYZ file may hold
 * unwrapped centres; frames are in the box already, and stay as they are
 * to the bit). */
static void wrap(const rd_view *v, double *x, double *y)
{
    if (v->boundary != DS_BOUNDARY_WALLS)
        *x -= v->box_x * floor(*x / v->box_x);
    if (v->boundary == DS_BOUNDARY_PERIODIC)
        *y -= v->box_y * floor(*y / v->box_y);
}

/* psi6 of every disk of the frame (cutoff 1.4 diameters of the largest
 * disk, as ds_sim_get_psi6) into re, im. */
static int frame_psi6(const ds_frame *frame, const rd_view *view, double *re, double *im, char *err,
                      size_t errlen)
{
    const size_t n = frame->count;
    double *x = malloc(n * sizeof *x), *y = malloc(n * sizeof *y), radius = 0.0;
    ds_status st = DS_ERR_NOMEM;
    ds_error why;
    snprintf(why.message, sizeof why.message, "out of memory");
    if (x && y) {
        for (size_t i = 0; i < n; ++i) {
            x[i] = frame->disks[i].x;
            y[i] = frame->disks[i].y;
            wrap(view, &x[i], &y[i]);
            radius = fmax(radius, frame->disks[i].r);
        }
        st = ds_psi6_local(n, x, y, view->box_x, view->box_y, view->boundary, 2.8 * radius, re, im,
                           &why);
    }
    free(x);
    free(y);
    if (st == DS_ERR_ARG && view->boundary != DS_BOUNDARY_WALLS)
        snprintf(err, errlen, "psi6: the periodic box is narrower than 2.8 diameters (%g)",
                 2.8 * 2.0 * radius);
    else if (st != DS_OK)
        snprintf(err, errlen, "psi6: %s", why.message);
    return st == DS_OK ? 0 : -1;
}

static GLuint compile(GLenum type, const char *src, char *err, size_t errlen)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[256] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        snprintf(err, errlen, "shader does not compile: %s", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

rd_renderer *rd_create(const rd_options *opt, char *err, size_t errlen)
{
    rd_renderer *r = calloc(1, sizeof *r);
    if (!r) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    r->opt = *opt;
    GLuint vs = compile(GL_VERTEX_SHADER, vertex_src, err, errlen);
    GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, fragment_src, err, errlen) : 0;
    if (!fs) {
        glDeleteShader(vs);
        free(r);
        return NULL;
    }
    r->program = glCreateProgram();
    glAttachShader(r->program, vs);
    glAttachShader(r->program, fs);
    glBindAttribLocation(r->program, ATTR_POS, "a_pos");
    glBindAttribLocation(r->program, ATTR_CIRCLE, "a_circle");
    glBindAttribLocation(r->program, ATTR_COLOR, "a_color");
    glLinkProgram(r->program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(r->program, GL_LINK_STATUS, &ok);
    if (!ok) {
        snprintf(err, errlen, "shader program does not link");
        rd_destroy(r);
        return NULL;
    }
    /* Everything below is state that never changes between frames. */
    glUseProgram(r->program);
    glUniform2f(glGetUniformLocation(r->program, "u_size"), (float)opt->size, (float)opt->size);
    glGenBuffers(1, &r->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, r->vbo);
    const GLsizei stride = FLOATS_PER_VERTEX * sizeof(float);
    glEnableVertexAttribArray(ATTR_POS);
    glEnableVertexAttribArray(ATTR_CIRCLE);
    glEnableVertexAttribArray(ATTR_COLOR);
    glVertexAttribPointer(ATTR_POS, 2, GL_FLOAT, GL_FALSE, stride, (const void *)0);
    glVertexAttribPointer(ATTR_CIRCLE, 3, GL_FLOAT, GL_FALSE, stride,
                          (const void *)(2 * sizeof(float)));
    glVertexAttribPointer(ATTR_COLOR, 3, GL_FLOAT, GL_FALSE, stride,
                          (const void *)(5 * sizeof(float)));
    glViewport(0, 0, opt->size, opt->size);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(RC_BACKGROUND.r, RC_BACKGROUND.g, RC_BACKGROUND.b, 1.0f);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "GL set-up failed (GL error 0x%x)", (unsigned)e);
        rd_destroy(r);
        return NULL;
    }
    return r;
}

/* What colours the disks of a frame, worked out once per frame. */
typedef struct palette {
    int speeds, psi6, sizes;
    double vmax, rmin, rmax;
    double *re, *im; /* psi6 of each disk */
} palette;

static rc_rgb disk_colour(const palette *p, const ds_frame_disk *d, size_t i)
{
    if (p->speeds)
        return rc_viridis(sqrt(d->vx * d->vx + d->vy * d->vy) / p->vmax);
    if (p->psi6)
        return rc_psi6(p->re[i], p->im[i]);
    if (p->sizes)
        return rc_viridis(p->rmax > p->rmin ? (d->r - p->rmin) / (p->rmax - p->rmin) : 0.5);
    return RC_DISK;
}

/* The shifts, in pixels, of a disk's copies along one axis: itself, and
 * its image across each edge of the box [lo, hi] its quad crosses. */
static int shifts(double c, double e, double lo, double hi, int periodic, double out[3])
{
    int n = 0;
    out[n++] = 0.0;
    if (periodic && c - e < lo)
        out[n++] = hi - lo;
    if (periodic && c + e > hi)
        out[n++] = lo - hi;
    return n;
}

/* A quad per disk, and in a periodic box one per image across an edge. */
static int disk_quads(rd_renderer *r, const ds_frame *frame, const rd_view *view,
                      const rl_layout *l, const palette *p)
{
    const int along_x = view->boundary != DS_BOUNDARY_WALLS,
              along_y = view->boundary == DS_BOUNDARY_PERIODIC;
    const double a0 = rl_px(l, 0.0), a1 = rl_px(l, l->box);
    const double b0 = rl_py(l, 0.0), b1 = rl_py(l, l->box_y);
    for (size_t i = 0; i < frame->count; ++i) {
        const ds_frame_disk *d = &frame->disks[i];
        double x = d->x, y = d->y;
        wrap(view, &x, &y);
        const double cx = rl_px(l, x), cy = rl_py(l, y), rad = d->r * l->scale;
        const rc_rgb c = disk_colour(p, d, i);
        /* One pixel beyond the radius holds the whole antialiased ramp. */
        const double e = rad + 1.0;
        double sx[3], sy[3];
        const int nx = shifts(cx, e, a0, a1, along_x, sx), ny = shifts(cy, e, b0, b1, along_y, sy);
        if (grow(r, (size_t)(nx * ny) * VERTICES_PER_QUAD))
            return -1;
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nx; ++k) {
                const double px = cx + sx[k], py = cy + sy[j];
                quad(r, px - e, py - e, px + e, py + e, px, py, rad, c);
            }
    }
    return 0;
}

/* The box's outline, the legend and the label, over the disks. */
static int decorations(rd_renderer *r, const rl_layout *l, const palette *p, const char *label)
{
    /* The outline goes over the disks: a disk touching a wall overlaps the
     * edge by a fraction of a step, and the box must stay visible. */
    const double h = 0.5 * l->outline;
    const double a0 = rl_px(l, 0.0), a1 = rl_px(l, l->box);
    const double b0 = rl_py(l, 0.0), b1 = rl_py(l, l->box_y);
    return rect(r, a0 - h, b0 - h, a1 + h, b0 + h, RC_OUTLINE) ||
           rect(r, a0 - h, b1 - h, a1 + h, b1 + h, RC_OUTLINE) ||
           rect(r, a0 - h, b0 + h, a0 + h, b1 - h, RC_OUTLINE) ||
           rect(r, a1 - h, b0 + h, a1 + h, b1 - h, RC_OUTLINE) ||
           (p->speeds && speed_legend(r, l, p->vmax)) ||
           /* The psi6 bar: bond orientations from -30 to +30 degrees at
            * full order, t as rc_psi6 maps the phase. */
           (p->psi6 && legend(r, l, rc_cyclic, "-30", "30", "psi6")) ||
           (p->sizes && size_legend(r, l, p->rmin, p->rmax)) ||
           (label && text(r, l->label_x, l->label_y, l->text_px, label, RC_OUTLINE));
}

/* Sends the vertices and draws them: the first disk_vertices (the disks)
 * clipped to the box along its periodic axes, where their images are. */
static int submit(rd_renderer *r, size_t disk_vertices, const rd_view *view, const rl_layout *l,
                  char *err, size_t errlen)
{
    glClear(GL_COLOR_BUFFER_BIT);
    /* Orphan and refill: the driver never waits for the previous frame. */
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(r->count * FLOATS_PER_VERTEX * sizeof(float)),
                 r->vertices, GL_STREAM_DRAW);
    if (view->boundary == DS_BOUNDARY_WALLS) {
        glDrawArrays(GL_TRIANGLES, 0, (GLsizei)r->count);
    } else {
        /* The pixels whose centres the box holds; the half pixel of rim
         * beyond is under the outline. */
        const int x0 = (int)floor(rl_px(l, 0.0)), x1 = (int)ceil(rl_px(l, l->box));
        const int y0 = view->boundary == DS_BOUNDARY_PERIODIC ? (int)floor(rl_py(l, 0.0)) : 0;
        const int y1 =
            view->boundary == DS_BOUNDARY_PERIODIC ? (int)ceil(rl_py(l, l->box_y)) : l->size;
        glEnable(GL_SCISSOR_TEST);
        glScissor(x0, y0, x1 - x0, y1 - y0);
        glDrawArrays(GL_TRIANGLES, 0, (GLsizei)disk_vertices);
        glDisable(GL_SCISSOR_TEST);
        glDrawArrays(GL_TRIANGLES, (GLint)disk_vertices, (GLsizei)(r->count - disk_vertices));
    }
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "drawing failed (GL error 0x%x)", (unsigned)e);
        return -1;
    }
    return 0;
}

int rd_draw(rd_renderer *r, const ds_frame *frame, const rd_view *view, char *err, size_t errlen)
{
    const rd_colour colour = r->opt.colour != RD_COLOUR_AUTO ? r->opt.colour
                             : frame->columns == 5           ? RD_COLOUR_SPEED
                                                             : RD_COLOUR_AUTO;
    if (colour == RD_COLOUR_SPEED && frame->columns != 5) {
        snprintf(err, errlen, "--colour speed needs frames of \"x y R vx vy\" lines");
        return -1;
    }
    palette p = {colour == RD_COLOUR_SPEED,
                 colour == RD_COLOUR_PSI6,
                 colour == RD_COLOUR_SIZE,
                 0.0,
                 INFINITY,
                 0.0,
                 NULL,
                 NULL};
    /* Sizes: the smallest radius at the map's bottom, the largest at its
     * top; one radius sits in the middle. */
    for (size_t i = 0; p.sizes && i < frame->count; ++i) {
        p.rmin = fmin(p.rmin, frame->disks[i].r);
        p.rmax = fmax(p.rmax, frame->disks[i].r);
    }
    rl_layout l;
    rl_make_view(&l, r->opt.size, view->box_x, view->box_y, p.speeds || p.psi6 || p.sizes,
                 r->opt.label);
    p.vmax = !p.speeds ? 0.0 : r->opt.vmax > 0.0 ? r->opt.vmax : rc_speed_scale(frame);
    if (p.psi6) {
        p.re = malloc(frame->count * sizeof *p.re);
        p.im = malloc(frame->count * sizeof *p.im);
        if (!p.re || !p.im)
            snprintf(err, errlen, "out of memory for %zu disks", frame->count);
        if (!p.re || !p.im || frame_psi6(frame, view, p.re, p.im, err, errlen) != 0) {
            free(p.re);
            free(p.im);
            return -1;
        }
    }
    r->count = 0;
    const int failed = disk_quads(r, frame, view, &l, &p);
    const size_t disk_vertices = r->count;
    free(p.re);
    free(p.im);
    if (failed || decorations(r, &l, &p, view->label)) {
        snprintf(err, errlen, "out of memory for %zu disks", frame->count);
        return -1;
    }
    return submit(r, disk_vertices, view, &l, err, errlen);
}

void rd_destroy(rd_renderer *r)
{
    if (!r)
        return;
    if (r->vbo)
        glDeleteBuffers(1, &r->vbo);
    if (r->program)
        glDeleteProgram(r->program);
    free(r->vertices);
    free(r);
}

void rd_describe_gl(char *out, size_t len)
{
    const char *renderer = (const char *)glGetString(GL_RENDERER);
    const char *version = (const char *)glGetString(GL_VERSION);
    snprintf(out, len, "%s, OpenGL %s", renderer ? renderer : "?", version ? version : "?");
}
