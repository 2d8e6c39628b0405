/* SPDX-License-Identifier: MIT */
/* The kinds of disk: a mixture's species, their names, and each disk's
 * kind (the disk column `kind`, core/disk_arrays.h). One table row and
 * this file are all the species index took (docs/architecture.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/sim.h"

/* Kind k's default name: "A" to "Z", then "K26", "K27", ... (fewer
 * kinds than disks, and disks are counted in 32 bits). */
static void default_name(size_t k, char out[DS_KIND_NAME_MAX])
{
    if (k < 26)
        snprintf(out, DS_KIND_NAME_MAX, "%c", (char)('A' + k));
    else
        snprintf(out, DS_KIND_NAME_MAX, "K%u", (unsigned)(uint32_t)k);
}

/* The length of a name held in at most DS_KIND_NAME_MAX bytes, and
 * whether it is one: 1 to DS_KIND_NAME_MAX - 1 printable characters
 * without a space, ended by a NUL. */
static int is_name(const char *name)
{
    size_t len = 0;
    while (len < DS_KIND_NAME_MAX && name[len] != '\0') {
        if (!(name[len] > ' ' && name[len] < 127))
            return 0;
        ++len;
    }
    return len > 0 && len < DS_KIND_NAME_MAX;
}

/* Species k's name as the simulation will hold it. */
static void name_of(const ds_mixture *m, size_t k, char out[DS_KIND_NAME_MAX])
{
    if (m->kinds[k].name)
        snprintf(out, DS_KIND_NAME_MAX, "%s", m->kinds[k].name);
    else
        default_name(k, out);
}

ds_status ds_kinds_check(const ds_mixture *m, ds_error *err)
{
    if (!m->kinds)
        return DS_OK;
    for (size_t k = 0; k < m->species; ++k) {
        const char *name = m->kinds[k].name;
        if (!name)
            continue;
        if (!is_name(name))
            return ds_refuse(err, DS_ERR_ARG, "mixture", NAN, DS_KIND_NAME_MAX - 1,
                             "mixture: species %zu's name must be 1 to %d printable characters "
                             "without a space",
                             k, DS_KIND_NAME_MAX - 1);
    }
    /* Each its own (a file's types are named by them): O(species^2),
     * species being few. */
    for (size_t a = 0; a < m->species; ++a)
        for (size_t b = a + 1; b < m->species; ++b) {
            char na[DS_KIND_NAME_MAX], nb[DS_KIND_NAME_MAX];
            name_of(m, a, na);
            name_of(m, b, nb);
            if (strcmp(na, nb) == 0)
                return ds_refuse(err, DS_ERR_ARG, "mixture", NAN, NAN,
                                 "mixture: species %zu and %zu are both named \"%s\"", a, b, na);
        }
    return DS_OK;
}

ds_status ds_kinds_make(ds_sim *sim, const ds_mixture *m)
{
    const size_t count = m && m->kinds ? m->species : 1;
    /* Zeroed past each name: checkpoints write all 16 bytes. */
    char(*names)[DS_KIND_NAME_MAX] = calloc(count, sizeof *names);
    if (!names)
        return DS_ERR_NOMEM;
    for (size_t k = 0; k < count; ++k) {
        if (m && m->kinds)
            name_of(m, k, names[k]);
        else
            default_name(k, names[k]);
    }
    /* A column only where disks differ: one kind needs none. */
    if (count > 1) {
        if (ds_disks_add(&sim->disks, DS_COLUMN_kind) != DS_OK) {
            free(names);
            return DS_ERR_NOMEM;
        }
        size_t i = 0;
        for (size_t k = 0; k < count; ++k)
            for (size_t c = 0; c < m->kinds[k].count; ++c, ++i)
                sim->disks.kind[sim->disks.slot[i]] = (uint32_t)k;
    }
    free(sim->kind_names);
    sim->kind_names = names;
    sim->kind_count = count;
    return DS_OK;
}

void ds_kinds_save(const ds_sim *sim, ds_state_writer *w)
{
    ds_put_u32(w, (uint32_t)sim->kind_count);
    for (size_t k = 0; k < sim->kind_count; ++k) {
        if (w->buf)
            memcpy(w->buf + w->len, sim->kind_names[k], DS_KIND_NAME_MAX);
        w->len += DS_KIND_NAME_MAX;
    }
}

/* After the disks (their kind column read): the names, each a string of
 * printable characters in its 16 bytes, and every disk's kind one of
 * them. 2.x's checkpoints (format 1 and 2) kept no kinds: one, "A". */
ds_status ds_kinds_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_error *err)
{
    if (version < 3)
        return ds_kinds_make(sim, NULL) == DS_OK
                   ? DS_OK
                   : ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the kinds");
    const uint32_t count = ds_get_u32(r);
    if (r->failed || count == 0 || count > sim->world.n || ds_left(r) / DS_KIND_NAME_MAX < count)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its kinds are not a list of them");
    char(*names)[DS_KIND_NAME_MAX] = malloc(count * sizeof *names);
    if (!names)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the kinds");
    free(sim->kind_names);
    sim->kind_names = names;
    sim->kind_count = count;
    for (uint32_t k = 0; k < count; ++k) {
        memcpy(names[k], ds_take(r, DS_KIND_NAME_MAX), DS_KIND_NAME_MAX);
        if (!is_name(names[k]))
            return ds_state_refuse(err, DS_ERR_FORMAT, "kind %u's name is not one", k);
    }
    if ((count > 1) != (sim->disks.kind != NULL))
        return ds_state_refuse(err, DS_ERR_FORMAT, "its kinds do not match its disks");
    for (size_t i = 0; sim->disks.kind && i < sim->world.n; ++i)
        if (sim->disks.kind[i] >= count)
            return ds_state_refuse(err, DS_ERR_FORMAT, "slot %zu's kind is not one", i);
    return DS_OK;
}

ds_status ds_sim_get_kinds(const ds_sim *sim, uint32_t *kinds, ds_error *err)
{
    ds_error_clear(err);
    if (!sim || !kinds)
        return ds_refuse(err, DS_ERR_ARG, sim ? "kinds" : "sim", NAN, NAN, "%s: NULL",
                         sim ? "kinds" : "sim");
    const ds_disks *a = &sim->disks;
    for (size_t k = 0; k < a->n; ++k)
        kinds[a->id[k]] = a->kind ? a->kind[k] : 0u;
    return DS_OK;
}

size_t ds_sim_get_kind_count(const ds_sim *sim) { return sim ? sim->kind_count : 0; }

const char *ds_sim_get_kind_name(const ds_sim *sim, size_t k)
{
    return sim && k < sim->kind_count ? sim->kind_names[k] : NULL;
}
