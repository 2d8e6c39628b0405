/* SPDX-License-Identifier: MIT */
/* Driving: white-noise forcing, the random kicks that hold a granular gas
 * in a steady state (Williams and MacKintosh 1996, Phys. Rev. E 54, R9;
 * van Noije and Ernst 1998, Granular Matter 1, 57), as a protocol. Each
 * disk feels a random force whose velocity increments are independent,
 * Gaussian, of variance S dt per component over a time dt: the velocities
 * diffuse, and the energy goes in at m S per disk per unit time in two
 * dimensions (d m S / 2). A run takes them as kicks at the end of every
 * step, the noise integrated over the step (Euler-Maruyama): dt must be
 * short beside the mean free time for the kicks to be white noise, as it
 * must for a time step to resolve anything.
 *
 * The kicks' mass-weighted mean is taken out, so they keep the total
 * momentum (a periodic box's centre of mass would otherwise random-walk
 * and take the energy with it); that leaves S m_i (1 - m_i / M) per disk
 * per unit time, (N - 1) m S for N equal masses. The numbers come from
 * the simulation's seed, a stream of its own (the seed mixed with a
 * constant of the drive's, so it shares none with the placement's), in
 * generation order whatever order the integrator keeps the disks in; a
 * checkpoint carries the stream, so a loaded run draws what the saved one
 * would have. The integrator adds the kicks (its kick service), and the
 * energy they put in to the tally's books. */
#include <math.h>
#include <stdlib.h>

#include "protocols/protocols.h"

/* The drive's stream: the seed xor "drive-38" (ds_rng_seed mixes it). */
#define DRIVE_STREAM 0x64726976652d3338u

typedef struct drive {
    double strength; /* S: velocity variance per component per unit time */
    ds_rng rng;
    double *draw; /* 2 n normal numbers, by generation index */
    double *dv;   /* 2 n kicks, by slot */
} drive;

static void set_clock(ds_sim *sim, const drive *d)
{
    ds_protocol_clock *c = ds_protocols_clock(sim, DS_PROTOCOL_DRIVE);
    c->next = INFINITY;
    c->asap = c->watching = 0;
    c->stepping = d->strength > 0.0;
}

/* Two independent standard normal numbers (Box and Muller 1958): 1 - u
 * is in (0, 1], so the logarithm is finite. */
static void two_normals(ds_rng *rng, double *a, double *b)
{
    const double r = sqrt(-2.0 * log(1.0 - ds_rng_uniform(rng, 0.0, 1.0)));
    const double angle = DS_TWO_PI * ds_rng_uniform(rng, 0.0, 1.0);
    *a = r * cos(angle);
    *b = r * sin(angle);
}

/* The step's kicks: drawn by generation index, their mass-weighted mean
 * taken out, handed to the integrator by slot. */
static ds_status step_end(ds_sim *sim, void *self)
{
    drive *d = self;
    const ds_disks *disks = &sim->disks;
    const size_t n = disks->n;
    const double sigma = sqrt(d->strength * sim->world.dt);
    double mx = 0.0, my = 0.0, mass = 0.0;
    for (size_t i = 0; i < n; ++i) {
        two_normals(&d->rng, &d->draw[2 * i], &d->draw[2 * i + 1]);
        d->draw[2 * i] *= sigma;
        d->draw[2 * i + 1] *= sigma;
    }
    for (size_t k = 0; k < n; ++k) {
        const double m = disks->m ? disks->m[k] : 1.0;
        const uint32_t i = disks->id[k];
        mx += m * d->draw[2 * i];
        my += m * d->draw[2 * i + 1];
        mass += m;
    }
    mx /= mass;
    my /= mass;
    for (size_t k = 0; k < n; ++k) {
        const uint32_t i = disks->id[k];
        d->dv[2 * k] = d->draw[2 * i] - mx;
        d->dv[2 * k + 1] = d->draw[2 * i + 1] - my;
    }
    sim->integrator->kick(sim, d->dv);
    return DS_OK;
}

static void save(const ds_sim *sim, const void *self, ds_state_writer *w)
{
    (void)sim;
    const drive *d = self;
    ds_put_f64(w, d->strength);
    ds_put_u64(w, d->rng.state);
}

/* A drive for sim's disks, its buffers allocated; NULL without memory. */
static drive *make(const ds_sim *sim)
{
    const size_t n = sim->world.n ? sim->world.n : 1;
    drive *d = calloc(1, sizeof *d);
    if (!d)
        return NULL;
    d->draw = malloc(2 * n * sizeof *d->draw);
    d->dv = malloc(2 * n * sizeof *d->dv);
    if (!d->draw || !d->dv) {
        free(d->draw);
        free(d->dv);
        free(d);
        return NULL;
    }
    return d;
}

static void destroy(void *self)
{
    drive *d = self;
    if (!d)
        return;
    free(d->draw);
    free(d->dv);
    free(d);
}

static ds_status load(ds_sim *sim, void **self, ds_reader *r, ds_error *err)
{
    const double strength = ds_get_f64(r);
    const uint64_t state = ds_get_u64(r);
    /* xorshift's state is never 0; the strength is the setter's. */
    if (r->failed || !(strength >= 0.0 && strength <= DS_DRIVE_MAX) || state == 0)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its drive's part is not one");
    if (!sim->integrator->kick)
        return ds_state_refuse(err, DS_ERR_FORMAT, "a drive on an integrator that takes no kicks");
    drive *d = make(sim);
    if (!d)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the drive of %zu disks",
                               sim->world.n);
    d->strength = strength;
    d->rng.state = state;
    *self = d;
    return DS_OK;
}

const ds_protocol_ops ds_drive_ops = {
    .name = "drive",
    .kind = DS_PROTOCOL_DRIVE,
    .step_end = step_end,
    .save = save,
    .load = load,
    .destroy = destroy,
};

ds_status ds_drive_start(ds_sim *sim, double strength)
{
    drive *d = ds_protocols_get(sim, DS_PROTOCOL_DRIVE);
    if (!d) {
        if (strength == 0.0)
            return DS_OK;
        if (!(d = make(sim)))
            return DS_ERR_NOMEM;
        ds_rng_seed(&d->rng, sim->world.seed ^ (uint64_t)DRIVE_STREAM);
        ds_protocols_install(sim, &ds_drive_ops, d);
    }
    /* Set again, the stream goes on where it was. */
    d->strength = strength;
    set_clock(sim, d);
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}

double ds_drive_strength(const ds_sim *sim)
{
    const drive *d = ds_protocols_get(sim, DS_PROTOCOL_DRIVE);
    return d ? d->strength : 0.0;
}
