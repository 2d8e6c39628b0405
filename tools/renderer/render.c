/* SPDX-License-Identifier: MIT */
/* render: frame files and extended XYZ trajectories to PNG images or one
 * movie, off-screen, no display or gnuplot.
 *
 *   render [options] FRAME.txt... RUN.xyz...     render [options] --dir DIR
 *   render --movie run.mp4 [options] --dir DIR   (or run.gif)
 *
 * The command line is read and checked (render_request.c), and the frames
 * listed, each with its box, boundary, number, time and PNG's name
 * (render_inputs.c, from the options, a run's frames.json or an XYZ
 * header), so every refusal comes before anything is made.
 * Each worker thread owns one GL context (render_backend.h) and one set of
 * shaders and buffers (render_draw.h), made once and reused for all the
 * frames it takes from a shared counter; a frame is read, drawn, read back
 * and written by render_png.c, or, for a movie, handed to ffmpeg by
 * render_movie.c in frame order. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "disk_sim.h"
#include "render_backend.h"
#include "render_draw.h"
#include "render_inputs.h"
#include "render_layout.h"
#include "render_movie.h"
#include "render_png.h"
#include "render_request.h"

typedef struct job {
    const ri_list *list;
    rd_options draw;
    rq_label label;
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
    size_t i = j->failed ? j->list->count : j->next;
    if (i < j->list->count)
        ++j->next;
    pthread_mutex_unlock(&j->lock);
    return i;
}

/* Reads and draws frame i; 0, or -1 with a message. */
static int draw_frame(job *j, rd_renderer *r, size_t i, char *msg, size_t len)
{
    const ri_frame *f = &j->list->frames[i];
    ds_frame frame;
    if (ri_read(j->list, i, &frame, msg, len) != 0)
        return -1;
    char label[64];
    if (j->label == RQ_LABEL_TIME)
        snprintf(label, sizeof label, "t = %.6g", f->time);
    else
        snprintf(label, sizeof label, "frame %ld", f->number);
    const rd_view view = {f->box_x, f->box_y, f->boundary, j->label ? label : NULL};
    char why[256];
    const int rc = rd_draw(r, &frame, &view, why, sizeof why);
    ds_frame_free(&frame);
    if (rc != 0)
        snprintf(msg, len, "%s: %s", f->path, why);
    return rc;
}

static void *worker(void *arg)
{
    job *j = arg;
    char msg[1024], why[256];
    rb_context *ctx = rb_create(j->draw.size, j->draw.size, why, sizeof why);
    rd_renderer *r = ctx ? rd_create(&j->draw, why, sizeof why) : NULL;
    unsigned char *rgb = j->movie ? malloc(rm_frame_bytes(j->movie)) : NULL;
    if (!r || (j->movie && !rgb)) {
        snprintf(msg, sizeof msg, "render: %s: %s", rb_name(), r ? "out of memory" : why);
        report(j, msg);
        rd_destroy(r);
        r = NULL;
    }
    for (size_t i; r && (i = take(j)) < j->list->count;) {
        if (draw_frame(j, r, i, msg, sizeof msg) != 0) {
            report(j, msg);
            break;
        }
        const unsigned char *rgba = rb_pixels(ctx, why, sizeof why);
        if (!rgba) {
            snprintf(msg, sizeof msg, "%s: %s", j->list->frames[i].path, why);
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
        } else if (rp_write(j->list->frames[i].output, rgba, j->draw.size, j->draw.size, j->mode,
                            msg, sizeof msg) != 0) {
            report(j, msg);
            break;
        }
    }
    free(rgb);
    rd_destroy(r);
    rb_destroy(ctx);
    return NULL;
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

/* Renders every frame with the given number of workers; 0 or 1. */
static int render_all(job *j, size_t workers, int quiet)
{
    char why[256];
    if (rb_open(why, sizeof why) != 0) {
        fprintf(stderr, "render: %s: %s\n", rb_name(), why);
        return 1;
    }
    const double start = ds_timer_now();
    pthread_t threads[RQ_MAX_WORKERS];
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
    const size_t count = j->list->count;
    if (!quiet)
        printf("render: %zu frame%s, %dx%d px, %s backend, %zu worker%s, %.2f s%s\n", count,
               count == 1 ? "" : "s", j->draw.size, j->draw.size, rb_name(), started + 1,
               started ? "s" : "", ds_timer_now() - start, j->movie ? ", one movie" : "");
    return 0;
}

int main(int argc, char **argv)
{
    rq_request q;
    memset(&q, 0, sizeof q);
    q.size = 800;
    q.fps = 25;
    q.box.boundary = -1;
    q.colour = RD_COLOUR_AUTO;
    q.inputs = calloc((size_t)argc, sizeof *q.inputs);
    q.is_dir = calloc((size_t)argc, sizeof *q.is_dir);
    if (!q.inputs || !q.is_dir) {
        fprintf(stderr, "render: out of memory\n");
        return 1;
    }
    int rc = 0, made = 0;
    ri_list list;
    memset(&list, 0, sizeof list);
    job j;
    memset(&j, 0, sizeof j);
    const int parsed = rq_parse(&q, argc, argv);
    if (parsed == RQ_HELP)
        printf("%sBackend: %s (render --version names the GL renderer).\n", rq_usage, rb_name());
    rc = parsed == RQ_VERSION ? print_version() : parsed > 0 ? parsed : 0;
    if (parsed != 0 || (rc = rq_check(&q)) != 0 || (rc = rq_prepare(&q, &list, &made)) != 0)
        goto done;
    j.list = &list;
    j.draw = (rd_options){(int)q.size, q.colour, q.vmax, q.label != RQ_LABEL_NONE};
    j.label = q.label;
    j.mode = umask(0);
    umask(j.mode);
    j.mode = 0666 & ~j.mode;
    if (q.movie) {
        char why[512];
        if (!(j.movie = rm_open(q.movie, (rm_format)rm_format_of(q.movie), j.draw.size, j.draw.size,
                                (int)q.fps, j.mode, why, sizeof why))) {
            fprintf(stderr, "render: %s\n", why);
            rc = 1;
            goto done;
        }
    }
    pthread_mutex_init(&j.lock, NULL);
    pthread_cond_init(&j.turn, NULL);
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    size_t workers = q.jobs > 0 ? (size_t)q.jobs : cores > 0 ? (size_t)cores : 1;
    if (workers > RQ_MAX_WORKERS)
        workers = RQ_MAX_WORKERS;
    if (workers > list.count)
        workers = list.count;
    rc = render_all(&j, workers, q.quiet);
    pthread_cond_destroy(&j.turn);
    pthread_mutex_destroy(&j.lock);
done:
    /* A failed render leaves no directory it made and left empty. */
    if (rc != 0 && made)
        rmdir(q.out);
    ri_free(&list);
    free(q.inputs);
    free(q.is_dir);
    return rc;
}
