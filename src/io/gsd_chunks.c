/* SPDX-License-Identifier: MIT */
/* The chunks of a GSD frame, as the HOOMD schema 1.4 names and types
 * them, from a simulation: the configuration (step, 2 dimensions, the
 * box), the particles (N, the kinds' names, each disk's kind, mass,
 * diameter, position, velocity and image) and what the command's --stats
 * logs, under log/disksim/. gsd.c lays them out in the file. */
#include <math.h>
#include <string.h>

#include "io/gsd_chunks.h"

static void put_f32(ds_state_writer *w, float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    ds_put_u32(w, bits);
}

static void put_u8(ds_state_writer *w, uint8_t v) { w->buf[w->len++] = v; }

/* ------------------------------------------------------------------ */
/* The chunks                                                          */
/* ------------------------------------------------------------------ */

/* Disk k's centre (slot k) as HOOMD places it, in the box centred on the
 * origin: -L/2 <= x < L/2 along each axis, in float. The library keeps a
 * centre in [0, L), so x - L/2 is in [-L/2, L/2) in double (exact from
 * L/4 on, by Sterbenz's lemma); only its rounding to float can reach
 * +L/2. A periodic axis then wraps it to -L/2 and counts the image;
 * along walls, where a centre is at least its radius inside, it is kept
 * below +L/2. */
typedef struct gsd_place {
    float at[2];
    int32_t image[2];
} gsd_place;

static gsd_place place(const ds_sim *sim, size_t k)
{
    const ds_disks *d = &sim->disks;
    const ds_box *b = &sim->world.box;
    const double x[2] = {d->x[k], d->y[k]};
    gsd_place p;
    p.image[0] = d->ix ? d->ix[k] : 0;
    p.image[1] = d->iy ? d->iy[k] : 0;
    for (int a = 0; a < 2; ++a) {
        const float half = (float)b->side[a] / 2.0f;
        p.at[a] = (float)(x[a] - 0.5 * b->side[a]);
        if (p.at[a] >= half && ds_box_periodic(b, a)) {
            p.at[a] = -half;
            ++p.image[a];
        } else if (p.at[a] >= half) {
            p.at[a] = nextafterf(half, 0.0f);
        }
    }
    return p;
}

static void fill_step(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                      uint32_t *cols)
{
    (void)log;
    ds_put_u64(w, sim->steps);
    *rows = *cols = 1;
}

static void fill_dimensions(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,
                            uint64_t *rows, uint32_t *cols)
{
    (void)sim;
    (void)log;
    put_u8(w, 2);
    *rows = *cols = 1;
}

/* Lx, Ly, Lz = 0 (HOOMD's 2D box: a box is 2D when Lz is 0), no tilt. */
static void fill_box(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                     uint32_t *cols)
{
    (void)log;
    const float box[6] = {(float)sim->world.box.side[0], (float)sim->world.box.side[1], 0, 0, 0, 0};
    for (int k = 0; k < 6; ++k)
        put_f32(w, box[k]);
    *rows = 6;
    *cols = 1;
}

static void fill_n(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                   uint32_t *cols)
{
    (void)log;
    ds_put_u32(w, (uint32_t)sim->world.n);
    *rows = *cols = 1;
}

/* The kinds' names, a row each, as long as the longest with its NUL
 * (one kind, "A", where a simulation keeps no names). */
static void fill_types(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                       uint32_t *cols)
{
    (void)log;
    static const char one[][2] = {"A"};
    const size_t count = sim->kind_names ? sim->kind_count : 1;
    const char(*names)[DS_KIND_NAME_MAX] = (const char(*)[DS_KIND_NAME_MAX])sim->kind_names;
    size_t width = 1;
    for (size_t t = 0; t < count; ++t) {
        const char *name = names ? names[t] : one[0];
        width = strlen(name) + 1 > width ? strlen(name) + 1 : width;
    }
    for (size_t t = 0; t < count; ++t) {
        const char *name = names ? names[t] : one[0];
        memset(w->buf + w->len, 0, width);
        memcpy(w->buf + w->len, name, strlen(name));
        w->len += width;
    }
    *rows = count;
    *cols = (uint32_t)width;
}

/* The per-disk chunks, in generation order (HOOMD's tag order). */
static void fill_typeid(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,
                        uint64_t *rows, uint32_t *cols)
{
    (void)log;
    const ds_disks *d = &sim->disks;
    for (size_t i = 0; i < d->n; ++i)
        ds_put_u32(w, d->kind ? d->kind[d->slot[i]] : 0u);
    *rows = d->n;
    *cols = 1;
}

static void fill_mass(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                      uint32_t *cols)
{
    (void)log;
    const ds_disks *d = &sim->disks;
    for (size_t i = 0; i < d->n; ++i)
        put_f32(w, d->m ? (float)d->m[d->slot[i]] : 1.0f);
    *rows = d->n;
    *cols = 1;
}

static void fill_diameter(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,
                          uint64_t *rows, uint32_t *cols)
{
    (void)log;
    const ds_disks *d = &sim->disks;
    for (size_t i = 0; i < d->n; ++i)
        put_f32(w, (float)(2.0 * (d->r ? d->r[d->slot[i]] : sim->world.radius)));
    *rows = d->n;
    *cols = 1;
}

static void fill_position(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,
                          uint64_t *rows, uint32_t *cols)
{
    (void)log;
    for (size_t i = 0; i < sim->disks.n; ++i) {
        const gsd_place p = place(sim, sim->disks.slot[i]);
        put_f32(w, p.at[0]);
        put_f32(w, p.at[1]);
        put_f32(w, 0.0f);
    }
    *rows = sim->disks.n;
    *cols = 3;
}

static void fill_velocity(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,
                          uint64_t *rows, uint32_t *cols)
{
    (void)log;
    const ds_disks *d = &sim->disks;
    for (size_t i = 0; i < d->n; ++i) {
        put_f32(w, (float)d->vx[d->slot[i]]);
        put_f32(w, (float)d->vy[d->slot[i]]);
        put_f32(w, 0.0f);
    }
    *rows = d->n;
    *cols = 3;
}

static void fill_image(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                       uint32_t *cols)
{
    (void)log;
    for (size_t i = 0; i < sim->disks.n; ++i) {
        const gsd_place p = place(sim, sim->disks.slot[i]);
        ds_put_i32(w, p.image[0]);
        ds_put_i32(w, p.image[1]);
        ds_put_i32(w, 0);
    }
    *rows = sim->disks.n;
    *cols = 3;
}

/* The Lees-Edwards images' offset along x, unwrapped (the box's, 0
 * without shear): a reader unfolds x + ix Lx + iy offset with it, where
 * the box itself stays rectangular (HOOMD's tilt xy would shear the frame
 * the positions are in, which disksim's is not). */
static void fill_shear_offset(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,
                              uint64_t *rows, uint32_t *cols)
{
    (void)log;
    ds_put_f64(w, sim->world.box.offset);
    *rows = *cols = 1;
}

/* The logged values, one scalar each. */
#define GSD_LOG_FILL(name, put, value)                                                             \
    static void fill_##name(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w,          \
                            uint64_t *rows, uint32_t *cols)                                        \
    {                                                                                              \
        (void)sim;                                                                                 \
        put(w, value);                                                                             \
        *rows = *cols = 1;                                                                         \
    }
GSD_LOG_FILL(time, ds_put_f64, log->time)
GSD_LOG_FILL(kinetic_energy, ds_put_f64, log->kinetic_energy)
GSD_LOG_FILL(px, ds_put_f64, log->px)
GSD_LOG_FILL(py, ds_put_f64, log->py)
GSD_LOG_FILL(collisions, ds_put_u64, log->collisions)
GSD_LOG_FILL(wall_reflections, ds_put_u64, log->wall_reflections)
GSD_LOG_FILL(pressure, ds_put_f64, log->pressure)
GSD_LOG_FILL(virial_pressure, ds_put_f64, log->virial_pressure)
GSD_LOG_FILL(psi6, ds_put_f64, log->psi6)
GSD_LOG_FILL(area_fraction, ds_put_f64, log->area_fraction)
#undef GSD_LOG_FILL

/* In the order of the name list (gsd_chunks.h). Only the position, the
 * velocity, the step and the log change in every frame: the rest is
 * written again only where it changes (the diameters of a growth, the
 * images of a periodic box). */
const ds_gsd_chunk ds_gsd_chunks[] = {
    {"configuration/step", DS_GSD_UINT64, 1, fill_step},
    {"configuration/dimensions", DS_GSD_UINT8, 0, fill_dimensions},
    {"configuration/box", DS_GSD_FLOAT, 0, fill_box},
    {"particles/N", DS_GSD_UINT32, 0, fill_n},
    {"particles/types", DS_GSD_INT8, 0, fill_types},
    {"particles/typeid", DS_GSD_UINT32, 0, fill_typeid},
    {"particles/mass", DS_GSD_FLOAT, 0, fill_mass},
    {"particles/diameter", DS_GSD_FLOAT, 0, fill_diameter},
    {"particles/position", DS_GSD_FLOAT, 1, fill_position},
    {"particles/velocity", DS_GSD_FLOAT, 1, fill_velocity},
    {"particles/image", DS_GSD_INT32, 0, fill_image},
    {"log/disksim/time", DS_GSD_DOUBLE, 1, fill_time},
    {"log/disksim/kinetic_energy", DS_GSD_DOUBLE, 1, fill_kinetic_energy},
    {"log/disksim/px", DS_GSD_DOUBLE, 1, fill_px},
    {"log/disksim/py", DS_GSD_DOUBLE, 1, fill_py},
    {"log/disksim/collisions", DS_GSD_UINT64, 1, fill_collisions},
    {"log/disksim/wall_reflections", DS_GSD_UINT64, 1, fill_wall_reflections},
    {"log/disksim/pressure", DS_GSD_DOUBLE, 1, fill_pressure},
    {"log/disksim/virial_pressure", DS_GSD_DOUBLE, 1, fill_virial_pressure},
    {"log/disksim/psi6", DS_GSD_DOUBLE, 1, fill_psi6},
    {"log/disksim/area_fraction", DS_GSD_DOUBLE, 1, fill_area_fraction},
    {"log/disksim/shear_offset", DS_GSD_DOUBLE, 1, fill_shear_offset},
};
typedef char ds_gsd_chunks_all_counted
    [sizeof ds_gsd_chunks / sizeof ds_gsd_chunks[0] == DS_GSD_CHUNK_COUNT ? 1 : -1];

size_t ds_gsd_chunk_cap(const ds_sim *sim)
{
    /* 12 bytes a disk at most (3 floats or int32), a row a kind. */
    return 12 * sim->world.n + DS_KIND_NAME_MAX * sim->kind_count + 64;
}

/* The log of sim now. psi6 is NaN where the library has none (a periodic
 * box too narrow for its cutoff), as in --stats; without memory for it
 * the frame is not written. The time and the area fraction as
 * ds_sim_get_time and ds_sim_get_area_fraction compute them (sim/ is
 * above io/). */
ds_status ds_gsd_log_of(const ds_sim *sim, ds_gsd_log *log, ds_error *err)
{
    const ds_world *w = &sim->world;
    log->time = (double)sim->steps * w->dt;
    log->kinetic_energy = ds_sim_get_kinetic_energy(sim);
    ds_sim_get_momentum(sim, &log->px, &log->py);
    log->collisions = sim->tally.collisions;
    log->wall_reflections = ds_sim_get_wall_count(sim);
    log->pressure = ds_sim_get_pressure(sim);
    log->virial_pressure = ds_sim_get_virial_pressure(sim);
    log->area_fraction = w->covered / (w->box.side[0] * w->box.side[1]);
    if (ds_sim_get_psi6(sim, &log->psi6, NULL) == DS_ERR_NOMEM)
        return ds_refuse(err, DS_ERR_NOMEM, "out", NAN, NAN, "out: no memory for psi6");
    return DS_OK;
}
