/* SPDX-License-Identifier: MIT */
/* Shear: Lees-Edwards boundaries (Lees and Edwards 1972, J. Phys. C 5,
 * 1921) as a protocol. A periodic box whose image above moves along x at
 * U = rate H relative to the box (the one below at -U) shears the disks
 * at the rate dv_x / dy = rate: the images stand offset U t along x
 * (core/box.h), a disk leaving through the top comes in at the bottom
 * as the image it was, U slower along x, and a pair across the top or
 * bottom meets as the images do. The integrator carries that out (its
 * table's shear service): its cell stencils reach across the top and
 * bottom to the columns the offset has moved to, which hold until the
 * offset passes the next cell edge. Those moments are this protocol's
 * clock: at each one the integrator moves its count by a cell and
 * predicts the two boundary rows again.
 *
 * The viscous heat the shear puts in is a thermostat's to take out (the
 * isokinetic one scales the peculiar velocities, about the profile U (y
 * / H - 1/2)); without one the sheared gas heats up, as it should. */
#include <math.h>
#include <stdlib.h>

#include "protocols/protocols.h"

typedef struct shear {
    double rate;  /* dv_x / dy, per unit time */
    double speed; /* the image above's speed along x: rate times the height */
} shear;

static ds_protocol_clock *clock_of(ds_sim *sim)
{
    return ds_protocols_clock(sim, DS_PROTOCOL_SHEAR);
}

/* The images pass a cell edge at the clock's time, before the event at t
 * of the step that ends at end: one edge per call (a fast shear's next
 * may come before that event too; the run loop asks again). */
static void fire(ds_sim *sim, void *self, double t, double end)
{
    const shear *s = self;
    ds_protocol_clock *c = clock_of(sim);
    const double at = c->next;
    if (!(at <= t && at <= end))
        return;
    c->next = sim->integrator->shear(sim, at, s->speed, s->speed > 0.0 ? 1 : -1);
}

/* A state built again (the same disks, its origin the present): the
 * images go on from where they stand. */
static void rebuilt(ds_sim *sim, void *self)
{
    const shear *s = self;
    clock_of(sim)->next = sim->integrator->shear(sim, sim->integrator->now(sim), s->speed, 0);
}

static void save(const ds_sim *sim, const void *self, ds_state_writer *w)
{
    (void)sim;
    const shear *s = self;
    ds_put_f64(w, s->rate);
    ds_put_f64(w, s->speed);
}

static ds_status load(ds_sim *sim, void **self, ds_reader *r, ds_error *err)
{
    const double rate = ds_get_f64(r), speed = ds_get_f64(r);
    /* The integrator's part, read before, holds the images' offset and
     * speed: the two must agree to the bit. */
    if (r->failed || !isfinite(rate) || speed != rate * sim->world.box.side[1] ||
        speed != sim->world.box.shift_speed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its shear's part is not one");
    if (!sim->integrator->shear)
        return ds_state_refuse(err, DS_ERR_FORMAT, "a shear on an integrator that cannot shear");
    shear *s = malloc(sizeof *s);
    if (!s)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the shear");
    s->rate = rate;
    s->speed = speed;
    *self = s;
    return DS_OK;
}

static void destroy(void *self) { free(self); }

const ds_protocol_ops ds_shear_ops = {
    .name = "shear",
    .kind = DS_PROTOCOL_SHEAR,
    .fire = fire,
    .rebuilt = rebuilt,
    .save = save,
    .load = load,
    .destroy = destroy,
};

ds_status ds_shear_start(ds_sim *sim, double rate)
{
    shear *s = ds_protocols_get(sim, DS_PROTOCOL_SHEAR);
    if (!s) {
        if (!(s = malloc(sizeof *s)))
            return DS_ERR_NOMEM;
        ds_protocols_install(sim, &ds_shear_ops, s);
    }
    s->rate = rate;
    s->speed = rate * sim->world.box.side[1];
    ds_protocol_clock *c = clock_of(sim);
    c->asap = c->watching = c->stepping = 0;
    c->next = sim->integrator->shear(sim, sim->integrator->now(sim), s->speed, 0);
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}

double ds_shear_rate(const ds_sim *sim)
{
    const shear *s = ds_protocols_get(sim, DS_PROTOCOL_SHEAR);
    return s ? s->rate : 0.0;
}
