/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "render_layout.h"
#include "render_movie.h"
#include "render_request.h"

const char rq_usage[] =
    "usage: render [options] FRAME.txt... RUN.xyz... RUN.gsd...\n"
    "       render [options] --dir DIR\n"
    "Writes one PNG per frame: frame_0012.txt -> frame_0012.png, frame 12 of\n"
    "run.xyz or run.gsd -> run_0012.png, next to the file or in --out DIR. Frames\n"
    "are lines \"x y R\" (one colour) or \"x y R vx vy\" (coloured by speed, with\n"
    "a legend), or the frames of an extended XYZ file (a disks trajectory, ASE)\n"
    "or of a GSD file (a disks or HOOMD trajectory); --colour psi6 colours any\n"
    "by the local crystal orientation. The box and its boundary come from the\n"
    "run's frames.json beside the frames, the XYZ header or the GSD box (GSD\n"
    "records no boundary: periodic, as HOOMD's); the options below replace them.\n"
    "  --dir DIR    render every frame_*.txt in DIR, in name order\n"
    "  --out DIR    write the PNGs into DIR (created if missing); --out F.png\n"
    "               writes the one frame given as F.png\n"
    "  --size PX    image width and height, 32..16384 (default 800)\n"
    "  --box L      side of the simulation box, its width if --box-y is given\n"
    "               (default: the run's, else 1000)\n"
    "  --box-y H    height of the box (default: the run's, else the width)\n"
    "  --boundary B walls, periodic or channel (periodic along x only): a disk\n"
    "               across a periodic edge is drawn on both sides, and psi6\n"
    "               counts neighbours across it (default: the run's, else walls;\n"
    "               periodic for a GSD file)\n"
    "  --periodic   the same as --boundary periodic\n"
    "  --colour C   what the colours show (also --color): speed (the default for\n"
    "               \"x y R vx vy\" frames) or psi6, the orientation arg(psi6)/6\n"
    "               of each disk's neighbours closer than 1.4 diameters, -30 to\n"
    "               +30 degrees on a cyclic colour wheel, darker where |psi6| is\n"
    "               small (brightness 0.3 + 0.7 |psi6|), or size, the radius\n"
    "               from the frame's smallest to its largest (mixtures)\n"
    "  --label L    write above the box each frame's time (time: from frames.json,\n"
    "               the XYZ Time= or the GSD log/disksim/time) or number (frame)\n"
    "  --vmax V     speed at the top of the colour scale (default 2.5 x rms speed)\n"
    "  -j N         frames rendered at once, 1..256 (default: number of cores)\n"
    "  --movie FILE write one movie of the frames instead of PNGs: FILE.mp4 (H.264)\n"
    "               or FILE.gif (needs ffmpeg on PATH; Debian package ffmpeg)\n"
    "  --fps N      movie frames per second, 1..240 (default 25, as the GIF)\n"
    "  --quiet      print nothing but errors and warnings\n"
    "  -h, --help, --version\n";

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

/* An option that takes no number; 1 if s was one, -1 on a bad value
 * (said), 0 if s is another. */
static int word_option(rq_request *q, const char *s, const char *v, int *a)
{
    if (!strcmp(s, "--quiet")) {
        q->quiet = 1;
        return 1;
    }
    if (!strcmp(s, "--periodic")) {
        q->box.boundary = DS_BOUNDARY_PERIODIC;
        return 1;
    }
    if (!v)
        return 0;
    if (!strcmp(s, "--colour") || !strcmp(s, "--color")) {
        ++*a;
        q->colour = !strcmp(v, "speed")  ? RD_COLOUR_SPEED
                    : !strcmp(v, "psi6") ? RD_COLOUR_PSI6
                    : !strcmp(v, "size") ? RD_COLOUR_SIZE
                                         : RD_COLOUR_AUTO;
        if (q->colour == RD_COLOUR_AUTO)
            fprintf(stderr, "render: %s must be speed, psi6 or size, got '%s'\n", s, v);
        return q->colour == RD_COLOUR_AUTO ? -1 : 1;
    }
    if (!strcmp(s, "--boundary")) {
        ++*a;
        ds_boundary b;
        if (ds_boundary_parse(v, &b, NULL) != DS_OK) {
            fprintf(stderr, "render: --boundary must be walls, periodic or channel, got '%s'\n", v);
            return -1;
        }
        q->box.boundary = (int)b;
        return 1;
    }
    if (!strcmp(s, "--label")) {
        ++*a;
        q->label = !strcmp(v, "time")    ? RQ_LABEL_TIME
                   : !strcmp(v, "frame") ? RQ_LABEL_FRAME
                                         : RQ_LABEL_NONE;
        if (q->label == RQ_LABEL_NONE)
            fprintf(stderr, "render: --label must be time or frame, got '%s'\n", v);
        return q->label == RQ_LABEL_NONE ? -1 : 1;
    }
    const char **into = !strcmp(s, "--out") ? &q->out : !strcmp(s, "--movie") ? &q->movie : NULL;
    if (into) {
        *into = v;
        ++*a;
        return 1;
    }
    if (!strcmp(s, "--dir")) {
        q->is_dir[q->count] = 1;
        q->inputs[q->count++] = v;
        ++*a;
        return 1;
    }
    return 0;
}

int rq_parse(rq_request *q, int argc, char **argv)
{
    for (int a = 1; a < argc; ++a) {
        const char *s = argv[a], *v = a + 1 < argc ? argv[a + 1] : NULL;
        if (!strcmp(s, "--help") || !strcmp(s, "-h"))
            return RQ_HELP;
        if (!strcmp(s, "--version"))
            return RQ_VERSION;
        const int word = word_option(q, s, v, &a);
        if (word < 0)
            return 2;
        if (word > 0)
            continue;
        double *into = !strcmp(s, "--fps")     ? &q->fps
                       : !strcmp(s, "--size")  ? &q->size
                       : !strcmp(s, "--box")   ? &q->box.box
                       : !strcmp(s, "--box-y") ? &q->box.box_y
                       : !strcmp(s, "--vmax")  ? &q->vmax
                       : !strcmp(s, "-j")      ? &q->jobs
                                               : NULL;
        const int whole = into == &q->fps || into == &q->size || into == &q->jobs;
        const double lo = into == &q->fps    ? 1
                          : into == &q->size ? RL_MIN_SIZE
                          : into == &q->jobs ? 1
                          : into == &q->vmax ? 1e-300
                                             : 1e-9;
        const double hi = into == &q->fps    ? 240
                          : into == &q->size ? RL_MAX_SIZE
                          : into == &q->jobs ? RQ_MAX_WORKERS
                          : into == &q->vmax ? 1e300
                                             : 1e15;
        if (into) {
            if (parse_number(s, v, lo, hi, into) != 0)
                return 2;
            if (whole && *into != floor(*into)) {
                fprintf(stderr, "render: %s needs a whole number\n", s);
                return 2;
            }
            ++a;
        } else if (s[0] == '-' && s[1]) {
            fprintf(stderr, "render: unknown option or missing value: %s (try --help)\n", s);
            return 2;
        } else {
            q->is_dir[q->count] = 0;
            q->inputs[q->count++] = s;
        }
    }
    return 0;
}

/* The checks that need only the command line; 0 or 2 (said). */
int rq_check(const rq_request *q)
{
    if (q->count == 0)
        fprintf(stderr, "render: no frame files given (try --help)\n");
    else if (q->movie && q->out)
        fprintf(stderr, "render: --movie writes no PNGs: give --movie or --out, not both\n");
    else if (q->movie && rm_format_of(q->movie) < 0)
        fprintf(stderr, "render: --movie %s: the name must end in .mp4 (H.264) or .gif\n",
                q->movie);
    else
        return 0;
    return 2;
}

/* --out names one PNG rather than a directory: it ends in .png and is
 * not a directory already. */
static int names_one_png(const char *out)
{
    const size_t n = strlen(out);
    struct stat st;
    return n > 4 && strcasecmp(out + n - 4, ".png") == 0 &&
           !(stat(out, &st) == 0 && S_ISDIR(st.st_mode));
}

/* What the frames must give for the request, before anything is made:
 * one frame for --out F.png, a time or a number for --label. 0, or the
 * exit status (said). */
static int check_frames(const rq_request *q, const ri_list *list)
{
    if (q->out && names_one_png(q->out) && list->count != 1) {
        fprintf(stderr,
                "render: --out %s names one PNG, but there are %zu frames: give --out a "
                "directory (e.g. --out pngs) for a PNG each, or one frame\n",
                q->out, list->count);
        return 2;
    }
    for (size_t i = 0; i < list->count; ++i) {
        const ri_frame *f = &list->frames[i];
        if (q->label == RQ_LABEL_TIME && !isfinite(f->time)) {
            fprintf(stderr, "render: --label time: %s has no time (%s): use --label frame\n",
                    f->path,
                    f->xyz   ? "its XYZ header has no Time="
                    : f->gsd ? "its GSD frame has no log/disksim/time"
                             : "no frames.json with dt and steps_per_frame beside it, or not "
                               "named frame_NNNN.txt");
            return 1;
        }
        if (q->label == RQ_LABEL_FRAME && f->number < 0) {
            fprintf(stderr, "render: --label frame: %s is not named frame_NNNN.txt\n", f->path);
            return 1;
        }
    }
    return 0;
}

/* Lists every frame, checks what they must give, names the outputs and
 * makes --out's directory (*made: it did not exist). 0, or the exit
 * status (said). */
int rq_prepare(const rq_request *q, ri_list *list, int *made)
{
    for (size_t k = 0; k < q->count; ++k)
        if ((q->is_dir[k] ? ri_add_dir : ri_add_file)(list, q->inputs[k], &q->box) != 0)
            return 1;
    int rc = check_frames(q, list);
    if (rc != 0)
        return rc;
    const int one_png = q->out && names_one_png(q->out);
    if (!q->movie && ri_name_outputs(list, one_png ? NULL : q->out, one_png ? q->out : NULL)) {
        fprintf(stderr, "render: out of memory\n");
        return 1;
    }
    if (q->out && !one_png) {
        if (mkdir(q->out, 0777) == 0) {
            *made = 1;
        } else if (errno != EEXIST) {
            fprintf(stderr, "render: %s: cannot create directory: %s\n", q->out, strerror(errno));
            return 1;
        }
    }
    return 0;
}
