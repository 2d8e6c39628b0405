/* SPDX-License-Identifier: MIT */
/* A caller's text kept with the simulation and carried by checkpoints
 * (ds_sim_set_metadata). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sim/sim.h"

ds_status ds_sim_set_metadata(ds_sim *sim, const char *text, ds_error *err)
{
    ds_error_clear(err);
    if (!sim)
        return ds_refuse(err, DS_ERR_ARG, "sim", NAN, NAN, "sim: NULL");
    size_t len = 0; /* strlen, but no further than one past the limit */
    while (text && len <= DS_METADATA_MAX && text[len] != '\0')
        ++len;
    if (len > DS_METADATA_MAX)
        return ds_refuse(err, DS_ERR_ARG, "metadata", NAN, DS_METADATA_MAX,
                         "metadata: more than %d bytes", DS_METADATA_MAX);
    char *copy = NULL;
    if (len > 0) {
        copy = malloc(len + 1);
        if (!copy)
            return ds_refuse(err, DS_ERR_NOMEM, "metadata", (double)len, NAN,
                             "metadata: no memory for %zu bytes", len);
        memcpy(copy, text, len + 1);
    }
    free(sim->metadata);
    sim->metadata = copy;
    return DS_OK;
}

const char *ds_sim_get_metadata(const ds_sim *sim)
{
    if (!sim)
        return NULL;
    return sim->metadata ? sim->metadata : "";
}

void ds_metadata_save(const ds_sim *sim, ds_state_writer *w)
{
    const size_t len = sim->metadata ? strlen(sim->metadata) : 0;
    ds_put_u32(w, (uint32_t)len);
    if (w->buf && len)
        memcpy(w->buf + w->len, sim->metadata, len);
    w->len += len;
}

/* At most DS_METADATA_MAX bytes, none of them NUL (the text is a C
 * string to its reader). */
ds_status ds_metadata_load(ds_sim *sim, ds_reader *r, uint32_t version, ds_error *err)
{
    if (version < 3)
        return DS_OK;
    const uint32_t len = ds_get_u32(r);
    if (r->failed || len > DS_METADATA_MAX || ds_left(r) < len)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its metadata is not a text of at most %d bytes",
                               DS_METADATA_MAX);
    if (len == 0)
        return DS_OK;
    const char *bytes = (const char *)ds_take(r, len);
    if (memchr(bytes, '\0', len))
        return ds_state_refuse(err, DS_ERR_FORMAT, "its metadata holds a NUL byte");
    sim->metadata = malloc((size_t)len + 1);
    if (!sim->metadata)
        return ds_state_refuse(err, DS_ERR_NOMEM, "no memory for its metadata");
    memcpy(sim->metadata, bytes, len);
    sim->metadata[len] = '\0';
    return DS_OK;
}
