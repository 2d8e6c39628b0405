/* SPDX-License-Identifier: MIT */
/* Growth: the Lubachevsky-Stillinger compression (Lubachevsky and
 * Stillinger 1990, J. Stat. Phys. 60, 561), as a protocol. The
 * integrator owns the dynamics of growing radii (every radius grows in
 * proportion to itself, a collision reflects in the frame of the receding
 * surfaces: the event-driven integrator's event/growing.c); this file owns
 * the control:
 *
 * - a collision in the receding frame adds energy, taken out by scaling
 *   every velocity back to the kinetic energy growth started with at the
 *   end of each window of 2 n collisions (once a frame is not enough: near
 *   jamming a cluster's collisions heat it a thousandfold within a frame,
 *   and the collision rate with it);
 * - the reduced pressure Z is watched over those windows, and growth
 *   slows past Z = 10^4 and stops past until_z;
 * - growth stops when the area fraction reaches until_eta, at the exact
 *   time, found in advance from the law of the radii;
 * - the cells must hold the next step's contacts: at each step's end the
 *   integrator is asked for room, and builds its state again with wider
 *   cells when there is none; without memory for that, growth stops. */
#include <math.h>
#include <stdlib.h>

#include "protocols/protocols.h"

#define GROWTH_SLOWS_AT_Z 10000.0

typedef struct growth {
    double asked;     /* the speed asked for, relative to the radii at the ask */
    double stop_time; /* integrator time the area fraction reaches until_eta */
    double until_eta; /* the target area fraction, or 0 */
    double until_z;   /* growth stops once Z passes this */
    /* The kinetic energy as growth's collisions add to it, the centre of
     * mass's share, and the energy growth started with. */
    double kinetic, momentum_energy, kinetic_target;
    uint64_t window; /* collisions in the window */
    double window_start, window_virial;
    int growing;   /* the radii grow */
    int stopped;   /* why it stopped: 0 still growing or never, 1 eta, 2 Z */
    double last_z; /* Z of the last window watched, 0 before the first */
} growth;

static void set_clock(ds_sim *sim, const growth *g)
{
    ds_protocol_clock *c = ds_protocols_clock(sim, DS_PROTOCOL_GROWTH);
    c->next = g->growing ? g->stop_time : INFINITY;
    c->asap = g->growing && g->window >= 2 * sim->world.n;
    c->watching = c->stepping = g->growing;
}

/* The target's time from the law of now, the area fraction growing as
 * the square of the radii: a restart never moves it. */
static void find_stop_time(const ds_sim *sim, growth *g)
{
    ds_growth_law law;
    sim->integrator->growth_law(sim, &law);
    if (law.rate > 0.0 && g->until_eta > 0.0)
        g->stop_time = law.from + (sqrt(g->until_eta / law.eta) - 1.0) / law.rate;
}

static void measure(const ds_sim *sim, growth *g)
{
    ds_kinetic k;
    sim->integrator->kinetic(sim, &k);
    g->kinetic = k.k;
    g->momentum_energy = (k.px * k.px + k.py * k.py) / (2.0 * k.mass);
}

/* The heat growth added, out at t, and the radii from t on at speed:
 * every velocity scaled at once back to the kinetic energy growth started
 * with (which keeps a zero momentum zero). */
static void heat_out(ds_sim *sim, growth *g, double t, double speed)
{
    const double factor = g->kinetic > 0.0 ? sqrt(g->kinetic_target / g->kinetic) : 1.0;
    (void)sim->integrator->grow(sim, t, factor, speed, 0);
    g->kinetic *= factor * factor;
    g->momentum_energy *= factor * factor;
}

/* Z over the window that ends at t: 1 + the window's virial over 2 t N kT,
 * N kT = N K_int / (N - 1) (a periodic box conserves the momentum, so the
 * centre of mass's energy is not the temperature's). */
static double window_z(const ds_sim *sim, const growth *g, double t)
{
    const double n = (double)sim->world.n;
    const double nkt = n * (g->kinetic - g->momentum_energy) / (n > 1.0 ? n - 1.0 : 1.0);
    const double span = t - g->window_start;
    return span > 0.0 && nkt > 0.0
               ? 1.0 + (sim->tally.virial - g->window_virial) / (2.0 * span * nkt)
               : 1.0;
}

/* A new window from t, its energy measured. */
static void open_window(const ds_sim *sim, growth *g, double t)
{
    g->window = 0;
    g->window_start = t;
    g->window_virial = sim->tally.virial;
}

static void fire(ds_sim *sim, void *self, double t, double end)
{
    growth *g = self;
    /* The target area fraction, at its own time, whether an event comes
     * before it in this step or not: the step that holds it (its end
     * included) ends with the radii of the target. */
    if (g->stop_time <= t && g->stop_time <= end) {
        g->stopped = 1;
        g->growing = 0;
        heat_out(sim, g, g->stop_time, 0.0);
        set_clock(sim, g);
        return;
    }
    /* Z is watched before events, not at a step's end. */
    if (!(t < end && g->window >= 2 * sim->world.n))
        return;
    const double z = window_z(sim, g, t);
    g->last_z = z;
    const int jammed = z >= g->until_z;
    g->stopped = jammed ? 2 : 0;
    g->growing = !jammed;
    /* Slower as the pressure rises, rate ~ 1 / Z past Z = 10^4: a
     * compression at a fixed rate outruns the disks' rearranging near
     * jamming, and the pressure it measures is its own push, not the
     * packing's (at a fixed rate 0.01, Z passed 10^6 with most gaps
     * between neighbours near 1e-4 of a diameter, a packing at Z ~ 10^4).
     * Slowing past 10^4 leaves the contacts 1e-6 to 1e-4 apart at Z =
     * 10^6, 4.00 per disk with the rattlers out, in 108 s at 1024 disks
     * from 0.476 at rate 0.01 (docs/physics.md). Donev, Torquato and
     * Stillinger 2005 slow down likewise. */
    const double rate = z > GROWTH_SLOWS_AT_Z ? g->asked * GROWTH_SLOWS_AT_Z / z : g->asked;
    heat_out(sim, g, t, jammed ? 0.0 : rate);
    open_window(sim, g, t);
    if (!jammed)
        find_stop_time(sim, g);
    set_clock(sim, g);
}

static void collided(ds_sim *sim, void *self, const ds_collision *c)
{
    growth *g = self;
    g->kinetic += c->energy;
    ++g->window;
    set_clock(sim, g);
}

/* The cells must hold every contact of the next step; when the
 * integrator builds its state again for that, the growth goes on in it
 * with a new window. Without memory for it the state stays as it was and
 * the growth stops now, its heat out, since its cells cannot hold the
 * next step's contacts: DS_ERR_NOMEM. */
static ds_status step_end(ds_sim *sim, void *self)
{
    growth *g = self;
    if (!g->growing)
        return DS_OK;
    int rebuilt = 0;
    const double now = sim->integrator->now(sim);
    const ds_status st = sim->integrator->widen(sim, now + sim->world.dt, &rebuilt);
    if (st != DS_OK) {
        heat_out(sim, g, now, 0.0);
        g->growing = 0;
        g->stopped = 0;
        set_clock(sim, g);
        return st;
    }
    if (rebuilt) {
        const double start = sim->integrator->now(sim); /* the new state's origin */
        g->stopped = 0;
        g->last_z = 0.0;
        measure(sim, g);
        open_window(sim, g, start);
        g->stop_time = INFINITY;
        find_stop_time(sim, g);
        set_clock(sim, g);
    }
    return DS_OK;
}

static void rebased(void *self, double by)
{
    growth *g = self;
    g->stop_time -= by;
    g->window_start -= by;
}

/* A new state (every disk set) forgets the growth; one disk set, the
 * radii of now are where the growth goes on from. */
static void disks_set(ds_sim *sim, void *self, int all)
{
    growth *g = self;
    if (all) {
        g->growing = 0;
        g->stopped = 0;
        g->last_z = 0.0;
    } else if (g->growing) {
        find_stop_time(sim, g);
    }
    set_clock(sim, g);
}

static void scaled(ds_sim *sim, void *self, double factor)
{
    growth *g = self;
    g->kinetic *= factor * factor;
    g->kinetic_target *= factor * factor;
    g->momentum_energy *= factor * factor;
    if (g->growing)
        find_stop_time(sim, g);
    set_clock(sim, g);
}

static void save(const ds_sim *sim, const void *self, ds_state_writer *w)
{
    (void)sim;
    const growth *g = self;
    ds_put_f64(w, g->asked);
    ds_put_f64(w, g->stop_time);
    ds_put_f64(w, g->until_eta);
    ds_put_f64(w, g->until_z);
    ds_put_f64(w, g->kinetic);
    ds_put_f64(w, g->kinetic_target);
    ds_put_f64(w, g->momentum_energy);
    ds_put_u64(w, g->window);
    ds_put_f64(w, g->window_start);
    ds_put_f64(w, g->window_virial);
    ds_put_u32(w, (uint32_t)g->stopped | (uint32_t)g->growing << 2);
    ds_put_f64(w, g->last_z);
}

/* What a growth's numbers must be for the run to go on (the checksum
 * catches the rest): numbers, targets in range, a clock not behind. */
static ds_status check(const ds_growth_record *r, ds_error *err)
{
    if (!(r->asked >= 0.0 && isfinite(r->asked)) || isnan(r->stop_time) ||
        !(r->until_eta >= 0.0 && r->until_eta < 1.0) ||
        !(r->until_z > 1.0 && r->until_z <= 1e9) || !isfinite(r->kinetic) ||
        !isfinite(r->kinetic_target) || !isfinite(r->momentum_energy) ||
        !isfinite(r->window_start) || !isfinite(r->window_virial) || !isfinite(r->last_z) ||
        r->stopped < 0 || r->stopped > 2)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its growth's numbers are not a growth's");
    return DS_OK;
}

static ds_status adopt(growth *g, const ds_growth_record *r, ds_error *err)
{
    const ds_status st = check(r, err);
    if (st != DS_OK)
        return st;
    g->asked = r->asked;
    g->stop_time = r->stop_time;
    g->until_eta = r->until_eta;
    g->until_z = r->until_z;
    g->kinetic = r->kinetic;
    g->kinetic_target = r->kinetic_target;
    g->momentum_energy = r->momentum_energy;
    g->window = r->window;
    g->window_start = r->window_start;
    g->window_virial = r->window_virial;
    g->stopped = r->stopped;
    g->growing = r->growing;
    g->last_z = r->last_z;
    return DS_OK;
}

static ds_status load(ds_sim *sim, void **self, ds_reader *r, ds_error *err)
{
    (void)sim;
    ds_growth_record rec;
    rec.asked = ds_get_f64(r);
    rec.stop_time = ds_get_f64(r);
    rec.until_eta = ds_get_f64(r);
    rec.until_z = ds_get_f64(r);
    rec.kinetic = ds_get_f64(r);
    rec.kinetic_target = ds_get_f64(r);
    rec.momentum_energy = ds_get_f64(r);
    rec.window = ds_get_u64(r);
    rec.window_start = ds_get_f64(r);
    rec.window_virial = ds_get_f64(r);
    const uint32_t flags = ds_get_u32(r);
    rec.last_z = ds_get_f64(r);
    rec.stopped = (int)(flags & 3u);
    rec.growing = (int)(flags >> 2 & 1u);
    if (r->failed || flags > 7u)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the growth's part is not one");
    growth *g = calloc(1, sizeof *g);
    if (!g)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the growth");
    *self = g;
    return adopt(g, &rec, err);
}

static void destroy(void *self) { free(self); }

const ds_protocol_ops ds_growth_ops = {
    .name = "growth",
    .kind = DS_PROTOCOL_GROWTH,
    .fire = fire,
    .collided = collided,
    .step_end = step_end,
    .rebased = rebased,
    .rebuilt = NULL,
    .disks_set = disks_set,
    .scaled = scaled,
    .save = save,
    .load = load,
    .destroy = destroy,
};

ds_status ds_growth_adopt(ds_sim *sim, const ds_growth_record *r)
{
    growth *g = calloc(1, sizeof *g);
    if (!g)
        return DS_ERR_NOMEM;
    if (adopt(g, r, NULL) != DS_OK) {
        free(g);
        return DS_ERR_FORMAT;
    }
    ds_protocols_install(sim, &ds_growth_ops, g);
    set_clock(sim, g);
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}

ds_status ds_growth_start(ds_sim *sim, double rate, double until_eta, double until_z)
{
    const ds_integrator_ops *in = sim->integrator;
    if (!in->grow || sim->world.boundary != DS_BOUNDARY_PERIODIC)
        return DS_ERR_ARG;
    growth *g = ds_protocols_get(sim, DS_PROTOCOL_GROWTH);
    const double now = in->now(sim);
    if (rate == 0.0) { /* stop */
        if (g && g->growing) {
            (void)in->grow(sim, now, 1.0, 0.0, 0);
            g->growing = 0;
            set_clock(sim, g);
            ds_protocols_refresh(&sim->protocols);
        }
        return DS_OK;
    }
    /* The memory first, so that without it nothing has changed. */
    growth *fresh = g ? NULL : calloc(1, sizeof *fresh);
    if (!g && !fresh)
        return DS_ERR_NOMEM;
    if (in->grow(sim, now, 1.0, rate, 1) != DS_OK) {
        free(fresh);
        return DS_ERR_NOMEM;
    }
    if (fresh) {
        ds_protocols_install(sim, &ds_growth_ops, fresh);
        g = fresh;
    }
    g->asked = rate;
    g->stop_time = INFINITY;
    g->until_eta = until_eta;
    g->until_z = until_z;
    g->stopped = 0;
    g->last_z = 0.0;
    g->growing = 1;
    measure(sim, g);
    g->kinetic_target = g->kinetic;
    open_window(sim, g, now);
    find_stop_time(sim, g);
    set_clock(sim, g);
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}

int ds_growth_state_get(const ds_sim *sim, double *z)
{
    const growth *g = ds_protocols_get(sim, DS_PROTOCOL_GROWTH);
    *z = g ? g->last_z : 0.0;
    if (!g)
        return DS_GROWTH_NONE;
    return g->growing        ? DS_GROWTH_GROWING
           : g->stopped == 1 ? DS_GROWTH_REACHED_ETA
           : g->stopped == 2 ? DS_GROWTH_JAMMED
                             : DS_GROWTH_NONE;
}
