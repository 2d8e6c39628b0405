/* SPDX-License-Identifier: MIT */
/* The event-driven integrator's fetching ahead (event/event_fetch.c) in a
 * long run: the ring of disks whose events come up soon counts its names
 * with 32-bit cursors, which wrap after some 10^9 events. A run that
 * crosses the wrap must go on as before: the cursors stay within a ring's
 * length of each other (ordered by their difference), where comparing
 * them as numbers made one event walk 4 10^9 names and a 65536-disk run
 * stand still. The cursors are set just short of the wrap, not run
 * there. */
#include "test_util.h"

#include <unistd.h>

#include "core/core.h"
#include "event/event_state.h"

static void test_the_fetch_ring_goes_on_past_its_cursors_wrapping(void **state)
{
    (void)state;
    /* 50,000 disks at area fraction 0.4: above the 8 MiB from which the
     * integrator fetches ahead (test_event_driven's system). */
    const size_t n = 50000;
    ds_params p = ds_params_default(n, sqrt(0.4 * 1e6 / (3.141592653589793 * (double)n)));
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.seed = 9;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_events *e = sim->state;
    assert_true(e->fetching);
    ds_fetch *f = &e->fetch;
    const uint32_t start = UINT32_MAX - 40u;
    f->tail = f->second = f->third = start; /* an empty ring, 41 names short of the wrap */
    /* A regression stands still rather than fails: end it. */
    alarm(600);
    const double e0 = ds_sim_get_kinetic_energy(sim);
    ds_sim_run(sim, quick_mode() ? 2 : 5, NULL);
    alarm(0);
    assert_true(f->tail < start && f->tail > 1000u); /* the names went past 2^32 */
    assert_true((uint32_t)(f->tail - f->second) <= DS_FETCH_AHEAD_MASK + 1u);
    assert_true((uint32_t)(f->second - f->third) <= DS_FETCH_AHEAD_MASK + 1u);
    assert_true(ds_sim_get_collision_count(sim) > 1000);
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) / e0 - 1.0) < 1e-12);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_the_fetch_ring_goes_on_past_its_cursors_wrapping),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
