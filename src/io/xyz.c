/* SPDX-License-Identifier: MIT */
/* Trajectories in extended XYZ, the text format ASE, OVITO, VMD and QUIP
 * read: frames one after another, each a count line, a comment line of
 * key=value pairs describing the cell and the columns, then one line per
 * particle. The box is 2D; it is written as a 3D cell of height 2R with
 * every disk at z = 0, so 3D readers see a flat layer of disks. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"

/* Column names as the readers know them: ASE maps species and pos to
 * symbols and positions; OVITO maps species, pos, radius and velo to its
 * Particle Type, Position, Radius and Velocity. ASE keeps radius and velo
 * as per-atom arrays of those names. "X" is ASE's dummy element. */
#define XYZ_PROPERTIES "species:S:1:pos:R:3:radius:R:1:velo:R:3"
/* A periodic box adds each disk's image counts (ds_sim_get_images): the
 * unwrapped centre is pos + image x the cell's side, as LAMMPS' ix iy and
 * OVITO's Periodic Image; ASE reads it as an (N, 2) integer array. */
#define XYZ_IMAGE_PROPERTY ":image:I:2"
#define XYZ_IMAGE_MAX (2 * 12) /* " -2147483648" twice */
#define XYZ_SPECIES "X"

/* Count line, and a comment line of fixed text plus four numbers. */
#define XYZ_HEADER_MAX (32 + 160 + 4 * DS_FIELD_MAX)

size_t ds_xyz_get_size(const ds_sim *sim)
{
    if (!sim)
        return 0;
    /* "X x y 0 R vx vy 0\n": four fixed fields, R, the rest constant. */
    char radius[DS_RADIUS_TEXT_MAX];
    size_t line = 4 * (DS_FIELD_MAX + 1) + ds_radius_text(sim, radius) + 16 +
                  (sim->disks.ix ? XYZ_IMAGE_MAX : 0);
    return XYZ_HEADER_MAX + sim->world.n * line;
}

/* The count and comment lines; returns their length. */
static size_t format_header(const ds_sim *sim, char *out)
{
    char box[32], box_y[32], height[32], time[DS_FIELD_MAX];
    const ds_world *w = &sim->world;
    ds_format_shortest(box, sizeof box, w->box.side[0]);
    ds_format_shortest(box_y, sizeof box_y, w->box.side[1]);
    ds_format_shortest(height, sizeof height, 2.0 * w->radius_max);
    /* The time as ds_sim_get_time computes it (sim/ is above io/). */
    time[ds_format_fixed6(time, (double)sim->steps * w->dt)] = '\0';
    /* Periodic as the box is along x and y, never along the flat z of the
     * layer. */
    char pbc[6] = "F F F";
    pbc[0] = ds_box_periodic(&w->box, 0) ? 'T' : 'F';
    pbc[2] = ds_box_periodic(&w->box, 1) ? 'T' : 'F';
    int len =
        snprintf(out, XYZ_HEADER_MAX,
                 "%zu\nLattice=\"%s 0 0 0 %s 0 0 0 %s\" Properties=" XYZ_PROPERTIES
                 "%s Time=%s pbc=\"%s\"\n",
                 w->n, box, box_y, height, sim->disks.ix ? XYZ_IMAGE_PROPERTY : "", time, pbc);
    return len > 0 && len < XYZ_HEADER_MAX ? (size_t)len : 0;
}

ds_status ds_xyz_format(const ds_sim *sim, char *buf, size_t cap, size_t *len, ds_error *err)
{
    ds_error_clear(err);
    if (len)
        *len = 0;
    if (!sim || (!buf && cap))
        return ds_refuse(err, DS_ERR_ARG, sim ? "buf" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "buf" : "sim");
    char line[XYZ_HEADER_MAX];
    size_t used = format_header(sim, line);
    if (used <= cap)
        memcpy(buf, line, used);
    ds_radius_cache radius;
    ds_radius_cache_init(&radius, sim);
    const ds_disks *d = &sim->disks;
    for (size_t i = 0; i < d->n; ++i) {
        const size_t k = d->slot[i];
        size_t l = 0;
        memcpy(line, XYZ_SPECIES " ", 2);
        l = 2;
        l += ds_format_fixed6(line + l, d->x[k]);
        line[l++] = ' ';
        l += ds_format_fixed6(line + l, d->y[k]);
        memcpy(line + l, " 0 ", 3);
        l += 3;
        size_t rlen = 0;
        const char *r = ds_radius_at(sim, k, &radius, &rlen);
        memcpy(line + l, r, rlen);
        l += rlen;
        line[l++] = ' ';
        l += ds_format_fixed6(line + l, d->vx[k]);
        line[l++] = ' ';
        l += ds_format_fixed6(line + l, d->vy[k]);
        memcpy(line + l, " 0", 2);
        l += 2;
        if (d->ix)
            l += (size_t)snprintf(line + l, XYZ_IMAGE_MAX + 1, " %ld %ld", (long)d->ix[k],
                                  (long)d->iy[k]);
        line[l++] = '\n';
        if (used + l <= cap)
            memcpy(buf + used, line, l);
        used += l;
    }
    if (len)
        *len = used;
    return used <= cap ? DS_OK : ds_refuse_cap(err, cap, used);
}

/* ds_xyz_format as a ds_format_fn: velocities are always written. */
static ds_status format_xyz(const ds_sim *sim, int velocities, char *buf, size_t cap, size_t *len,
                            ds_error *err)
{
    (void)velocities;
    return ds_xyz_format(sim, buf, cap, len, err);
}

ds_status ds_xyz_write(const ds_sim *sim, FILE *out, ds_error *err)
{
    return ds_write_formatted(sim, 1, out, ds_xyz_get_size(sim), format_xyz, err);
}

/* The writer of extended XYZ: a frame a write, velocities always. */
static ds_status write_frame(void *self, FILE *out, unsigned flags, const ds_sim *sim,
                             ds_error *err)
{
    (void)self;
    (void)flags;
    return ds_xyz_write(sim, out, err);
}

const ds_writer_ops ds_xyz_writer = {
    .name = "xyz",
    .flags = DS_WRITE_VELOCITIES,
    .open = NULL,
    .frame = write_frame,
    .close = NULL,
};
