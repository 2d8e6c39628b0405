/* SPDX-License-Identifier: MIT */
/* Parameters: the defaults, what a request may ask for and why not, and
 * the memory it needs. Every refusal is made here (or by the integrator's
 * own check, through its table) and explained in one sentence, so the
 * command prints the library's reason instead of deriving it again. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "sim/sim.h"
#include "init/init.h"

ds_params ds_default_params(size_t n, double radius)
{
    ds_params p;
    memset(&p, 0, sizeof p);
    p.n = n;
    p.radius = radius;
    p.seed = DS_DEFAULT_SEED;
    p.broadphase = DS_AUTO;
    return p;
}

ds_world ds_world_of(const ds_params *p)
{
    ds_world w;
    memset(&w, 0, sizeof w);
    w.n = p->n;
    w.radius = p->radius;
    w.box = p->box == 0.0 ? 1000.0 : p->box;
    w.box_y = p->box_y == 0.0 ? w.box : p->box_y;
    w.speed = p->speed == 0.0 ? 100.0 : p->speed;
    w.dt = p->dt == 0.0 ? 0.001 : p->dt;
    w.integrator = p->integrator;
    w.boundary = p->boundary;
    w.broadphase = p->broadphase;
    w.placement = p->placement;
    w.seed = p->seed;
    return w;
}

/* Oler's inequality (1961; Folkman and Graham 1969 for any convex set):
 * points at mutual distance >= 1 inside a convex polygon of area A and
 * perimeter P number at most (2/sqrt 3) A + P/2 + 1. With walls, disk
 * centres are 2R apart inside the rectangle of sides box - 2R and
 * box_y - 2R, so in units of 2R that rectangle has sides s, t and at most
 * (2/sqrt 3) s t + s + t + 1 disks fit. The bound is exact for one disk
 * and tends to the hexagonal packing, area fraction pi / (2 sqrt 3) =
 * 0.907, for many. A periodic box has no edge: the hexagonal packing
 * density bounds it, (2/sqrt 3) box box_y / (2R)^2 disks. */
static int disks_cannot_fit(const ds_world *w)
{
    const int periodic = w->boundary == DS_PERIODIC;
    const double d = 2.0 * w->radius;
    const double s = periodic ? w->box / d : (w->box - d) / d;
    const double t = periodic ? w->box_y / d : (w->box_y - d) / d;
    const double most = 1.1547005383792515 * s * t + (periodic ? 0.0 : s + t + 1.0);
    return (double)w->n > most * (1.0 + 1e-12); /* slack: never refuse a fit to rounding */
}

/* A length of the box: 0 asks for the default, anything else is in
 * (0, 1e9], which keeps every coordinate far below 2^53 so that frames
 * print exactly. */
static ds_status check_length(ds_params_error *err, const char *field, double given, double most)
{
    if (given == 0.0 || (given > 0.0 && given <= most))
        return DS_OK;
    return ds_refuse(err, DS_ERR_ARG, field, "%s = %g must be > 0 and <= %g (0 means the default)",
                     field, given, most);
}

static ds_status check_numbers(const ds_params *p, ds_params_error *err)
{
    ds_status st = check_length(err, "box", p->box, 1e9);
    if (st == DS_OK)
        st = check_length(err, "box_y", p->box_y, 1e9);
    if (st == DS_OK)
        st = check_length(err, "speed", p->speed, 1e9);
    if (st == DS_OK)
        st = check_length(err, "dt", p->dt, 1.0);
    return st;
}

static ds_status check_kinds(const ds_params *p, ds_params_error *err)
{
    const ds_integrator_ops *ops = ds_integrator_ops_of(p->integrator);
    if (!ops)
        return ds_refuse(err, DS_ERR_ARG, "integrator", "integrator = %d is not a ds_integrator",
                         (int)p->integrator);
    if ((unsigned)p->boundary > (unsigned)DS_PERIODIC)
        return ds_refuse(err, DS_ERR_ARG, "boundary", "boundary = %d is not a ds_boundary",
                         (int)p->boundary);
    if ((unsigned)p->placement > (unsigned)DS_LATTICE)
        return ds_refuse(err, DS_ERR_ARG, "placement", "placement = %d is not a ds_placement",
                         (int)p->placement);
    if ((unsigned)p->broadphase > (unsigned)DS_CELLS)
        return ds_refuse(err, DS_ERR_ARG, "broadphase", "broadphase = %d is not a ds_broadphase",
                         (int)p->broadphase);
    if (p->broadphase != DS_AUTO && !ops->fits(p->broadphase)) {
        char fit[96] = "";
        for (int bp = 0; bp <= (int)DS_CELLS; ++bp)
            if (bp != DS_AUTO && ops->fits((ds_broadphase)bp))
                snprintf(fit + strlen(fit), sizeof fit - strlen(fit), "%s, ",
                         ds_broadphase_name((ds_broadphase)bp));
        return ds_refuse(err, DS_ERR_ARG, "broadphase",
                         "broadphase = %s does not serve the %s integrator, which takes %sor auto",
                         ds_broadphase_name(p->broadphase), ops->name, fit);
    }
    return DS_OK;
}

/* A disk fits between the walls; in a periodic box two disks in contact
 * must be so through one image only (boundary.h), so each side is more
 * than two diameters. */
static ds_status check_size(const ds_world *w, double min_room, ds_params_error *err)
{
    if (w->n < 1)
        return ds_refuse(err, DS_ERR_ARG, "n", "n = 0: there must be at least one disk");
    const int periodic = w->boundary == DS_PERIODIC;
    const double most = (periodic ? 0.25 : 0.5) * fmin(w->box, w->box_y);
    if (!(w->radius > 0.0) || !isfinite(w->radius))
        return ds_refuse(err, DS_ERR_ARG, "radius", "radius = %g must be a number > 0", w->radius);
    if (!(w->radius < most))
        return ds_refuse(err, DS_ERR_ARG, "radius",
                         periodic ? "radius = %g is too large for a periodic box of %g x %g: it "
                                    "must be below a quarter of each side (%g)"
                                  : "radius = %g does not fit a box of %g x %g: it must be below "
                                    "half of its shorter side (%g)",
                         w->radius, w->box, w->box_y, most);
    /* The band a centre moves in between the walls, for an integrator that
     * needs room: a disk in a band a rounding error wider than itself
     * would turn at the walls a rounding error apart. */
    const double band = fmin(w->box, w->box_y) - 2.0 * w->radius;
    if (!periodic && min_room > 0.0 && !(band >= 2.0 * w->radius * min_room))
        return ds_refuse(err, DS_ERR_ARG, "radius",
                         "radius = %.17g leaves its centre a band of %g between the walls: the "
                         "%s integrator needs %g of a diameter at least (%g)",
                         w->radius, band, ds_integrator_ops_of(w->integrator)->name, min_room,
                         2.0 * w->radius * min_room);
    /* Ids are 32-bit; beyond that no machine this runs on has the memory. */
    if (w->n >= UINT32_MAX ||
        w->n > (SIZE_MAX - 64) / (DS_DISKS_BYTES_PER_DISK + DS_PLACEMENT_BYTES_PER_DISK))
        return ds_refuse(err, DS_ERR_NOMEM, "n", "n = %zu disks cannot be held in memory", w->n);
    return DS_OK;
}

/* The packings refused before trying (see DS_MANY_DISKS in the header). */
static ds_status check_packing(const ds_world *w, double min_room, ds_params_error *err)
{
    const int periodic = w->boundary == DS_PERIODIC;
    const double fraction =
        (double)w->n * DS_TWO_PI * 0.5 * w->radius * w->radius / (w->box * w->box_y);
    if (w->placement == DS_LATTICE) {
        if (!ds_lattice_fits(w->n, w->radius, w->box, w->box_y, periodic))
            return ds_refuse(err, DS_ERR_PLACEMENT, "n",
                             "n = %zu disks of radius %g cover %.3f of the box; no triangular "
                             "lattice of them fits without overlap (close packing is 0.9069)",
                             w->n, w->radius, fraction);
        const double closest = ds_lattice_closest(w->n, w->radius, w->box, w->box_y, periodic);
        if (min_room > 0.0 && !(closest >= 2.0 * w->radius * (1.0 + min_room)))
            return ds_refuse(err, DS_ERR_PLACEMENT, "n",
                             "n = %zu disks of radius %g cover %.7f of the box: their lattice is "
                             "at close packing, its neighbours %.3g of a diameter apart beyond "
                             "contact; the %s integrator needs %g at least (a slightly larger "
                             "box or smaller disks)",
                             w->n, w->radius, fraction, closest / (2.0 * w->radius) - 1.0,
                             ds_integrator_ops_of(w->integrator)->name, min_room);
        return DS_OK;
    }
    if (disks_cannot_fit(w))
        return ds_refuse(err, DS_ERR_PLACEMENT, "n",
                         "n = %zu disks of radius %g cannot fit in the box without overlap", w->n,
                         w->radius);
    if (w->n > DS_MANY_DISKS && fraction > DS_MAX_AREA_FRACTION)
        return ds_refuse(err, DS_ERR_PLACEMENT, "n",
                         "n = %zu disks of radius %g cover %.3f of the box; random placement of "
                         "more than %d disks cannot exceed %.2f",
                         w->n, w->radius, fraction, DS_MANY_DISKS, DS_MAX_AREA_FRACTION);
    return DS_OK;
}

ds_status ds_diagnose_params(const ds_params *p, unsigned *warnings, ds_params_error *err)
{
    if (warnings)
        *warnings = 0;
    if (err)
        memset(err, 0, sizeof *err);
    if (!p)
        return ds_refuse(err, DS_ERR_ARG, "", "no parameters (NULL)");
    ds_status st = check_numbers(p, err);
    if (st == DS_OK)
        st = check_kinds(p, err);
    const ds_world w = ds_world_of(p);
    const double min_room = st == DS_OK ? ds_integrator_ops_of(w.integrator)->min_room : 0.0;
    if (st == DS_OK)
        st = check_size(&w, min_room, err);
    if (st == DS_OK)
        st = ds_integrator_ops_of(w.integrator)->check(&w, warnings, err);
    if (st == DS_OK)
        st = check_packing(&w, min_room, err);
    if (st != DS_OK && warnings)
        *warnings = 0;
    if (st != DS_OK && err)
        err->warning[0] = '\0';
    return st;
}

ds_status ds_check_params(const ds_params *params, unsigned *warnings)
{
    return ds_diagnose_params(params, warnings, NULL);
}

ds_status ds_memory_needed(const ds_params *params, size_t *bytes)
{
    if (!bytes)
        return DS_ERR_ARG;
    ds_status st = ds_check_params(params, NULL);
    if (st == DS_ERR_PLACEMENT)
        st = DS_OK; /* memory is still a meaningful answer */
    if (st != DS_OK)
        return st;
    ds_world w = ds_world_of(params);
    const ds_integrator_ops *ops = ds_integrator_ops_of(w.integrator);
    if (w.broadphase == DS_AUTO)
        w.broadphase = ops->choose(&w);
    *bytes = (w.n + 1) * (DS_DISKS_BYTES_PER_DISK + DS_PLACEMENT_BYTES_PER_DISK) + ops->bytes(&w);
    return DS_OK;
}
