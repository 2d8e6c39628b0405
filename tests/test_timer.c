/* SPDX-License-Identifier: MIT */
/* The CLOCK_MONOTONIC timer: never backwards, accumulates intervals. No
 * test asserts an upper bound on a duration: the machine is shared. */
#include "test_util.h"

#include <time.h>

static void sleep_seconds(double s)
{
    struct timespec ts = {(time_t)s, (long)((s - (double)(time_t)s) * 1e9)};
    while (nanosleep(&ts, &ts) != 0) {
    }
}

static void test_clock_never_goes_backwards(void **state)
{
    (void)state;
    double prev = ds_timer_now();
    for (int k = 0; k < 100000; ++k) {
        double now = ds_timer_now();
        assert_true(now >= prev);
        prev = now;
    }
}

static void test_timer_measures_at_least_a_slept_interval(void **state)
{
    (void)state;
    ds_timer t;
    ds_timer_reset(&t);
    assert_true(ds_timer_seconds(&t) == 0.0);
    ds_timer_start(&t);
    sleep_seconds(0.02);
    ds_timer_stop(&t);
    assert_true(ds_timer_seconds(&t) >= 0.02);
}

static void test_timer_accumulates_over_start_stop_pairs(void **state)
{
    (void)state;
    ds_timer t;
    ds_timer_reset(&t);
    for (int k = 0; k < 3; ++k) {
        ds_timer_start(&t);
        sleep_seconds(0.01);
        ds_timer_stop(&t);
    }
    double total = ds_timer_seconds(&t);
    assert_true(total >= 0.03);
    /* Stopped: reading twice gives the same value, and stopping again
     * adds nothing. */
    sleep_seconds(0.01);
    ds_timer_stop(&t);
    assert_true(ds_timer_seconds(&t) == total);
}

static void test_running_timer_includes_current_interval(void **state)
{
    (void)state;
    ds_timer t;
    ds_timer_reset(&t);
    ds_timer_start(&t);
    sleep_seconds(0.01);
    double a = ds_timer_seconds(&t);
    assert_true(a >= 0.01);
    assert_true(ds_timer_seconds(&t) >= a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_clock_never_goes_backwards),
        cmocka_unit_test(test_timer_measures_at_least_a_slept_interval),
        cmocka_unit_test(test_timer_accumulates_over_start_stop_pairs),
        cmocka_unit_test(test_running_timer_includes_current_interval),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
