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

ds_params ds_params_default(size_t n, double radius)
{
    ds_params p;
    memset(&p, 0, sizeof p); /* every choice's default is its 0 */
    p.n = n;
    p.radius = radius;
    p.seed = DS_DEFAULT_SEED;
    return p;
}

ds_world ds_world_of(const ds_params *p)
{
    ds_world w;
    memset(&w, 0, sizeof w);
    w.n = p->n;
    w.radius = p->radius;
    const double width = p->box == 0.0 ? 1000.0 : p->box;
    w.box = ds_box_of(p->boundary, width, p->box_y == 0.0 ? width : p->box_y);
    w.speed = p->speed == 0.0 ? 100.0 : p->speed;
    w.dt = p->dt == 0.0 ? 0.001 : p->dt;
    w.integrator = p->integrator;
    w.boundary = p->boundary;
    w.broadphase = p->broadphase;
    w.placement = p->placement;
    w.seed = p->seed;
    w.radius_min = w.radius_max = p->radius;
    w.covered = ds_covered_by((double)p->n, p->radius);
    w.rules = ds_rules_default(&w);
    return w;
}

/* Elastic collisions, straight flights, and the TC model's default
 * contact time, DS_CONTACT_TIME_DEFAULT of the time a disk at the initial
 * speed takes to cross its diameter (docs/physics.md says why). */
ds_rules ds_rules_default(const ds_world *w)
{
    ds_rules r;
    memset(&r, 0, sizeof r);
    r.restitution = r.wall_restitution = 1.0;
    r.contact_time = DS_CONTACT_TIME_DEFAULT * 2.0 * w->radius / w->speed;
    return r;
}

/* The radius and mass of disk i of a mixture (checked). */
double ds_mixture_radius(const ds_mixture *m, size_t i)
{
    if (!m->kinds)
        return m->radii[i];
    for (size_t k = 0;; ++k) {
        if (i < m->kinds[k].count)
            return m->kinds[k].radius;
        i -= m->kinds[k].count;
    }
}

double ds_mixture_mass(const ds_mixture *m, double reference_radius, size_t i)
{
    double mass = 0.0;
    if (m->kinds) {
        size_t k = 0;
        for (size_t left = i; left >= m->kinds[k].count; ++k)
            left -= m->kinds[k].count;
        mass = m->kinds[k].mass;
    } else if (m->masses) {
        mass = m->masses[i];
    }
    if (mass > 0.0)
        return mass;
    const double r = ds_mixture_radius(m, i) / reference_radius;
    return m->mass_rule == DS_MASS_AREA ? r * r : 1.0;
}

/* A refusal of the mixture: field "mixture", no numbers. */
#define refuse_mixture(err, ...) ds_refuse(err, DS_ERR_ARG, "mixture", NAN, NAN, __VA_ARGS__)

/* A mixture's form, its counts, radii and masses; on DS_OK its smallest
 * and largest radius and the area its disks cover are in w. */
static ds_status check_mixture(const ds_mixture *m, double reference, ds_world *w, ds_error *err)
{
    if ((unsigned)m->mass_rule >= (unsigned)DS_MASS_RULE_COUNT)
        return refuse_mixture(err, "mixture: mass rule %d is not a ds_mass_rule",
                              (int)m->mass_rule);
    if ((m->species > 0) == (m->radii != NULL) || (m->species > 0 && !m->kinds) ||
        (m->species == 0 && m->masses && !m->radii))
        return refuse_mixture(err, "mixture: give either species (kinds, with their count) or "
                                   "radii per disk, not both and not neither");
    if (m->species > 0 && m->masses)
        return refuse_mixture(err, "mixture: masses per disk go with radii per disk; species "
                                   "give each kind's mass in ds_species.mass");
    if (m->kinds) {
        size_t total = 0;
        for (size_t k = 0; k < m->species; ++k) {
            if (m->kinds[k].count > w->n - total)
                return ds_refuse(err, DS_ERR_ARG, "mixture", NAN, (double)w->n,
                                 "mixture: the species' counts add up to more than n = %zu", w->n);
            total += m->kinds[k].count;
        }
        if (total != w->n)
            return ds_refuse(err, DS_ERR_ARG, "mixture", (double)total, (double)w->n,
                             "mixture: the species' counts add up to %zu, not n = %zu", total,
                             w->n);
    }
    double lo = INFINITY, hi = 0.0, covered = 0.0;
    for (size_t i = 0; i < w->n; ++i) {
        const double r = ds_mixture_radius(m, i);
        const double given = m->kinds ? 0.0 : m->masses ? m->masses[i] : 1.0;
        if (!(r > 0.0) || !isfinite(r)) {
            ds_error_index(err, i);
            return ds_refuse(err, DS_ERR_ARG, "mixture", r, 0.0,
                             "mixture: disk %zu's radius %g is not a number > 0", i, r);
        }
        if (!(ds_mixture_mass(m, reference, i) > 0.0) ||
            !isfinite(ds_mixture_mass(m, reference, i)) || !(given >= 0.0) || !isfinite(given)) {
            ds_error_index(err, i);
            return ds_refuse(err, DS_ERR_ARG, "mixture", ds_mixture_mass(m, reference, i), 0.0,
                             "mixture: disk %zu's mass is not a finite number > 0", i);
        }
        lo = fmin(lo, r);
        hi = fmax(hi, r);
        covered += ds_covered_by(1.0, r);
    }
    if (m->kinds)
        for (size_t k = 0; k < m->species; ++k)
            if (!(m->kinds[k].mass >= 0.0) || !isfinite(m->kinds[k].mass))
                return ds_refuse(err, DS_ERR_ARG, "mixture", m->kinds[k].mass, 0.0,
                                 "mixture: species %zu's mass %g is not a finite number >= 0 (0 "
                                 "for the rule)",
                                 k, m->kinds[k].mass);
    const ds_status named = ds_kinds_check(m, err);
    if (named != DS_OK)
        return named;
    w->radius_min = lo;
    w->radius_max = hi;
    w->covered = covered;
    return DS_OK;
}

/* Oler's inequality (1961; Folkman and Graham 1969 for any convex set):
 * points at mutual distance >= 1 inside a convex polygon of area A and
 * perimeter P number at most (2/sqrt 3) A + P/2 + 1. With walls, disk
 * centres are 2R apart inside the rectangle of sides box - 2R and
 * box_y - 2R, so in units of 2R that rectangle has sides s, t and at most
 * (2/sqrt 3) s t + s + t + 1 disks fit. The bound is exact for one disk
 * and tends to the hexagonal packing, area fraction pi / (2 sqrt 3) =
 * 0.907, for many. A periodic box has no edge: the hexagonal packing
 * density bounds it, (2/sqrt 3) box box_y / (2R)^2 disks; a channel's two
 * walls add s, a row's worth along them. */
static int disks_cannot_fit(const ds_world *w)
{
    const int px = ds_box_periodic(&w->box, 0), py = ds_box_periodic(&w->box, 1);
    const double d = 2.0 * w->radius;
    const double s = px ? w->box.side[0] / d : (w->box.side[0] - d) / d;
    const double t = py ? w->box.side[1] / d : (w->box.side[1] - d) / d;
    const double edges = px && py ? 0.0 : !px && !py ? s + t + 1.0 : px ? s : t;
    const double most = 1.1547005383792515 * s * t + edges;
    return (double)w->n > most * (1.0 + 1e-12); /* slack: never refuse a fit to rounding */
}

/* A length of the box: 0 asks for the default, anything else is in
 * (0, 1e9], which keeps every coordinate far below 2^53 so that frames
 * print exactly. */
static ds_status check_length(ds_error *err, const char *field, double given, double most)
{
    if (given == 0.0 || (given > 0.0 && given <= most))
        return DS_OK;
    return ds_refuse(err, DS_ERR_ARG, field, given, given > 0.0 ? most : 0.0,
                     "%s = %g must be > 0 and <= %g (0 means the default)", field, given, most);
}

static ds_status check_numbers(const ds_params *p, ds_error *err)
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

/* A choice that is none of its enumeration's values. */
static ds_status check_choice(ds_error *err, const char *field, int value, int count,
                              const char *type)
{
    if (value >= 0 && value < count)
        return DS_OK;
    return ds_refuse(err, DS_ERR_ARG, field, (double)value, (double)count, "%s = %d is not a %s",
                     field, value, type);
}

static ds_status check_kinds(const ds_params *p, ds_error *err)
{
    ds_status st =
        check_choice(err, "integrator", (int)p->integrator, DS_INTEGRATOR_COUNT, "ds_integrator");
    if (st == DS_OK)
        st = check_choice(err, "boundary", (int)p->boundary, DS_BOUNDARY_COUNT, "ds_boundary");
    if (st == DS_OK)
        st = check_choice(err, "placement", (int)p->placement, DS_PLACEMENT_COUNT, "ds_placement");
    if (st == DS_OK)
        st = check_choice(err, "broadphase", (int)p->broadphase, DS_BROADPHASE_COUNT,
                          "ds_broadphase");
    if (st != DS_OK)
        return st;
    const ds_integrator_ops *ops = ds_integrator_ops_of(p->integrator);
    if (p->broadphase != DS_BROADPHASE_AUTO && !ops->fits(p->broadphase)) {
        char fit[96] = "";
        for (int bp = 0; bp < DS_BROADPHASE_COUNT; ++bp)
            if (bp != DS_BROADPHASE_AUTO && ops->fits((ds_broadphase)bp))
                snprintf(fit + strlen(fit), sizeof fit - strlen(fit), "%s, ",
                         ds_broadphase_name((ds_broadphase)bp));
        return ds_refuse(err, DS_ERR_ARG, "broadphase", (double)p->broadphase, NAN,
                         "broadphase = %s does not serve the %s integrator, which takes %sor auto",
                         ds_broadphase_name(p->broadphase), ops->name, fit);
    }
    return DS_OK;
}

/* A disk fits between the walls; in a periodic box two disks in contact
 * must be so through one image only (boundary.h), so each side is more
 * than two diameters. */
static ds_status check_size(const ds_world *w, int mixture, double min_room, ds_error *err)
{
    if (w->n < 1)
        return ds_refuse(err, DS_ERR_ARG, "n", 0.0, 1.0, "n = 0: there must be at least one disk");
    const ds_box *b = &w->box;
    const int periodic = ds_box_periodic(b, 0) && ds_box_periodic(b, 1);
    const int walls = !ds_box_periodic(b, 0) && !ds_box_periodic(b, 1);
    double most = INFINITY, band = INFINITY;
    for (int a = 0; a < 2; ++a) {
        most = fmin(most, (ds_box_periodic(b, a) ? 0.25 : 0.5) * b->side[a]);
        if (!ds_box_periodic(b, a))
            band = fmin(band, b->side[a]);
    }
    if (!(w->radius > 0.0) || !isfinite(w->radius))
        return ds_refuse(err, DS_ERR_ARG, "radius", w->radius, 0.0,
                         "radius = %g must be a number > 0", w->radius);
    /* A mixture is held to this by its largest disk. */
    const char *field = mixture ? "mixture" : "radius";
    const char *what = mixture ? "mixture: its largest radius," : "radius =";
    const char *sep = mixture ? "," : "";
    const double r = w->radius_max;
    if (!(r < most))
        return ds_refuse(err, DS_ERR_ARG, field, r, most,
                         periodic ? "%s %g%s is too large for a periodic box of %g x %g: it "
                                    "must be below a quarter of each side (%g)"
                         : walls  ? "%s %g%s does not fit a box of %g x %g: it must be below "
                                    "half of its shorter side (%g)"
                                  : "%s %g%s does not fit a channel of %g x %g: it must be "
                                    "below a quarter of its periodic side and half of its "
                                    "walled one (%g)",
                         what, r, sep, b->side[0], b->side[1], most);
    /* The band a centre moves in between walls, for an integrator that
     * needs room: a disk in a band a rounding error wider than itself
     * would turn at the walls a rounding error apart. */
    const double side = band;
    band -= 2.0 * r;
    if (!periodic && min_room > 0.0 && !(band >= 2.0 * r * min_room))
        return ds_refuse(err, DS_ERR_ARG, field, r, side / (2.0 * (1.0 + min_room)),
                         "%s %.17g%s leaves its centre a band of %g between the walls: the %s "
                         "integrator needs %g of a diameter at least (%g)",
                         what, r, sep, band, ds_integrator_ops_of(w->integrator)->name, min_room,
                         2.0 * r * min_room);
    /* Ids are 32-bit; beyond that no machine this runs on has the memory. */
    const size_t most_n = (SIZE_MAX - 64) / (DS_DISKS_BYTES_PER_DISK + DS_DISKS_MIXTURE_BYTES +
                                             DS_DISKS_IMAGE_BYTES + DS_PLACEMENT_BYTES_PER_DISK);
    if (w->n >= UINT32_MAX || w->n > most_n)
        return ds_refuse(err, DS_ERR_NOMEM, "n", (double)w->n,
                         fmin((double)UINT32_MAX - 1.0, (double)most_n),
                         "n = %zu disks cannot be held in memory", w->n);
    return DS_OK;
}

/* The packings refused before trying (see DS_MANY_DISKS in the header).
 * A mixture is held to them with its largest radius where a disk needs
 * room (a lattice's sites) and its smallest where every disk must keep
 * its distance (Oler's bound: centres 2 r_min apart at least). */
static ds_status check_packing(const ds_world *w, int mixture, double min_room, ds_error *err)
{
    const double fraction = w->covered / (w->box.side[0] * w->box.side[1]);
    const double site = w->radius_max; /* what a lattice's sites must hold */
    char disks[96];
    if (mixture)
        snprintf(disks, sizeof disks, "disks of radii %g to %g", w->radius_min, w->radius_max);
    else
        snprintf(disks, sizeof disks, "disks of radius %g", w->radius);
    if (w->placement == DS_PLACEMENT_LATTICE) {
        if (!ds_lattice_fits(w->n, site, &w->box))
            return ds_refuse(err, DS_ERR_PLACEMENT, "n", (double)w->n, NAN,
                             "n = %zu %s cover %.3f of the box; no triangular lattice of them "
                             "fits without overlap (close packing is 0.9069%s)",
                             w->n, disks, fraction, mixture ? " for the largest" : "");
        const double closest = ds_lattice_closest(w->n, site, &w->box);
        if (min_room > 0.0 && !(closest >= 2.0 * site * (1.0 + min_room)))
            return ds_refuse(err, DS_ERR_PLACEMENT, "n", (double)w->n, NAN,
                             "n = %zu %s cover %.7f of the box: their lattice is at close "
                             "packing, its neighbours %.3g of a diameter apart beyond contact; "
                             "the %s integrator needs %g at least (a slightly larger box or "
                             "smaller disks)",
                             w->n, disks, fraction, closest / (2.0 * site) - 1.0,
                             ds_integrator_ops_of(w->integrator)->name, min_room);
        return DS_OK;
    }
    ds_world smallest = *w;
    smallest.radius = w->radius_min;
    if (disks_cannot_fit(&smallest) || fraction > 1.0)
        return ds_refuse(err, DS_ERR_PLACEMENT, "n", (double)w->n, NAN,
                         "n = %zu %s cannot fit in the box without overlap", w->n, disks);
    if (w->n > DS_MANY_DISKS && fraction > DS_MAX_AREA_FRACTION)
        return ds_refuse(err, DS_ERR_PLACEMENT, "n", (double)w->n, NAN,
                         "n = %zu %s cover %.3f of the box; random placement of more than %d "
                         "disks cannot exceed %.2f",
                         w->n, disks, fraction, DS_MANY_DISKS, DS_MAX_AREA_FRACTION);
    return DS_OK;
}

/* ds_params_check's checks; on DS_OK, *world is the request's world
 * (the mixture's radii in it), broad phase as given. */
static ds_status check_request(const ds_params *p, const ds_mixture *mixture, unsigned *warnings,
                               ds_error *err, ds_world *world)
{
    if (warnings)
        *warnings = 0;
    ds_error_clear(err);
    if (!p)
        return ds_refuse(err, DS_ERR_ARG, "", NAN, NAN, "no parameters (NULL)");
    ds_status st = check_numbers(p, err);
    if (st == DS_OK)
        st = check_kinds(p, err);
    ds_world w = ds_world_of(p);
    if (st == DS_OK && !(w.radius > 0.0 && isfinite(w.radius)))
        st = ds_refuse(err, DS_ERR_ARG, "radius", w.radius, 0.0, "radius = %g must be a number > 0",
                       w.radius);
    if (st == DS_OK && w.n < 1)
        st = ds_refuse(err, DS_ERR_ARG, "n", 0.0, 1.0, "n = 0: there must be at least one disk");
    if (st == DS_OK && mixture)
        st = check_mixture(mixture, w.radius, &w, err);
    const double min_room = st == DS_OK ? ds_integrator_ops_of(w.integrator)->min_room : 0.0;
    if (st == DS_OK)
        st = check_size(&w, mixture != NULL, min_room, err);
    if (st == DS_OK)
        st = ds_integrator_ops_of(w.integrator)->check(&w, warnings, err);
    if (st == DS_OK)
        st = check_packing(&w, mixture != NULL, min_room, err);
    if (st != DS_OK && warnings)
        *warnings = 0;
    if (st != DS_OK && err)
        err->warning[0] = '\0';
    if (world)
        *world = w;
    return ds_error_done(err, st);
}

ds_status ds_params_check(const ds_params *params, const ds_mixture *mixture, unsigned *warnings,
                          ds_error *err)
{
    return check_request(params, mixture, warnings, err, NULL);
}

ds_status ds_world_of_request(const ds_params *params, const ds_mixture *mixture, ds_world *world,
                              ds_error *err)
{
    return check_request(params, mixture, NULL, err, world);
}

ds_status ds_params_memory(const ds_params *params, const ds_mixture *mixture, size_t *bytes,
                           ds_error *err)
{
    ds_world w;
    ds_status st = check_request(params, mixture, NULL, err, &w);
    if (st == DS_ERR_PLACEMENT)
        st = ds_error_done(err, DS_OK); /* memory is still a meaningful answer */
    if (st == DS_OK && !bytes)
        st = ds_refuse(err, DS_ERR_ARG, "bytes", NAN, NAN, "bytes: NULL");
    if (st != DS_OK)
        return st;
    const ds_integrator_ops *ops = ds_integrator_ops_of(w.integrator);
    if (w.broadphase == DS_BROADPHASE_AUTO)
        w.broadphase = ops->choose(&w);
    const size_t per_disk = DS_DISKS_BYTES_PER_DISK + DS_PLACEMENT_BYTES_PER_DISK +
                            (mixture ? DS_DISKS_MIXTURE_BYTES : 0) +
                            (ds_box_any_periodic(&w.box) ? DS_DISKS_IMAGE_BYTES : 0);
    *bytes = (w.n + 1) * per_disk + ops->bytes(&w);
    return DS_OK;
}
