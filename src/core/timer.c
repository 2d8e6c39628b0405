/* SPDX-License-Identifier: MIT */
/* Monotonic wall-clock timer, the C counterpart of std::chrono::steady_clock. */
#define _POSIX_C_SOURCE 199309L
#include <time.h>

#include "disk_sim.h"

double ds_timer_now(void)
{
    struct timespec ts;
    /* CLOCK_MONOTONIC cannot fail with a valid pointer on POSIX systems. */
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void ds_timer_reset(ds_timer *timer)
{
    timer->started = 0.0;
    timer->total = 0.0;
    timer->running = 0;
}

void ds_timer_start(ds_timer *timer)
{
    timer->started = ds_timer_now();
    timer->running = 1;
}

void ds_timer_stop(ds_timer *timer)
{
    if (timer->running) {
        double elapsed = ds_timer_now() - timer->started;
        timer->total += elapsed > 0.0 ? elapsed : 0.0;
        timer->running = 0;
    }
}

double ds_timer_seconds(const ds_timer *timer)
{
    if (!timer->running)
        return timer->total;
    double elapsed = ds_timer_now() - timer->started;
    return timer->total + (elapsed > 0.0 ? elapsed : 0.0);
}
