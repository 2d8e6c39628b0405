/* SPDX-License-Identifier: MIT */
/* render: frame files to PNG images or one movie, off-screen, no display
 * or gnuplot.
 *
 *   render [options] FRAME.txt...      render [options] --dir DIR
 *   render --movie run.mp4 [options] --dir DIR
 *
 * Each worker thread owns one GL context (render_backend.h) and one set of
 * shaders and buffers (render_draw.h), made once and reused for all the
 * frames it takes from a shared counter; a frame is read with the
 * library's ds_frame_read, drawn, read back and written by render_png.c,
 * or, for a movie, handed to ffmpeg by render_movie.c in frame order. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "disk_sim.h"
#include "render_backend.h"
#include "render_draw.h"
#include "render_layout.h"
#include "render_movie.h"
#include "render_png.h"

#define MAX_WORKERS 256

static const char usage[] =
    "usage: render [options] FRAME.txt...\n"
    "       render [options] --dir DIR\n"
    "Writes one PNG per frame file: frame_0012.txt -> frame_0012.png, next to\n"
    "the frame or in --out DIR. Frames are lines \"x y R\" (one colour) or\n"
    "\"x y R vx vy\" (coloured by speed, with a legend); --colour psi6 colours\n"
    "either by the local crystal orientation.\n"
    "  --dir DIR    render every frame_*.txt in DIR, in name order\n"
    "  --out DIR    write the PNGs into DIR (created if missing)\n"
    "  --size PX    image width and height, 32..16384 (default 800)\n"
    "  --box L      side of the simulation box, its width if --box-y is given\n"
    "               (default 1000)\n"
    "  --box-y H    height of the box (default: the width)\n"
    "  --colour C   what the colours show (also --color): speed (the default for\n"
    "               \"x y R vx vy\" frames) or psi6, the orientation arg(psi6)/6\n"
    "               of each disk's neighbours closer than 1.4 diameters, -30 to\n"
    "               +30 degrees on a cyclic colour wheel, darker where |psi6| is\n"
    "               small (brightness 0.3 + 0.7 |psi6|), or size, the radius\n"
    "               from the frame's smallest to its largest (mixtures)\n"
    "  --periodic   the box is periodic: psi6 counts neighbours across its edges\n"
    "  --vmax V     speed at the top of the colour scale (default 2.5 x rms speed)\n"
    "  -j N         frames rendered at once, 1..256 (default: number of cores)\n"
    "  --movie FILE write one H.264 MP4 movie of the frames instead of PNGs\n"
    "               (needs ffmpeg on PATH; Debian package ffmpeg)\n"
    "  --fps N      movie frames per second, 1..240 (default 25, as the GIF)\n"
    "  --quiet      print nothing but errors\n"
    "  -h, --help, --version\n";

typedef struct job {
    char **inputs, **outputs;
    size_t count;
    rd_options draw;
    mode_t mode;
    rm_movie *movie;      /* --movie: frames go to ffmpeg, no PNGs are written */
    pthread_mutex_t lock; /* guards next, next_write, failed and stderr */
    pthread_cond_t turn;  /* next_write advanced, or a worker failed */
    size_t next, next_write;
    int failed;
} job;

static void report(job *j, const char *message)
{
    pthread_mutex_lock(&j->lock);
    fprintf(stderr, "%s\n", message);
    j->failed = 1;
    pthread_cond_broadcast(&j->turn);
    pthread_mutex_unlock(&j->lock);
}

/* Hands frame i to the movie once every frame before it has been: the
 * workers render in parallel and take turns to write. 0 when written, 1
 * when another worker failed (stop quietly), -1 with a message. */
static int movie_put(job *j, size_t i, const unsigned char *rgb, char *msg, size_t len)
{
    pthread_mutex_lock(&j->lock);
    while (!j->failed && j->next_write != i)
        pthread_cond_wait(&j->turn, &j->lock);
    int stop = j->failed;
    pthread_mutex_unlock(&j->lock);
    if (stop)
        return 1;
    int rc = rm_write(j->movie, rgb, msg, len);
    pthread_mutex_lock(&j->lock);
    ++j->next_write;
    pthread_cond_broadcast(&j->turn);
    pthread_mutex_unlock(&j->lock);
    return rc;
}

/* The next frame to render, or count when done or after any failure:
 * the run stops at the first error instead of burying it in output. */
static size_t take(job *j)
{
    pthread_mutex_lock(&j->lock);
    size_t i = j->failed ? j->count : j->next;
    if (i < j->count)
        ++j->next;
    pthread_mutex_unlock(&j->lock);
    return i;
}

static void *worker(void *arg)
{
    job *j = arg;
    char msg[512], why[256];
    rb_context *ctx = rb_create(j->draw.size, j->draw.size, why, sizeof why);
    rd_renderer *r = ctx ? rd_create(&j->draw, why, sizeof why) : NULL;
    unsigned char *rgb = j->movie ? malloc(rm_frame_bytes(j->movie)) : NULL;
    if (!r || (j->movie && !rgb)) {
        snprintf(msg, sizeof msg, "render: %s: %s", rb_name(), r ? "out of memory" : why);
        report(j, msg);
        rd_destroy(r);
        r = NULL;
    }
    for (size_t i; r && (i = take(j)) < j->count;) {
        ds_frame frame;
        ds_error fe;
        ds_status st = ds_frame_read(j->inputs[i], &frame, &fe);
        if (st != DS_OK) {
            const char *text = fe.message;
            if (fe.index)
                snprintf(msg, sizeof msg, "%s:%zu: %s", j->inputs[i], fe.index, text);
            else
                snprintf(msg, sizeof msg, "%s: %s", j->inputs[i], text);
            report(j, msg);
            break;
        }
        const unsigned char *rgba = NULL;
        int ok = rd_draw(r, &frame, why, sizeof why) == 0 &&
                 (rgba = rb_pixels(ctx, why, sizeof why)) != NULL;
        ds_frame_free(&frame);
        if (!ok) {
            snprintf(msg, sizeof msg, "%s: %s", j->inputs[i], why);
            report(j, msg);
            break;
        }
        if (j->movie) {
            rm_convert(j->movie, rgba, rgb);
            int put = movie_put(j, i, rgb, msg, sizeof msg);
            if (put < 0)
                report(j, msg);
            if (put != 0)
                break;
        } else if (rp_write(j->outputs[i], rgba, j->draw.size, j->draw.size, j->mode, msg,
                            sizeof msg) != 0) {
            report(j, msg);
            break;
        }
    }
    free(rgb);
    rd_destroy(r);
    rb_destroy(ctx);
    return NULL;
}

static int name_order(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static char *join(const char *dir, const char *name)
{
    size_t d = strlen(dir), n = strlen(name);
    char *s = malloc(d + n + 2);
    if (s) {
        memcpy(s, dir, d);
        s[d] = '/';
        memcpy(s + d + 1, name, n + 1);
    }
    return s;
}

/* frame_0012.txt -> frame_0012.png, in out_dir if given, else beside it. */
static char *png_path(const char *input, const char *out_dir)
{
    const char *slash = strrchr(input, '/');
    const char *base = slash ? slash + 1 : input;
    size_t stem = strlen(base);
    if (stem > 4 && strcmp(base + stem - 4, ".txt") == 0)
        stem -= 4;
    size_t dir = out_dir ? strlen(out_dir) + 1 : (size_t)(base - input);
    char *s = malloc(dir + stem + 5);
    if (!s)
        return NULL;
    if (out_dir) {
        memcpy(s, out_dir, dir - 1);
        s[dir - 1] = '/';
    } else {
        memcpy(s, input, dir);
    }
    memcpy(s + dir, base, stem);
    memcpy(s + dir + stem, ".png", 5);
    return s;
}

/* Appends DIR/frame_*.txt to the list; -1 with a message on failure. */
static int list_dir(const char *dir, char ***list, size_t *count, size_t *cap)
{
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "render: %s: cannot open directory: %s\n", dir, strerror(errno));
        return -1;
    }
    size_t first = *count;
    struct dirent *e;
    errno = 0;
    while ((e = readdir(d)) != NULL) {
        size_t n = strlen(e->d_name);
        if (n < 10 || strncmp(e->d_name, "frame_", 6) != 0 ||
            strcmp(e->d_name + n - 4, ".txt") != 0)
            continue;
        if (*count == *cap) {
            size_t ncap = *cap ? 2 * *cap : 1024;
            char **grown = realloc(*list, ncap * sizeof *grown);
            if (!grown)
                break;
            *list = grown;
            *cap = ncap;
        }
        if (!((*list)[*count] = join(dir, e->d_name)))
            break;
        ++*count;
        errno = 0;
    }
    int failed = errno != 0;
    int saved = errno;
    closedir(d);
    if (failed) {
        fprintf(stderr, "render: %s: cannot read directory: %s\n", dir, strerror(saved));
        return -1;
    }
    if (*count == first) {
        fprintf(stderr, "render: %s: no frame_*.txt files\n", dir);
        return -1;
    }
    qsort(*list + first, *count - first, sizeof **list, name_order);
    return 0;
}

static int parse_number(const char *opt, const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = s ? strtod(s, &end) : 0.0;
    if (!s || end == s || *end || errno || !(v >= lo && v <= hi)) {
        fprintf(stderr, "render: %s needs a number in [%g, %g], got '%s'\n", opt, lo, hi,
                s ? s : "");
        return -1;
    }
    *out = v;
    return 0;
}

static int print_version(void)
{
    char why[256], gl[256];
    printf("render (disksim %s), backend %s\n", ds_version(), rb_name());
    rb_context *ctx = rb_open(why, sizeof why) == 0 ? rb_create(64, 64, why, sizeof why) : NULL;
    if (!ctx) {
        fprintf(stderr, "render: %s: %s\n", rb_name(), why);
        rb_close();
        return 1;
    }
    rd_describe_gl(gl, sizeof gl);
    printf("GL renderer: %s\n", gl);
    rb_destroy(ctx);
    rb_close();
    return 0;
}

static int add_input(char ***list, size_t *count, size_t *cap, const char *name)
{
    if (*count == *cap) {
        size_t ncap = *cap ? 2 * *cap : 64;
        char **grown = realloc(*list, ncap * sizeof *grown);
        if (!grown)
            return -1;
        *list = grown;
        *cap = ncap;
    }
    size_t n = strlen(name) + 1;
    if (!((*list)[*count] = malloc(n)))
        return -1;
    memcpy((*list)[*count], name, n);
    ++*count;
    return 0;
}

static void free_list(char **list, size_t count)
{
    for (size_t i = 0; list && i < count; ++i)
        free(list[i]);
    free(list);
}

/* Renders every input with the given number of workers; 0 or 1. */
static int render_all(job *j, size_t workers, int quiet)
{
    char why[256];
    if (rb_open(why, sizeof why) != 0) {
        fprintf(stderr, "render: %s: %s\n", rb_name(), why);
        return 1;
    }
    const double start = ds_timer_now();
    pthread_t threads[MAX_WORKERS];
    size_t started = 0;
    /* Worker 0 is this thread; the others get a thread each. */
    for (size_t w = 1; w < workers; ++w, ++started)
        if (pthread_create(&threads[started], NULL, worker, j) != 0)
            break;
    worker(j);
    for (size_t w = 0; w < started; ++w)
        pthread_join(threads[w], NULL);
    rb_close();
    if (j->movie && j->failed)
        rm_abort(j->movie);
    else if (j->movie && rm_finish(j->movie, why, sizeof why) != 0) {
        fprintf(stderr, "render: %s\n", why);
        return 1;
    }
    if (j->failed)
        return 1;
    if (!quiet)
        printf("render: %zu frame%s, %dx%d px, %s backend, %zu worker%s, %.2f s%s\n", j->count,
               j->count == 1 ? "" : "s", j->draw.size, j->draw.size, rb_name(), started + 1,
               started ? "s" : "", ds_timer_now() - start, j->movie ? ", one H.264 movie" : "");
    return 0;
}

int main(int argc, char **argv)
{
    const char *out_dir = NULL, *movie = NULL;
    double size = 800, box = 1000, box_y = 0, vmax = 0, jobs = 0, fps = 25;
    int quiet = 0, rc = 0, periodic = 0;
    rd_colour colour = RD_COLOUR_AUTO;
    char **inputs = NULL;
    size_t count = 0, cap = 0;
    job j;
    memset(&j, 0, sizeof j);
    for (int a = 1; a < argc && rc == 0; ++a) {
        const char *s = argv[a], *v = a + 1 < argc ? argv[a + 1] : NULL;
        int bad = 0;
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            printf("%sBackend: %s (render --version names the GL renderer).\n", usage, rb_name());
            goto done;
        } else if (!strcmp(s, "--version")) {
            rc = print_version();
            goto done;
        } else if (!strcmp(s, "--quiet")) {
            quiet = 1;
            continue;
        } else if (!strcmp(s, "--periodic")) {
            periodic = 1;
            continue;
        } else if ((!strcmp(s, "--colour") || !strcmp(s, "--color")) && v) {
            ++a;
            if (!strcmp(v, "speed")) {
                colour = RD_COLOUR_SPEED;
            } else if (!strcmp(v, "psi6")) {
                colour = RD_COLOUR_PSI6;
            } else if (!strcmp(v, "size")) {
                colour = RD_COLOUR_SIZE;
            } else {
                fprintf(stderr, "render: %s must be speed, psi6 or size, got '%s'\n", s, v);
                rc = 2;
            }
            continue;
        } else if (!strcmp(s, "--dir") && v) {
            /* Listed now, so files and directories keep the command's order. */
            rc = list_dir(argv[++a], &inputs, &count, &cap) != 0;
            continue;
        } else if (!strcmp(s, "--out") && v) {
            out_dir = argv[++a];
            continue;
        } else if (!strcmp(s, "--movie") && v) {
            movie = argv[++a];
            continue;
        } else if (!strcmp(s, "--fps")) {
            bad = parse_number(s, v, 1, 240, &fps) || fps != (int)fps;
        } else if (!strcmp(s, "--size")) {
            bad = parse_number(s, v, RL_MIN_SIZE, RL_MAX_SIZE, &size) || size != (int)size;
        } else if (!strcmp(s, "--box")) {
            bad = parse_number(s, v, 1e-9, 1e15, &box);
        } else if (!strcmp(s, "--box-y")) {
            bad = parse_number(s, v, 1e-9, 1e15, &box_y);
        } else if (!strcmp(s, "--vmax")) {
            bad = parse_number(s, v, 1e-300, 1e300, &vmax);
        } else if (!strcmp(s, "-j")) {
            bad = parse_number(s, v, 1, MAX_WORKERS, &jobs) || jobs != (int)jobs;
        } else if (s[0] == '-' && s[1]) {
            fprintf(stderr, "render: unknown option or missing value: %s (try --help)\n", s);
            rc = 2;
            continue;
        } else {
            rc = add_input(&inputs, &count, &cap, s) != 0;
            continue;
        }
        if (bad) {
            if (size != (int)size || jobs != (int)jobs || fps != (int)fps)
                fprintf(stderr, "render: %s needs a whole number\n", s);
            rc = 2;
        }
        ++a;
    }
    if (rc != 0)
        goto done;
    if (count == 0) {
        fprintf(stderr, "render: no frame files given (try --help)\n");
        rc = 2;
        goto done;
    }
    if (movie && out_dir) {
        fprintf(stderr, "render: --movie writes no PNGs: give --movie or --out, not both\n");
        rc = 2;
        goto done;
    }
    if (out_dir && mkdir(out_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "render: %s: cannot create directory: %s\n", out_dir, strerror(errno));
        rc = 1;
        j.failed = 1; /* reported: not the "out of memory" guess at done */
        goto done;
    }
    j.inputs = inputs;
    j.count = count;
    rc = 1;
    if (!(j.outputs = calloc(count, sizeof *j.outputs)))
        goto done;
    for (size_t i = 0; i < count; ++i)
        if (!(j.outputs[i] = png_path(inputs[i], out_dir)))
            goto done;
    j.draw.size = (int)size;
    j.draw.box = box;
    j.draw.box_y = box_y;
    j.draw.periodic = periodic;
    j.draw.colour = colour;
    j.draw.vmax = vmax;
    j.mode = umask(0);
    umask(j.mode);
    j.mode = 0666 & ~j.mode;
    if (movie) {
        char why[512];
        if (!(j.movie =
                  rm_open(movie, j.draw.size, j.draw.size, (int)fps, j.mode, why, sizeof why))) {
            fprintf(stderr, "render: %s\n", why);
            j.failed = 1; /* reported */
            goto done;
        }
    }
    pthread_mutex_init(&j.lock, NULL);
    pthread_cond_init(&j.turn, NULL);

    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    size_t workers = jobs > 0 ? (size_t)jobs : cores > 0 ? (size_t)cores : 1;
    if (workers > MAX_WORKERS)
        workers = MAX_WORKERS;
    if (workers > count)
        workers = count;
    rc = render_all(&j, workers, quiet);
    pthread_cond_destroy(&j.turn);
    pthread_mutex_destroy(&j.lock);
done:
    if (rc == 1 && !j.failed && count && !j.outputs)
        fprintf(stderr, "render: out of memory\n");
    free_list(j.outputs, j.outputs ? count : 0);
    free_list(inputs, count);
    return rc;
}
