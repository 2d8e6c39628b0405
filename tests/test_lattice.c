/* SPDX-License-Identifier: MIT */
/* Lattice placement (DS_PLACEMENT_LATTICE): every disk inside the box and none
 * overlapping, at any density a triangular lattice reaches; a request no
 * lattice fits is refused before anything is allocated; the lattice is
 * triangular (six neighbours at one distance in the bulk); speeds as for
 * random placement. */
#include "test_util.h"

static ds_params lattice_params(size_t n, double eta)
{
    ds_params p = ds_params_default(n, sqrt(eta * 1e6 / (3.141592653589793 * (double)n)));
    p.placement = DS_PLACEMENT_LATTICE;
    return p;
}

/* Inside [R, box - R]^2 and no two centres closer than 2R (up to the
 * placement's 1e-12 rounding slack); returns the closest distance / 2R. */
static double check_inside_and_apart(const ds_sim *sim)
{
    const size_t n = ds_sim_get_count(sim);
    const double r = ds_sim_get_radius(sim), box = ds_sim_get_box_width(sim);
    ds_disk *d = malloc(n * sizeof *d);
    assert_non_null(d);
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    double closest2 = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        assert_true(d[i].x >= r && d[i].x <= box - r);
        assert_true(d[i].y >= r && d[i].y <= box - r);
        for (size_t j = i + 1; j < n; ++j) {
            const double dx = d[j].x - d[i].x, dy = d[j].y - d[i].y;
            if (dx * dx + dy * dy < closest2)
                closest2 = dx * dx + dy * dy;
        }
    }
    free(d);
    const double closest = sqrt(closest2) / (2.0 * r);
    assert_true(closest >= 1.0 - 1e-12);
    return closest;
}

static void test_a_dense_lattice_is_inside_and_apart_at_any_density_it_reaches(void **state)
{
    (void)state;
    /* From a dilute gas up to 0.86 with walls, far beyond random
     * placement's 0.54; both integrators take it. */
    const double etas[] = {0.1, 0.5, 0.7, 0.8, 0.86};
    for (size_t k = 0; k < sizeof etas / sizeof etas[0]; ++k) {
        ds_params p = lattice_params(quick_mode() ? 1000 : 4096, etas[k]);
        p.integrator = (ds_integrator)(k % DS_INTEGRATOR_COUNT); /* each in turn */
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        assert_int_equal(ds_sim_get_count(sim), p.n);
        check_inside_and_apart(sim);
        ds_sim_destroy(sim);
    }
}

static void test_few_disks_spread_over_the_whole_box(void **state)
{
    (void)state;
    /* Two disks covering 0.3 of the box fit only far apart (diagonally):
     * the lattice spans the box edge to edge. One disk sits in the middle. */
    ds_params p = lattice_params(2, 0.3);
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_true(check_inside_and_apart(sim) > 1.5);
    ds_sim_destroy(sim);
    p = lattice_params(1, 0.5);
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    const ds_disk d = ds_sim_get_disk(sim, 0);
    assert_true(d.x == 500.0 && d.y == 500.0);
    ds_sim_destroy(sim);
}

static void test_a_lattice_that_cannot_fit_is_refused_before_creating(void **state)
{
    (void)state;
    /* Above close packing (0.9069) nothing fits; just below it a square box
     * with walls does not fit a triangular lattice of 4096 either. */
    ds_params p = lattice_params(4096, 0.93);
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_ERR_PLACEMENT);
    ds_sim *sim = (ds_sim *)&p; /* must be set to NULL on failure */
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_ERR_PLACEMENT);
    assert_null(sim);
    p = lattice_params(4096, 0.90);
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_ERR_PLACEMENT);
    p = lattice_params(4096, 0.86);
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_OK);
    /* A lattice is no answer to a bad value. */
    p.placement = (ds_placement)9;
    assert_int_equal(ds_params_check(&p, NULL, NULL, NULL), DS_ERR_ARG);
}

static void test_the_lattice_is_triangular(void **state)
{
    (void)state;
    /* In a dense lattice a disk away from the walls has six neighbours
     * within 1.2 times the closest distance (the next shell is sqrt 3 =
     * 1.73 times farther in a triangular lattice, up to the small strain of
     * a square box), two of them straight along x; fewer only next to one
     * of the empty sites (fewer than one per row: at most ~1 in 32 sites
     * here, each touching six disks). */
    ds_params p = lattice_params(1024, 0.8);
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    const double closest = 2.0 * p.radius * check_inside_and_apart(sim);
    ds_disk d[1024];
    assert_int_equal(ds_sim_get_disks(sim, d, NULL), DS_OK);
    size_t bulk = 0, six = 0;
    for (size_t i = 0; i < 1024; ++i) {
        if (d[i].x < 100.0 || d[i].x > 900.0 || d[i].y < 100.0 || d[i].y > 900.0)
            continue;
        int neighbours = 0, along_x = 0;
        for (size_t j = 0; j < 1024; ++j) {
            const double dx = d[j].x - d[i].x, dy = d[j].y - d[i].y;
            const double r = sqrt(dx * dx + dy * dy);
            if (j != i && r < 1.2 * closest) {
                ++neighbours;
                along_x += fabs(dy) < 1e-9;
            }
        }
        assert_true(neighbours <= 6 && along_x <= 2);
        six += neighbours == 6 && along_x == 2;
        ++bulk;
    }
    assert_true(bulk > 400);
    assert_true((double)six > (1.0 - 6.0 / 32.0) * (double)bulk);
    ds_sim_destroy(sim);
}

static void test_lattice_speeds_are_the_initial_speed_in_random_directions(void **state)
{
    (void)state;
    /* With walls, as random placement: every speed 100, directions
     * uniform, so the mean velocity is ~100 / sqrt(2 N) per component
     * (bounded at 5 of those). */
    const size_t n = 2048;
    ds_params p = lattice_params(n, 0.6);
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    double px = 0.0, py = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const ds_disk d = ds_sim_get_disk(sim, i);
        assert_true(fabs(hypot(d.vx, d.vy) - 100.0) < 1e-9);
    }
    ds_sim_get_momentum(sim, &px, &py);
    const double sigma_mean = 100.0 / sqrt(2.0 * (double)n);
    assert_true(fabs(px / (double)n) < 5.0 * sigma_mean);
    assert_true(fabs(py / (double)n) < 5.0 * sigma_mean);
    ds_sim_destroy(sim);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_dense_lattice_is_inside_and_apart_at_any_density_it_reaches),
        cmocka_unit_test(test_few_disks_spread_over_the_whole_box),
        cmocka_unit_test(test_a_lattice_that_cannot_fit_is_refused_before_creating),
        cmocka_unit_test(test_the_lattice_is_triangular),
        cmocka_unit_test(test_lattice_speeds_are_the_initial_speed_in_random_directions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
