/* SPDX-License-Identifier: MIT */
/* Thermostats: a heat bath at temperature kT, as a protocol.
 *
 * - Andersen's (1980, J. Chem. Phys. 72, 2384): each disk collides with
 *   the bath at the times of a Poisson process of rate nu, and comes out
 *   with a velocity drawn afresh from Maxwell-Boltzmann at kT with its
 *   own mass, each component normal with variance kT / m. The redraws of
 *   all n disks are one Poisson process of rate n nu, each on a disk
 *   chosen uniformly: the protocol keeps the next one's time as its
 *   clock, and the integrator sets the velocity there (set_velocity). The
 *   event-driven integrator's redraws are events at their exact times;
 *   the time step's are applied at the end of the step they fall in, which
 *   is exact for it as well: a step sees a velocity only at its
 *   boundaries, so a disk redrawn once or more in a step comes out of it
 *   with one fresh draw, with probability 1 - exp(-nu dt), the law of a
 *   redraw at each step's end with that probability. Hard disks have no
 *   potential energy, so the canonical ensemble is Maxwell's velocities
 *   times the uniform measure on configurations without overlap, which
 *   both the flights and the redraws keep: the sampling is exactly
 *   canonical. The momentum is no longer conserved, so in any box every
 *   one of the 2 n velocity components is the bath's: the kinetic energy
 *   is Gamma(n, kT) distributed (mean n kT, variance n kT^2).
 * - isokinetic: at the end of every step every velocity is scaled so that
 *   the kinetic temperature (core.h, ds_kinetic_temperature: the kinetic
 *   energy less the conserved momentum's, over the degrees of freedom
 *   left) is kT; for a driven system, whose driving heats it. Elastic
 *   collisions keep the energy to rounding, so a run that nothing heats is
 *   scaled once, and then only when rounding has moved it by 1e-12.
 *
 * The redraws use a stream of the simulation's seed, kept here and
 * carried by checkpoints, so a run is the same to the bit however it is
 * cut into calls and checkpoints. */
#include <math.h>
#include <stdlib.h>

#include "protocols/protocols.h"

/* The stream's own seed: the simulation's, mixed with "thermost" (the
 * generator spreads nearby seeds over its state). */
#define STREAM 0x746865726d6f7374ull
/* A rescaling is due when the kinetic temperature is this far from kT
 * (relative): what rounding alone cannot do in a long run. */
#define ISOKINETIC_SLACK 1e-12

typedef struct thermostat {
    ds_thermostat kind;
    double kt;   /* the bath's temperature */
    double rate; /* Andersen: collisions with the bath per disk per unit time */
    ds_rng rng;
} thermostat;

static ds_protocol_clock *clock_of(ds_sim *sim)
{
    return ds_protocols_clock(sim, DS_PROTOCOL_THERMOSTAT);
}

/* An exponential variable of mean 1 (u < 1: finite). */
static double exponential(ds_rng *rng) { return -log1p(-ds_rng_uniform(rng, 0.0, 1.0)); }

/* The time of the next redraw after t: the n disks' process, rate n nu. */
static double next_redraw(const ds_sim *sim, thermostat *h, double t)
{
    return t + exponential(&h->rng) / (h->rate * (double)sim->world.n);
}

static void set_clock(ds_sim *sim, thermostat *h, double now)
{
    ds_protocol_clock *c = clock_of(sim);
    c->asap = c->watching = 0;
    c->stepping = h->kind == DS_THERMOSTAT_ISOKINETIC;
    c->next = h->kind == DS_THERMOSTAT_ANDERSEN ? next_redraw(sim, h, now) : INFINITY;
}

/* A velocity from Maxwell-Boltzmann with each component's standard
 * deviation s = sqrt(kT / m): Box and Muller's two normal variables from
 * two uniform ones, a radius sqrt(-2 ln(1 - u)) (at most 8.58, u being
 * at most 1 - 2^-53) and an angle. */
static void maxwell(ds_rng *rng, double s, double *vx, double *vy)
{
    const double u = ds_rng_uniform(rng, 0.0, 1.0), angle = ds_rng_uniform(rng, 0.0, DS_TWO_PI);
    const double r = s * sqrt(-2.0 * log1p(-u));
    *vx = r * cos(angle);
    *vy = r * sin(angle);
}

/* Andersen's redraw at its time, before the event at t of the step that
 * ends at end; one per call, since the disk redrawn may now collide
 * before the next redraw (the run loop asks again). */
static void fire(ds_sim *sim, void *self, double t, double end)
{
    thermostat *h = self;
    ds_protocol_clock *c = clock_of(sim);
    const double at = c->next;
    if (!(at <= t && at <= end))
        return;
    const size_t n = sim->world.n;
    /* A slot chosen uniformly; u n rounds up to n only for n near 2^53. */
    size_t k = (size_t)(ds_rng_uniform(&h->rng, 0.0, 1.0) * (double)n);
    k = k < n ? k : n - 1;
    const double m = sim->disks.m ? sim->disks.m[k] : 1.0;
    double vx, vy;
    maxwell(&h->rng, sqrt(h->kt / m), &vx, &vy);
    sim->integrator->set_velocity(sim, k, at, vx, vy);
    c->next = next_redraw(sim, h, at);
}

static ds_status step_end(ds_sim *sim, void *self)
{
    thermostat *h = self;
    ds_kinetic k;
    sim->integrator->kinetic(sim, &k);
    const double t = ds_kinetic_temperature(&sim->world.box, sim->world.n, &k);
    /* Disks at rest (or moving as one) have no temperature to scale. */
    if (t > 0.0 && fabs(t - h->kt) > ISOKINETIC_SLACK * h->kt)
        (void)sim->integrator->scale_velocities(sim, sqrt(h->kt / t));
    return DS_OK;
}

/* Every disk set anew: the state's clock starts again at the present, and
 * the next redraw (the process has no memory) is drawn from there. */
static void disks_set(ds_sim *sim, void *self, int all)
{
    thermostat *h = self;
    if (all && h->kind == DS_THERMOSTAT_ANDERSEN)
        clock_of(sim)->next = next_redraw(sim, h, sim->integrator->now(sim));
}

static double temperature(const void *self) { return ((const thermostat *)self)->kt; }

static void save(const ds_sim *sim, const void *self, ds_state_writer *w)
{
    (void)sim;
    const thermostat *h = self;
    ds_put_u32(w, (uint32_t)h->kind);
    ds_put_f64(w, h->kt);
    ds_put_f64(w, h->rate);
    ds_put_u64(w, h->rng.state);
}

/* What a thermostat's numbers must be for the run to go on: a kind, a
 * temperature, Andersen's rate (the isokinetic has none), a generator's
 * state (never 0). */
static ds_status load(ds_sim *sim, void **self, ds_reader *r, ds_error *err)
{
    (void)sim;
    const uint32_t kind = ds_get_u32(r);
    const double kt = ds_get_f64(r), rate = ds_get_f64(r);
    const uint64_t state = ds_get_u64(r);
    const int andersen = kind == DS_THERMOSTAT_ANDERSEN;
    if (r->failed || !(andersen || kind == DS_THERMOSTAT_ISOKINETIC) ||
        !(kt > 0.0 && isfinite(kt)) || !(andersen ? rate > 0.0 && isfinite(rate) : rate == 0.0) ||
        state == 0)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its thermostat's part is not one");
    thermostat *h = calloc(1, sizeof *h);
    if (!h)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the thermostat");
    h->kind = (ds_thermostat)kind;
    h->kt = kt;
    h->rate = rate;
    h->rng.state = state;
    *self = h;
    return DS_OK;
}

static void destroy(void *self) { free(self); }

const ds_protocol_ops ds_thermostat_ops = {
    .name = "thermostat",
    .kind = DS_PROTOCOL_THERMOSTAT,
    .fire = fire,
    .step_end = step_end,
    .disks_set = disks_set,
    .save = save,
    .load = load,
    .destroy = destroy,
    .temperature = temperature,
};

ds_status ds_thermostat_start(ds_sim *sim, ds_thermostat kind, double kt, double rate)
{
    thermostat *h = ds_protocols_get(sim, DS_PROTOCOL_THERMOSTAT);
    if (!h) {
        if (!(h = calloc(1, sizeof *h)))
            return DS_ERR_NOMEM;
        ds_rng_seed(&h->rng, sim->world.seed ^ STREAM);
        ds_protocols_install(sim, &ds_thermostat_ops, h);
    }
    /* Set again, the stream goes on: a run is the same however often. */
    h->kind = kind;
    h->kt = kt;
    h->rate = kind == DS_THERMOSTAT_ANDERSEN ? rate : 0.0;
    set_clock(sim, h, sim->integrator->now(sim));
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}

ds_thermostat ds_thermostat_get(const ds_sim *sim, double *kt)
{
    const thermostat *h = ds_protocols_get(sim, DS_PROTOCOL_THERMOSTAT);
    *kt = h ? h->kt : 0.0;
    return h ? h->kind : DS_THERMOSTAT_NONE;
}
