/* The simulation: parameters, creation, the step loop, accessors and
 * observables. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "number_text.h"
#include "sim_internal.h"

/* Bytes per disk: x, y, vx, vy, id, slot, plus the placement grid's node
 * (centre and link, 24 bytes). DS_SAP_STRIPS adds DS_STRIPS_BYTES_PER_DISK. */
#define BYTES_PER_DISK (4 * sizeof(double) + 2 * sizeof(uint32_t) + 3 * sizeof(double))

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

typedef struct resolved {
    double box, box_y, speed, dt;
} resolved;

static resolved resolve_defaults(const ds_params *p)
{
    resolved r;
    r.box = p->box == 0.0 ? 1000.0 : p->box;
    r.box_y = p->box_y == 0.0 ? r.box : p->box_y;
    r.speed = p->speed == 0.0 ? 100.0 : p->speed;
    r.dt = p->dt == 0.0 ? 0.001 : p->dt;
    return r;
}

/* The broad phases each integrator runs: the time step has the sweeps,
 * the event-driven integrator its cell grid; both have brute force. */
static int broadphase_fits(ds_broadphase bp, ds_integrator integrator)
{
    switch (bp) {
    case DS_AUTO:
    case DS_BRUTE_FORCE:
        return 1;
    case DS_SAP:
    case DS_SAP_STRIPS:
        return integrator == DS_TIME_STEP;
    case DS_CELLS:
        return integrator == DS_EVENT_DRIVEN;
    }
    return 0;
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
static int disks_cannot_fit(size_t n, double radius, double box, double box_y, int periodic)
{
    const double d = 2.0 * radius;
    const double s = periodic ? box / d : (box - d) / d, t = periodic ? box_y / d : (box_y - d) / d;
    const double most = 1.1547005383792515 * s * t + (periodic ? 0.0 : s + t + 1.0);
    return (double)n > most * (1.0 + 1e-12); /* slack: never refuse a fit to rounding */
}

ds_status ds_check_params(const ds_params *p, unsigned *warnings)
{
    if (warnings)
        *warnings = 0;
    if (!p)
        return DS_ERR_ARG;
    resolved r = resolve_defaults(p);
    /* Bounds keep every coordinate far below 2^53 so frames print exactly. */
    if (!(r.box > 0.0 && r.box <= 1e9) || !(r.box_y > 0.0 && r.box_y <= 1e9) ||
        !(r.speed > 0.0 && r.speed <= 1e9) || !(r.dt > 0.0 && r.dt <= 1.0))
        return DS_ERR_ARG;
    if ((unsigned)p->integrator > (unsigned)DS_EVENT_DRIVEN ||
        (unsigned)p->boundary > (unsigned)DS_PERIODIC ||
        (unsigned)p->placement > (unsigned)DS_LATTICE ||
        !broadphase_fits(p->broadphase, p->integrator))
        return DS_ERR_ARG;
    /* A disk fits between the walls; in a periodic box two disks in
     * contact must be so through one image only (boundary.h), so each
     * side is more than two diameters. */
    const double most_radius = (p->boundary == DS_PERIODIC ? 0.25 : 0.5) * fmin(r.box, r.box_y);
    if (p->n < 1 || !(p->radius > 0.0) || !(p->radius < most_radius))
        return DS_ERR_ARG;
    /* Ids are 32-bit, the event calendar's 30-bit; beyond that no machine
     * this runs on has the memory. */
    if (p->n >= UINT32_MAX || p->n > (SIZE_MAX - 64) / BYTES_PER_DISK ||
        (p->integrator == DS_EVENT_DRIVEN && p->n >= ((size_t)1 << 30)))
        return DS_ERR_NOMEM;
    double fraction = (double)p->n * DS_TWO_PI * 0.5 * p->radius * p->radius / (r.box * r.box_y);
    if (p->placement == DS_LATTICE) {
        if (!ds_lattice_fits(p->n, p->radius, r.box, r.box_y, p->boundary == DS_PERIODIC))
            return DS_ERR_PLACEMENT;
    } else if (disks_cannot_fit(p->n, p->radius, r.box, r.box_y, p->boundary == DS_PERIODIC) ||
               (p->n > DS_MANY_DISKS && fraction > DS_MAX_AREA_FRACTION)) {
        return DS_ERR_PLACEMENT;
    }
    if (warnings && p->integrator == DS_TIME_STEP && 2.0 * 3.0 * r.speed * r.dt > 4.0 * p->radius)
        *warnings |= DS_WARN_TUNNELING;
    return DS_OK;
}

static ds_broadphase choose_broadphase(const ds_params *p, double box);

ds_status ds_memory_needed(const ds_params *params, size_t *bytes)
{
    if (!bytes)
        return DS_ERR_ARG;
    ds_status st = ds_check_params(params, NULL);
    if (st == DS_ERR_PLACEMENT)
        st = DS_OK; /* memory is still a meaningful answer */
    if (st != DS_OK)
        return st;
    const resolved r = resolve_defaults(params);
    *bytes = (params->n + 1) * BYTES_PER_DISK;
    if (params->integrator == DS_EVENT_DRIVEN)
        *bytes += ds_ed_bytes(params->n, params->radius, r.box, r.box_y, params->broadphase);
    else if (choose_broadphase(params, r.box) == DS_SAP_STRIPS)
        *bytes += (params->n + 2) * DS_STRIPS_BYTES_PER_DISK;
    if (params->integrator == DS_TIME_STEP && params->boundary == DS_PERIODIC &&
        choose_broadphase(params, r.box) != DS_BRUTE_FORCE)
        *bytes += ds_seam_bytes(params->n);
    return DS_OK;
}

static ds_broadphase choose_broadphase(const ds_params *p, double box)
{
    if (p->broadphase != DS_AUTO)
        return p->broadphase;
    if (p->integrator == DS_EVENT_DRIVEN)
        return DS_CELLS;
    /* Plain SAP tests ~ n 2R / box candidates per disk (those within 2R in
     * x, anywhere in y); strips test a constant few but pay for disks
     * changing strip. Measured (N = 1000, 2000, 4000, candidates per disk
     * 4 to 11, best of 5): SAP is 3.6x faster at 4 (the seed case) and
     * 1.1-1.2x faster at 8 at N <= 2000; they break even between 8 and 9;
     * strips are 1.15-1.35x faster at 10. */
    double per_disk = (double)p->n * 2.0 * p->radius / box;
    return per_disk > 8.5 ? DS_SAP_STRIPS : DS_SAP;
}

ds_status ds_create(const ds_params *params, ds_sim **out)
{
    if (!out)
        return DS_ERR_ARG;
    *out = NULL;
    ds_status st = ds_check_params(params, NULL);
    if (st != DS_OK)
        return st;
    resolved r = resolve_defaults(params);

    ds_sim *sim = calloc(1, sizeof *sim);
    if (!sim)
        return DS_ERR_NOMEM;
    const size_t n = params->n, cap = n + 1;
    sim->n = n;
    sim->radius = params->radius;
    sim->box = r.box;
    sim->box_y = r.box_y;
    sim->integrator = params->integrator;
    sim->boundary = params->boundary;
    sim->speed = r.speed;
    sim->dt = r.dt;
    sim->broadphase = choose_broadphase(params, r.box);
    sim->scan = ds_bp_widest_scan();
    ds_format_shortest(sim->radius_text, sizeof sim->radius_text, sim->radius);

    sim->x = malloc(cap * sizeof(double));
    sim->y = malloc(cap * sizeof(double));
    sim->vx = malloc(cap * sizeof(double));
    sim->vy = malloc(cap * sizeof(double));
    sim->id = malloc(cap * sizeof(uint32_t));
    sim->slot = malloc(cap * sizeof(uint32_t));
    if (!sim->x || !sim->y || !sim->vx || !sim->vy || !sim->id || !sim->slot) {
        ds_destroy(sim);
        return DS_ERR_NOMEM;
    }
    st = params->placement == DS_LATTICE ? ds_place_lattice(sim, params->seed)
                                         : ds_place_disks(sim, params->seed);
    if (st != DS_OK) {
        ds_destroy(sim);
        return st;
    }
    for (size_t k = 0; k < n; ++k)
        sim->id[k] = (uint32_t)k;
    /* Slot n is the sweep sentinel: never inside any x window. */
    sim->x[n] = INFINITY;
    sim->y[n] = INFINITY;
    sim->vx[n] = sim->vy[n] = 0.0;
    sim->id[n] = UINT32_MAX;

    if (sim->integrator == DS_EVENT_DRIVEN) {
        st = ds_ed_create(sim);
        if (st != DS_OK) {
            ds_destroy(sim);
            return st;
        }
    } else if (sim->broadphase == DS_SAP_STRIPS) {
        st = ds_strips_create(sim);
        if (st != DS_OK) {
            ds_destroy(sim);
            return st;
        }
    } else if (sim->broadphase == DS_SAP) {
        ds_bp_insertion_sort_x(sim);
    }
    if (sim->integrator == DS_TIME_STEP && sim->boundary == DS_PERIODIC &&
        sim->broadphase != DS_BRUTE_FORCE) {
        st = ds_seam_create(sim);
        if (st != DS_OK) {
            ds_destroy(sim);
            return st;
        }
    }
    ds_rebuild_slots(sim);
    ds_timer_reset(&sim->collision_timer);
    *out = sim;
    return DS_OK;
}

void ds_destroy(ds_sim *sim)
{
    if (!sim)
        return;
    ds_strips_destroy(sim);
    ds_seam_destroy(sim);
    ds_ed_destroy(sim);
    free(sim->x);
    free(sim->y);
    free(sim->vx);
    free(sim->vy);
    free(sim->id);
    free(sim->slot);
    free(sim);
}

void ds_rebuild_slots(ds_sim *sim)
{
    for (size_t k = 0; k < sim->n; ++k)
        sim->slot[sim->id[k]] = (uint32_t)k;
}

void ds_run(ds_sim *sim, uint64_t steps)
{
    if (!sim || steps == 0)
        return;
    if (sim->integrator == DS_EVENT_DRIVEN)
        ds_ed_run(sim, steps);
    else
        ds_ts_run(sim, steps);
}

void ds_step(ds_sim *sim) { ds_run(sim, 1); }

size_t ds_count(const ds_sim *sim) { return sim ? sim->n : 0; }
double ds_radius(const ds_sim *sim) { return sim ? sim->radius : 0.0; }
double ds_box(const ds_sim *sim) { return sim ? sim->box : 0.0; }
double ds_box_y(const ds_sim *sim) { return sim ? sim->box_y : 0.0; }
ds_boundary ds_boundary_used(const ds_sim *sim) { return sim ? sim->boundary : DS_WALLS; }

const char *ds_boundary_name(ds_boundary boundary)
{
    switch (boundary) {
    case DS_WALLS:
        return "walls";
    case DS_PERIODIC:
        return "periodic";
    }
    return "unknown";
}
double ds_dt(const ds_sim *sim) { return sim ? sim->dt : 0.0; }
/* steps * dt rather than a running sum, so time carries no rounding drift. */
double ds_time(const ds_sim *sim) { return sim ? (double)sim->steps * sim->dt : 0.0; }
uint64_t ds_steps(const ds_sim *sim) { return sim ? sim->steps : 0; }
ds_broadphase ds_broadphase_used(const ds_sim *sim) { return sim ? sim->broadphase : DS_SAP; }
ds_integrator ds_integrator_used(const ds_sim *sim) { return sim ? sim->integrator : DS_TIME_STEP; }

const char *ds_integrator_name(ds_integrator integrator)
{
    switch (integrator) {
    case DS_TIME_STEP:
        return "step";
    case DS_EVENT_DRIVEN:
        return "event";
    }
    return "unknown";
}

const char *ds_broadphase_name(ds_broadphase bp)
{
    switch (bp) {
    case DS_SAP:
        return "sap";
    case DS_BRUTE_FORCE:
        return "brute";
    case DS_SAP_STRIPS:
        return "strips";
    case DS_AUTO:
        return "auto";
    case DS_CELLS:
        return "cells";
    }
    return "unknown";
}

ds_disk ds_get(const ds_sim *sim, size_t i)
{
    ds_disk d = {0.0, 0.0, 0.0, 0.0};
    if (!sim || i >= sim->n)
        return d;
    size_t k = sim->slot[i];
    d.x = sim->x[k];
    d.y = sim->y[k];
    d.vx = sim->vx[k];
    d.vy = sim->vy[k];
    return d;
}

ds_status ds_get_all(const ds_sim *sim, ds_disk *out)
{
    if (!sim || !out)
        return DS_ERR_ARG;
    /* Read the arrays front to back and scatter by id: one scattered write
     * per disk, where gathering through slot[] would read four arrays at
     * scattered places. */
    for (size_t k = 0; k < sim->n; ++k) {
        ds_disk *d = &out[sim->id[k]];
        d->x = sim->x[k];
        d->y = sim->y[k];
        d->vx = sim->vx[k];
        d->vy = sim->vy[k];
    }
    return DS_OK;
}

ds_status ds_set(ds_sim *sim, size_t i, ds_disk d)
{
    if (!sim || i >= sim->n)
        return DS_ERR_ARG;
    /* With walls the centre stays R from each wall; a periodic box takes
     * any point of [0, box) x [0, box_y), as its frames show them. */
    const int inside = sim->boundary == DS_PERIODIC
                           ? d.x >= 0.0 && d.x < sim->box && d.y >= 0.0 && d.y < sim->box_y
                           : d.x >= sim->radius && d.x <= sim->box - sim->radius &&
                                 d.y >= sim->radius && d.y <= sim->box_y - sim->radius;
    if (!inside || !isfinite(d.vx) || !isfinite(d.vy) || fabs(d.vx) > 1e12 || fabs(d.vy) > 1e12)
        return DS_ERR_ARG;
    size_t k = sim->slot[i];
    if (sim->integrator == DS_EVENT_DRIVEN)
        return ds_ed_set(sim, k, d);
    sim->x[k] = d.x;
    sim->y[k] = d.y;
    sim->vx[k] = d.vx;
    sim->vy[k] = d.vy;
    /* The broad phase re-sorts on the next step; insertion sort copes with
     * any displacement, just more slowly for a large one. */
    return DS_OK;
}

double ds_collision_seconds(const ds_sim *sim)
{
    return sim ? ds_timer_seconds(&sim->collision_timer) : 0.0;
}
uint64_t ds_collision_count(const ds_sim *sim) { return sim ? sim->collisions : 0; }
uint64_t ds_pairs_tested(const ds_sim *sim) { return sim ? sim->pairs_tested : 0; }

double ds_kinetic_energy(const ds_sim *sim)
{
    if (!sim)
        return 0.0;
    double e = 0.0;
    for (size_t k = 0; k < sim->n; ++k)
        e += sim->vx[k] * sim->vx[k] + sim->vy[k] * sim->vy[k];
    return 0.5 * e;
}

void ds_momentum(const ds_sim *sim, double *px, double *py)
{
    double sx = 0.0, sy = 0.0;
    for (size_t k = 0; sim && k < sim->n; ++k) {
        sx += sim->vx[k];
        sy += sim->vy[k];
    }
    if (px)
        *px = sx;
    if (py)
        *py = sy;
}

uint64_t ds_wall_count(const ds_sim *sim) { return sim ? sim->wall_count : 0; }
double ds_wall_impulse(const ds_sim *sim) { return sim ? sim->wall_impulse : 0.0; }

double ds_pressure(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    if (sim->boundary == DS_PERIODIC) /* no wall to push on */
        return ds_virial_pressure(sim);
    double elapsed = (double)(sim->steps - sim->observables_since_step) * sim->dt;
    double perimeter =
        2.0 * (sim->box - 2.0 * sim->radius) + 2.0 * (sim->box_y - 2.0 * sim->radius);
    return sim->wall_impulse / (elapsed * perimeter);
}

/* The area the centres reach: with walls they stay R from each wall. */
static double centre_area(const ds_sim *sim)
{
    if (sim->boundary == DS_PERIODIC)
        return sim->box * sim->box_y;
    return (sim->box - 2.0 * sim->radius) * (sim->box_y - 2.0 * sim->radius);
}

double ds_virial_pressure(const ds_sim *sim)
{
    if (!sim || sim->steps == sim->observables_since_step)
        return 0.0;
    const double elapsed = (double)(sim->steps - sim->observables_since_step) * sim->dt;
    return (ds_kinetic_energy(sim) + sim->virial / (2.0 * elapsed)) / centre_area(sim);
}

void ds_reset_observables(ds_sim *sim)
{
    if (!sim)
        return;
    sim->wall_count = 0;
    sim->wall_impulse = 0.0;
    sim->virial = 0.0;
    sim->observables_since_step = sim->steps;
}
