/* SPDX-License-Identifier: MIT */
/* The time step's broad phases behind one dispatcher (broad_phase.h):
 * creating and freeing each one's state, its memory, and finding pairs
 * with the seam pass added where a sweep runs in a periodic box. */
#include "timestep/broad_phase.h"

/* A sweep sees the box as the coordinates stand; in a periodic box the
 * pairs across its edges need the seam pass. Brute force takes every
 * pair to its nearest image itself. */
static int needs_seam(ds_broadphase kind, const ds_box *box)
{
    return ds_box_any_periodic(box) && kind != DS_BROADPHASE_BRUTE;
}

static void set_up(ds_bp *bp, ds_broadphase kind, const ds_world *w)
{
    bp->kind = kind;
    bp->scan = ds_bp_widest_scan();
    bp->diameter = 2.0 * w->radius_max; /* a mixture prunes with its largest */
    bp->box = w->box;
}

ds_status ds_bp_create(ds_bp *bp, ds_broadphase kind, const ds_world *w, ds_disks *d)
{
    set_up(bp, kind, w);
    ds_status st = DS_OK;
    switch (kind) {
    case DS_BROADPHASE_STRIPS:
        st = ds_strips_create(bp, w, d);
        break;
    case DS_BROADPHASE_SAP:
        st = ds_bp_sort(d, bp->scan);
        break;
    default:
        break;
    }
    if (st == DS_OK && needs_seam(kind, &bp->box))
        st = ds_seam_create(bp, d->n);
    return st;
}

void ds_bp_save(const ds_bp *bp, ds_state_writer *w)
{
    ds_put_u32(w, ds_broadphase_code(bp->kind));
    if (bp->strips)
        ds_strips_save(bp, w);
}

ds_status ds_bp_load(ds_bp *bp, const ds_world *w, ds_disks *d, ds_reader *r, ds_error *err)
{
    set_up(bp, w->broadphase, w);
    if (ds_get_u32(r) != ds_broadphase_code(bp->kind) || r->failed)
        return ds_state_refuse(err, DS_ERR_FORMAT, "the broad phase's part is not %s's",
                               ds_broadphase_name(bp->kind));
    ds_status st = bp->kind == DS_BROADPHASE_STRIPS ? ds_strips_load(bp, w, d, r, err) : DS_OK;
    if (st == DS_OK && needs_seam(bp->kind, &bp->box) && ds_seam_create(bp, d->n) != DS_OK)
        st = ds_state_refuse(err, DS_ERR_NOMEM, "no memory for the seam pass of %zu disks", d->n);
    return st;
}

void ds_bp_destroy(ds_bp *bp)
{
    ds_strips_destroy(bp);
    ds_seam_destroy(bp);
}

size_t ds_bp_bytes(const ds_world *w)
{
    size_t bytes = 0;
    if (w->broadphase == DS_BROADPHASE_STRIPS)
        bytes += (w->n + 2) * DS_STRIPS_BYTES_PER_DISK;
    if (needs_seam(w->broadphase, &w->box))
        bytes += ds_seam_bytes(w->n);
    return bytes;
}

uint64_t ds_bp_find_pairs(ds_bp *bp, ds_disks *d, ds_pair_fn on_pair, void *ctx)
{
    uint64_t tested;
    switch (bp->kind) {
    case DS_BROADPHASE_BRUTE:
        return ds_brute_force_find_pairs(bp, d, on_pair, ctx);
    case DS_BROADPHASE_STRIPS:
        tested = ds_strips_find_pairs(bp, d, on_pair, ctx);
        break;
    default:
        tested = ds_sap_find_pairs(bp, d, on_pair, ctx);
        break;
    }
    return bp->seam ? tested + ds_seam_find_pairs(bp, d, on_pair, ctx) : tested;
}
