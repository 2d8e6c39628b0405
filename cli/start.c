/* SPDX-License-Identifier: MIT */
/* Where a run starts, checked before any work: a new request (what the
 * library refuses, its reason in the command's words, and what this
 * machine cannot hold), a checkpoint (--restart) or a frame (--from); and
 * --grow, the granular rules, --thermostat, --pressure and --shear,
 * which the library refuses or sets. */
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
    ds_error why;
    char words[sizeof why.message + 16];
    ds_status st = ds_params_check(p, mixture, &warnings, &why);
    if (st == DS_ERR_NOMEM)
        refuse(from, EXIT_USAGE, "%s", in_command_words(&why, words, sizeof words));
    size_t bytes = 0;
    if (st != DS_ERR_ARG && ds_params_memory(p, mixture, &bytes, NULL) != DS_OK)
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
               in_command_words(&why, words, sizeof words));
    /* Random placement's limit is not the lattice's: say so. */
    const int lattice_would = st == DS_ERR_PLACEMENT && p->placement == DS_PLACEMENT_RANDOM &&
                              strstr(why.message, "random placement") != NULL;
    if (st != DS_OK)
        refuse(from, st == DS_ERR_PLACEMENT ? EXIT_RUN : EXIT_USAGE, "%s%s",
               in_command_words(&why, words, sizeof words),
               lattice_would ? "; --lattice places them up to close packing (0.9069)" : "");
    /* The warning is about the radius (ds_params_check). */
    if (warnings) {
        ds_error warned = why;
        snprintf(warned.field, sizeof warned.field, "radius");
        memcpy(warned.message, why.warning, sizeof warned.message);
        fprintf(stderr, "disks: warning: %s\n", in_command_words(&warned, words, sizeof words));
    }
}

ds_params params_of(const options *o)
{
    ds_params p = ds_params_default(o->n, o->radius);
    p.seed = o->seed;
    p.broadphase = o->broadphase;
    p.integrator = o->integrator;
    p.placement = o->placement;
    p.boundary = o->boundary;
    p.box_y = o->box_y;
    if (o->box > 0.0)
        p.box = o->box;
    if (o->dt > 0.0)
        p.dt = o->dt;
    if (o->speed > 0.0)
        p.speed = o->speed;
    return p;
}

const ds_mixture *mixture_of(const options *o, ds_species kinds[2], ds_mixture *mix)
{
    if (!o->mixture_text && o->mass_rule == DS_MASS_EQUAL)
        return NULL;
    /* The large disks: the nearest whole number to FRACTION N. */
    const size_t large = o->mixture_text ? (size_t)floor(o->mix_fraction * (double)o->n + 0.5) : 0;
    kinds[0] = (ds_species){o->n - large, o->radius, 0.0, NULL};
    kinds[1] = (ds_species){large, o->mix_ratio * o->radius, 0.0, NULL};
    *mix = (ds_mixture){large ? 2 : 1, kinds, NULL, NULL, o->mass_rule};
    return mix;
}

ds_sim *create_fresh(const ds_params *p, const ds_mixture *mixture)
{
    ds_sim *sim = NULL;
    ds_error err;
    ds_status st = ds_sim_create(p, mixture, &sim, &err);
    if (st == DS_ERR_PLACEMENT)
        die(EXIT_RUN, "could not place %zu disks of R = %g%s without overlap (seed %llu): %s", p->n,
            p->radius, mixture ? " and their mixture" : "", (unsigned long long)p->seed,
            p->placement == DS_PLACEMENT_RANDOM
                ? "try another --seed, fewer or smaller disks, or --lattice (up to close packing, "
                  "0.9069)"
                : "try fewer or smaller disks");
    if (st != DS_OK)
        die(EXIT_RUN, "cannot create the simulation: %s", err.message);
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
    ds_error err;
    ds_status st = ds_checkpoint_parse(data, len, &sim, &err);
    free(data);
    if (st != DS_OK)
        die(EXIT_RUN, "cannot restart from %s: %s", path, err.message);
    return sim;
}

long restart_frame(const options *o, const ds_sim *sim)
{
    const uint64_t steps = ds_sim_get_steps(sim), k = o->steps_per_frame;
    /* A growth that jammed ended its run between frames, in the frame it
     * was making: the restart goes on from the next. */
    const int jammed = ds_sim_get_growth_state(sim) == DS_GROWTH_JAMMED;
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
        size_t cap = ds_frame_get_size(sim, velocities), got = 0;
        char *mine = malloc(cap ? cap : 1);
        if (!mine)
            die(EXIT_RUN, "out of memory for the frame buffer");
        ds_frame_format(sim, velocities, mine, cap, &got, NULL);
        same = got == len && memcmp(mine, data, len) == 0;
        free(mine);
    }
    free(data);
    if (!same)
        die(EXIT_RUN,
            "cannot restart from %s: %s is not its state (step %llu, frame %ld with "
            "--steps-per-frame %llu): give the run's --steps-per-frame, or another --out",
            o->restart_path, path, (unsigned long long)ds_sim_get_steps(sim), frame,
            (unsigned long long)o->steps_per_frame);
}

ds_sim *start_from_frame(options *o)
{
    const char *path = o->from_path;
    size_t len = 0;
    char *text = read_input("--from", path, &len);
    if (len >= 8 && memcmp(text, "DSIMSTAT", 8) == 0) { /* ds_checkpoint_save's first bytes */
        free(text);
        refuse(path, EXIT_RUN,
               "it is a checkpoint, not a frame: continue its run with --restart %s", path);
    }
    ds_frame frame;
    ds_error ferr;
    ds_status st = ds_frame_parse(text, len, &frame, &ferr);
    free(text);
    if (st != DS_OK && ferr.index)
        refuse(path, EXIT_RUN, "line %zu: %s", ferr.index, ferr.message);
    if (st != DS_OK)
        refuse(path, EXIT_RUN, "%s", ferr.message);
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
    /* placed, then replaced: a lattice is quick and never fails */
    o->placement = DS_PLACEMENT_LATTICE;
    ds_params p = params_of(o);
    check_request(&p, NULL, path);
    ds_sim *sim = create_fresh(&p, NULL);
    ds_disk *disks = malloc(frame.count * sizeof *disks);
    if (!disks) {
        ds_sim_destroy(sim);
        refuse(path, EXIT_RUN, "out of memory for %zu disks", frame.count);
    }
    const double box = ds_sim_get_box_width(sim), box_y = ds_sim_get_box_height(sim);
    /* Periodic along x in a periodic box and a channel, along y only in
     * a periodic box. */
    const ds_boundary boundary = ds_sim_get_boundary(sim);
    const int periodic_x = boundary != DS_BOUNDARY_WALLS;
    const int periodic_y = boundary == DS_BOUNDARY_PERIODIC;
    for (size_t k = 0; k < frame.count; ++k) {
        const ds_frame_disk *f = &frame.disks[k];
        ds_disk d = {f->x, f->y, f->vx, f->vy};
        /* Six decimals can round a periodic centre just below the side up
         * to the side itself, the same point as 0. */
        if (periodic_x && d.x == box)
            d.x = 0.0;
        if (periodic_y && d.y == box_y)
            d.y = 0.0;
        disks[k] = d;
    }
    ds_frame_free(&frame);
    ds_error err;
    st = ds_sim_set_disks(sim, disks, &err);
    free(disks);
    if (st != DS_OK) { /* nothing left behind, for the leak checkers too */
        ds_sim_destroy(sim);
        refuse(path, EXIT_RUN, "%s", err.message);
    }
    return sim;
}

/* --grow, once the simulation exists (a new one, a checkpoint's or a
 * frame's): the library checks the rate and the targets against the
 * disks as they are and says why it refuses. */
void start_growth(const options *o, ds_sim *sim)
{
    if (!(o->grow_rate > 0.0))
        return;
    ds_error err;
    if (ds_sim_set_growth(sim, o->grow_rate, o->until_eta, o->until_z, &err) == DS_OK)
        return;
    if (err.status == DS_ERR_NOMEM)
        die(EXIT_RUN, "cannot grow the disks: %s", err.message);
    const char *source = o->restart_path ? o->restart_path : o->from_path;
    /* A checkpoint's integrator, box or shear (the command's own options
     * refuse a new run's, options.c). */
    if (strcmp(err.field, "integrator") == 0 || strcmp(err.field, "boundary") == 0 ||
        strcmp(err.field, "shear") == 0)
        die(EXIT_USAGE, "cannot grow the disks of %s: %s", source ? source : "the request",
            err.message);
    /* The area fraction a target is held to is the source's. */
    const int where = source && strcmp(err.field, "until_eta") == 0;
    char words[sizeof err.message + 16];
    die(EXIT_USAGE, "%s%s%s", in_command_words(&err, words, sizeof words), where ? " in " : "",
        where ? source : "");
}

/* The granular rules, once the simulation exists (a new one, a
 * checkpoint's, whose rules they change, or a frame's): what the library
 * refuses is a usage error in its words, before anything is made. A
 * restitution not given stays the simulation's. */
void start_granular(const options *o, ds_sim *sim)
{
    ds_error err;
    ds_status st = DS_OK;
    if (!isnan(o->restitution) || !isnan(o->wall_restitution))
        st = ds_sim_set_restitution(
            sim, isnan(o->restitution) ? ds_sim_get_restitution(sim) : o->restitution,
            isnan(o->wall_restitution) ? ds_sim_get_wall_restitution(sim) : o->wall_restitution,
            &err);
    if (st == DS_OK && o->contact_time > 0.0)
        st = ds_sim_set_contact_time(sim, o->contact_time, &err);
    if (st == DS_OK && o->gravity > 0.0)
        st = ds_sim_set_gravity(sim, 0.0, -o->gravity, &err);
    if (st == DS_OK && o->drive > 0.0)
        st = ds_sim_set_drive(sim, o->drive, &err);
    if (st == DS_OK)
        return;
    if (err.status == DS_ERR_NOMEM)
        die(EXIT_RUN, "cannot make the disks granular: %s", err.message);
    /* The library's field is the component, -G: the command's is G. */
    if (strcmp(err.field, "gy") == 0)
        die(EXIT_USAGE, "--gravity %g: %s", o->gravity, err.message);
    char words[sizeof err.message + 32];
    die(EXIT_USAGE, "%s", in_command_words(&err, words, sizeof words));
}

/* A refusal of --thermostat, --pressure or --shear: a checkpoint's
 * integrator, box or shear named as the checkpoint's, the rest in the
 * command's words. */
static void refuse_ensemble(const options *o, const char *what, const ds_error *err)
{
    if (err->status == DS_ERR_NOMEM)
        die(EXIT_RUN, "cannot set the %s: %s", what, err->message);
    const char *source = o->restart_path ? o->restart_path : o->from_path;
    if (strcmp(err->field, "integrator") == 0 || strcmp(err->field, "boundary") == 0 ||
        strcmp(err->field, "shear") == 0)
        die(EXIT_USAGE, "cannot set the %s of %s: %s", what, source ? source : "the request",
            err->message);
    /* The shear's "rate = 2000 ..." is --shear's (report.c's "rate" is
     * --grow's). */
    if (strcmp(what, "shear") == 0 && strcmp(err->field, "rate") == 0 &&
        strncmp(err->message, "rate = ", 7) == 0)
        die(EXIT_USAGE, "--shear %s", err->message + 7);
    /* No --temperature: the library was asked for the disks' own. */
    if (strcmp(err->field, "kt") == 0 && !(o->temperature > 0.0))
        die(EXIT_USAGE,
            "--thermostat %s needs --temperature KT: the disks%s%s have no temperature of their "
            "own (at rest, or moving as one)",
            ds_thermostat_name(o->thermostat), source ? " of " : "", source ? source : "");
    char words[sizeof err->message + 32];
    die(EXIT_USAGE, "%s", in_command_words(err, words, sizeof words));
}

/* --thermostat, --pressure and --shear, once the simulation exists: the
 * library checks them against the disks as they are (the temperature of
 * now when --temperature is not given) and says why it refuses. The
 * shear comes last, so that its refusal names a heat bath or a barostat
 * in its way. A checkpoint's shear goes on unless --shear is given (its
 * own rate again changes nothing; 0 stops it). */
void start_ensemble(const options *o, ds_sim *sim)
{
    ds_error err;
    if (o->thermostat != DS_THERMOSTAT_NONE &&
        ds_sim_set_thermostat(sim, o->thermostat, o->temperature, o->thermostat_rate, &err) !=
            DS_OK)
        refuse_ensemble(o, "thermostat", &err);
    if (o->pressure > 0.0 &&
        ds_sim_set_barostat(sim, o->pressure, o->barostat_every, o->barostat_step,
                            o->barostat_aspect, &err) != DS_OK)
        refuse_ensemble(o, "barostat", &err);
    if (o->shear_given && ds_sim_set_shear(sim, o->shear, &err) != DS_OK)
        refuse_ensemble(o, "shear", &err);
}
