/* SPDX-License-Identifier: MIT */
/* Trajectories in extended XYZ, the text format ASE, OVITO, VMD and QUIP
 * read: frames one after another, each a count line, a comment line of
 * key=value pairs describing the cell and the columns, then one line per
 * particle. The box is 2D; it is written as a 3D cell of height 2R with
 * every disk at z = 0, so 3D readers see a flat layer of disks (OVITO
 * makes a cell 2D only when the file has no z column, and ASE needs one:
 * its positions have three). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/io.h"

/* Column names as the two readers map them (ASE 3.22's ase.io.extxyz,
 * OVITO's XYZ reader): OVITO maps type to its Particle Type (any name:
 * here the kinds' names), pos to Position, radius to Radius, velo to
 * Velocity, mass to Mass and map_shift to Periodic Image. ASE maps pos to
 * positions and keeps every other column as a per-atom array of its name;
 * of those it reads momenta as get_momenta() and masses as get_masses(),
 * so get_velocities() is momenta / masses. Each reader takes its own
 * column where their names differ (velo and momenta, mass and masses).
 * No species column: ASE would take it for chemical symbols, which a
 * kind's name is not; without one its atoms are "X", its dummy. */
#define XYZ_PROPERTIES "type:S:1:pos:R:3:radius:R:1:velo:R:3:momenta:R:3:mass:R:1:masses:R:1"
/* A periodic box adds each disk's image counts (ds_sim_get_images): the
 * unwrapped centre is pos + image x the cell's side, as LAMMPS' ix iy iz
 * and OVITO's Periodic Image (0 along z). */
#define XYZ_IMAGE_PROPERTY ":map_shift:I:3"
#define XYZ_IMAGE_MAX (2 * 12 + 2) /* " -2147483648" twice, " 0" */

/* Count line, and a comment line of fixed text plus five numbers. */
#define XYZ_HEADER_MAX (32 + 220 + 5 * DS_FIELD_MAX)
/* A disk's line: its kind's name, six fixed fields, three zeros, the
 * radius and the mass twice, the images, each with a space. */
#define XYZ_LINE_MAX                                                                               \
    (DS_KIND_NAME_MAX + 6 * DS_FIELD_MAX + 6 + 3 * DS_RADIUS_TEXT_MAX + XYZ_IMAGE_MAX + 2)

size_t ds_xyz_get_size(const ds_sim *sim)
{
    if (!sim)
        return 0;
    /* "T x y 0 r vx vy 0 px py 0 m m": the kind's name, six fixed fields,
     * the radius, the mass twice (24 characters at most each), zeros. */
    char radius[DS_RADIUS_TEXT_MAX];
    size_t line = DS_KIND_NAME_MAX + 6 * (DS_FIELD_MAX + 1) + ds_radius_text(sim, radius) +
                  2 * (DS_RADIUS_TEXT_MAX + 1) + 8 + (sim->disks.ix ? XYZ_IMAGE_MAX : 0);
    return XYZ_HEADER_MAX + sim->world.n * line;
}

/* The count and comment lines; returns their length. */
static size_t format_header(const ds_sim *sim, char *out)
{
    char box[32], box_y[32], height[32], time[DS_FIELD_MAX], shear[48] = "";
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
    /* A sheared box (Lees-Edwards) names its image above's offset along
     * x, unwrapped: the unwrapped centre is pos + map_shift x the sides +
     * iy shear_offset along x. The cell stays rectangular. */
    if (w->box.shift_speed != 0.0 || w->box.offset != 0.0) {
        memcpy(shear, " shear_offset=", 15);
        ds_format_shortest(shear + 14, sizeof shear - 14, w->box.offset);
    }
    int len = snprintf(out, XYZ_HEADER_MAX,
                       "%zu\nLattice=\"%s 0 0 0 %s 0 0 0 %s\" Properties=" XYZ_PROPERTIES
                       "%s Time=%s pbc=\"%s\"%s\n",
                       w->n, box, box_y, height, sim->disks.ix ? XYZ_IMAGE_PROPERTY : "", time, pbc,
                       shear);
    return len > 0 && len < XYZ_HEADER_MAX ? (size_t)len : 0;
}

/* text (len bytes) and a space at line + *l. */
static void put_text(char *line, size_t *l, const char *text, size_t len)
{
    memcpy(line + *l, text, len);
    *l += len;
    line[(*l)++] = ' ';
}

/* A fixed-six-decimals field and a space. */
static void put_fixed6(char *line, size_t *l, double v)
{
    *l += ds_format_fixed6(line + *l, v);
    line[(*l)++] = ' ';
}

/* The line of the disk in slot k, without its newline; returns its
 * length. radius and mass cache the last text of each (kinds repeat). */
static size_t format_disk(const ds_sim *sim, size_t k, ds_radius_cache *radius,
                          ds_radius_cache *mass, char *line)
{
    const ds_disks *d = &sim->disks;
    const char *name = sim->kind_names ? sim->kind_names[d->kind ? d->kind[k] : 0] : "A";
    const double m = d->m ? d->m[k] : 1.0;
    size_t l = 0, len = 0;
    put_text(line, &l, name, strlen(name));
    put_fixed6(line, &l, d->x[k]);
    put_fixed6(line, &l, d->y[k]);
    put_text(line, &l, "0", 1);
    const char *r = ds_radius_at(sim, k, radius, &len);
    put_text(line, &l, r, len);
    put_fixed6(line, &l, d->vx[k]);
    put_fixed6(line, &l, d->vy[k]);
    put_text(line, &l, "0", 1);
    put_fixed6(line, &l, m * d->vx[k]);
    put_fixed6(line, &l, m * d->vy[k]);
    put_text(line, &l, "0", 1);
    if (m != mass->value) { /* the radius cache's rule, for the masses */
        mass->value = m;
        ds_format_shortest(mass->text, sizeof mass->text, m);
        mass->len = strlen(mass->text);
    }
    put_text(line, &l, mass->text, mass->len);
    put_text(line, &l, mass->text, mass->len);
    if (d->ix)
        l += (size_t)snprintf(line + l, XYZ_IMAGE_MAX + 1, "%ld %ld 0 ", (long)d->ix[k],
                              (long)d->iy[k]);
    return l - 1; /* the last space */
}

ds_status ds_xyz_format(const ds_sim *sim, char *buf, size_t cap, size_t *len, ds_error *err)
{
    ds_error_clear(err);
    if (len)
        *len = 0;
    if (!sim || (!buf && cap))
        return ds_refuse(err, DS_ERR_ARG, sim ? "buf" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "buf" : "sim");
    char header[XYZ_HEADER_MAX], line[XYZ_LINE_MAX];
    size_t used = format_header(sim, header);
    if (used <= cap)
        memcpy(buf, header, used);
    ds_radius_cache radius, mass = {NAN, 0, ""};
    ds_radius_cache_init(&radius, sim);
    const ds_disks *d = &sim->disks;
    for (size_t i = 0; i < d->n; ++i) {
        size_t l = format_disk(sim, d->slot[i], &radius, &mass, line);
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
