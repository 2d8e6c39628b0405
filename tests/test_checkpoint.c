/* SPDX-License-Identifier: MIT */
/* Checkpoints: a simulation saved and loaded goes on bit for bit as the
 * one that never stopped, for every integrator, both boundaries (and the
 * channel with event chains) and every broad phase; a truncated, corrupted, foreign or
 * future-version checkpoint is refused with a reason and never crashes the loader. */
#include "test_util.h"

typedef struct combination {
    ds_integrator integrator;
    ds_broadphase broadphase;
    ds_boundary boundary;
} combination;

static const combination ALL[] = {
    {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_SAP, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_SAP, DS_BOUNDARY_PERIODIC},
    {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_STRIPS, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_STRIPS, DS_BOUNDARY_PERIODIC},
    {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_BRUTE, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_BRUTE, DS_BOUNDARY_PERIODIC},
    {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS, DS_BOUNDARY_PERIODIC},
    {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_BRUTE, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_BRUTE, DS_BOUNDARY_PERIODIC},
    {DS_INTEGRATOR_EVENT_CHAIN, DS_BROADPHASE_CELLS, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_EVENT_CHAIN, DS_BROADPHASE_CELLS, DS_BOUNDARY_PERIODIC},
    {DS_INTEGRATOR_EVENT_CHAIN, DS_BROADPHASE_CELLS, DS_BOUNDARY_CHANNEL},
    {DS_INTEGRATOR_EVENT_CHAIN, DS_BROADPHASE_BRUTE, DS_BOUNDARY_WALLS},
    {DS_INTEGRATOR_EVENT_CHAIN, DS_BROADPHASE_BRUTE, DS_BOUNDARY_PERIODIC},
};

/* 600 disks at area fraction 0.3 in a rectangle: thousands of collisions
 * in the steps below, strips crossed, seams crossed, walls hit. */
static ds_sim *make(const combination *c)
{
    ds_params p = ds_params_default(600, 9.0);
    p.box_y = 850.0;
    p.integrator = c->integrator;
    p.broadphase = c->broadphase;
    p.boundary = c->boundary;
    p.seed = 31;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    return sim;
}

static uint8_t *saved(const ds_sim *sim, size_t *len)
{
    const size_t need = ds_checkpoint_get_size(sim);
    uint8_t *buf = malloc(need);
    assert_non_null(buf);
    assert_int_equal(ds_checkpoint_format(sim, buf, need, len, NULL), DS_OK);
    assert_int_equal(*len, need);
    return buf;
}

/* Everything a user reads of a simulation, to the bit. */
static void assert_same_run(const ds_sim *a, const ds_sim *b)
{
    const size_t n = ds_sim_get_count(a);
    assert_int_equal(ds_sim_get_count(b), n);
    ds_disk *da = malloc(n * sizeof *da), *db = malloc(n * sizeof *db);
    assert_non_null(da);
    assert_non_null(db);
    assert_int_equal(ds_sim_get_disks(a, da, NULL), DS_OK);
    assert_int_equal(ds_sim_get_disks(b, db, NULL), DS_OK);
    assert_memory_equal(da, db, n * sizeof *da);
    free(da);
    free(db);
    assert_int_equal(ds_sim_get_steps(a), ds_sim_get_steps(b));
    assert_true(ds_sim_get_time(a) == ds_sim_get_time(b));
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
    assert_int_equal(ds_sim_get_wall_count(a), ds_sim_get_wall_count(b));
    assert_int_equal(ds_sim_get_pairs_tested(a), ds_sim_get_pairs_tested(b));
    const double pa = ds_sim_get_pressure(a), pb = ds_sim_get_pressure(b);
    const double va = ds_sim_get_virial_pressure(a), vb = ds_sim_get_virial_pressure(b);
    assert_memory_equal(&pa, &pb, sizeof pa);
    assert_memory_equal(&va, &vb, sizeof va);
    const double ea = ds_sim_get_area_fraction(a), eb = ds_sim_get_area_fraction(b);
    assert_memory_equal(&ea, &eb, sizeof ea);
}

/* The stress integral, to the bit, of two runs made of the same ds_sim_run
 * calls: each call sums the kinetic tensor afresh from the disks (so
 * that whatever set them between runs is in it), and the rounding of
 * that sum differs from the one its collisions carried. */
static void assert_same_stress(const ds_sim *a, const ds_sim *b)
{
    double sa[3], sb[3];
    assert_int_equal(ds_sim_get_stress_integral(a, sa, NULL), DS_OK);
    assert_int_equal(ds_sim_get_stress_integral(b, sb, NULL), DS_OK);
    assert_memory_equal(sa, sb, sizeof sa);
}

static void test_a_loaded_run_goes_on_bit_for_bit(void **state)
{
    (void)state;
    for (size_t c = 0; c < sizeof ALL / sizeof ALL[0]; ++c) {
        ds_sim *a = make(&ALL[c]);
        ds_sim_run(a, 150, NULL);
        ds_sim_reset_observables(a);
        ds_sim_run(a, 50, NULL); /* observables accumulating when saved */
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        ds_sim *b = NULL;
        ds_error why;
        assert_int_equal(ds_checkpoint_parse(buf, len, &b, &why), DS_OK);
        assert_int_equal(ds_sim_get_integrator(b), ALL[c].integrator);
        assert_int_equal(ds_sim_get_broadphase(b), ALL[c].broadphase);
        assert_int_equal(ds_sim_get_boundary(b), ALL[c].boundary);
        assert_same_run(a, b); /* at once */
        /* ~0.5 collisions per disk per 1000 steps at this density. */
        const uint64_t before = ds_sim_get_collision_count(a), steps = quick_mode() ? 400 : 2000;
        ds_sim_run(a, steps, NULL);
        ds_sim_run(b, steps / 3, NULL);
        ds_sim_run(b, steps - steps / 3, NULL);
        assert_true(ds_sim_get_collision_count(a) > before + steps / 20); /* not an idle case */
        assert_same_run(a, b); /* and after many more steps, in other pieces */
        free(buf);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
    }
}

/* A granular run goes on bit for bit from its checkpoint: restitution
 * of pairs and walls, a contact time of the TC model (each disk's time of
 * last collision, a disk column), a field in a channel and a drive (its
 * stream of random numbers), with both integrators, the energy books
 * and the rules read back as they were. */
static void test_a_granular_run_goes_on_bit_for_bit(void **state)
{
    (void)state;
    FOR_EACH_DYNAMIC_INTEGRATOR(integrator)
    {
        ds_params p = ds_params_default(300, 6.0);
        p.integrator = (ds_integrator)integrator;
        p.boundary = DS_BOUNDARY_CHANNEL;
        p.box = 400.0;
        p.seed = 17;
        ds_sim *a = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &a, NULL), DS_OK);
        assert_int_equal(ds_sim_set_restitution(a, 0.7, 0.8, NULL), DS_OK);
        assert_int_equal(ds_sim_set_contact_time(a, 1e-3, NULL), DS_OK);
        assert_int_equal(ds_sim_set_gravity(a, 0.0, -200.0, NULL), DS_OK);
        assert_int_equal(ds_sim_set_drive(a, 4e5, NULL), DS_OK);
        ds_sim_run(a, 700, NULL);
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        ds_sim *b = NULL;
        ds_error why;
        if (ds_checkpoint_parse(buf, len, &b, &why) != DS_OK)
            fail_msg("%s", why.message);
        assert_true(ds_sim_get_restitution(b) == 0.7 && ds_sim_get_wall_restitution(b) == 0.8);
        assert_true(ds_sim_get_contact_time(b) == 1e-3 && ds_sim_get_drive(b) == 4e5);
        double gx, gy;
        ds_sim_get_gravity(b, &gx, &gy);
        assert_true(gx == 0.0 && gy == -200.0);
        for (int part = 0; part < 2; ++part) {
            assert_same_run(a, b);
            const double la = ds_sim_get_energy_lost(a), lb = ds_sim_get_energy_lost(b);
            const double ia = ds_sim_get_energy_input(a), ib = ds_sim_get_energy_input(b);
            assert_memory_equal(&la, &lb, sizeof la);
            assert_memory_equal(&ia, &ib, sizeof ia);
            assert_true(la > 0.0 && ia > 0.0);
            ds_sim_run(a, 600, NULL);
            ds_sim_run(b, 250, NULL);
            ds_sim_run(b, 350, NULL);
        }
        free(buf);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
    }
}

/* The time step turns a disk at a wall after it has moved: between steps
 * its centre may be past the band a radius from the wall. Saved at such
 * a step, the run loads and goes on bit for bit (the classic case, which
 * has a disk past the band within its first hundred steps). */
static void test_a_time_step_saved_with_a_disk_past_the_wall_band_loads(void **state)
{
    (void)state;
    ds_sim *a = test_create(400, 5.0, 1, DS_BROADPHASE_SAP);
    int found = 0;
    for (int step = 0; step < 2000 && !found; ++step) {
        ds_sim_step(a, NULL);
        for (size_t k = 0; k < ds_sim_get_count(a) && !found; ++k) {
            const ds_disk d = ds_sim_get_disk(a, k);
            found = d.x < 5.0 || d.x > ds_sim_get_box_width(a) - 5.0 || d.y < 5.0 ||
                    d.y > ds_sim_get_box_height(a) - 5.0;
        }
    }
    assert_true(found);
    size_t len = 0;
    uint8_t *buf = saved(a, &len);
    ds_sim *b = NULL;
    ds_error why;
    assert_int_equal(ds_checkpoint_parse(buf, len, &b, &why), DS_OK);
    ds_sim_run(a, 500, NULL);
    ds_sim_run(b, 500, NULL);
    assert_same_run(a, b);
    free(buf);
    ds_sim_destroy(a);
    ds_sim_destroy(b);
}

/* A checkpoint of a checkpoint is the same run too, through a file. */
static void test_a_checkpoint_goes_through_a_file(void **state)
{
    (void)state;
    const combination c = {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS, DS_BOUNDARY_PERIODIC};
    ds_sim *a = make(&c);
    ds_sim_run(a, 100, NULL);
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(ds_checkpoint_save(a, f, NULL), DS_OK);
    rewind(f);
    ds_sim *b = NULL;
    assert_int_equal(ds_checkpoint_load(f, &b, NULL), DS_OK);
    fclose(f);
    ds_sim_run(a, 100, NULL);
    ds_sim_run(b, 100, NULL);
    assert_same_run(a, b);
    ds_sim_destroy(a);
    ds_sim_destroy(b);
}

/* The run never stops for ds_sim_set_disks either: a disk set, then saved. */
static void test_a_state_set_by_hand_is_saved_exactly(void **state)
{
    (void)state;
    for (int integrator = 0; integrator < DS_INTEGRATOR_COUNT; ++integrator) {
        const combination c = {(ds_integrator)integrator, DS_BROADPHASE_AUTO, DS_BOUNDARY_WALLS};
        ds_sim *a = make(&c);
        ds_sim_run(a, 30, NULL);
        ds_disk d = ds_sim_get_disk(a, 17);
        d.vx = -d.vx;
        assert_int_equal(ds_sim_set_disk(a, 17, d, NULL), DS_OK);
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        ds_sim *b = NULL;
        assert_int_equal(ds_checkpoint_parse(buf, len, &b, NULL), DS_OK);
        ds_sim_run(a, 200, NULL);
        ds_sim_run(b, 200, NULL);
        assert_same_run(a, b);
        free(buf);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
    }
}

/* FNV-1a as the file has it, to forge a consistent checkpoint. */
static uint64_t fnv(const uint8_t *p, size_t len)
{
    uint64_t h = 14695981039346656037ull;
    for (size_t k = 0; k < len; ++k)
        h = (h ^ p[k]) * 1099511628211ull;
    return h;
}

static void fix_checksum(uint8_t *buf, size_t len)
{
    const uint64_t h = fnv(buf, len - 8);
    for (int k = 0; k < 8; ++k)
        buf[len - 8 + (size_t)k] = (uint8_t)(h >> (8 * k));
}

static void assert_refused(const uint8_t *buf, size_t len, const char *why_contains)
{
    ds_sim *b = (ds_sim *)1;
    ds_error why;
    assert_int_equal(ds_checkpoint_parse(buf, len, &b, &why), DS_ERR_FORMAT);
    assert_null(b);
    assert_true(strlen(why.message) > 0);
    if (why_contains && !strstr(why.message, why_contains))
        fail_msg("\"%s\" does not say \"%s\"", why.message, why_contains);
}

static void test_a_bad_checkpoint_is_refused_with_a_reason(void **state)
{
    (void)state;
    const combination c = {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS, DS_BOUNDARY_WALLS};
    ds_sim *a = make(&c);
    ds_sim_run(a, 20, NULL);
    size_t len = 0;
    uint8_t *buf = saved(a, &len);
    uint8_t *bad = malloc(len + 16);
    assert_non_null(bad);
    /* Truncated anywhere. */
    for (size_t cut = 0; cut < len; cut += cut < 64 ? 1 : 997)
        assert_refused(buf, cut, cut < 8 ? "not a disksim state" : NULL);
    assert_refused(buf, len - 1, "truncated");
    /* One byte changed anywhere: the checksum. */
    for (size_t at = 40; at < len - 8; at += 1009) {
        memcpy(bad, buf, len);
        bad[at] ^= 0x20;
        assert_refused(bad, len, "checksum");
    }
    /* Foreign, future, and bytes beyond the end. */
    memcpy(bad, buf, len);
    memcpy(bad, "NOTSTATE", 8);
    assert_refused(bad, len, "not a disksim state");
    memcpy(bad, buf, len);
    bad[8] = DS_CHECKPOINT_FORMAT_VERSION + 1;
    fix_checksum(bad, len);
    char future[32];
    snprintf(future, sizeof future, "format version %d", DS_CHECKPOINT_FORMAT_VERSION + 1);
    assert_refused(bad, len, future);
    bad[8] = 0;
    fix_checksum(bad, len);
    assert_refused(bad, len, "format version 0");
    memcpy(bad, buf, len);
    memset(bad + len, 0, 16);
    assert_refused(bad, len + 16, "after the end");
    free(bad);
    free(buf);
    ds_sim_destroy(a);
}

/* Forged checkpoints (consistent checksums) with random bytes changed in
 * the payload: the loader refuses what would break the library and never
 * crashes (the sanitizer and valgrind runs of CI watch this test), and a
 * checkpoint it accepts runs. */
static void test_forged_checkpoints_never_crash_the_loader(void **state)
{
    (void)state;
    ds_rng rng;
    ds_rng_seed(&rng, 99);
    for (size_t c = 0; c < sizeof ALL / sizeof ALL[0]; c += 3) {
        ds_sim *a = make(&ALL[c]);
        ds_sim_run(a, 10, NULL);
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        uint8_t *bad = malloc(len);
        assert_non_null(bad);
        const int tries = quick_mode() ? 20 : 200;
        for (int t = 0; t < tries; ++t) {
            memcpy(bad, buf, len);
            const int changes = 1 + (int)(ds_rng_next(&rng) % 4);
            for (int k = 0; k < changes; ++k) {
                const size_t at = 40 + (size_t)(ds_rng_next(&rng) % (len - 48));
                bad[at] = (uint8_t)ds_rng_next(&rng);
            }
            fix_checksum(bad, len);
            ds_sim *b = NULL;
            const ds_status st = ds_checkpoint_parse(bad, len, &b, NULL);
            assert_true(st == DS_OK || st == DS_ERR_FORMAT);
            if (st == DS_OK) {
                ds_sim_run(b, 3, NULL);
                ds_sim_destroy(b);
            }
        }
        free(bad);
        free(buf);
        ds_sim_destroy(a);
    }
}

/* The time integral of the pressure tensor (the Helfand moments of the
 * viscosity) goes on across a checkpoint: saved mid-run, it is the
 * straight run's to the bit, then and after more steps, with both
 * integrators and both boundaries. */
static void test_a_loaded_run_goes_on_with_the_stress_integral(void **state)
{
    (void)state;
    for (int integrator = 0; integrator < DS_INTEGRATOR_COUNT; ++integrator)
        for (int boundary = 0; boundary < DS_BOUNDARY_COUNT; ++boundary) {
            const combination c = {(ds_integrator)integrator, DS_BROADPHASE_AUTO,
                                   (ds_boundary)boundary};
            ds_sim *a = make(&c);
            ds_sim_run(a, 100, NULL);
            size_t len = 0;
            uint8_t *buf = saved(a, &len);
            ds_sim *b = NULL;
            assert_int_equal(ds_checkpoint_parse(buf, len, &b, NULL), DS_OK);
            double s[3];
            assert_int_equal(ds_sim_get_stress_integral(b, s, NULL), DS_OK);
            assert_true(s[0] > 0.0 && s[1] > 0.0); /* a run's, not a fresh start */
            assert_same_run(a, b);
            assert_same_stress(a, b);
            ds_sim_run(a, 150, NULL);
            ds_sim_run(b, 150, NULL);
            assert_same_run(a, b);
            assert_same_stress(a, b);
            free(buf);
            ds_sim_destroy(a);
            ds_sim_destroy(b);
        }
}

/* A mixture's area fraction is the same double after a checkpoint: the
 * load used to sum the disks' areas in the order of the slots (sorted by
 * x, or by cell), creation in generation order. Every broad phase, both
 * boundaries, and a growing run (whose radii change every step). */
static void test_a_mixture_keeps_its_area_fraction_to_the_bit(void **state)
{
    (void)state;
    const ds_species kinds[] = {{300, 9.0, 0.0, NULL}, {300, 6.3, 0.0, NULL}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    for (size_t c = 0; c < sizeof ALL / sizeof ALL[0]; ++c) {
        ds_params p = ds_params_default(600, 9.0);
        p.box_y = 850.0;
        p.integrator = ALL[c].integrator;
        p.broadphase = ALL[c].broadphase;
        p.boundary = ALL[c].boundary;
        p.seed = 31;
        ds_sim *a = NULL;
        assert_int_equal(ds_sim_create(&p, &mixture, &a, NULL), DS_OK);
        ds_sim_run(a, 100, NULL);
        const int growing = ALL[c].integrator == DS_INTEGRATOR_EVENT_DRIVEN &&
                            ALL[c].boundary == DS_BOUNDARY_PERIODIC;
        if (growing) {
            assert_int_equal(ds_sim_set_growth(a, 0.05, 0.0, 0.0, NULL), DS_OK);
            ds_sim_run(a, 20, NULL);
        }
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        ds_sim *b = NULL;
        assert_int_equal(ds_checkpoint_parse(buf, len, &b, NULL), DS_OK);
        assert_same_run(a, b); /* the area fraction among the rest */
        assert_same_stress(a, b);
        ds_sim_run(a, 50, NULL);
        ds_sim_run(b, 50, NULL);
        assert_same_run(a, b);
        assert_same_stress(a, b);
        free(buf);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
    }
}

/* The bytes of a double, to find a saved value in a checkpoint. */
static size_t replace_double(uint8_t *buf, size_t len, double was, double now)
{
    uint8_t from[8], to[8];
    memcpy(from, &was, 8); /* the file is little-endian, as this test's machines */
    memcpy(to, &now, 8);
    size_t found = 0;
    for (size_t at = 40; at + 8 <= len - 8; ++at)
        if (memcmp(buf + at, from, 8) == 0) {
            memcpy(buf + at, to, 8);
            ++found;
        }
    return found;
}

/* A loader checks every disk as ds_sim_set_disk does (finite, no velocity
 * component beyond 1e12, in the box): a forged checkpoint (its checksum
 * made again) with a disk too fast was loaded by the time step, which
 * then ran a disk out of the walls; a periodic centre at box itself, which
 * ds_sim_set_disk refuses, was taken too. Both integrators; the limit itself loads. */
static void test_a_forged_disk_is_refused_as_ds_set_refuses_it(void **state)
{
    (void)state;
    for (int integrator = 0; integrator < DS_INTEGRATOR_COUNT; ++integrator)
        for (int boundary = 0; boundary < DS_BOUNDARY_COUNT; ++boundary) {
            const combination c = {(ds_integrator)integrator, DS_BROADPHASE_AUTO,
                                   (ds_boundary)boundary};
            ds_sim *a = make(&c);
            ds_sim_run(a, 20, NULL);
            const ds_disk d = ds_sim_get_disk(a, 7);
            size_t len = 0;
            uint8_t *buf = saved(a, &len);
            uint8_t *bad = malloc(len);
            assert_non_null(bad);
            const double too_fast[] = {1e77, 1.5e12, -1.0000000000000002e12};
            for (size_t k = 0; k < sizeof too_fast / sizeof too_fast[0]; ++k) {
                memcpy(bad, buf, len);
                /* The arrays' copy, and the event-driven record's. */
                assert_true(replace_double(bad, len, d.vx, too_fast[k]) >= 1);
                fix_checksum(bad, len);
                assert_refused(bad, len, "beyond 1e12");
            }
            if (boundary == DS_BOUNDARY_PERIODIC && integrator == DS_INTEGRATOR_TIME_STEP) {
                memcpy(bad, buf, len);
                assert_int_equal(replace_double(bad, len, d.x, ds_sim_get_box_width(a)), 1);
                fix_checksum(bad, len);
                assert_refused(bad, len, "outside the periodic box");
            }
            /* ds_sim_set_disk's own limit is a state a run may have. */
            ds_disk fast = d;
            fast.vx = d.vx < 0.0 ? -1e12 : 1e12;
            if (integrator == DS_INTEGRATOR_TIME_STEP) {
                assert_int_equal(ds_sim_set_disk(a, 7, fast, NULL), DS_OK);
                free(buf);
                buf = saved(a, &len);
                ds_sim *b = NULL;
                assert_int_equal(ds_checkpoint_parse(buf, len, &b, NULL), DS_OK);
                ds_sim_destroy(b);
            }
            free(bad);
            free(buf);
            ds_sim_destroy(a);
        }
}

/* A length field that announces more than the file holds is a truncated
 * checkpoint (DS_ERR_FORMAT, as ds_checkpoint_parse says), not a lack of
 * memory: the loader reads in chunks up to what the header announces, so
 * its memory follows the bytes present (2^42 was allocated first, and
 * AddressSanitizer aborted on it). */
static void test_a_length_field_past_the_file_is_a_truncated_checkpoint(void **state)
{
    (void)state;
    const combination c = {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_SAP, DS_BOUNDARY_WALLS};
    ds_sim *a = make(&c);
    size_t len = 0;
    uint8_t *buf = saved(a, &len);
    const uint64_t lengths[] = {(uint64_t)1 << 42, (uint64_t)1 << 33, (uint64_t)len};
    for (size_t k = 0; k < sizeof lengths / sizeof lengths[0]; ++k) {
        for (int b = 0; b < 8; ++b)
            buf[32 + b] = (uint8_t)(lengths[k] >> (8 * b));
        FILE *f = tmpfile();
        assert_non_null(f);
        assert_int_equal(fwrite(buf, 1, len, f), len);
        rewind(f);
        ds_sim *b = (ds_sim *)1;
        ds_error why;
        assert_int_equal(ds_checkpoint_load(f, &b, &why), DS_ERR_FORMAT);
        assert_null(b);
        assert_non_null(strstr(why.message, "truncated"));
        fclose(f);
    }
    free(buf);
    ds_sim_destroy(a);
}

/* An event-driven run's part of format version 5 ends with its sheared
 * images (a flag, the offset, the speed and the cell count: 28 bytes),
 * which versions before 5 do not have: taken out, `tail` the bytes of
 * the file after the integrator's part (the protocols, the metadata and
 * the checksum). The integrator's number is 88 bytes in. */
static size_t without_shear(uint8_t *buf, size_t len, size_t tail)
{
    if (buf[88] != (uint8_t)DS_INTEGRATOR_EVENT_DRIVEN)
        return len;
    const size_t at = len - tail - 28;
    memmove(buf + at, buf + at + 28, tail);
    return len - 28;
}

/* The payload of format version 1: version 4's without the pressure
 * tensor's parts and the rules and energy books (10 and 7 doubles after
 * the collision timer, 188 bytes into the file), without the kinds and
 * without the list of protocols (its count at the end; a growth, which
 * version 1 kept in the integrator's part, is not in these runs). */
static size_t as_version_1(uint8_t *buf, size_t len)
{
    len = without_shear(buf, len, 4 + 4 + 8); /* no protocols, no metadata */
    /* The columns' mask (112 bytes in): version 4's bit per column,
     * 2.x's 1 radii, 2 masses, 4 image counts. */
    const uint32_t bits = (uint32_t)buf[112] | (uint32_t)buf[113] << 8;
    const uint32_t old = (bits >> 5 & 1u) | (bits >> 6 & 1u) << 1 | (bits >> 7 & 1u) << 2;
    buf[112] = (uint8_t)old;
    buf[113] = 0;
    const size_t at = 188, cut = 80 + 56;
    memmove(buf + at, buf + at + cut, len - at - cut);
    len -= cut;
    /* Version 3's kinds (a count and 16 bytes a name) after the disks:
     * n (40 bytes in) times x, y, vx, vy, id and the optional columns. */
    uint64_t n = 0;
    for (int b = 0; b < 8; ++b)
        n |= (uint64_t)buf[40 + b] << (8 * b);
    const size_t disk = 36 + 8 * (old & 1u) + 8 * (old >> 1 & 1u) + 8 * (old >> 2 & 1u);
    assert_true((bits >> 9 & 1u) == 0); /* one kind: no kind column */
    const size_t kinds = at + (size_t)n * disk;
    const uint32_t count = (uint32_t)buf[kinds] | (uint32_t)buf[kinds + 1] << 8;
    const size_t kinds_len = 4 + 16 * (size_t)count;
    memmove(buf + kinds, buf + kinds + kinds_len, len - kinds - kinds_len);
    len -= kinds_len;
    /* Version 3's list of protocols (a count, 0 here) and its metadata (a
     * length, 0 here) are the last things before the checksum; version 1
     * had neither. */
    memmove(buf + len - 16, buf + len - 8, 8);
    len -= 8;
    buf[8] = 1;
    const uint64_t payload = len - 48;
    for (int b = 0; b < 8; ++b)
        buf[32 + b] = (uint8_t)(payload >> (8 * b));
    fix_checksum(buf, len);
    return len;
}

/* A checkpoint of format version 2 written by disksim 2.1 during a growth
 * (tests/checkpoint-v2-growth.state: a mixture of 40 disks of 12 and 20
 * of 8, mass by area, event-driven, periodic box 260, seed 7, 30 steps,
 * then growth at rate 0.02 to area fraction 0.6, 5000 steps more), where
 * the growth's law and its protocol's part were one block of the
 * integrator's: it loads, and goes on to the bit as the same run made now,
 * the growth's state, Z and area fraction included. */
static void test_a_version_2_checkpoint_of_a_growth_goes_on_to_the_bit(void **state)
{
    (void)state;
    FILE *f = fopen("tests/checkpoint-v2-growth.state", "rb");
    assert_non_null(f);
    ds_sim *old = NULL;
    ds_error why;
    if (ds_checkpoint_load(f, &old, &why) != DS_OK)
        fail_msg("%s", why.message);
    fclose(f);
    ds_params p = ds_params_default(60, 12.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = 260.0;
    p.seed = 7;
    const ds_species kinds[] = {{40, 12.0, 0.0, NULL}, {20, 8.0, 0.0, NULL}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    ds_sim *now = NULL;
    assert_int_equal(ds_sim_create(&p, &mixture, &now, NULL), DS_OK);
    ds_sim_run(now, 30, NULL);
    assert_int_equal(ds_sim_set_growth(now, 0.02, 0.6, 0.0, NULL), DS_OK);
    ds_sim_run(now, 5000, NULL);
    for (int part = 0; part < 3; ++part) {
        ds_disk da[60], db[60];
        double ra[60], rb[60];
        assert_int_equal(ds_sim_get_disks(now, da, NULL), DS_OK);
        assert_int_equal(ds_sim_get_disks(old, db, NULL), DS_OK);
        assert_memory_equal(da, db, sizeof da);
        assert_int_equal(ds_sim_get_radii(now, ra, NULL), DS_OK);
        assert_int_equal(ds_sim_get_radii(old, rb, NULL), DS_OK);
        assert_memory_equal(ra, rb, sizeof ra);
        assert_int_equal(ds_sim_get_growth_state(now), ds_sim_get_growth_state(old));
        const double za = ds_sim_get_growth_z(now), zb = ds_sim_get_growth_z(old);
        assert_memory_equal(&za, &zb, sizeof za);
        const double ea = ds_sim_get_area_fraction(now), eb = ds_sim_get_area_fraction(old);
        assert_memory_equal(&ea, &eb, sizeof ea);
        assert_int_equal(ds_sim_get_collision_count(now), ds_sim_get_collision_count(old));
        ds_sim_run(now, 3000, NULL);
        ds_sim_run(old, 3000, NULL);
    }
    assert_int_equal(ds_sim_get_growth_state(old), DS_GROWTH_GROWING);
    assert_true(ds_sim_get_growth_z(old) > 1.0);
    ds_sim_destroy(now);
    ds_sim_destroy(old);
}

/* A checkpoint of format version 1 still loads and goes on bit for bit,
 * its stress integral starting at 0 (it did not carry it): one made by
 * hand from each combination (event chains, which 2.x did not have,
 * refused), and one written by disksim 2.1.0 (main
 * before version 2: tests/checkpoint-v1.state, a mixture of 40 disks,
 * event-driven, periodic, seed 5, after 60 steps). */
static void test_a_version_1_checkpoint_loads_with_the_stress_integral_at_zero(void **state)
{
    (void)state;
    for (size_t c = 0; c < sizeof ALL / sizeof ALL[0]; ++c) {
        ds_sim *a = make(&ALL[c]);
        ds_sim_run(a, 50, NULL);
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        len = as_version_1(buf, len);
        ds_sim *b = NULL;
        ds_error why;
        if (ALL[c].integrator == DS_INTEGRATOR_EVENT_CHAIN) { /* 2.x had none */
            assert_refused(buf, len, "no event chains");
            free(buf);
            ds_sim_destroy(a);
            continue;
        }
        if (ds_checkpoint_parse(buf, len, &b, &why) != DS_OK)
            fail_msg("%s", why.message);
        double s[3];
        assert_int_equal(ds_sim_get_stress_integral(b, s, NULL), DS_OK);
        assert_true(s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.0);
        ds_sim_run(a, 100, NULL);
        ds_sim_run(b, 100, NULL);
        assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
        ds_disk *da = malloc(600 * sizeof *da), *db = malloc(600 * sizeof *db);
        assert_non_null(da);
        assert_non_null(db);
        assert_int_equal(ds_sim_get_disks(a, da, NULL), DS_OK);
        assert_int_equal(ds_sim_get_disks(b, db, NULL), DS_OK);
        assert_memory_equal(da, db, 600 * sizeof *da);
        free(da);
        free(db);
        free(buf);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
    }
    /* The file of the old library against the same run made now. */
    FILE *f = fopen("tests/checkpoint-v1.state", "rb");
    assert_non_null(f);
    ds_sim *old = NULL;
    ds_error why;
    if (ds_checkpoint_load(f, &old, &why) != DS_OK)
        fail_msg("%s", why.message);
    fclose(f);
    ds_params p = ds_params_default(40, 20.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = 600.0;
    p.seed = 5;
    const ds_species kinds[] = {{25, 20.0, 0.0, NULL}, {15, 13.0, 0.0, NULL}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    ds_sim *now = NULL;
    assert_int_equal(ds_sim_create(&p, &mixture, &now, NULL), DS_OK);
    ds_sim_run(now, 60, NULL);
    double s[3];
    assert_int_equal(ds_sim_get_stress_integral(old, s, NULL), DS_OK);
    assert_true(s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.0);
    for (int part = 0; part < 2; ++part) {
        ds_disk da[40], db[40];
        int32_t ia[80], ib[80];
        assert_int_equal(ds_sim_get_disks(now, da, NULL), DS_OK);
        assert_int_equal(ds_sim_get_disks(old, db, NULL), DS_OK);
        assert_memory_equal(da, db, sizeof da);
        assert_int_equal(ds_sim_get_images(now, ia, NULL), DS_OK);
        assert_int_equal(ds_sim_get_images(old, ib, NULL), DS_OK);
        assert_memory_equal(ia, ib, sizeof ia);
        assert_int_equal(ds_sim_get_steps(now), ds_sim_get_steps(old));
        assert_int_equal(ds_sim_get_collision_count(now), ds_sim_get_collision_count(old));
        const double ea = ds_sim_get_area_fraction(now), eb = ds_sim_get_area_fraction(old);
        assert_memory_equal(&ea, &eb, sizeof ea);
        ds_sim_run(now, 200, NULL);
        ds_sim_run(old, 200, NULL);
    }
    ds_sim_destroy(old);
    ds_sim_destroy(now);
}

/* A checkpoint of version 3 (3.0's before the granular rules, which
 * ends with the caller's metadata) as version 4 writes it less its rules:
 * the 7 doubles after the stress integral (188 + 80 bytes in). */
static size_t as_version_3(uint8_t *buf, size_t len)
{
    len = without_shear(buf, len, 4 + 4 + 8 + 8); /* the test's metadata "frames=7" */
    const size_t at = 188 + 80, cut = 56;
    memmove(buf + at, buf + at + cut, len - at - cut);
    len -= cut;
    buf[8] = 3;
    const uint64_t payload = len - 48;
    for (int b = 0; b < 8; ++b)
        buf[32 + b] = (uint8_t)(payload >> (8 * b));
    fix_checksum(buf, len);
    return len;
}

/* A version 3 checkpoint, with its metadata, loads as an elastic run
 * without a field, its text given back, and goes on to the bit as the
 * run it was saved from, with every integrator, broad phase and box. */
static void test_a_version_3_checkpoint_loads_as_an_elastic_run_with_its_metadata(void **state)
{
    (void)state;
    for (size_t c = 0; c < sizeof ALL / sizeof ALL[0]; ++c) {
        ds_sim *a = make(&ALL[c]);
        assert_int_equal(ds_sim_set_metadata(a, "frames=7", NULL), DS_OK);
        ds_sim_run(a, 50, NULL);
        size_t len = 0;
        uint8_t *buf = saved(a, &len);
        len = as_version_3(buf, len);
        ds_sim *b = NULL;
        ds_error why;
        if (ds_checkpoint_parse(buf, len, &b, &why) != DS_OK)
            fail_msg("%s", why.message);
        assert_string_equal(ds_sim_get_metadata(b), "frames=7");
        assert_true(ds_sim_get_restitution(b) == 1.0 && ds_sim_get_wall_restitution(b) == 1.0);
        double gx = 1.0, gy = 1.0;
        ds_sim_get_gravity(b, &gx, &gy);
        assert_true(gx == 0.0 && gy == 0.0);
        ds_sim_run(a, 100, NULL);
        ds_sim_run(b, 100, NULL);
        assert_same_run(a, b);
        free(buf);
        ds_sim_destroy(a);
        ds_sim_destroy(b);
    }
}

/* A stream without end (/dev/zero) is read as far as a header could be,
 * not to its end: refused at once, no memory grown for ever. */
static void test_a_stream_without_end_is_refused_at_once(void **state)
{
    (void)state;
    FILE *f = fopen("/dev/zero", "rb");
    if (!f)
        skip();
    ds_sim *b = NULL;
    ds_error why;
    assert_int_equal(ds_checkpoint_load(f, &b, &why), DS_ERR_FORMAT);
    assert_non_null(strstr(why.message, "not a disksim state"));
    fclose(f);
}

static void test_null_arguments_are_refused(void **state)
{
    (void)state;
    ds_sim *b = NULL;
    assert_int_equal(ds_checkpoint_parse(NULL, 10, &b, NULL), DS_ERR_ARG);
    assert_int_equal(ds_checkpoint_parse("x", 1, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_checkpoint_load(NULL, &b, NULL), DS_ERR_ARG);
    assert_int_equal(ds_checkpoint_save(NULL, stdout, NULL), DS_ERR_ARG);
    assert_int_equal(ds_checkpoint_get_size(NULL), 0);
    size_t len = 5;
    assert_int_equal(ds_checkpoint_format(NULL, NULL, 0, &len, NULL), DS_ERR_ARG);
    assert_int_equal(len, 0);
}

/* 3.0 writes format version 5, which keeps version 2's fields where they
 * were: the broad phase is saved by 2.x's numbers (SAP 0, brute force 1,
 * strips 2, cells 4), whatever the order of the public enumeration, so
 * the numbers in a file mean one thing in every version. The payload's
 * fields before it: n, radius, box, box_y, speed, dt, integrator and
 * boundary (8 x 6 + 4 + 4 bytes). */
static void test_checkpoints_keep_the_broad_phase_numbers_of_2x(void **state)
{
    (void)state;
    static const struct {
        ds_integrator integrator;
        ds_broadphase broadphase;
        uint32_t code;
    } cases[] = {{DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_SAP, 0},
                 {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_BRUTE, 1},
                 {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_STRIPS, 2},
                 {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS, 4},
                 {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_BRUTE, 1}};
    assert_int_equal(DS_CHECKPOINT_FORMAT_VERSION, 5);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        ds_params p = ds_params_default(30, 5.0);
        p.integrator = cases[c].integrator;
        p.broadphase = cases[c].broadphase;
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
        const size_t len = ds_checkpoint_get_size(sim);
        uint8_t *buf = malloc(len);
        assert_non_null(buf);
        assert_int_equal(ds_checkpoint_format(sim, buf, len, NULL, NULL), DS_OK);
        assert_memory_equal(buf, "DSIMSTAT\5\0\0\0", 12);
        const size_t at = 40 + 6 * 8 + 4 + 4;
        const uint32_t code = (uint32_t)buf[at] | (uint32_t)buf[at + 1] << 8 |
                              (uint32_t)buf[at + 2] << 16 | (uint32_t)buf[at + 3] << 24;
        assert_int_equal(code, cases[c].code);
        ds_sim *back = NULL;
        assert_int_equal(ds_checkpoint_parse(buf, len, &back, NULL), DS_OK);
        assert_int_equal(ds_sim_get_broadphase(back), cases[c].broadphase);
        ds_sim_destroy(back);
        free(buf);
        ds_sim_destroy(sim);
    }
}

/* A caller's text goes into the checkpoint and comes back as it was; a
 * simulation without one, or cleared, gives ""; a text past the limit is
 * refused, the old one kept; a file whose text holds a NUL, or claims more
 * bytes than the limit, is refused. */
static void test_the_callers_metadata_rides_in_the_checkpoint(void **state)
{
    (void)state;
    const combination c = {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS, DS_BOUNDARY_PERIODIC};
    ds_sim *a = make(&c);
    assert_string_equal(ds_sim_get_metadata(a), "");
    const char *text = "disks 1\nsteps_per_frame=1000\nout=dense\n";
    assert_int_equal(ds_sim_set_metadata(a, text, NULL), DS_OK);
    size_t len = 0;
    uint8_t *buf = saved(a, &len);
    ds_sim *b = NULL;
    assert_int_equal(ds_checkpoint_parse(buf, len, &b, NULL), DS_OK);
    assert_string_equal(ds_sim_get_metadata(b), text);
    /* It goes on to the bit as without a text: the library does not read it. */
    ds_sim_run(a, 50, NULL);
    ds_sim_run(b, 50, NULL);
    assert_int_equal(ds_sim_get_collision_count(a), ds_sim_get_collision_count(b));
    /* The text is the payload's last field, before the checksum: a NUL in
     * it, or a length past the limit, is refused. */
    const size_t text_at = len - 8 - strlen(text);
    buf[text_at + 3] = 0;
    fix_checksum(buf, len);
    ds_sim *bad = (ds_sim *)1;
    ds_error why;
    assert_int_equal(ds_checkpoint_parse(buf, len, &bad, &why), DS_ERR_FORMAT);
    assert_null(bad);
    assert_non_null(strstr(why.message, "NUL"));
    buf[text_at + 3] = 's';
    const uint32_t huge = DS_METADATA_MAX + 1;
    for (int k = 0; k < 4; ++k)
        buf[text_at - 4 + k] = (uint8_t)(huge >> (8 * k));
    fix_checksum(buf, len);
    assert_int_equal(ds_checkpoint_parse(buf, len, &bad, &why), DS_ERR_FORMAT);
    /* Too long a text is refused, the old one kept; "" clears it. */
    char *long_text = malloc(DS_METADATA_MAX + 2);
    assert_non_null(long_text);
    memset(long_text, 'x', DS_METADATA_MAX + 1);
    long_text[DS_METADATA_MAX + 1] = '\0';
    assert_int_equal(ds_sim_set_metadata(b, long_text, &why), DS_ERR_ARG);
    assert_string_equal(why.field, "metadata");
    assert_string_equal(ds_sim_get_metadata(b), text);
    long_text[DS_METADATA_MAX] = '\0'; /* exactly the limit */
    assert_int_equal(ds_sim_set_metadata(b, long_text, NULL), DS_OK);
    assert_int_equal(strlen(ds_sim_get_metadata(b)), DS_METADATA_MAX);
    assert_int_equal(ds_sim_set_metadata(b, "", NULL), DS_OK);
    assert_string_equal(ds_sim_get_metadata(b), "");
    assert_int_equal(ds_sim_set_metadata(NULL, "x", NULL), DS_ERR_ARG);
    assert_null(ds_sim_get_metadata(NULL));
    free(long_text);
    free(buf);
    ds_sim_destroy(a);
    ds_sim_destroy(b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_loaded_run_goes_on_bit_for_bit),
        cmocka_unit_test(test_a_granular_run_goes_on_bit_for_bit),
        cmocka_unit_test(test_a_checkpoint_goes_through_a_file),
        cmocka_unit_test(test_a_time_step_saved_with_a_disk_past_the_wall_band_loads),
        cmocka_unit_test(test_a_state_set_by_hand_is_saved_exactly),
        cmocka_unit_test(test_a_bad_checkpoint_is_refused_with_a_reason),
        cmocka_unit_test(test_forged_checkpoints_never_crash_the_loader),
        cmocka_unit_test(test_a_loaded_run_goes_on_with_the_stress_integral),
        cmocka_unit_test(test_a_mixture_keeps_its_area_fraction_to_the_bit),
        cmocka_unit_test(test_a_forged_disk_is_refused_as_ds_set_refuses_it),
        cmocka_unit_test(test_a_length_field_past_the_file_is_a_truncated_checkpoint),
        cmocka_unit_test(test_a_version_1_checkpoint_loads_with_the_stress_integral_at_zero),
        cmocka_unit_test(test_a_version_3_checkpoint_loads_as_an_elastic_run_with_its_metadata),
        cmocka_unit_test(test_a_version_2_checkpoint_of_a_growth_goes_on_to_the_bit),
        cmocka_unit_test(test_a_stream_without_end_is_refused_at_once),
        cmocka_unit_test(test_null_arguments_are_refused),
        cmocka_unit_test(test_checkpoints_keep_the_broad_phase_numbers_of_2x),
        cmocka_unit_test(test_the_callers_metadata_rides_in_the_checkpoint),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
