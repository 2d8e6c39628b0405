/* SPDX-License-Identifier: MIT */
/* A simulation's whole state at once: checking a state to start from,
 * setting every disk (ds_set_all), and checkpoints (ds_save_state,
 * ds_load_state and their in-memory forms). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/boundary.h"
#include "core/overlap.h"
#include "protocols/protocols.h"
#include "sim/sim.h"

ds_status ds_check_disk(const ds_world *w, size_t i, double radius, double past, ds_disk d,
                        ds_state_error *err)
{
    if (!isfinite(d.x) || !isfinite(d.y) || !isfinite(d.vx) || !isfinite(d.vy))
        return ds_state_refuse(err, DS_ERR_ARG, "disk %zu has a value that is not a finite number",
                               i);
    if (fabs(d.vx) > DS_VELOCITY_MAX || fabs(d.vy) > DS_VELOCITY_MAX)
        return ds_state_refuse(err, DS_ERR_ARG,
                               "disk %zu moves at (%g, %g): a velocity component beyond 1e12", i,
                               d.vx, d.vy);
    /* With walls the centre stays R from each wall (past that by past); a
     * periodic box takes any point of [0, box) x [0, box_y), as its
     * frames show them. */
    if (w->boundary == DS_PERIODIC) {
        if (!(d.x >= 0.0 && d.x < w->box && d.y >= 0.0 && d.y < w->box_y))
            return ds_state_refuse(err, DS_ERR_ARG,
                                   "disk %zu at (%g, %g) is outside the periodic box [0, %g) x "
                                   "[0, %g)",
                                   i, d.x, d.y, w->box, w->box_y);
        return DS_OK;
    }
    const double lo = radius - past, hi_x = w->box - radius + past, hi_y = w->box_y - radius + past;
    if (!(d.x >= lo && d.x <= hi_x && d.y >= lo && d.y <= hi_y))
        return ds_state_refuse(err, DS_ERR_ARG,
                               "disk %zu at (%g, %g) is outside [%g, %g] x [%g, %g], where the "
                               "centre of a disk of radius %g stays between the walls",
                               i, d.x, d.y, lo, hi_x, lo, hi_y, radius);
    return DS_OK;
}

/* The first pair closer than contact allows, named; radii in generation
 * order (NULL: one radius). */
static ds_status check_overlaps(const ds_world *w, const ds_disk *disks, const double *radii,
                                ds_state_error *err)
{
    const size_t n = w->n;
    double *xy = malloc(2 * n * sizeof *xy);
    if (!xy)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to check %zu disks", n);
    for (size_t i = 0; i < n; ++i) {
        xy[i] = disks[i].x;
        xy[n + i] = disks[i].y;
    }
    size_t j = 0, k = 0;
    const ds_status st = ds_find_overlap(w, xy, xy + n, radii, &j, &k);
    free(xy);
    if (st == DS_ERR_NOMEM)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to check %zu disks", n);
    if (st != DS_OK) {
        double dx = disks[k].x - disks[j].x, dy = disks[k].y - disks[j].y;
        if (w->boundary == DS_PERIODIC) {
            dx = ds_nearest(dx, w->box);
            dy = ds_nearest(dy, w->box_y);
        }
        return ds_state_refuse(err, DS_ERR_OVERLAP,
                               "disks %zu and %zu overlap: their centres are %.17g apart, closer "
                               "than their radii's sum, %.17g",
                               j, k, sqrt(dx * dx + dy * dy),
                               radii ? radii[j] + radii[k] : 2.0 * w->radius);
    }
    return DS_OK;
}

ds_status ds_set_all(ds_sim *sim, const ds_disk *disks, ds_state_error *err)
{
    if (err)
        err->message[0] = '\0';
    if (!sim || !disks)
        return ds_state_refuse(err, DS_ERR_ARG, "no simulation or no disks (NULL)");
    const ds_world *w = &sim->world;
    double *radii = NULL;
    if (sim->disks.r) {
        if (!(radii = malloc(w->n * sizeof *radii)))
            return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to check %zu disks", w->n);
        ds_get_radii(sim, radii, NULL);
    }
    ds_status st = DS_OK;
    for (size_t i = 0; i < w->n && st == DS_OK; ++i)
        st = ds_check_disk(w, i, radii ? radii[i] : w->radius, 0.0, disks[i], err);
    if (st == DS_OK)
        st = check_overlaps(w, disks, radii, err);
    if (st != DS_OK) {
        free(radii);
        return st;
    }
    /* A fresh simulation from the new state, at the present time; the old
     * one is replaced only once the new one stands, so a failure changes
     * nothing. */
    ds_sim fresh = *sim;
    fresh.state = NULL;
    st = ds_disks_alloc(&fresh.disks, w->n);
    if (st == DS_OK)
        st = ds_disks_add_mixture(&fresh.disks, sim->disks.r != NULL, sim->disks.m != NULL);
    if (st == DS_OK && sim->disks.ix)
        st = ds_disks_add_images(&fresh.disks); /* a new state: images 0 */
    if (st == DS_OK) {
        for (size_t i = 0; i < w->n; ++i) {
            fresh.disks.x[i] = disks[i].x;
            fresh.disks.y[i] = disks[i].y;
            fresh.disks.vx[i] = disks[i].vx;
            fresh.disks.vy[i] = disks[i].vy;
        }
        if (fresh.disks.r || fresh.disks.m)
            ds_get_radii(sim, fresh.disks.r, fresh.disks.m);
        st = fresh.integrator->create(&fresh);
    }
    free(radii);
    if (st != DS_OK) {
        fresh.integrator->destroy(&fresh);
        ds_disks_free(&fresh.disks);
        return ds_state_refuse(err, st, "no memory for the new state of %zu disks", w->n);
    }
    ds_disks_rebuild_slots(&fresh.disks);
    sim->integrator->destroy(sim);
    ds_disks_free(&sim->disks);
    *sim = fresh;
    ds_protocols_disks_set(sim, 1);
    return DS_OK;
}

/* ------------------------------------------------------------------ */
/* Checkpoints                                                          */
/* ------------------------------------------------------------------ */

#define MAGIC "DSIMSTAT"
/* Version 2 added the pressure tensor's parts of the tally (after the
 * collision timer); a file of version 1 is read with them 0: its stress
 * integral starts at the load. */
#define FORMAT_VERSION ((uint32_t)DS_STATE_FORMAT_VERSION)
#define OLDEST_FORMAT_VERSION 1u
#define BYTE_ORDER_MARK 0x01020304u
#define HEADER_BYTES 40 /* magic, version, byte order, library version, payload length */
#define CHECKSUM_BYTES 8

/* FNV-1a, 64 bits: a corrupted byte anywhere changes it. */
static uint64_t checksum(const uint8_t *p, size_t len)
{
    uint64_t h = 14695981039346656037ull;
    for (size_t k = 0; k < len; ++k) {
        h ^= p[k];
        h *= 1099511628211ull;
    }
    return h;
}

/* The pressure tensor's parts (ds_stress_integral), since version 2. */
static void put_stress(const ds_tally *t, ds_writer *w)
{
    for (int c = 0; c < 3; ++c)
        ds_put_f64(w, t->stress_virial[c]);
    for (int c = 0; c < 3; ++c)
        ds_put_f64(w, t->kinetic[c]);
    for (int c = 0; c < 3; ++c)
        ds_put_f64(w, t->kinetic_integral[c]);
    ds_put_f64(w, t->stress_clock);
}

static int get_stress(ds_reader *r, ds_tally *t)
{
    int finite = 1;
    for (int c = 0; c < 3; ++c) {
        t->stress_virial[c] = ds_get_f64(r);
        finite &= isfinite(t->stress_virial[c]);
    }
    for (int c = 0; c < 3; ++c) {
        t->kinetic[c] = ds_get_f64(r);
        finite &= isfinite(t->kinetic[c]);
    }
    for (int c = 0; c < 3; ++c) {
        t->kinetic_integral[c] = ds_get_f64(r);
        finite &= isfinite(t->kinetic_integral[c]);
    }
    t->stress_clock = ds_get_f64(r);
    return finite && isfinite(t->stress_clock);
}

static void put_payload(const ds_sim *sim, ds_writer *w)
{
    const ds_world *wo = &sim->world;
    ds_put_u64(w, wo->n);
    ds_put_f64(w, wo->radius);
    ds_put_f64(w, wo->box);
    ds_put_f64(w, wo->box_y);
    ds_put_f64(w, wo->speed);
    ds_put_f64(w, wo->dt);
    ds_put_u32(w, (uint32_t)wo->integrator);
    ds_put_u32(w, (uint32_t)wo->boundary);
    ds_put_u32(w, (uint32_t)wo->broadphase);
    ds_put_u32(w, (uint32_t)wo->placement);
    ds_put_u64(w, wo->seed);
    /* Which of the optional arrays follow each disk: 1 radii, 2 masses,
     * 4 image counters (a periodic box; a state without them has 0). */
    ds_put_u32(w, (sim->disks.r ? 1u : 0u) | (sim->disks.m ? 2u : 0u) | (sim->disks.ix ? 4u : 0u));
    ds_put_u64(w, sim->steps);
    ds_put_u64(w, sim->observables_since_step);
    ds_put_u64(w, sim->tally.collisions);
    ds_put_u64(w, sim->tally.pairs_tested);
    ds_put_u64(w, sim->tally.wall_count);
    ds_put_f64(w, sim->tally.wall_impulse);
    ds_put_f64(w, sim->tally.wall_reach);
    ds_put_f64(w, sim->tally.virial);
    ds_put_f64(w, ds_timer_seconds(&sim->collision_timer));
    put_stress(&sim->tally, w);
    const ds_disks *d = &sim->disks;
    for (size_t k = 0; k < d->n; ++k) {
        ds_put_f64(w, d->x[k]);
        ds_put_f64(w, d->y[k]);
        ds_put_f64(w, d->vx[k]);
        ds_put_f64(w, d->vy[k]);
        ds_put_u32(w, d->id[k]);
        if (d->r)
            ds_put_f64(w, d->r[k]);
        if (d->m)
            ds_put_f64(w, d->m[k]);
        if (d->ix) {
            ds_put_u32(w, (uint32_t)d->ix[k]);
            ds_put_u32(w, (uint32_t)d->iy[k]);
        }
    }
    sim->integrator->save(sim, w);
    ds_protocols_save(sim, w);
}

/* The whole file into w: header, payload, checksum. */
static void put_state(const ds_sim *sim, ds_writer *w)
{
    ds_writer count = {NULL, 0};
    put_payload(sim, &count);
    const size_t start = w->len;
    if (w->buf)
        memcpy(w->buf + w->len, MAGIC, 8);
    w->len += 8;
    ds_put_u32(w, FORMAT_VERSION);
    ds_put_u32(w, BYTE_ORDER_MARK);
    if (w->buf) {
        memset(w->buf + w->len, 0, 16);
        memcpy(w->buf + w->len, DS_VERSION_STRING, strlen(DS_VERSION_STRING));
    }
    w->len += 16;
    ds_put_u64(w, count.len);
    put_payload(sim, w);
    ds_put_u64(w, w->buf ? checksum(w->buf + start, w->len - start) : 0);
}

size_t ds_state_size(const ds_sim *sim)
{
    if (!sim)
        return 0;
    ds_writer count = {NULL, 0};
    put_state(sim, &count);
    return count.len;
}

ds_status ds_format_state(const ds_sim *sim, void *buf, size_t cap, size_t *len)
{
    if (len)
        *len = 0;
    if (!sim || (!buf && cap))
        return DS_ERR_ARG;
    const size_t need = ds_state_size(sim);
    if (len)
        *len = need;
    if (need > cap)
        return DS_ERR_ARG;
    ds_writer w = {buf, 0};
    put_state(sim, &w);
    return DS_OK;
}

ds_status ds_save_state(const ds_sim *sim, FILE *out)
{
    if (!sim || !out)
        return DS_ERR_ARG;
    const size_t need = ds_state_size(sim);
    void *buf = malloc(need);
    if (!buf)
        return DS_ERR_NOMEM;
    size_t len = 0;
    ds_status st = ds_format_state(sim, buf, need, &len);
    /* fwrite into stdio's buffer succeeds even on a full disk: the flush
     * decides. */
    if (st == DS_OK && (fwrite(buf, 1, len, out) != len || fflush(out) != 0 || ferror(out)))
        st = DS_ERR_IO;
    free(buf);
    return st;
}

/* The frame of the file: magic, version, byte order, length, checksum.
 * On DS_OK, *payload spans the payload and *version is the format's. */
static ds_status check_frame(const uint8_t *p, size_t len, ds_reader *payload,
                             uint32_t *version_out, ds_state_error *err)
{
    if (len < 8 || memcmp(p, MAGIC, 8) != 0)
        return ds_state_refuse(err, DS_ERR_FORMAT, "not a disksim state file (no %s at its start)",
                               MAGIC);
    if (len < HEADER_BYTES)
        return ds_state_refuse(err, DS_ERR_FORMAT, "truncated: %zu bytes, not even a header", len);
    ds_reader r = {p + 8, p + len, 0};
    const uint32_t version = ds_get_u32(&r), mark = ds_get_u32(&r);
    char made_by[17] = {0};
    memcpy(made_by, ds_take(&r, 16), 16);
    for (int k = 0; k < 16; ++k)
        made_by[k] = made_by[k] >= ' ' && made_by[k] < 127 ? made_by[k] : made_by[k] ? '?' : 0;
    const uint64_t bytes = ds_get_u64(&r);
    if (mark != BYTE_ORDER_MARK)
        return ds_state_refuse(err, DS_ERR_FORMAT,
                               "the byte order mark is 0x%08x, not 0x%08x: not a state this "
                               "library wrote",
                               (unsigned)mark, BYTE_ORDER_MARK);
    if (version < OLDEST_FORMAT_VERSION || version > FORMAT_VERSION)
        return ds_state_refuse(err, DS_ERR_FORMAT,
                               "format version %u (written by disksim %s); this library (%s) "
                               "reads versions %u to %u",
                               (unsigned)version, made_by, DS_VERSION_STRING, OLDEST_FORMAT_VERSION,
                               FORMAT_VERSION);
    if (bytes > len - HEADER_BYTES || len - HEADER_BYTES - bytes < CHECKSUM_BYTES)
        return ds_state_refuse(err, DS_ERR_FORMAT,
                               "truncated: %zu bytes, where the header announces %llu", len,
                               (unsigned long long)(bytes + HEADER_BYTES + CHECKSUM_BYTES));
    if (len - HEADER_BYTES - bytes > CHECKSUM_BYTES)
        return ds_state_refuse(err, DS_ERR_FORMAT, "%llu bytes after the end of the state",
                               (unsigned long long)(len - HEADER_BYTES - bytes - CHECKSUM_BYTES));
    ds_reader tail = {p + HEADER_BYTES + bytes, p + len, 0};
    if (ds_get_u64(&tail) != checksum(p, HEADER_BYTES + (size_t)bytes))
        return ds_state_refuse(err, DS_ERR_FORMAT,
                               "the checksum does not match: the file is corrupted");
    payload->at = p + HEADER_BYTES;
    payload->end = p + HEADER_BYTES + bytes;
    payload->failed = 0;
    *version_out = version;
    return DS_OK;
}

/* The world, checked as ds_create checks parameters. */
static ds_status read_world(ds_reader *r, ds_world *w, ds_state_error *err)
{
    ds_params p;
    memset(&p, 0, sizeof p);
    p.n = (size_t)ds_get_u64(r);
    p.radius = ds_get_f64(r);
    p.box = ds_get_f64(r);
    p.box_y = ds_get_f64(r);
    p.speed = ds_get_f64(r);
    p.dt = ds_get_f64(r);
    p.integrator = (ds_integrator)ds_get_u32(r);
    p.boundary = (ds_boundary)ds_get_u32(r);
    p.broadphase = (ds_broadphase)ds_get_u32(r);
    p.placement = (ds_placement)ds_get_u32(r);
    p.seed = ds_get_u64(r);
    if (r->failed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside its parameters");
    /* Work and memory in proportion to the file: every disk's slot is in
     * it (36 bytes), so a forged count of disks is refused before the
     * parameters are checked (a lattice's check searches O(sqrt n) shapes)
     * or anything is allocated. */
    if (ds_left(r) / 36 < p.n)
        return ds_state_refuse(err, DS_ERR_FORMAT, "%zu bytes cannot hold the %zu disks announced",
                               ds_left(r), p.n);
    ds_params_error why;
    const ds_status st = ds_diagnose_params(&p, NULL, &why);
    if (st != DS_OK || p.broadphase == DS_AUTO)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its parameters are refused: %s",
                               st != DS_OK ? why.message : "no broad phase");
    *w = ds_world_of(&p);
    return DS_OK;
}

/* A mixture's radii (after read_disks): the world's smallest, largest and
 * covered area from them as creation computed them, the largest held to
 * what ds_check_params holds a radius to. */
static ds_status mixture_world(ds_sim *sim, ds_state_error *err)
{
    ds_world *w = &sim->world;
    if (!sim->disks.r)
        return DS_OK;
    ds_world_take_radii(w, &sim->disks);
    const double most = (w->boundary == DS_PERIODIC ? 0.25 : 0.5) * fmin(w->box, w->box_y);
    if (!(w->radius_max < most))
        return ds_state_refuse(err, DS_ERR_FORMAT, "its largest radius %g does not fit its box",
                               w->radius_max);
    return DS_OK;
}

/* How far past the band a radius from the walls a saved centre may be:
 * rounding, and the time step turns a disk after it has moved, so its
 * centre may be past the band by what it moves in a step, and a
 * collision in that step may send it out again once more: twice the
 * fastest disk's step. (A periodic box's centres are in the box: ds_wrap
 * leaves every one in [0, box).) */
static double past_the_walls(const ds_sim *sim)
{
    const ds_world *w = &sim->world;
    const ds_disks *d = &sim->disks;
    double past = 1e-9 * fmax(w->box, w->box_y);
    if (w->boundary == DS_WALLS && w->integrator == DS_TIME_STEP) {
        double fastest = 0.0;
        for (size_t k = 0; k < d->n; ++k)
            fastest = fmax(fastest, hypot(d->vx[k], d->vy[k]));
        past += 2.0 * fastest * w->dt;
    }
    return past;
}

/* The disks in their slots: each generation index once, radii and masses
 * numbers > 0, and every disk one ds_set would take (finite, no faster
 * than DS_VELOCITY_MAX, in the box up to past_the_walls): the same check,
 * so a forged file cannot start a run no caller could. */
static ds_status read_disks(ds_reader *r, ds_sim *sim, int images, ds_state_error *err)
{
    const ds_world *w = &sim->world;
    ds_disks *d = &sim->disks;
    for (size_t k = 0; k < d->n; ++k) {
        d->x[k] = ds_get_f64(r);
        d->y[k] = ds_get_f64(r);
        d->vx[k] = ds_get_f64(r);
        d->vy[k] = ds_get_f64(r);
        d->id[k] = ds_get_u32(r);
        if (d->r)
            d->r[k] = ds_get_f64(r);
        if (d->m)
            d->m[k] = ds_get_f64(r);
        if (images) { /* any counts: every pair of int32 is a place */
            d->ix[k] = (int32_t)ds_get_u32(r);
            d->iy[k] = (int32_t)ds_get_u32(r);
        }
        if (r->failed)
            return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside slot %zu", k);
        const double radius = d->r ? d->r[k] : w->radius;
        if (!(radius > 0.0) || !isfinite(radius) || (d->m && !(d->m[k] > 0.0 && isfinite(d->m[k]))))
            return ds_state_refuse(err, DS_ERR_FORMAT, "slot %zu's radius or mass is no number > 0",
                                   k);
        if (d->id[k] >= d->n || d->slot[d->id[k]] != UINT32_MAX)
            return ds_state_refuse(err, DS_ERR_FORMAT, "slot %zu holds no disk of this box", k);
        d->slot[d->id[k]] = (uint32_t)k; /* seen */
    }
    const double past = past_the_walls(sim);
    for (size_t k = 0; k < d->n; ++k) {
        const ds_disk disk = {d->x[k], d->y[k], d->vx[k], d->vy[k]};
        if (ds_check_disk(w, d->id[k], d->r ? d->r[k] : w->radius, past, disk, err) != DS_OK)
            return DS_ERR_FORMAT;
    }
    return mixture_world(sim, err);
}

/* The integrator's part and the protocols'. Format versions 1 and 2 had
 * no list of protocols: a growth's part came in the event-driven
 * integrator's, which hands it over (legacy). */
static ds_status load_parts(ds_sim *sim, ds_reader *r, uint32_t version, ds_state_error *err)
{
    ds_legacy legacy;
    memset(&legacy, 0, sizeof legacy);
    ds_status st = sim->integrator->load(sim, r, version, &legacy, err);
    if (st == DS_OK && version >= 3)
        st = ds_protocols_load(sim, ds_protocol_table, r, err);
    if (st == DS_OK && legacy.has_growth && ds_growth_adopt(sim, &legacy.growth) != DS_OK)
        st = ds_state_refuse(err, DS_ERR_FORMAT, "its growth's numbers are not a growth's");
    return st;
}

ds_status ds_parse_state(const void *data, size_t len, ds_sim **out, ds_state_error *err)
{
    if (err)
        err->message[0] = '\0';
    if (!out)
        return ds_state_refuse(err, DS_ERR_ARG, "nowhere to put the simulation (NULL)");
    *out = NULL;
    if (!data && len)
        return ds_state_refuse(err, DS_ERR_ARG, "no data (NULL)");
    ds_reader r;
    uint32_t version = 0;
    ds_status st = check_frame(data, len, &r, &version, err);
    ds_world w;
    if (st == DS_OK)
        st = read_world(&r, &w, err);
    if (st != DS_OK)
        return st;
    ds_sim *sim = calloc(1, sizeof *sim);
    if (sim)
        ds_protocols_refresh(&sim->protocols);
    if (!sim || ds_disks_alloc(&sim->disks, w.n) != DS_OK) {
        ds_destroy(sim);
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for %zu disks", w.n);
    }
    sim->world = w;
    sim->integrator = ds_integrator_ops_of(w.integrator);
    const uint32_t arrays = ds_get_u32(&r);
    const int periodic = w.boundary == DS_PERIODIC;
    if (arrays > 7u)
        st = ds_state_refuse(err, DS_ERR_FORMAT, "it names arrays this library does not know");
    else if ((arrays & 4u) && !periodic)
        st = ds_state_refuse(err, DS_ERR_FORMAT, "it has image counters without a periodic box");
    else if (ds_disks_add_mixture(&sim->disks, arrays & 1u, arrays & 2u) != DS_OK ||
             (periodic && ds_disks_add_images(&sim->disks) != DS_OK))
        st = ds_state_refuse(err, DS_ERR_NOMEM, "no memory for %zu disks", w.n);
    sim->steps = ds_get_u64(&r);
    sim->observables_since_step = ds_get_u64(&r);
    sim->tally.collisions = ds_get_u64(&r);
    sim->tally.pairs_tested = ds_get_u64(&r);
    sim->tally.wall_count = ds_get_u64(&r);
    sim->tally.wall_impulse = ds_get_f64(&r);
    sim->tally.wall_reach = ds_get_f64(&r);
    sim->tally.virial = ds_get_f64(&r);
    ds_timer_reset(&sim->collision_timer);
    sim->collision_timer.total = ds_get_f64(&r);
    const int stress = version < 2 || get_stress(&r, &sim->tally); /* else 0, from calloc */
    if (st == DS_OK &&
        (r.failed || sim->observables_since_step > sim->steps ||
         !isfinite(sim->tally.wall_impulse) || !isfinite(sim->tally.wall_reach) ||
         !isfinite(sim->tally.virial) || !stress || !(sim->collision_timer.total >= 0.0) ||
         !((double)sim->steps * w.dt < 1e300)))
        st = ds_state_refuse(err, DS_ERR_FORMAT, "its clock or tally is not a run's");
    for (size_t k = 0; st == DS_OK && k < w.n; ++k)
        sim->disks.slot[k] = UINT32_MAX;
    if (st == DS_OK)
        st = read_disks(&r, sim, (arrays & 4u) != 0, err);
    if (st == DS_OK)
        st = load_parts(sim, &r, version, err);
    if (st == DS_OK && ds_left(&r) != 0)
        st = ds_state_refuse(err, DS_ERR_FORMAT, "%zu bytes of the state were not read",
                             ds_left(&r));
    if (st != DS_OK) {
        ds_destroy(sim);
        return st;
    }
    *out = sim;
    return DS_OK;
}

/* The rest of a stream after the len bytes of head, up to want bytes in
 * all, into a buffer that grows (doubling) as the bytes arrive: a length
 * field forged to 2^42 costs what the stream holds, not what it says. */
static ds_status read_up_to(FILE *in, const uint8_t *head, size_t len, size_t want, uint8_t **out,
                            size_t *got)
{
    size_t cap = want < ((size_t)1 << 16) ? want : (size_t)1 << 16;
    cap = cap > len ? cap : len;
    uint8_t *buf = malloc(cap ? cap : 1);
    if (!buf)
        return DS_ERR_NOMEM;
    memcpy(buf, head, len);
    for (;;) {
        len += fread(buf + len, 1, cap - len, in);
        if (len < cap || cap >= want)
            break; /* the stream ended, or all that was wanted is here */
        const size_t next = cap > want / 2 ? want : 2 * cap;
        uint8_t *more = realloc(buf, next);
        if (!more) {
            free(buf);
            return DS_ERR_NOMEM;
        }
        buf = more;
        cap = next;
    }
    *out = buf;
    *got = len;
    return DS_OK;
}

ds_status ds_load_state(FILE *in, ds_sim **out, ds_state_error *err)
{
    if (err)
        err->message[0] = '\0';
    if (out)
        *out = NULL;
    if (!in || !out)
        return ds_state_refuse(err, DS_ERR_ARG, "no file or nowhere to put the simulation (NULL)");
    /* The header says how long the state is: read that much and one byte
     * more (which must not be there), never to the end of whatever the
     * stream is (/dev/zero has none). */
    uint8_t head[HEADER_BYTES];
    size_t len = fread(head, 1, sizeof head, in);
    size_t total = len;
    if (len == sizeof head && memcmp(head, MAGIC, 8) == 0) {
        uint64_t payload = 0;
        for (int k = 0; k < 8; ++k)
            payload |= (uint64_t)head[32 + k] << (8 * k);
        if (payload > SIZE_MAX / 2)
            return ds_state_refuse(err, DS_ERR_FORMAT,
                                   "its header announces %llu bytes, more than can be held",
                                   (unsigned long long)payload);
        total = HEADER_BYTES + (size_t)payload + CHECKSUM_BYTES;
    }
    uint8_t *buf = NULL;
    if (read_up_to(in, head, len, total > len ? total + 1 : len, &buf, &len) != DS_OK)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to read the state");
    if (ferror(in)) {
        free(buf);
        return ds_state_refuse(err, DS_ERR_IO, "the state could not be read");
    }
    const ds_status st = ds_parse_state(buf, len, out, err);
    free(buf);
    return st;
}
