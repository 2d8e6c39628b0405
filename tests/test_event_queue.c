/* SPDX-License-Identifier: MIT */
/* The event calendar against the indexed binary heap it is checked by:
 * the same disk first after the same operations, whatever the times, in
 * workloads shaped like an event-driven run's (reschedule the first disk
 * a little ahead; now and then reschedule another, sometimes to the time
 * it already has), and at the edges:
 * equal times, +infinity, times beyond the calendar's window, a bucket
 * far fuller than a cache line, and the whole calendar rebuilt. */
#include "test_util.h"

#include "event/event_queue.h"

/* Each queue keeps its disks' times in memory of its own, as the
 * integrator keeps them in its disk records: here 16 bytes apart, so that
 * the stride is not that of a plain array. */
typedef struct timed {
    double time, other;
} timed;

typedef struct pair {
    ds_event_queue *calendar, *heap;
    timed *calendar_times, *heap_times;
} pair;

/* The calendar's mode for systems larger than the caches (buffered
 * insertions, buckets read ahead, disks announced) or its plain mode: every
 * comparison with the heap runs in both (the tests' `large` flag). */
typedef struct announced {
    uint64_t count;
    uint64_t checked; /* disks that came first after a name */
    double *until;    /* NULL, or per disk: the last name's until since its
                         last reschedule (NAN: none) */
} announced;

static void count_soon(void *ctx, uint32_t i, double until)
{
    announced *a = ctx;
    ++a->count;
    if (a->until)
        a->until[i] = until;
}

static announced soon_calls;

static pair make_mode(size_t n, int large)
{
    pair p;
    p.calendar_times = calloc(n, sizeof *p.calendar_times);
    p.heap_times = calloc(n, sizeof *p.heap_times);
    assert_non_null(p.calendar_times);
    assert_non_null(p.heap_times);
    assert_int_equal(
        ds_eq_create(&p.calendar, n, DS_EQ_CALENDAR, &p.calendar_times[0].time, sizeof(timed)),
        DS_OK);
    assert_int_equal(ds_eq_create(&p.heap, n, DS_EQ_HEAP, &p.heap_times[0].time, sizeof(timed)),
                     DS_OK);
    if (large)
        ds_eq_on_soon(p.calendar, count_soon, &soon_calls, 16);
    return p;
}

static int large_mode;
static pair make(size_t n) { return make_mode(n, large_mode); }

static void destroy(pair p)
{
    ds_eq_destroy(p.calendar);
    ds_eq_destroy(p.heap);
    free(p.calendar_times);
    free(p.heap_times);
}

static void build(pair p, const double *times, size_t n, double now)
{
    for (size_t i = 0; i < n; ++i)
        p.calendar_times[i].time = p.heap_times[i].time = times[i];
    ds_eq_build(p.calendar, now);
    ds_eq_build(p.heap, now);
}

/* Reschedules disk i in both; each writes the time into its memory. */
static void set(pair p, uint32_t i, double t)
{
    if (soon_calls.until)
        soon_calls.until[i] = NAN;
    ds_eq_set(p.calendar, i, t);
    ds_eq_set(p.heap, i, t);
    assert_true(p.calendar_times[i].time == t);
    assert_true(p.heap_times[i].time == t);
}

/* Both agree on the earliest time and on the disk: with ties, the lowest
 * numbered disk of that time. Returns it. */
static uint32_t first(pair p)
{
    const uint32_t c = ds_eq_first(p.calendar), h = ds_eq_first(p.heap);
    assert_true(ds_eq_time(p.calendar, c) == ds_eq_time(p.heap, h));
    assert_int_equal(c, h);
    return c;
}

/* Exponential time to the next event, mean tau: what a disk's next event
 * looks like in a gas. */
static double ahead(ds_rng *rng, double tau)
{
    return -tau * log(1.0 - ds_rng_uniform(rng, 0.0, 1.0));
}

static void run_like_a_simulation(size_t n, uint64_t operations, double far_fraction, uint64_t seed)
{
    ds_rng rng;
    ds_rng_seed(&rng, seed);
    pair p = make(n);
    double *times = malloc(n * sizeof *times);
    assert_non_null(times);
    for (size_t i = 0; i < n; ++i)
        times[i] = ahead(&rng, 1.0);
    build(p, times, n, 0.0);
    double now = 0.0;
    for (uint64_t op = 0; op < operations; ++op) {
        const uint32_t i = first(p);
        const double t = ds_eq_time(p.calendar, i);
        assert_true(t >= now); /* time never runs backwards */
        /* A disk named since its last reschedule was named with the end
         * of the bucket its time is in, or of a later one (a stale entry
         * of a disk moved earlier): an integrator that finds a named
         * disk's time past `until` may leave it, it is named again. The
         * slack is rounding: until is (b + 1) times the bucket width,
         * computed from the inverse width, off by an ulp or two. */
        if (soon_calls.until && !isnan(soon_calls.until[i])) {
            assert_true(t < soon_calls.until[i] * (1.0 + 1e-12));
            ++soon_calls.checked;
        }
        now = t;
        /* The disk itself, then (a collision) its partner, sometimes far
         * ahead (beyond the window), sometimes exactly now. */
        const double u = ds_rng_uniform(&rng, 0.0, 1.0);
        set(p, i, u < far_fraction ? now + 50.0 * (double)n : now + ahead(&rng, 1.0));
        if (u > 0.5) {
            const uint32_t j = (uint32_t)(ds_rng_next(&rng) % n);
            set(p, j, u > 0.98 ? now : now + ahead(&rng, 1.0));
        }
        /* Rescheduled to the time it already has: the calendar's old entry
         * and its new one both name it at that time, and it must still
         * come exactly once per time (the heap says when). */
        if (u > 0.9 && u < 0.93) {
            const uint32_t j = (uint32_t)(ds_rng_next(&rng) % n);
            set(p, j, ds_eq_time(p.calendar, j));
        }
    }
    free(times);
    destroy(p);
}

static void test_calendar_agrees_with_heap_in_a_gas_like_run(void **state)
{
    (void)state;
    run_like_a_simulation(1000, 200000, 0.0, 1);
    run_like_a_simulation(17, 50000, 0.0, 2);
    run_like_a_simulation(1, 1000, 0.0, 3);
}

static void test_calendar_agrees_with_heap_with_times_beyond_its_window(void **state)
{
    (void)state;
    run_like_a_simulation(500, 100000, 0.05, 4);
}

static void test_rest_and_ties_are_handled(void **state)
{
    (void)state;
    /* Disks at rest have no event (+infinity); disks with equal times all
     * come before any later one; only +infinity left is still "first". */
    const size_t n = 64;
    pair p = make(n);
    double times[64];
    for (size_t i = 0; i < n; ++i)
        times[i] = i % 3 == 0 ? INFINITY : 2.0;
    build(p, times, n, 0.0);
    uint32_t last = 0;
    for (int k = 0; k < 42; ++k) {
        const uint32_t i = first(p);
        assert_true(ds_eq_time(p.calendar, i) == 2.0);
        assert_true(k == 0 || i > last); /* ties in the order of the disks */
        last = i;
        set(p, i, INFINITY);
    }
    const uint32_t i = first(p);
    assert_true(isinf(ds_eq_time(p.calendar, i)));
    set(p, 5, 7.5); /* back from rest */
    assert_int_equal(first(p), 5);
    destroy(p);
}

/* Takes `count` disks off the front, each sent to rest (+infinity) once
 * taken: their times must never go backwards. */
static void take_in_order(pair p, size_t count)
{
    double last = 0.0;
    for (size_t k = 0; k < count; ++k) {
        const uint32_t i = first(p);
        const double t = ds_eq_time(p.calendar, i);
        assert_true(t >= last);
        last = t;
        set(p, i, INFINITY);
    }
}

static void test_a_bucket_fuller_than_a_cache_line_loses_nothing(void **state)
{
    (void)state;
    /* Every disk within one bucket's width: the bucket spills into its
     * pool, and the order is still exact. */
    const size_t n = 4096;
    pair p = make(n);
    double *times = malloc(n * sizeof *times);
    assert_non_null(times);
    for (size_t i = 0; i < n; ++i)
        times[i] = 1.0 + (double)i * 1e-3;
    build(p, times, n, 0.0);
    for (size_t i = 0; i < n; ++i)
        set(p, (uint32_t)i, 5.0 + (double)((i * 7919) % n) * 1e-9);
    take_in_order(p, n);
    free(times);
    destroy(p);
}

static void test_rescheduling_the_same_disk_many_times_runs_in_bounded_memory(void **state)
{
    (void)state;
    /* Each reschedule leaves a stale entry behind; a disk rescheduled over
     * and over into the future must not exhaust anything (the calendar
     * rebuilds itself from the times when its pool runs out). */
    const size_t n = 8;
    pair p = make(n);
    double times[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    build(p, times, n, 0.0);
    for (int k = 0; k < 100000; ++k)
        set(p, (uint32_t)(k % 8), 1.0 + 1e-6 * (double)(k % 977));
    for (int k = 0; k < 8; ++k) {
        const uint32_t i = first(p);
        set(p, i, INFINITY);
    }
    destroy(p);
}

static void test_disks_rescheduled_beyond_the_window_again_and_again_keep_their_order(void **state)
{
    (void)state;
    /* The far list takes a disk again each time it is rescheduled beyond
     * the window, stale entries and all, until it is full and the
     * calendar rebuilds itself from the times. Then some come back into
     * the window, and every disk must still come in time order. */
    const size_t n = 8;
    pair p = make(n);
    double times[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    build(p, times, n, 0.0);
    for (int k = 0; k < 10000; ++k)
        set(p, (uint32_t)(k % 8), 1e4 + (double)((k * 7919) % 10007));
    set(p, 3, 2.5);
    set(p, 5, 9.0);
    take_in_order(p, n);
    assert_true(isinf(ds_eq_time(p.calendar, first(p))));
    destroy(p);
}

static void test_the_large_mode_names_disks_before_their_turn(void **state)
{
    (void)state;
    /* In a gas-like run every disk whose time comes first was named ahead
     * of it (at least once per bucket read: about one name per event),
     * before the end of time that the name gives. */
    const size_t n = 2000;
    soon_calls.count = soon_calls.checked = 0;
    soon_calls.until = malloc(n * sizeof *soon_calls.until);
    assert_non_null(soon_calls.until);
    for (size_t i = 0; i < n; ++i)
        soon_calls.until[i] = NAN;
    large_mode = 1;
    run_like_a_simulation(n, 100000, 0.0, 5);
    large_mode = 0;
    free(soon_calls.until);
    soon_calls.until = NULL;
    assert_true(soon_calls.count > 50000);
    /* Most disks come up after a name, each checked against its until. */
    assert_true(soon_calls.checked > 50000);
}

static void test_bad_sizes_are_refused(void **state)
{
    (void)state;
    ds_event_queue *q = NULL;
    double times[4];
    assert_int_equal(ds_eq_create(&q, 0, DS_EQ_CALENDAR, times, sizeof *times), DS_ERR_ARG);
    assert_int_equal(ds_eq_create(&q, (size_t)1 << 30, DS_EQ_HEAP, times, sizeof *times),
                     DS_ERR_ARG);
    assert_int_equal(ds_eq_create(NULL, 4, DS_EQ_HEAP, times, sizeof *times), DS_ERR_ARG);
    assert_int_equal(ds_eq_create(&q, 4, DS_EQ_HEAP, NULL, sizeof *times), DS_ERR_ARG);
    assert_int_equal(ds_eq_create(&q, 4, DS_EQ_CALENDAR, times, 4), DS_ERR_ARG);
    assert_null(q);
    ds_eq_destroy(NULL);
}

static int plain(void **state)
{
    (void)state;
    large_mode = 0;
    return 0;
}

static int large(void **state)
{
    (void)state;
    large_mode = 1;
    return 0;
}

int main(void)
{
    const struct CMUnitTest in_both_modes[] = {
        cmocka_unit_test(test_calendar_agrees_with_heap_in_a_gas_like_run),
        cmocka_unit_test(test_calendar_agrees_with_heap_with_times_beyond_its_window),
        cmocka_unit_test(test_rest_and_ties_are_handled),
        cmocka_unit_test(test_a_bucket_fuller_than_a_cache_line_loses_nothing),
        cmocka_unit_test(test_rescheduling_the_same_disk_many_times_runs_in_bounded_memory),
        cmocka_unit_test(test_disks_rescheduled_beyond_the_window_again_and_again_keep_their_order),
    };
    int failed = cmocka_run_group_tests_name("calendar in cache", in_both_modes, plain, NULL);
    failed +=
        cmocka_run_group_tests_name("calendar larger than the caches", in_both_modes, large, plain);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_the_large_mode_names_disks_before_their_turn),
        cmocka_unit_test(test_bad_sizes_are_refused),
    };
    return failed + cmocka_run_group_tests(tests, NULL, NULL);
}
