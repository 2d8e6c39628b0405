/* SPDX-License-Identifier: MIT */
/* Where a run starts, checked before any work: a new request (what the
 * library would refuse, in the command's words, and what this machine
 * cannot hold), a checkpoint (--restart) or a frame (--from). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* The library's sentence about a field, in the command's words: a
 * message begins with the ds_params member it is about ("radius = 600
 * ..."), which the command calls by its option or argument. */
static const char *in_command_words(const char *field, const char *message, char *out, size_t cap)
{
    static const char *const names[][2] = {
        {"n", "N"},
        {"radius", "R"},
        {"box_y", "--box-y"},
        {"broadphase", "--broadphase"},
        {"integrator", "--integrator"},
    };
    const size_t flen = strlen(field);
    /* "mixture: its largest radius, ..." is about --mixture. */
    if (strcmp(field, "mixture") == 0 && strncmp(message, "mixture: ", 9) == 0) {
        snprintf(out, cap, "--mixture: %s", message + 9);
        return out;
    }
    for (size_t k = 0; *field && k < sizeof names / sizeof names[0]; ++k) {
        if (strcmp(field, names[k][0]) != 0 || strncmp(message, field, flen) != 0 ||
            strncmp(message + flen, " = ", 3) != 0)
            continue;
        /* An option takes its value as "--box-y 5", an argument as "R = 5". */
        snprintf(out, cap, "%s%s%s", names[k][1], names[k][1][0] == '-' ? " " : " = ",
                 message + flen + 3);
        return out;
    }
    return message;
}

/* A refusal of the request; with --from, of the frame, which is where N
 * and R came from: a run-time error naming the file. */
static void refuse(const char *from, int code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((noreturn, format(printf, 3, 4)))
#endif
    ;
static void refuse(const char *from, int code, const char *fmt, ...)
{
    char message[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(message, sizeof message, fmt, ap);
    va_end(ap);
    if (from)
        die(EXIT_RUN, "cannot start from %s: %s", from, message);
    die(code, "%s", message);
}

/* Refuses, before any work, what the library would refuse (in its words)
 * or what this machine cannot hold, and passes on its warnings. */
void check_request(const ds_params *p, const ds_mixture *mixture, const char *from)
{
    unsigned warnings = 0;
    ds_params_error why;
    char words[sizeof why.message + 16];
    ds_status st = ds_diagnose_mixture(p, mixture, &warnings, &why);
    if (st == DS_ERR_NOMEM)
        refuse(from, EXIT_USAGE, "%s",
               in_command_words(why.field, why.message, words, sizeof words));
    size_t bytes = 0;
    if (st != DS_ERR_ARG && ds_memory_needed_mixture(p, mixture, &bytes) != DS_OK)
        refuse(from, EXIT_USAGE, "N = %zu disks cannot be held in memory", p->n);
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0 && (double)bytes > 0.8 * (double)pages * (double)page)
        refuse(from, EXIT_USAGE, "N = %zu disks need %.1f GiB, more than this machine's %.1f GiB",
               p->n, (double)bytes / 1073741824.0, (double)pages * (double)page / 1073741824.0);
    /* --from makes the simulation on a lattice, then sets the frame's
     * disks: a box no lattice of them fits is refused, however the frame
     * holds them. */
    if (st == DS_ERR_PLACEMENT && from)
        refuse(from, EXIT_RUN, "the library places the disks before setting them and refuses: %s",
               in_command_words(why.field, why.message, words, sizeof words));
    if (st != DS_OK)
        refuse(from, st == DS_ERR_PLACEMENT ? EXIT_RUN : EXIT_USAGE, "%s",
               in_command_words(why.field, why.message, words, sizeof words));
    if (warnings)
        fprintf(stderr, "disks: warning: %s\n",
                in_command_words("radius", why.warning, words, sizeof words));
}

ds_params params_of(const options *o)
{
    ds_params p = ds_default_params(o->n, o->radius);
    p.seed = o->seed;
    p.broadphase = o->broadphase;
    p.integrator = o->integrator;
    p.placement = o->placement;
    p.boundary = o->boundary;
    p.box_y = o->box_y;
    return p;
}

const ds_mixture *mixture_of(const options *o, ds_species kinds[2], ds_mixture *mix)
{
    if (!o->mixture_text && o->mass_rule == DS_MASS_EQUAL)
        return NULL;
    /* The large disks: the nearest whole number to FRACTION N. */
    const size_t large = o->mixture_text ? (size_t)floor(o->mix_fraction * (double)o->n + 0.5) : 0;
    kinds[0] = (ds_species){o->n - large, o->radius, 0.0};
    kinds[1] = (ds_species){large, o->mix_ratio * o->radius, 0.0};
    *mix = (ds_mixture){large ? 2 : 1, kinds, NULL, NULL, o->mass_rule};
    return mix;
}

ds_sim *create_fresh(const ds_params *p, const ds_mixture *mixture)
{
    ds_sim *sim = NULL;
    ds_status st = ds_create_mixture(p, mixture, &sim);
    if (st == DS_ERR_PLACEMENT)
        die(EXIT_RUN, "could not place %zu disks of R = %g%s without overlap (seed %llu): %s",
            p->n, p->radius, mixture ? " and their mixture" : "", (unsigned long long)p->seed,
            "try another --seed, or fewer or smaller disks");
    if (st != DS_OK)
        die(EXIT_RUN, "cannot create the simulation: %s", ds_status_str(st));
    return sim;
}

/* A whole regular file in memory (a checkpoint or a frame is read to its
 * end: a device or a pipe could have none). Opened without blocking, since
 * opening a named pipe waits for a writer, possibly forever; then what was
 * opened is judged, so nothing can replace it between a check and the
 * open; then reads block again. */
static char *read_input(const char *option, const char *path, size_t *len)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    struct stat st;
    if (fd < 0 || fstat(fd, &st) != 0)
        die(EXIT_RUN, "cannot read %s %s: %s", option, path, strerror(errno));
    if (S_ISDIR(st.st_mode))
        die(EXIT_RUN, "cannot read %s %s: %s", option, path, strerror(EISDIR));
    if (!S_ISREG(st.st_mode))
        die(EXIT_RUN, "cannot read %s %s: not a regular file", option, path);
    const int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0)
        die(EXIT_RUN, "cannot read %s %s: %s", option, path, strerror(errno));
    size_t cap = (size_t)st.st_size + 1, got = 0;
    char *data = malloc(cap);
    if (!data)
        die(EXIT_RUN, "cannot read %s %s: out of memory", option, path);
    for (;;) {
        if (got == cap) {
            char *grown = realloc(data, cap *= 2);
            if (grown)
                data = grown;
            else
                die(EXIT_RUN, "cannot read %s %s: out of memory", option, path);
        }
        ssize_t r = read(fd, data + got, cap - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r < 0)
            die(EXIT_RUN, "cannot read %s %s: %s", option, path, strerror(errno));
        if (r == 0)
            break;
        got += (size_t)r;
    }
    close(fd);
    *len = got;
    return data;
}

ds_sim *restart_from(const char *path)
{
    size_t len = 0;
    char *data = read_input("--restart", path, &len);
    ds_sim *sim = NULL;
    ds_state_error err;
    ds_status st = ds_parse_state(data, len, &sim, &err);
    free(data);
    if (st != DS_OK)
        die(EXIT_RUN, "cannot restart from %s: %s", path,
            st == DS_ERR_FORMAT && err.message[0] ? err.message : ds_status_str(st));
    return sim;
}

long restart_frame(const options *o, const ds_sim *sim)
{
    const uint64_t steps = ds_steps(sim), k = o->steps_per_frame;
    /* A growth that jammed ended its run between frames, in the frame it
     * was making: the restart goes on from the next. */
    const int jammed = ds_growth_state_of(sim) == DS_GROWTH_JAMMED;
    if (steps % k != 0 && !jammed)
        die(EXIT_RUN,
            "cannot restart from %s: its step %llu is not a whole number of frames of "
            "--steps-per-frame %llu; give the run's --steps-per-frame",
            o->restart_path, (unsigned long long)steps, (unsigned long long)k);
    const uint64_t frame = steps / k + (steps % k != 0);
    if (frame + (uint64_t)o->frames > MAX_FRAMES - 1)
        die(EXIT_RUN,
            "cannot restart from %s at frame %llu: --frames %ld would go past frame_%04d.txt "
            "(at most %llu more)",
            o->restart_path, (unsigned long long)frame, o->frames, MAX_FRAMES - 1,
            frame < MAX_FRAMES - 1 ? (unsigned long long)(MAX_FRAMES - 1 - frame) : 0ull);
    return (long)frame;
}

/* A restart into the directory of its run finds its own last frame there:
 * it must be the checkpoint's state, or the frames would be numbered by
 * another --steps-per-frame (or be another run's). */
void check_restart_frame_file(const options *o, const ds_sim *sim, long frame)
{
    char path[PATH_CAP];
    snprintf(path, sizeof path, "%s/frame_%04ld.txt", o->out_dir, frame);
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return;
    size_t len = 0;
    char *data = read_input("--restart", path, &len);
    int same = 0;
    for (int velocities = 0; velocities < 2 && !same; ++velocities) {
        size_t cap = ds_frame_size(sim, velocities), got = 0;
        char *mine = malloc(cap ? cap : 1);
        if (!mine)
            die(EXIT_RUN, "out of memory for the frame buffer");
        ds_format_frame(sim, velocities, mine, cap, &got);
        same = got == len && memcmp(mine, data, len) == 0;
        free(mine);
    }
    free(data);
    if (!same)
        die(EXIT_RUN,
            "cannot restart from %s: %s is not its state (step %llu, frame %ld with "
            "--steps-per-frame %llu): give the run's --steps-per-frame, or another --out",
            o->restart_path, path, (unsigned long long)ds_steps(sim), frame,
            (unsigned long long)o->steps_per_frame);
}

ds_sim *start_from_frame(options *o)
{
    const char *path = o->from_path;
    size_t len = 0;
    char *text = read_input("--from", path, &len);
    ds_frame frame;
    ds_frame_error ferr;
    ds_status st = ds_parse_frame(text, len, &frame, &ferr);
    free(text);
    if (st != DS_OK && ferr.line)
        refuse(path, EXIT_RUN, "line %zu: %s", ferr.line, ferr.message);
    if (st != DS_OK)
        refuse(path, EXIT_RUN, "%s", ferr.message[0] ? ferr.message : ds_status_str(st));
    if (frame.columns != 5)
        refuse(path, EXIT_RUN,
               "it has no velocities (%d columns, x y R): --from needs a frame written with "
               "--velocities",
               frame.columns);
    const double r = frame.disks[0].r;
    for (size_t k = 1; k < frame.count; ++k)
        if (frame.disks[k].r != r)
            refuse(path, EXIT_RUN,
                   "disk %zu has R = %.17g, disk 0 R = %.17g: a mixture's run goes on from its "
                   "--checkpoint, with --restart",
                   k, frame.disks[k].r, r);
    if (o->have_n && frame.count != o->n)
        refuse(path, EXIT_RUN, "it holds %zu disks, not N = %zu", frame.count, o->n);
    if (o->have_n && r != o->radius)
        refuse(path, EXIT_RUN, "its disks have R = %.17g, not R = %.17g", r, o->radius);
    o->n = frame.count;
    o->radius = r;
    o->placement = DS_LATTICE; /* placed, then replaced: a lattice is quick and never fails */
    ds_params p = params_of(o);
    check_request(&p, NULL, path);
    ds_sim *sim = create_fresh(&p, NULL);
    ds_disk *disks = malloc(frame.count * sizeof *disks);
    if (!disks)
        refuse(path, EXIT_RUN, "out of memory for %zu disks", frame.count);
    const double box = ds_box(sim), box_y = ds_box_y(sim);
    const int periodic = ds_boundary_used(sim) == DS_PERIODIC;
    for (size_t k = 0; k < frame.count; ++k) {
        const ds_frame_disk *f = &frame.disks[k];
        ds_disk d = {f->x, f->y, f->vx, f->vy};
        /* Six decimals can round a periodic centre just below the side up
         * to the side itself, the same point as 0. */
        if (periodic && d.x == box)
            d.x = 0.0;
        if (periodic && d.y == box_y)
            d.y = 0.0;
        disks[k] = d;
    }
    ds_frame_free(&frame);
    ds_state_error err;
    st = ds_set_all(sim, disks, &err);
    free(disks);
    if (st != DS_OK)
        refuse(path, EXIT_RUN, "%s", err.message[0] ? err.message : ds_status_str(st));
    return sim;
}

/* The area fraction a new request starts at. */
static double request_eta(const ds_params *p, const ds_mixture *m)
{
    const double box = p->box > 0.0 ? p->box : 1000.0, box_y = p->box_y > 0.0 ? p->box_y : box;
    double covered = 0.0;
    if (!m)
        covered = (double)p->n * p->radius * p->radius;
    else
        for (size_t k = 0; k < m->species; ++k)
            covered += (double)m->kinds[k].count * m->kinds[k].radius * m->kinds[k].radius;
    return 3.14159265358979323846 * covered / (box * box_y);
}

/* The library's bound on the rate: the largest pair's surfaces recede at
 * 2 r_max rate, at most 10 rms speeds. */
static void check_growth_rate(const options *o, double radius_max, double rms)
{
    const double most = 10.0 * rms / (2.0 * radius_max);
    if (o->grow_rate > 0.0 && !(o->grow_rate <= most))
        die(EXIT_USAGE,
            "--grow %g is too fast: the largest disks' surfaces would recede at %g, more than 10 "
            "times the rms speed %g; at most --grow %.6g",
            o->grow_rate, 2.0 * radius_max * o->grow_rate, rms, most);
}

void check_growth_request(const options *o, const ds_params *p, const ds_mixture *mixture)
{
    double radius_max = p->radius;
    for (size_t k = 0; mixture && k < mixture->species; ++k)
        radius_max = mixture->kinds[k].count ? fmax(radius_max, mixture->kinds[k].radius) : radius_max;
    /* A new start: every disk at the speed (0 means 100). */
    check_growth_rate(o, radius_max, p->speed > 0.0 ? p->speed : 100.0);
    const double eta = request_eta(p, mixture);
    if (o->grow_rate > 0.0 && o->until_eta > 0.0 && !(o->until_eta > eta))
        die(EXIT_USAGE, "--until-eta %g must be above the start's area fraction %.6g", o->until_eta,
            eta);
}

void start_growth(const options *o, ds_sim *sim)
{
    if (!(o->grow_rate > 0.0))
        return;
    const char *source = o->restart_path ? o->restart_path : o->from_path;
    if (ds_integrator_used(sim) != DS_EVENT_DRIVEN || ds_boundary_used(sim) != DS_PERIODIC)
        die(EXIT_USAGE, "--grow needs an event-driven run in a periodic box; %s is %s, %s",
            source ? source : "the request", ds_integrator_name(ds_integrator_used(sim)),
            ds_boundary_name(ds_boundary_used(sim)));
    if (o->until_eta > 0.0 && !(o->until_eta > ds_area_fraction(sim)))
        die(EXIT_USAGE, "--until-eta %g must be above the start's area fraction %.6g%s%s",
            o->until_eta, ds_area_fraction(sim), source ? " in " : "", source ? source : "");
    double mass = 0.0;
    for (size_t i = 0; i < ds_count(sim); ++i)
        mass += ds_mass_of(sim, i);
    check_growth_rate(o, ds_radius_max(sim), sqrt(2.0 * ds_kinetic_energy(sim) / mass));
    ds_status st = ds_set_growth(sim, o->grow_rate, o->until_eta, o->until_z);
    if (st != DS_OK)
        die(EXIT_RUN, "cannot grow the disks: %s", ds_status_str(st));
}
