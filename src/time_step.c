/* DS_TIME_STEP: the seed's fixed time step. Each step moves every disk by
 * v dt and turns those past a wall, or wraps them in a periodic box
 * (collision.c), then the broad phase finds the overlapping pairs and the
 * approaching ones exchange their normal velocities (broad_phase.c,
 * broad_phase_strips.c, broad_phase_seam.c, collision.c). */
#include "sim_internal.h"

void ds_ts_run(ds_sim *sim, uint64_t steps)
{
    const int periodic = sim->boundary == DS_PERIODIC;
    const ds_pair_fn resolve = periodic ? ds_resolve_pair_periodic : ds_resolve_pair;
    for (uint64_t s = 0; s < steps; ++s) {
        if (periodic)
            ds_move_and_wrap(sim);
        else
            ds_move_and_reflect(sim);
        ds_timer_start(&sim->collision_timer);
        sim->pairs_tested += ds_bp_find_pairs(sim, resolve, NULL);
        ds_timer_stop(&sim->collision_timer);
        ++sim->steps;
    }
    ds_rebuild_slots(sim);
}
