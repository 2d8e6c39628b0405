/* Shared includes and helpers for the cmocka tests. */
#ifndef DS_TEST_UTIL_H
#define DS_TEST_UTIL_H

#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "disk_sim.h"

/* Creates a simulation or fails the test. */
static inline ds_sim *test_create(size_t n, double radius, uint64_t seed, ds_broadphase bp)
{
    ds_params p = ds_default_params(n, radius);
    p.seed = seed;
    p.broadphase = bp;
    ds_sim *sim = NULL;
    assert_int_equal(ds_create(&p, &sim), DS_OK);
    assert_non_null(sim);
    return sim;
}

#endif
