/* SPDX-License-Identifier: MIT */
/* Every allocation of the library fails in turn: the k-th call of malloc,
 * calloc, realloc, posix_memalign or aligned_alloc made inside an
 * operation returns nothing (alone, or with every call after it: memory
 * that stays short), for k = 1, 2, ... until the operation makes fewer
 * than k calls. The operations are creation (ds_sim_create: both
 * integrators, every boundary, both placements, every broad phase, one
 * kind and mixtures), growth (ds_sim_set_growth, and a run in which growth
 * builds its state again), checkpoints (ds_checkpoint_parse, ds_checkpoint_load),
 * ds_sim_set_disks and the granular setters. Each time the operation either refuses with
 * DS_ERR_NOMEM, leaving no simulation or one that steps on exactly as if
 * it had never been called, or does what it does without the failure
 * (a fallback), to the bit; a growing run that cannot widen its cells
 * returns DS_ERR_NOMEM at the end of a whole step: there growth stops,
 * says so (DS_GROWTH_NONE), and the simulation runs on sound. A plain run
 * allocates nothing.
 *
 * The calls are counted by the linker (-Wl,--wrap=malloc,...: the
 * Makefile's rule for this test), and the library's large arrays come
 * from posix_memalign (core/large_alloc.c; it maps no memory itself).
 * Under AddressSanitizer (make test SANITIZE=1) a read of what a failed
 * path freed, or a leak, ends the test. */
#include <errno.h>

#include "test_util.h"

/* ------------------------------------------------------------------ */
/* The counting wrapper                                                 */
/* ------------------------------------------------------------------ */

void *__real_malloc(size_t size);
void *__real_calloc(size_t count, size_t size);
void *__real_realloc(void *p, size_t size);
int __real_posix_memalign(void **p, size_t align, size_t size);
void *__real_aligned_alloc(size_t align, size_t size);

static struct {
    int armed;
    int persistent; /* every call from fail_at on fails, not that one alone */
    unsigned long calls, fail_at;
    int failed; /* a call failed since arming */
} inject;

/* Counts the calls made while armed (fail_at 0: never fail) and fails
 * the fail_at-th, and with persistent every one after it. */
static int fail_now(void)
{
    if (!inject.armed)
        return 0;
    ++inject.calls;
    const int fail = inject.fail_at != 0 && (inject.calls == inject.fail_at ||
                                             (inject.persistent && inject.calls > inject.fail_at));
    inject.failed |= fail;
    return fail;
}

void *__wrap_malloc(size_t size);
void *__wrap_malloc(size_t size) { return fail_now() ? NULL : __real_malloc(size); }
void *__wrap_calloc(size_t count, size_t size);
void *__wrap_calloc(size_t count, size_t size)
{
    return fail_now() ? NULL : __real_calloc(count, size);
}
void *__wrap_realloc(void *p, size_t size);
void *__wrap_realloc(void *p, size_t size) { return fail_now() ? NULL : __real_realloc(p, size); }
int __wrap_posix_memalign(void **p, size_t align, size_t size);
int __wrap_posix_memalign(void **p, size_t align, size_t size)
{
    return fail_now() ? ENOMEM : __real_posix_memalign(p, align, size);
}
void *__wrap_aligned_alloc(size_t align, size_t size);
void *__wrap_aligned_alloc(size_t align, size_t size)
{
    return fail_now() ? NULL : __real_aligned_alloc(align, size);
}

static void arm(unsigned long fail_at, int persistent)
{
    inject.calls = 0;
    inject.fail_at = fail_at;
    inject.persistent = persistent;
    inject.failed = 0;
    inject.armed = 1;
}

/* Whether a call failed since arm. */
static int disarm(void)
{
    inject.armed = 0;
    return inject.failed;
}

/* The calls an operation makes: armed, never failing. */
static unsigned long calls_counted(void)
{
    inject.armed = 0;
    return inject.calls;
}

/* ------------------------------------------------------------------ */
/* Simulations and what they show                                       */
/* ------------------------------------------------------------------ */

typedef struct config {
    const char *name;
    ds_integrator integrator;
    ds_boundary boundary;
    ds_broadphase broadphase;
    ds_placement placement;
    int mixture; /* 0 none, 1 two species, 2 radii and masses per disk */
} config;

#define N_DISKS 40

static const config configs[] = {
    {"step walls sap", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_WALLS, DS_BROADPHASE_SAP,
     DS_PLACEMENT_RANDOM, 0},
    {"step walls brute", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_WALLS, DS_BROADPHASE_BRUTE,
     DS_PLACEMENT_RANDOM, 0},
    {"step walls strips", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_WALLS, DS_BROADPHASE_STRIPS,
     DS_PLACEMENT_RANDOM, 0},
    {"step periodic sap", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_SAP,
     DS_PLACEMENT_RANDOM, 0},
    {"step periodic brute", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_BRUTE,
     DS_PLACEMENT_RANDOM, 0},
    {"step periodic strips", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_STRIPS,
     DS_PLACEMENT_LATTICE, 0},
    {"step periodic strips, species", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_PERIODIC,
     DS_BROADPHASE_STRIPS, DS_PLACEMENT_RANDOM, 1},
    {"step walls sap, per disk", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_WALLS, DS_BROADPHASE_SAP,
     DS_PLACEMENT_LATTICE, 2},
    {"event walls cells", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS, DS_BROADPHASE_CELLS,
     DS_PLACEMENT_RANDOM, 0},
    {"event walls brute", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS, DS_BROADPHASE_BRUTE,
     DS_PLACEMENT_LATTICE, 0},
    {"event periodic cells", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_CELLS,
     DS_PLACEMENT_RANDOM, 0},
    {"event periodic brute", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_BRUTE,
     DS_PLACEMENT_RANDOM, 0},
    {"event periodic cells, lattice", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC,
     DS_BROADPHASE_CELLS, DS_PLACEMENT_LATTICE, 0},
    {"event periodic cells, species", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC,
     DS_BROADPHASE_CELLS, DS_PLACEMENT_RANDOM, 1},
    {"event walls cells, per disk", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_WALLS,
     DS_BROADPHASE_CELLS, DS_PLACEMENT_RANDOM, 2},
    {"step channel strips, species", DS_INTEGRATOR_TIME_STEP, DS_BOUNDARY_CHANNEL,
     DS_BROADPHASE_STRIPS, DS_PLACEMENT_RANDOM, 1},
    {"event channel cells, species", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_CHANNEL,
     DS_BROADPHASE_CELLS, DS_PLACEMENT_LATTICE, 1},
};
#define CONFIGS (sizeof configs / sizeof configs[0])

static ds_params params_of(const config *c)
{
    /* Area fraction 0.11, each disk moving 1 (a 30th of its radius) a
     * step: some 20 collisions in GO_ON steps. */
    ds_params p = ds_params_default(N_DISKS, 30.0);
    p.dt = 0.01;
    p.integrator = c->integrator;
    p.boundary = c->boundary;
    p.broadphase = c->broadphase;
    p.placement = c->placement;
    p.seed = 11;
    return p;
}

/* The mixture of c: 1:1.4 in two species, or radii and masses disk by
 * disk. */
static ds_species kinds[2] = {{N_DISKS / 2, 25.0, 0.0, NULL},
                              {N_DISKS - N_DISKS / 2, 35.0, 0.0, NULL}};
static double radii[N_DISKS], masses[N_DISKS];
static ds_mixture mixture_of(const config *c)
{
    for (size_t i = 0; i < N_DISKS; ++i) {
        radii[i] = 20.0 + (double)(i % 5) * 3.0;
        masses[i] = 1.0 + (double)(i % 3);
    }
    ds_mixture m = {0, NULL, NULL, NULL, DS_MASS_AREA};
    if (c->mixture == 1) {
        m.species = 2;
        m.kinds = kinds;
    } else {
        m.radii = radii;
        m.masses = masses;
    }
    return m;
}

static ds_status create(const config *c, ds_sim **out)
{
    const ds_params p = params_of(c);
    if (!c->mixture)
        return ds_sim_create(&p, NULL, out, NULL);
    const ds_mixture m = mixture_of(c);
    return ds_sim_create(&p, &m, out, NULL);
}

static ds_sim *created(const config *c)
{
    ds_sim *sim = NULL;
    assert_int_equal(create(c, &sim), DS_OK);
    return sim;
}

/* A checkpoint in memory, and simulations from it (never failing). */
typedef struct bytes {
    uint8_t *p;
    size_t len;
} bytes;

static bytes saved(const ds_sim *sim)
{
    bytes b = {NULL, ds_checkpoint_get_size(sim)};
    b.p = malloc(b.len);
    assert_non_null(b.p);
    assert_int_equal(ds_checkpoint_format(sim, b.p, b.len, NULL, NULL), DS_OK);
    return b;
}

static ds_sim *loaded(bytes b)
{
    ds_sim *sim = NULL;
    ds_error err;
    if (ds_checkpoint_parse(b.p, b.len, &sim, &err) != DS_OK)
        fail_msg("a checkpoint of %zu bytes was refused: %s", b.len, err.message);
    return sim;
}

/* What a simulation shows, to the bit. */
typedef struct shown {
    size_t n;
    ds_disk disk[N_DISKS];
    double radius[N_DISKS];
    int32_t image[2 * N_DISKS];
    uint64_t steps, collisions;
    ds_growth_state growth;
    double area_fraction;
} shown;

static shown show(const ds_sim *sim)
{
    shown s;
    memset(&s, 0, sizeof s);
    s.n = ds_sim_get_count(sim);
    assert_true(s.n <= N_DISKS);
    assert_int_equal(ds_sim_get_disks(sim, s.disk, NULL), DS_OK);
    assert_int_equal(ds_sim_get_radii(sim, s.radius, NULL), DS_OK);
    assert_int_equal(ds_sim_get_images(sim, s.image, NULL), DS_OK);
    s.steps = ds_sim_get_steps(sim);
    s.collisions = ds_sim_get_collision_count(sim);
    s.growth = ds_sim_get_growth_state(sim);
    s.area_fraction = ds_sim_get_area_fraction(sim);
    return s;
}

static int same(const shown *a, const shown *b)
{
    return a->n == b->n && memcmp(a->disk, b->disk, sizeof a->disk) == 0 &&
           memcmp(a->radius, b->radius, sizeof a->radius) == 0 &&
           memcmp(a->image, b->image, sizeof a->image) == 0 && a->steps == b->steps &&
           a->collisions == b->collisions && a->growth == b->growth &&
           a->area_fraction == b->area_fraction;
}

static void assert_shows(const ds_sim *sim, const shown *expected, const char *what,
                         unsigned long k)
{
    const shown s = show(sim);
    if (!same(&s, expected))
        fail_msg("%s, allocation %lu failing: the run differs from one without the failure", what,
                 k);
}

/* sim, run on by steps, shows what `expected` showed. */
static void assert_goes_on_as(ds_sim *sim, uint64_t steps, const shown *expected, const char *what,
                              unsigned long k)
{
    ds_sim_run(sim, steps, NULL);
    assert_shows(sim, expected, what, k);
}

/* sim is, to the bit, the simulation checkpoint b holds. */
static void assert_unchanged(const ds_sim *sim, bytes b, const char *what, unsigned long k)
{
    bytes now = saved(sim);
    if (now.len != b.len || memcmp(now.p, b.p, b.len) != 0)
        fail_msg("%s, allocation %lu failing: refused, but the simulation changed", what, k);
    free(now.p);
}

/* What sim shows after steps more steps, sim itself unchanged (a copy
 * through a checkpoint runs). */
static shown shown_after(const ds_sim *sim, uint64_t steps)
{
    bytes b = saved(sim);
    ds_sim *copy = loaded(b);
    free(b.p);
    ds_sim_run(copy, steps, NULL);
    const shown s = show(copy);
    ds_sim_destroy(copy);
    return s;
}

#define GO_ON 100 /* steps run after each operation to compare */

/* ------------------------------------------------------------------ */
/* Soundness, where the run cannot be compared to one without failure  */
/* ------------------------------------------------------------------ */

/* Every disk finite and in the box, and no two overlapping (nearest
 * image; within DS_CONTACT_TOLERANCE and the rounding of the centres). */
static void assert_sound(const ds_sim *sim, const char *what, unsigned long k)
{
    const shown s = show(sim);
    const double bx = ds_sim_get_box_width(sim), by = ds_sim_get_box_height(sim);
    const ds_boundary boundary = ds_sim_get_boundary(sim);
    const int px = boundary != DS_BOUNDARY_WALLS, py = boundary == DS_BOUNDARY_PERIODIC;
    const double past = 1e-9 * fmax(bx, by); /* a centre shown a hair past its wall turn */
    for (size_t i = 0; i < s.n; ++i) {
        const ds_disk d = s.disk[i];
        const double r = s.radius[i];
        const int inside =
            (px ? d.x >= 0.0 && d.x < bx : d.x >= r - past && d.x <= bx - r + past) &&
            (py ? d.y >= 0.0 && d.y < by : d.y >= r - past && d.y <= by - r + past);
        if (!isfinite(d.vx) || !isfinite(d.vy) || !inside)
            fail_msg("%s, allocation %lu failing: disk %zu at (%g, %g) is not in the box", what, k,
                     i, d.x, d.y);
    }
    if (ds_sim_get_integrator(sim) != DS_INTEGRATOR_EVENT_DRIVEN)
        return; /* the time step resolves its overlaps a step late */
    for (size_t i = 0; i < s.n; ++i)
        for (size_t j = i + 1; j < s.n; ++j) {
            double dx = s.disk[j].x - s.disk[i].x, dy = s.disk[j].y - s.disk[i].y;
            if (px)
                dx -= bx * round(dx / bx);
            if (py)
                dy -= by * round(dy / by);
            const double gap = sqrt(dx * dx + dy * dy) / (s.radius[i] + s.radius[j]) - 1.0;
            if (gap < -1e-9)
                fail_msg("%s, allocation %lu failing: disks %zu and %zu overlap by %g", what, k, i,
                         j, -gap);
        }
}

/* ------------------------------------------------------------------ */
/* Creation                                                             */
/* ------------------------------------------------------------------ */

/* The k-th allocation of ds_sim_create (or ds_sim_create) fails, for
 * every k, alone or with the rest: DS_ERR_NOMEM and no simulation, or the
 * simulation of a creation without failure (the time step's sort has an
 * in-place fallback), which then runs the same to the bit. */
static void test_creation_survives_every_failed_allocation(void **state)
{
    (void)state;
    static int not_null;
    for (size_t c = 0; c < CONFIGS; ++c) {
        ds_sim *ref = created(&configs[c]);
        const shown expected = shown_after(ref, GO_ON);
        ds_sim_destroy(ref);
        arm(0, 0);
        ds_sim *sim = NULL;
        assert_int_equal(create(&configs[c], &sim), DS_OK);
        const unsigned long calls = calls_counted();
        ds_sim_destroy(sim);
        for (int persistent = 0; persistent <= 1; ++persistent)
            for (unsigned long k = 1; k <= calls; ++k) {
                sim = (ds_sim *)&not_null; /* the refusal must clear it */
                arm(k, persistent);
                const ds_status st = create(&configs[c], &sim);
                assert_true(disarm());
                if (st == DS_ERR_NOMEM) {
                    assert_null(sim);
                    continue;
                }
                assert_int_equal(st, DS_OK);
                assert_goes_on_as(sim, GO_ON, &expected, configs[c].name, k);
                ds_sim_destroy(sim);
            }
        print_message("%-32s create: %lu allocations\n", configs[c].name, calls);
    }
}

/* A run of a simulation that does not grow allocates nothing: ds_sim_run
 * returns no status, and needs none. */
static void test_a_plain_run_allocates_nothing(void **state)
{
    (void)state;
    for (size_t c = 0; c < CONFIGS; ++c) {
        ds_sim *sim = created(&configs[c]);
        arm(0, 0);
        ds_sim_run(sim, 200, NULL);
        assert_int_equal(calls_counted(), 0);
        ds_sim_destroy(sim);
    }
}

/* Nor does predicting every disk again, which growth does at each
 * window, and ds_sim_set_disk and ds_sim_scale_velocities and a new ds_sim_set_growth do
 * while it grows: none of them can fail. (Brute force's one cell never
 * needs a new state with wider cells.) */
static void test_predicting_everyone_again_allocates_nothing(void **state)
{
    (void)state;
    const config c = {"event periodic brute", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC,
                      DS_BROADPHASE_BRUTE,    DS_PLACEMENT_RANDOM,        0};
    ds_sim *sim = created(&c);
    assert_int_equal(ds_sim_set_growth(sim, 0.05, 0.5, 0.0, NULL), DS_OK);
    arm(0, 0);
    ds_sim_run(sim, 2000, NULL); /* to about 0.4, through windows of 2 n collisions */
    assert_true(ds_sim_get_growth_z(sim) > 1.0); /* a window was watched */
    assert_int_equal(ds_sim_set_disk(sim, 0, ds_sim_get_disk(sim, 0), NULL), DS_OK);
    assert_int_equal(ds_sim_scale_velocities(sim, 1.01, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, 0.04, 0.5, 0.0, NULL), DS_OK);
    ds_sim_run(sim, 10, NULL);
    assert_int_equal(calls_counted(), 0);
    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_GROWING);
    print_message("a growing run: %llu collisions, area fraction %.3f\n",
                  (unsigned long long)ds_sim_get_collision_count(sim),
                  ds_sim_get_area_fraction(sim));
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* Checkpoints                                                          */
/* ------------------------------------------------------------------ */

/* ds_checkpoint_parse and ds_checkpoint_load with the k-th allocation failing:
 * DS_ERR_NOMEM and no simulation, or the simulation saved; for every
 * configuration, growing or not. */
static void check_loading(ds_sim *source, const char *what)
{
    bytes b = saved(source);
    const shown expected = shown_after(source, GO_ON);
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(fwrite(b.p, 1, b.len, f), b.len);
    for (int from_file = 0; from_file <= 1; ++from_file) {
        ds_sim *sim = NULL;
        ds_error err;
        rewind(f);
        arm(0, 0);
        assert_int_equal(from_file ? ds_checkpoint_load(f, &sim, &err)
                                   : ds_checkpoint_parse(b.p, b.len, &sim, &err),
                         DS_OK);
        const unsigned long calls = calls_counted();
        ds_sim_destroy(sim);
        for (int persistent = 0; persistent <= 1; ++persistent)
            for (unsigned long k = 1; k <= calls; ++k) {
                rewind(f);
                arm(k, persistent);
                const ds_status st = from_file ? ds_checkpoint_load(f, &sim, &err)
                                               : ds_checkpoint_parse(b.p, b.len, &sim, &err);
                assert_true(disarm());
                if (st == DS_ERR_NOMEM) {
                    assert_null(sim);
                    assert_true(err.message[0] != '\0');
                    continue;
                }
                assert_int_equal(st, DS_OK);
                assert_goes_on_as(sim, GO_ON, &expected, what, k);
                ds_sim_destroy(sim);
            }
        print_message("%-32s %s: %lu allocations\n", what,
                      from_file ? "ds_checkpoint_load" : "ds_checkpoint_parse", calls);
    }
    fclose(f);
    free(b.p);
}

static void test_loading_a_checkpoint_survives_every_failed_allocation(void **state)
{
    (void)state;
    for (size_t c = 0; c < CONFIGS; ++c) {
        ds_sim *sim = created(&configs[c]);
        ds_sim_run(sim, 7, NULL);
        check_loading(sim, configs[c].name);
        ds_sim_destroy(sim);
    }
}

/* ------------------------------------------------------------------ */
/* ds_sim_set_disks                                                           */
/* ------------------------------------------------------------------ */

/* ds_sim_set_disks with the k-th allocation failing: DS_ERR_NOMEM with the
 * reason, and the simulation goes on as if it had not been called; or
 * it goes on as after a ds_sim_set_disks without failure. The new state is the
 * simulation's own some steps on (one that fits its box and radii). */
static void test_set_all_survives_every_failed_allocation(void **state)
{
    (void)state;
    for (size_t c = 0; c < CONFIGS; ++c) {
        ds_sim *sim = created(&configs[c]);
        ds_sim *later = created(&configs[c]);
        ds_sim_run(later, 50, NULL);
        ds_disk next[N_DISKS];
        assert_int_equal(ds_sim_get_disks(later, next, NULL), DS_OK);
        ds_sim_destroy(later);
        ds_sim_run(sim, 5, NULL);
        bytes b = saved(sim);
        const shown unchanged = shown_after(sim, GO_ON);
        assert_int_equal(ds_sim_set_disks(sim, next, NULL), DS_OK);
        const shown set = shown_after(sim, GO_ON);
        ds_sim_destroy(sim);
        sim = loaded(b);
        arm(0, 0);
        assert_int_equal(ds_sim_set_disks(sim, next, NULL), DS_OK);
        const unsigned long calls = calls_counted();
        ds_sim_destroy(sim);
        for (int persistent = 0; persistent <= 1; ++persistent)
            for (unsigned long k = 1; k <= calls; ++k) {
                sim = loaded(b);
                ds_error err;
                arm(k, persistent);
                const ds_status st = ds_sim_set_disks(sim, next, &err);
                assert_true(disarm());
                if (st == DS_ERR_NOMEM) {
                    assert_true(err.message[0] != '\0');
                    assert_unchanged(sim, b, configs[c].name, k);
                    assert_goes_on_as(sim, GO_ON, &unchanged, configs[c].name, k);
                } else {
                    assert_int_equal(st, DS_OK);
                    assert_goes_on_as(sim, GO_ON, &set, configs[c].name, k);
                }
                ds_sim_destroy(sim);
            }
        free(b.p);
        print_message("%-32s ds_sim_set_disks: %lu allocations\n", configs[c].name, calls);
    }
}

/* ------------------------------------------------------------------ */
/* Growth                                                               */
/* ------------------------------------------------------------------ */

/* Growth runs event-driven in a periodic box: of one radius (which
 * growth gives an array of radii) and a mixture. */
static const config growing[] = {
    {"event periodic cells", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_CELLS,
     DS_PLACEMENT_RANDOM, 0},
    {"event periodic brute", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC, DS_BROADPHASE_BRUTE,
     DS_PLACEMENT_RANDOM, 0},
    {"event periodic cells, species", DS_INTEGRATOR_EVENT_DRIVEN, DS_BOUNDARY_PERIODIC,
     DS_BROADPHASE_CELLS, DS_PLACEMENT_RANDOM, 1},
};
#define GROWING (sizeof growing / sizeof growing[0])
#define RATE 0.5        /* relative, per time unit: radii 5% larger in 0.1 */
#define UNTIL_ETA 0.3   /* from about 0.11, at t = 1.3 */
#define GROWTH_STEPS 40 /* at dt 0.01: three or four new states for wider cells */

/* ds_sim_set_growth with the k-th allocation failing: DS_ERR_NOMEM and the
 * simulation goes on as if it had not been asked, or it grows as without
 * the failure. */
static void test_starting_growth_survives_every_failed_allocation(void **state)
{
    (void)state;
    for (size_t c = 0; c < GROWING; ++c) {
        ds_sim *sim = created(&growing[c]);
        ds_sim_run(sim, 5, NULL);
        bytes b = saved(sim);
        const shown unchanged = shown_after(sim, GO_ON);
        assert_int_equal(ds_sim_set_growth(sim, RATE, UNTIL_ETA, 0.0, NULL), DS_OK);
        const shown grown = shown_after(sim, GO_ON);
        assert_int_equal(grown.growth, DS_GROWTH_GROWING);
        ds_sim_destroy(sim);
        sim = loaded(b);
        arm(0, 0);
        assert_int_equal(ds_sim_set_growth(sim, RATE, UNTIL_ETA, 0.0, NULL), DS_OK);
        const unsigned long calls = calls_counted();
        ds_sim_destroy(sim);
        for (int persistent = 0; persistent <= 1; ++persistent)
            for (unsigned long k = 1; k <= calls; ++k) {
                sim = loaded(b);
                arm(k, persistent);
                const ds_status st = ds_sim_set_growth(sim, RATE, UNTIL_ETA, 0.0, NULL);
                assert_true(disarm());
                if (st == DS_ERR_NOMEM) {
                    assert_unchanged(sim, b, growing[c].name, k);
                    assert_goes_on_as(sim, GO_ON, &unchanged, growing[c].name, k);
                } else {
                    assert_int_equal(st, DS_OK);
                    assert_goes_on_as(sim, GO_ON, &grown, growing[c].name, k);
                }
                ds_sim_destroy(sim);
            }
        free(b.p);
        print_message("%-32s ds_sim_set_growth: %lu allocations\n", growing[c].name, calls);
    }
}

/* The granular setters with the k-th allocation failing (the
 * event-driven integrator's time of last collision, a disk column, and a
 * drive's kicks): DS_ERR_NOMEM and the simulation unchanged to the bit,
 * or the rules set as without the failure; and a granular run (restitution,
 * a field, a drive) allocates nothing, with every configuration whose
 * box has walls along y. */
static ds_status make_granular(ds_sim *sim)
{
    ds_status st = ds_sim_set_restitution(sim, 0.8, 0.9, NULL);
    if (st == DS_OK && ds_sim_get_boundary(sim) != DS_BOUNDARY_PERIODIC)
        st = ds_sim_set_gravity(sim, 0.0, -50.0, NULL);
    return st == DS_OK ? ds_sim_set_drive(sim, 100.0, NULL) : st;
}

static void test_granular_rules_survive_every_failed_allocation(void **state)
{
    (void)state;
    for (size_t c = 0; c < CONFIGS; ++c) {
        ds_sim *sim = created(&configs[c]);
        ds_sim_run(sim, 5, NULL);
        bytes b = saved(sim);
        const shown unchanged = shown_after(sim, GO_ON);
        assert_int_equal(make_granular(sim), DS_OK);
        const shown granular = shown_after(sim, GO_ON);
        arm(0, 0);
        ds_sim_run(sim, GO_ON, NULL);
        assert_int_equal(calls_counted(), 0);
        ds_sim_destroy(sim);
        sim = loaded(b);
        arm(0, 0);
        assert_int_equal(make_granular(sim), DS_OK);
        const unsigned long calls = calls_counted();
        ds_sim_destroy(sim);
        for (int persistent = 0; persistent <= 1; ++persistent)
            for (unsigned long k = 1; k <= calls; ++k) {
                sim = loaded(b);
                arm(k, persistent);
                const ds_status st = ds_sim_set_restitution(sim, 0.8, 0.9, NULL);
                assert_true(disarm() || st == DS_OK);
                if (st == DS_ERR_NOMEM) {
                    assert_unchanged(sim, b, configs[c].name, k);
                    assert_goes_on_as(sim, GO_ON, &unchanged, configs[c].name, k);
                } else {
                    assert_int_equal(st, DS_OK);
                    arm(k, persistent);
                    const ds_status rest = make_granular(sim);
                    (void)disarm();
                    if (rest == DS_OK)
                        assert_goes_on_as(sim, GO_ON, &granular, configs[c].name, k);
                    else
                        assert_int_equal(rest, DS_ERR_NOMEM);
                }
                ds_sim_destroy(sim);
            }
        free(b.p);
        print_message("%-32s granular rules: %lu allocations\n", configs[c].name, calls);
    }
}

/* A growing run makes its state again with wider cells as the radii
 * grow; with the k-th allocation of the run failing, growth stops at that
 * step's end (the cells could not hold the contacts of the next), and so
 * does the run: DS_ERR_NOMEM, err naming the steps and the step it
 * stopped after, every step to there taken. The simulation is then sound
 * (no disk out of the box or overlapping), the heat out (the kinetic
 * energy of the call, to rounding: the energy growth tracks through the
 * collisions since it last measured it, 1e-16 each), and it runs on at
 * fixed radii, the energy conserved from then on (elastic collisions,
 * 1e-12 over the run), its checkpoint going on as it does. Or the run is
 * the one without the failure. Growing runs are saved and loaded with the
 * same failures (the growth's part of a checkpoint). */
static void test_a_growing_run_survives_every_failed_allocation(void **state)
{
    (void)state;
    for (size_t c = 0; c < GROWING; ++c) {
        ds_sim *sim = created(&growing[c]);
        ds_sim_run(sim, 5, NULL);
        const double energy = ds_sim_get_kinetic_energy(sim);
        assert_int_equal(ds_sim_set_growth(sim, RATE, UNTIL_ETA, 0.0, NULL), DS_OK);
        bytes b = saved(sim);
        const shown expected = shown_after(sim, GROWTH_STEPS);
        assert_int_equal(expected.growth, DS_GROWTH_GROWING);
        arm(0, 0);
        assert_int_equal(ds_sim_run(sim, GROWTH_STEPS, NULL), DS_OK);
        const unsigned long calls = calls_counted();
        unsigned long stopped = 0;
        /* The run made its state again (one cell, brute force, never needs to). */
        assert_true(calls > 0 || growing[c].broadphase == DS_BROADPHASE_BRUTE);
        check_loading(sim, growing[c].name); /* a growing run's checkpoint */
        ds_sim_destroy(sim);
        for (int persistent = 0; persistent <= 1; ++persistent)
            for (unsigned long k = 1; k <= calls; ++k) {
                sim = loaded(b);
                const uint64_t steps = ds_sim_get_steps(sim);
                arm(k, persistent);
                ds_error err;
                const ds_status st = ds_sim_run(sim, GROWTH_STEPS, &err);
                assert_true(disarm());
                assert_sound(sim, growing[c].name, k);
                if (st == DS_OK) {
                    assert_int_equal(ds_sim_get_steps(sim), steps + GROWTH_STEPS);
                    assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_GROWING);
                    assert_shows(sim, &expected, growing[c].name, k);
                    ds_sim_destroy(sim);
                    continue;
                }
                assert_int_equal(st, DS_ERR_NOMEM);
                assert_int_equal(err.status, DS_ERR_NOMEM);
                assert_string_equal(err.field, "steps");
                const uint64_t done = ds_sim_get_steps(sim);
                assert_true(done > steps && done <= steps + GROWTH_STEPS);
                assert_true(err.value == (double)done);
                assert_int_equal(ds_sim_get_growth_state(sim), DS_GROWTH_NONE);
                ++stopped;
                assert_true(fabs(ds_sim_get_kinetic_energy(sim) / energy - 1.0) < 1e-12);
                const double eta = ds_sim_get_area_fraction(sim);
                /* It runs on, and is a state a checkpoint holds and goes
                 * on from to the bit. */
                const uint64_t rest = steps + GROWTH_STEPS - done + 300;
                const shown through_checkpoint = shown_after(sim, rest);
                assert_int_equal(ds_sim_run(sim, rest, NULL), DS_OK);
                assert_shows(sim, &through_checkpoint, growing[c].name, k);
                assert_sound(sim, growing[c].name, k);
                assert_true(fabs(ds_sim_get_kinetic_energy(sim) / energy - 1.0) < 1e-12);
                assert_true(ds_sim_get_area_fraction(sim) == eta);
                ds_sim_destroy(sim);
            }
        free(b.p);
        print_message("%-32s a growing run of %d steps: %lu allocations, %lu of %lu failures "
                      "stopped growth and the run\n",
                      growing[c].name, GROWTH_STEPS, calls, stopped, 2 * calls);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_creation_survives_every_failed_allocation),
        cmocka_unit_test(test_a_plain_run_allocates_nothing),
        cmocka_unit_test(test_predicting_everyone_again_allocates_nothing),
        cmocka_unit_test(test_loading_a_checkpoint_survives_every_failed_allocation),
        cmocka_unit_test(test_set_all_survives_every_failed_allocation),
        cmocka_unit_test(test_starting_growth_survives_every_failed_allocation),
        cmocka_unit_test(test_a_growing_run_survives_every_failed_allocation),
        cmocka_unit_test(test_granular_rules_survive_every_failed_allocation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
