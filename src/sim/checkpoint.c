/* SPDX-License-Identifier: MIT */
/* Checkpoints: a simulation saved and loaded to the bit
 * (ds_checkpoint_save, ds_checkpoint_load and their in-memory forms).
 * This file writes and reads the frame of the file, the world, the
 * tally and the disk arrays; each integrator its own part, through its
 * table (save, load). Every value read is held to the limits a caller's
 * would be (ds_params_check, ds_check_disk), so a forged file cannot
 * start a run no caller could. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"
#include "protocols/protocols.h"
#include "sim/sim.h"

#define MAGIC "DSIMSTAT"
/* Version 2 added the pressure tensor's parts of the tally (after the
 * collision timer); a file of version 1 is read with them 0: its stress
 * integral starts at the load. Version 4 added the rules of collisions
 * and flights and the energy books after them; an older file's run is
 * elastic and straight. */
#define FORMAT_VERSION ((uint32_t)DS_CHECKPOINT_FORMAT_VERSION)
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

/* The pressure tensor's parts (ds_sim_get_stress_integral), since version 2. */
static void put_stress(const ds_tally *t, ds_state_writer *w)
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

static void put_payload(const ds_sim *sim, ds_state_writer *w)
{
    const ds_world *wo = &sim->world;
    ds_put_u64(w, wo->n);
    ds_put_f64(w, wo->radius);
    ds_put_f64(w, wo->box.side[0]);
    ds_put_f64(w, wo->box.side[1]);
    ds_put_f64(w, wo->speed);
    ds_put_f64(w, wo->dt);
    ds_put_u32(w, (uint32_t)wo->integrator);
    ds_put_u32(w, (uint32_t)wo->boundary);
    ds_put_u32(w, ds_broadphase_code(wo->broadphase)); /* 2.x's numbers */
    ds_put_u32(w, (uint32_t)wo->placement);
    ds_put_u64(w, wo->seed);
    /* Which columns follow each disk: bit c for column c of
     * DS_DISK_COLUMNS (format 2's 1 radii, 2 masses, 4 image counters are
     * mapped when read). */
    ds_put_u32(w, ds_disks_columns(&sim->disks));
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
    ds_rules_save(sim, w);
    ds_disks_save(&sim->disks, w);
    ds_kinds_save(sim, w);
    sim->integrator->save(sim, w);
    ds_protocols_save(sim, w);
    ds_metadata_save(sim, w);
}

/* The whole file into w: header, payload, checksum. */
static void put_state(const ds_sim *sim, ds_state_writer *w)
{
    ds_state_writer count = {NULL, 0};
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

size_t ds_checkpoint_get_size(const ds_sim *sim)
{
    if (!sim)
        return 0;
    ds_state_writer count = {NULL, 0};
    put_state(sim, &count);
    return count.len;
}

/* The refusal of a NULL argument. */
static ds_status refuse_null(ds_error *err, const char *field)
{
    return ds_refuse(err, DS_ERR_ARG, field, NAN, NAN, "%s: NULL", field);
}

ds_status ds_checkpoint_format(const ds_sim *sim, void *buf, size_t cap, size_t *len, ds_error *err)
{
    ds_error_clear(err);
    if (len)
        *len = 0;
    if (!sim || (!buf && cap))
        return refuse_null(err, sim ? "buf" : "sim");
    const size_t need = ds_checkpoint_get_size(sim);
    if (len)
        *len = need;
    if (need > cap)
        return ds_refuse(err, DS_ERR_ARG, "cap", (double)cap, (double)need,
                         "cap = %zu bytes is too small: the checkpoint needs %zu", cap, need);
    ds_state_writer w = {buf, 0};
    put_state(sim, &w);
    return DS_OK;
}

ds_status ds_checkpoint_save(const ds_sim *sim, FILE *out, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !out)
        return refuse_null(err, sim ? "out" : "sim");
    const size_t need = ds_checkpoint_get_size(sim);
    void *buf = malloc(need);
    if (!buf)
        return ds_refuse(err, DS_ERR_NOMEM, "checkpoint", (double)need, NAN,
                         "checkpoint: no memory for its %zu bytes", need);
    size_t len = 0;
    ds_status st = ds_checkpoint_format(sim, buf, need, &len, err);
    /* fwrite into stdio's buffer succeeds even on a full disk: the flush
     * decides. */
    if (st == DS_OK && (fwrite(buf, 1, len, out) != len || fflush(out) != 0 || ferror(out)))
        st = ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: the write of %zu bytes failed", len);
    free(buf);
    return st;
}

/* The frame of the file: magic, version, byte order, length, checksum.
 * On DS_OK, *payload spans the payload and *version is the format's. */
static ds_status check_frame(const uint8_t *p, size_t len, ds_reader *payload,
                             uint32_t *version_out, ds_error *err)
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

/* The world, checked as ds_sim_create checks parameters. */
static ds_status read_world(ds_reader *r, ds_world *w, ds_error *err)
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
    p.broadphase = ds_broadphase_of_code(ds_get_u32(r)); /* _COUNT if none */
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
    ds_error why;
    ds_status st = ds_params_check(&p, NULL, NULL, &why);
    /* A state's disks are placed already (and checked below): a box a
     * barostat has compressed may hold more than placement would try to
     * put in it. */
    if (st == DS_ERR_PLACEMENT)
        st = DS_OK;
    if (st != DS_OK || p.broadphase == DS_BROADPHASE_AUTO)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its parameters are refused: %s",
                               st != DS_OK ? why.message : "no broad phase");
    *w = ds_world_of(&p);
    return DS_OK;
}

/* A mixture's radii (after read_disks): the world's smallest, largest and
 * covered area from them as creation computed them, the largest held to
 * what ds_params_check holds a radius to. */
static ds_status mixture_world(ds_sim *sim, ds_error *err)
{
    ds_world *w = &sim->world;
    if (!sim->disks.r)
        return DS_OK;
    ds_world_take_radii(w, &sim->disks);
    double most = INFINITY;
    for (int a = 0; a < 2; ++a)
        most = fmin(most, (ds_box_periodic(&w->box, a) ? 0.25 : 0.5) * w->box.side[a]);
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
    double past = 1e-9 * fmax(w->box.side[0], w->box.side[1]);
    if (!(ds_box_periodic(&w->box, 0) && ds_box_periodic(&w->box, 1)) &&
        w->integrator == DS_INTEGRATOR_TIME_STEP) {
        double fastest = 0.0;
        for (size_t k = 0; k < d->n; ++k)
            fastest = fmax(fastest, hypot(d->vx[k], d->vy[k]));
        past += 2.0 * fastest * w->dt;
    }
    return past;
}

/* The disks in their slots: each generation index once, radii and masses
 * numbers > 0, and every disk one ds_sim_set_disk would take (finite, no
 * faster than DS_VELOCITY_MAX, in the box up to past_the_walls): the same
 * check, so a forged file cannot start a run no caller could. */
static ds_status read_disks(ds_reader *r, ds_sim *sim, ds_error *err)
{
    const ds_world *w = &sim->world;
    ds_disks *d = &sim->disks;
    /* Any image counts: every pair of int32 is a place. */
    if (!ds_disks_load_all(d, r))
        return ds_state_refuse(err, DS_ERR_FORMAT, "the file ends inside its disks");
    if (ds_box_any_periodic(&w->box) && !d->ix && ds_disks_add_images(d) != DS_OK)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for %zu disks", d->n);
    for (size_t k = 0; k < d->n; ++k) {
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
        ds_error why;
        if (ds_check_disk(w, d->id[k], d->r ? d->r[k] : w->radius, past, disk, &why) != DS_OK) {
            ds_error_index(err, d->id[k]);
            return ds_state_refuse(err, DS_ERR_FORMAT, "%s", why.message);
        }
    }
    return mixture_world(sim, err);
}

/* The integrator's part and the protocols'. Format versions 1 and 2 had
 * no list of protocols: a growth's part came in the event-driven
 * integrator's, which hands it over (legacy). */
static ds_status load_parts(ds_sim *sim, ds_reader *r, uint32_t version, ds_error *err)
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

/* Which columns follow each disk, and the optional ones made: version 3
 * names a bit per column of DS_DISK_COLUMNS (ds_disks_columns); 2.x's
 * versions named 1 radii, 2 masses, 4 image counts, in the same order. */
static ds_status read_columns(ds_reader *r, ds_sim *sim, uint32_t version, ds_error *err)
{
    uint32_t bits = ds_get_u32(r);
    if (version < 3) {
        if (bits > 7u)
            return ds_state_refuse(err, DS_ERR_FORMAT,
                                   "it names arrays this library does not know");
        bits = DS_DISKS_EVERY_COLUMN | (bits & 1u ? 1u << DS_COLUMN_r : 0u) |
               (bits & 2u ? 1u << DS_COLUMN_m : 0u) |
               (bits & 4u ? 1u << DS_COLUMN_ix | 1u << DS_COLUMN_iy : 0u);
    }
    const uint32_t images = 1u << DS_COLUMN_ix | 1u << DS_COLUMN_iy;
    const int periodic = ds_box_any_periodic(&sim->world.box);
    if ((bits & DS_DISKS_EVERY_COLUMN) != DS_DISKS_EVERY_COLUMN || bits >> DS_COLUMN_COUNT ||
        ((bits & images) != 0u && (bits & images) != images))
        return ds_state_refuse(err, DS_ERR_FORMAT, "it names arrays this library does not know");
    if ((bits & images) && !periodic)
        return ds_state_refuse(err, DS_ERR_FORMAT, "it has image counters without a periodic box");
    if (!(bits & images) && periodic && version >= 3)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its periodic box has no image counters");
    /* A 2.x state from before image counts: its disks start at 0 (added
     * once the disks are read, read_disks). */
    for (int c = 0; c < DS_COLUMN_COUNT; ++c)
        if ((bits >> c & 1u) && ds_disks_add(&sim->disks, (ds_column)c) != DS_OK)
            return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for %zu disks", sim->world.n);
    return DS_OK;
}

ds_status ds_checkpoint_parse(const void *data, size_t len, ds_sim **out, ds_error *err)
{
    ds_error_clear(err);
    if (!out)
        return ds_refuse(err, DS_ERR_ARG, "out", NAN, NAN,
                         "out: nowhere to put the simulation (NULL)");
    *out = NULL;
    if (!data && len)
        return ds_refuse(err, DS_ERR_ARG, "data", NAN, NAN, "data: NULL");
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
        ds_sim_destroy(sim);
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for %zu disks", w.n);
    }
    sim->world = w;
    sim->integrator = ds_integrator_ops_of(w.integrator);
    const ds_status columns = read_columns(&r, sim, version, err);
    st = columns;
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
    /* Version 4's rules (before, elastic and straight: the world's). */
    if (st == DS_OK && version >= 4)
        st = ds_rules_load(sim, &r, err);
    for (size_t k = 0; st == DS_OK && k < w.n; ++k)
        sim->disks.slot[k] = UINT32_MAX;
    if (st == DS_OK)
        st = read_disks(&r, sim, err);
    if (st == DS_OK)
        st = ds_kinds_load(sim, &r, version, err);
    if (st == DS_OK)
        st = load_parts(sim, &r, version, err);
    if (st == DS_OK)
        st = ds_metadata_load(sim, &r, version, err);
    if (st == DS_OK && ds_left(&r) != 0)
        st = ds_state_refuse(err, DS_ERR_FORMAT, "%zu bytes of the state were not read",
                             ds_left(&r));
    if (st != DS_OK) {
        ds_sim_destroy(sim);
        return ds_error_done(err, st);
    }
    *out = sim;
    return DS_OK;
}

ds_status ds_checkpoint_load(FILE *in, ds_sim **out, ds_error *err)
{
    ds_error_clear(err);
    if (out)
        *out = NULL;
    if (!in || !out)
        return ds_refuse(err, DS_ERR_ARG, in ? "out" : "in", NAN, NAN,
                         "%s: no file or nowhere to put the simulation (NULL)", in ? "out" : "in");
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
    if (ds_read_up_to(in, head, len, total > len ? total + 1 : len, &buf, &len) != DS_OK)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory to read the state");
    if (ferror(in)) {
        free(buf);
        return ds_state_refuse(err, DS_ERR_IO, "the state could not be read");
    }
    const ds_status st = ds_checkpoint_parse(buf, len, out, err);
    free(buf);
    return st;
}
