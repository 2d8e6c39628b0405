/* DS_SAP_STRIPS: sweep and prune in horizontal strips. Not implemented yet. */
#include "sim_internal.h"

ds_status ds_strips_create(ds_sim *sim)
{
    (void)sim;
    return DS_ERR_ARG;
}

void ds_strips_destroy(ds_sim *sim) { (void)sim; }

uint64_t ds_strips_find_pairs(ds_sim *sim, ds_pair_fn on_pair, void *ctx)
{
    (void)sim;
    (void)on_pair;
    (void)ctx;
    return 0;
}
