/* SPDX-License-Identifier: MIT */
/* Mixtures: disks of their own radius and mass. Unequal masses collide
 * as the elastic rule says, to rounding, conserving energy and momentum;
 * every broad phase finds the pairs brute force finds (ratios 1.4 and 3,
 * walls and periodic); a dilute binary mixture's pressure has the exact
 * second virial coefficient of mixtures; the energy of a long event-driven
 * run with unequal masses stays put; one kind of disk is the plain
 * simulation to the bit; refusals name the mixture. */
#include "test_util.h"

#include "timestep/broad_phase.h"
#include "timestep/timestep.h"

#define PI 3.14159265358979323846

static ds_sim *pair_sim(ds_integrator integrator, const double r[2], const double m[2])
{
    ds_params p = ds_params_default(2, r[0]);
    p.integrator = integrator;
    p.box = 1e5; /* the two disks alone in the middle */
    ds_mixture mix = {0, NULL, r, m, DS_MASS_EQUAL};
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, &mix, &sim, NULL), DS_OK);
    return sim;
}

static void put(ds_sim *sim, size_t i, double x, double y, double vx, double vy)
{
    const ds_disk d = {x, y, vx, vy};
    assert_int_equal(ds_sim_set_disk(sim, i, d, NULL), DS_OK);
}

/* Within 1e-12 of the speed scale: the rule's few products and sums. */
static void assert_velocity(const ds_sim *sim, size_t i, double vx, double vy)
{
    const ds_disk d = ds_sim_get_disk(sim, i);
    if (fabs(d.vx - vx) > 1e-12 * 100.0 || fabs(d.vy - vy) > 1e-12 * 100.0)
        fail_msg("disk %zu: (%.17g, %.17g), want (%.17g, %.17g)", i, d.vx, d.vy, vx, vy);
}

static void assert_conserved(const ds_sim *sim, double e0, double px0, double py0)
{
    double px, py;
    ds_sim_get_momentum(sim, &px, &py);
    assert_true(fabs(ds_sim_get_kinetic_energy(sim) - e0) <= 1e-12 * e0);
    assert_true(fabs(px - px0) <= 1e-12 * 1e3 && fabs(py - py0) <= 1e-12 * 1e3);
}

/* Head on, masses 1 and 3, radii 5 and 7, speeds 40 and -60 along x:
 * v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2) = (-80 - 360) / 4 = -110,
 * v2' = ((m2 - m1) v2 + 2 m1 v1) / (m1 + m2) = (-120 + 80) / 4 = -10. Both
 * integrators: the line of centres is x however late the time step sees
 * the contact. (Event chains have no velocities to change.) */
static void test_unequal_masses_collide_head_on_as_the_elastic_rule_says(void **state)
{
    (void)state;
    const double r[2] = {5.0, 7.0}, m[2] = {1.0, 3.0};
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ) {
        if (integ == DS_INTEGRATOR_EVENT_CHAIN)
            continue; /* no dynamics, no collisions */
        ds_sim *sim = pair_sim((ds_integrator)integ, r, m);
        put(sim, 0, 50000.0, 50000.0, 40.0, 0.0);
        put(sim, 1, 50020.0, 50000.0, -60.0, 0.0);
        const double e0 = ds_sim_get_kinetic_energy(sim);
        ds_sim_run(sim, 200, NULL);
        assert_int_equal(ds_sim_get_collision_count(sim), 1);
        assert_velocity(sim, 0, -110.0, 0.0);
        assert_velocity(sim, 1, -10.0, 0.0);
        assert_conserved(sim, e0, 40.0 - 180.0, 0.0);
        ds_sim_destroy(sim);
    }
}

/* Oblique, event-driven: disk 0 (R 4, m 2) at rest, disk 1 (R 6, m 0.5)
 * coming along -x with impact parameter b = 6: at contact the line of
 * centres is n = (sqrt(100 - 36), 6) / 10 = (0.8, 0.6). Disk 0 takes
 * 2 m1 / (m0 + m1) (v1 . n) n = 0.4 (-80)(0.8, 0.6) = (-25.6, -19.2), and
 * disk 1 gives 2 m0 / (m0 + m1) times that along n: (-100, 0) - 1.6 (-80)
 * (0.8, 0.6) = (2.4, 76.8). */
static void test_unequal_masses_collide_obliquely_along_the_line_of_centres(void **state)
{
    (void)state;
    const double r[2] = {4.0, 6.0}, m[2] = {2.0, 0.5};
    ds_sim *sim = pair_sim(DS_INTEGRATOR_EVENT_DRIVEN, r, m);
    put(sim, 0, 50000.0, 50000.0, 0.0, 0.0);
    put(sim, 1, 50030.0, 50006.0, -100.0, 0.0);
    const double e0 = ds_sim_get_kinetic_energy(sim);
    ds_sim_run(sim, 500, NULL);
    assert_int_equal(ds_sim_get_collision_count(sim), 1);
    assert_velocity(sim, 0, -25.6, -19.2);
    assert_velocity(sim, 1, 2.4, 76.8);
    assert_conserved(sim, e0, -50.0, 0.0);
    ds_sim_destroy(sim);
}

/* A mixture of n disks, 50:50 radii r and ratio r, masses by area. */
static ds_sim *binary(size_t n, double r, double ratio, double box_y, ds_integrator integ,
                      ds_broadphase bp, ds_boundary boundary, uint64_t seed)
{
    ds_params p = ds_params_default(n, r);
    p.integrator = integ;
    p.broadphase = bp;
    p.boundary = boundary;
    p.box_y = box_y;
    p.seed = seed;
    const ds_species kinds[2] = {{n / 2, r, 0.0, NULL}, {n - n / 2, ratio * r, 0.0, NULL}};
    ds_mixture mix = {2, kinds, NULL, NULL, DS_MASS_AREA};
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, &mix, &sim, NULL), DS_OK);
    return sim;
}

/* ------------------------------------------------------------------ */
/* Every broad phase, the pairs of brute force                          */
/* ------------------------------------------------------------------ */

typedef struct pair_list {
    uint64_t *pairs;
    size_t count, cap;
    double box_x, box_y; /* periodic: the sides for the nearest image; else 0 */
} pair_list;

/* A broad phase reports the pairs closer than the largest diameter; the
 * pair test of a mixture is its own contact distance: kept here as the
 * time step keeps it. */
static void record_touching(ds_disks *d, size_t a, size_t b, void *ctx)
{
    pair_list *list = ctx;
    double dx = d->x[b] - d->x[a], dy = d->y[b] - d->y[a];
    if (list->box_x > 0.0) {
        dx -= list->box_x * round(dx / list->box_x);
        dy -= list->box_y * round(dy / list->box_y);
    }
    const double sigma = d->r[a] + d->r[b];
    if (!(dx * dx + dy * dy < sigma * sigma))
        return;
    if (list->count == list->cap) {
        list->cap = list->cap ? 2 * list->cap : 256;
        list->pairs = realloc(list->pairs, list->cap * sizeof *list->pairs);
        assert_non_null(list->pairs);
    }
    const uint64_t ia = d->id[a], ib = d->id[b];
    list->pairs[list->count++] = ia < ib ? ia << 32 | ib : ib << 32 | ia;
}

static int compare_u64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static pair_list touching(ds_sim *sim, ds_broadphase kind)
{
    const int periodic = ds_sim_get_boundary(sim) == DS_BOUNDARY_PERIODIC;
    pair_list list = {NULL, 0, 0, periodic ? ds_sim_get_box_width(sim) : 0.0,
                      periodic ? ds_sim_get_box_height(sim) : 0.0};
    ds_bp *bp = sim->state;
    const ds_broadphase own = bp->kind;
    bp->kind = kind;
    ds_bp_find_pairs(bp, &sim->disks, record_touching, &list);
    bp->kind = own;
    ds_disks_rebuild_slots(&sim->disks);
    if (list.count)
        qsort(list.pairs, list.count, sizeof *list.pairs, compare_u64);
    return list;
}

static void test_every_broad_phase_finds_the_pairs_of_brute_force(void **state)
{
    (void)state;
    static const double ratios[] = {1.4, 3.0};
    ds_rng rng;
    ds_rng_seed(&rng, 17);
    size_t total = 0;
    for (int k = 0; k < 2; ++k)
        for (int b = 0; b < DS_BOUNDARY_COUNT; ++b)
            for (int s = 0; s < DS_BROADPHASE_COUNT; ++s) {
                /* Every broad phase of the time step against the reference. */
                if (s == DS_BROADPHASE_AUTO || s == DS_BROADPHASE_BRUTE ||
                    !ds_time_step_ops.fits((ds_broadphase)s))
                    continue;
                ds_sim *sim = binary(3000, 2.0, ratios[k], 800.0, DS_INTEGRATOR_TIME_STEP,
                                     (ds_broadphase)s, (ds_boundary)b, 5);
                /* Scatter every disk anywhere (overlaps and all: the time
                 * step takes them), then let them move. */
                for (size_t i = 0; i < ds_sim_get_count(sim); ++i) {
                    const double r = radius_of(sim, i);
                    const double lo = b == DS_BOUNDARY_PERIODIC ? 0.0 : r;
                    ds_disk d = {ds_rng_uniform(&rng, lo, ds_sim_get_box_width(sim) - lo),
                                 ds_rng_uniform(&rng, lo, ds_sim_get_box_height(sim) - lo),
                                 ds_rng_uniform(&rng, -100.0, 100.0),
                                 ds_rng_uniform(&rng, -100.0, 100.0)};
                    assert_int_equal(ds_sim_set_disk(sim, i, d, NULL), DS_OK);
                }
                for (int step = 0; step < 4; ++step) {
                    pair_list got = touching(sim, (ds_broadphase)s);
                    pair_list want = touching(sim, DS_BROADPHASE_BRUTE);
                    assert_int_equal(got.count, want.count);
                    for (size_t p = 0; p < want.count; ++p)
                        assert_true(got.pairs[p] == want.pairs[p]);
                    total += want.count;
                    free(got.pairs);
                    free(want.pairs);
                    ds_sim_run(sim, 5, NULL);
                }
                ds_sim_destroy(sim);
            }
    assert_true(total > 1000); /* not empty cases */
}

/* The event-driven integrator, cells against brute force: the same
 * collisions at the same times, positions equal up to rounding, which
 * collisions amplify, so about 2 collisions per disk. */
static void test_event_cells_follow_brute_force_in_a_mixture(void **state)
{
    (void)state;
    static const double ratios[] = {1.4, 3.0};
    for (int k = 0; k < 2; ++k)
        for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
            ds_sim *cells = binary(300, 8.0, ratios[k], 0.0, DS_INTEGRATOR_EVENT_DRIVEN,
                                   DS_BROADPHASE_CELLS, (ds_boundary)b, 3);
            ds_sim *brute = binary(300, 8.0, ratios[k], 0.0, DS_INTEGRATOR_EVENT_DRIVEN,
                                   DS_BROADPHASE_BRUTE, (ds_boundary)b, 3);
            while (ds_sim_get_collision_count(cells) < 600) {
                ds_sim_step(cells, NULL);
                ds_sim_step(brute, NULL);
                assert_int_equal(ds_sim_get_collision_count(cells),
                                 ds_sim_get_collision_count(brute));
            }
            for (size_t i = 0; i < 300; ++i) {
                const ds_disk c = ds_sim_get_disk(cells, i), d = ds_sim_get_disk(brute, i);
                assert_true(fabs(c.x - d.x) < 1e-6 && fabs(c.y - d.y) < 1e-6);
            }
            /* And no pair closer than its contact distance. */
            ds_disk all[300];
            assert_int_equal(ds_sim_get_disks(cells, all, NULL), DS_OK);
            assert_int_equal(ds_sim_set_disks(cells, all, NULL), DS_OK);
            ds_sim_destroy(cells);
            ds_sim_destroy(brute);
        }
}

/* ------------------------------------------------------------------ */
/* Pressure and energy                                                  */
/* ------------------------------------------------------------------ */

/* Z = P A / (N kT) = 1 + B2 rho + B3 rho^2 + ..., and for a mixture
 * B2 = (pi / 2) sum_ij x_i x_j sigma_ij^2, sigma_ij = r_i + r_j. A dilute
 * 50:50 mixture of ratio 1.4, periodic, event-driven. The B3 term is
 * bounded with the one-kind ratio B3 / B2^2 = 4/3 - sqrt(3)/pi = 0.782,
 * taken twice for the mixture's asymmetry; the statistical error from 10
 * blocks (each many sound crossings of the box). N kT is the kinetic
 * energy (zero total momentum: the canonical temperature of the pair's
 * motion differs by 1/N, 2e-4 here, far below the tolerance). */
static void test_a_dilute_mixture_has_the_second_virial_coefficient_of_mixtures(void **state)
{
    (void)state;
    const size_t n = 4000;
    const double r = 1.0, ratio = 1.4; /* area fraction 0.019 */
    ds_sim *sim = binary(n, r, ratio, 0.0, DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_AUTO,
                         DS_BOUNDARY_PERIODIC, 21);
    const double sigma[3] = {2.0 * r, r + ratio * r, 2.0 * ratio * r}; /* 11, 12, 22 */
    const double b2 =
        PI / 2.0 *
        (0.25 * sigma[0] * sigma[0] + 0.5 * sigma[1] * sigma[1] + 0.25 * sigma[2] * sigma[2]);
    const double rho = (double)n / (ds_sim_get_box_width(sim) * ds_sim_get_box_height(sim));
    const double expected = b2 * rho; /* Z - 1 to first order */
    ds_sim_run(sim, 2000, NULL);
    const int blocks = quick_mode() ? 4 : 10;
    double sum = 0.0, sum2 = 0.0;
    for (int k = 0; k < blocks; ++k) {
        ds_sim_reset_observables(sim);
        ds_sim_run(sim, quick_mode() ? 2000 : 5000, NULL);
        const double z = ds_sim_get_virial_pressure(sim) * ds_sim_get_box_width(sim) *
                             ds_sim_get_box_height(sim) / ds_sim_get_kinetic_energy(sim) -
                         1.0;
        sum += z;
        sum2 += z * z;
    }
    const double mean = sum / blocks;
    const double error = sqrt(fmax(sum2 / blocks - mean * mean, 0.0) / (blocks - 1));
    const double third = 2.0 * 0.782 * expected * expected;
    print_message("Z - 1 = %.6f +- %.6f, B2 rho = %.6f (B3 bound %.6f)\n", mean, error, expected,
                  third);
    assert_true(fabs(mean - expected) < third + 4.0 * error);
    assert_true(error < 0.05 * expected); /* a measurement, not noise */
    ds_sim_destroy(sim);
}

/* Masses 1 and 9 (ratio 3, by area), walls and periodic: the energy of an
 * event-driven run is conserved to rounding, 1e-12 relative, over 10^6
 * collisions (each exchange is exact to a few ulps; the errors add as a
 * random walk, ~1e-16 sqrt(1e6) = 1e-13). */
static void test_energy_is_conserved_over_a_million_collisions_with_unequal_masses(void **state)
{
    (void)state;
    const uint64_t target = quick_mode() ? 20000 : 1000000;
    ds_sim *sim = binary(2000, 4.0, 3.0, 0.0, DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_AUTO,
                         DS_BOUNDARY_WALLS, 8);
    const double e0 = ds_sim_get_kinetic_energy(sim);
    while (ds_sim_get_collision_count(sim) < target)
        ds_sim_run(sim, 100, NULL);
    const double e1 = ds_sim_get_kinetic_energy(sim);
    print_message("%llu collisions: energy %.17g -> %.17g\n",
                  (unsigned long long)ds_sim_get_collision_count(sim), e0, e1);
    assert_true(fabs(e1 - e0) <= 1e-12 * e0);
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* One kind, placement, refusals                                        */
/* ------------------------------------------------------------------ */

static void test_one_kind_is_the_plain_simulation_to_the_bit(void **state)
{
    (void)state;
    for (int integ = 0; integ < DS_INTEGRATOR_COUNT; ++integ) {
        ds_params p = ds_params_default(400, 5.0);
        p.integrator = (ds_integrator)integ;
        const ds_species one = {400, 5.0, 0.0, NULL};
        ds_mixture mix = {1, &one, NULL, NULL, DS_MASS_AREA};
        ds_sim *plain = NULL, *mixed = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &plain, NULL), DS_OK);
        assert_int_equal(ds_sim_create(&p, &mix, &mixed, NULL), DS_OK);
        ds_sim_run(plain, 1000, NULL);
        ds_sim_run(mixed, 1000, NULL);
        char a[65536], b[65536];
        size_t la = 0, lb = 0;
        assert_int_equal(ds_frame_format(plain, 1, a, sizeof a, &la, NULL), DS_OK);
        assert_int_equal(ds_frame_format(mixed, 1, b, sizeof b, &lb, NULL), DS_OK);
        assert_int_equal(la, lb);
        assert_memory_equal(a, b, la);
        assert_true(ds_sim_get_pressure(plain) == ds_sim_get_pressure(mixed));
        /* n pi R^2 as one product, not a sum of n terms (which differed
         * in its last bits). */
        const double eta_plain = ds_sim_get_area_fraction(plain),
                     eta_mixed = ds_sim_get_area_fraction(mixed);
        assert_memory_equal(&eta_plain, &eta_mixed, sizeof eta_plain);
        ds_sim_destroy(plain);
        ds_sim_destroy(mixed);
    }
}

/* Every disk inside the box at its own radius, none overlapping, masses
 * (r / R)^2, the frames' third column each disk's radius. */
static void test_a_random_mixture_is_placed_inside_and_apart(void **state)
{
    (void)state;
    for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
        ds_sim *sim = binary(2000, 6.0, 1.4, 0.0, DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_AUTO,
                             (ds_boundary)b, 4);
        ds_disk all[2000];
        assert_int_equal(ds_sim_get_disks(sim, all, NULL), DS_OK);
        /* Inside and apart: what ds_sim_set_disks checks. */
        assert_int_equal(ds_sim_set_disks(sim, all, NULL), DS_OK);
        assert_true(fabs(mass_of(sim, 1999) - 1.96) < 1e-15);
        assert_true(mass_of(sim, 0) == 1.0);
        assert_true(radius_of(sim, 1999) == 6.0 * 1.4 && ds_sim_get_radius_max(sim) == 6.0 * 1.4);
        const double eta = 1000.0 * PI * (36.0 + 36.0 * 1.96) / 1e6;
        assert_true(fabs(ds_sim_get_area_fraction(sim) - eta) < 1e-12);
        /* The frame's third column reads back as each disk's radius. */
        static char text[200000];
        size_t len = 0;
        assert_int_equal(ds_frame_format(sim, 0, text, sizeof text, &len, NULL), DS_OK);
        ds_frame frame;
        assert_int_equal(ds_frame_parse(text, len, &frame, NULL), DS_OK);
        assert_int_equal(frame.count, 2000);
        for (size_t i = 0; i < 2000; ++i)
            assert_true(frame.disks[i].r == radius_of(sim, i));
        ds_frame_free(&frame);
        ds_sim_destroy(sim);
    }
}

static void test_a_bad_mixture_is_refused_with_its_reason(void **state)
{
    (void)state;
    ds_params p = ds_params_default(10, 5.0);
    ds_error why;
    ds_species kinds[2] = {{4, 5.0, 0.0, NULL}, {5, 7.0, 0.0, NULL}};
    ds_mixture mix = {2, kinds, NULL, NULL, DS_MASS_EQUAL};
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "mixture");
    assert_non_null(strstr(why.message, "add up to 9, not n = 10"));
    kinds[1].count = 6;
    kinds[1].radius = NAN;
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    kinds[1].radius = 600.0;
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    assert_non_null(strstr(why.message, "largest radius"));
    kinds[1].radius = 7.0;
    kinds[1].mass = -1.0;
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    kinds[1].mass = 0.0;
    mix.mass_rule = (ds_mass_rule)7;
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    mix.mass_rule = DS_MASS_AREA;
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_OK);
    const double radii[10] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    /* Masses per disk beside species were ignored without a word: each
     * species gives its mass. */
    const double masses[10] = {1, 1, 1, 1, 1, 2, 2, 2, 2, 2};
    mix.masses = masses;
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "mixture");
    assert_non_null(strstr(why.message, "masses per disk go with radii per disk"));
    ds_sim *refused = (ds_sim *)1;
    assert_int_equal(ds_sim_create(&p, &mix, &refused, NULL), DS_ERR_ARG);
    assert_null(refused);
    mix.masses = NULL;
    mix.radii = radii; /* both forms */
    assert_int_equal(ds_params_check(&p, &mix, NULL, &why), DS_ERR_ARG);
    ds_mixture per_disk = {0, NULL, radii, NULL, DS_MASS_EQUAL};
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, &per_disk, &sim, NULL), DS_OK);
    assert_true(radius_of(sim, 9) == 10.0 && mass_of(sim, 9) == 1.0);
    ds_sim_destroy(sim);
    /* Many disks beyond random placement's reach, counted with each
     * radius. */
    ds_params many = ds_params_default(4000, 6.0);
    const ds_species dense[2] = {{2000, 6.0, 0.0, NULL}, {2000, 8.4, 0.0, NULL}};
    ds_mixture big = {2, dense, NULL, NULL, DS_MASS_EQUAL};
    assert_int_equal(ds_params_check(&many, &big, NULL, &why), DS_ERR_PLACEMENT);
    assert_non_null(strstr(why.message, "radii 6 to 8.4"));
}

/* With walls a disk's centre stays its own radius from each wall, as
 * ds_sim_set_disk's contract says: a large disk of a mixture is refused where a
 * small one (of the reference R) is taken, on each side and with either
 * integrator, and ds_sim_set_disks names the radius. */
static void test_set_keeps_a_mixture_disk_its_own_radius_from_the_walls(void **state)
{
    (void)state;
    const double r[2] = {3.0, 7.0};
    for (int integrator = 0; integrator < DS_INTEGRATOR_COUNT; ++integrator) {
        ds_params p = ds_params_default(2, r[0]);
        p.integrator = (ds_integrator)integrator;
        p.box = 200.0;
        p.box_y = 150.0;
        ds_mixture mix = {0, NULL, r, NULL, DS_MASS_EQUAL};
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, &mix, &sim, NULL), DS_OK);
        put(sim, 0, 100.0, 75.0, 1.0, 0.0); /* out of the way, in the middle */
        const ds_disk inside[4] = {
            {7.0, 40.0, 0, 0}, {193.0, 40.0, 0, 0}, {40.0, 7.0, 0, 0}, {40.0, 143.0, 0, 0}};
        const ds_disk within_r_not_7[4] = {
            {5.0, 40.0, 0, 0}, {195.0, 40.0, 0, 0}, {40.0, 5.0, 0, 0}, {40.0, 145.0, 0, 0}};
        for (int k = 0; k < 4; ++k) {
            assert_int_equal(ds_sim_set_disk(sim, 1, inside[k], NULL), DS_OK);
            assert_int_equal(ds_sim_set_disk(sim, 1, within_r_not_7[k], NULL), DS_ERR_ARG);
            put(sim, 1, 150.0, 75.0, 0.0, 1.0);
            /* The small disk, of R = 3, fits there. */
            put(sim, 0, within_r_not_7[k].x, within_r_not_7[k].y, 0.0, 0.0);
            put(sim, 0, 100.0, 75.0, 1.0, 0.0);
        }
        ds_disk all[2] = {{100.0, 75.0, 1.0, 0.0}, within_r_not_7[0]};
        ds_error why;
        assert_int_equal(ds_sim_set_disks(sim, all, &why), DS_ERR_ARG);
        assert_non_null(strstr(why.message, "[7, 193] x [7, 143]"));
        ds_sim_destroy(sim);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_unequal_masses_collide_head_on_as_the_elastic_rule_says),
        cmocka_unit_test(test_unequal_masses_collide_obliquely_along_the_line_of_centres),
        cmocka_unit_test(test_every_broad_phase_finds_the_pairs_of_brute_force),
        cmocka_unit_test(test_event_cells_follow_brute_force_in_a_mixture),
        cmocka_unit_test(test_a_dilute_mixture_has_the_second_virial_coefficient_of_mixtures),
        cmocka_unit_test(test_energy_is_conserved_over_a_million_collisions_with_unequal_masses),
        cmocka_unit_test(test_one_kind_is_the_plain_simulation_to_the_bit),
        cmocka_unit_test(test_a_random_mixture_is_placed_inside_and_apart),
        cmocka_unit_test(test_set_keeps_a_mixture_disk_its_own_radius_from_the_walls),
        cmocka_unit_test(test_a_bad_mixture_is_refused_with_its_reason),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
