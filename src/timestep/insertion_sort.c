/* SPDX-License-Identifier: MIT */
/* The insertion sort that keeps the slots in x order between steps, for
 * DS_BROADPHASE_SAP (the whole range) and DS_BROADPHASE_STRIPS (one strip at a time). The
 * order barely changes from one step to the next, so the sort is nearly
 * linear: it spends its time looking for the few disks out of order. */
#include <stdlib.h>
#include <string.h>

#include "timestep/broad_phase.h"

/* AVX-512 code is compiled with gcc/clang target attributes on x86-64
 * whatever the build flags, and run only on a CPU that has it. */
#if defined(__GNUC__) && defined(__x86_64__)
#define HAVE_X86_VECTORS 1
#include <immintrin.h>
#endif

/* The first k' in [k, hi) with x[k'] < x[k' - 1], or hi. Between two steps
 * only a few disks in a hundred change order, so this is where the sort
 * spends its time. */
static size_t next_inversion_portable(const double *x, size_t k, size_t hi)
{
    while (k < hi && !(x[k] < x[k - 1]))
        ++k;
    return k;
}

#if defined(HAVE_X86_VECTORS)
/* Eight neighbours per comparison: one predictable branch per eight disks
 * instead of one per disk. */
__attribute__((target("avx512f"))) static size_t next_inversion_avx512(const double *x, size_t k,
                                                                       size_t hi)
{
    for (; k + 8 <= hi; k += 8) {
        const unsigned down = (unsigned)_mm512_cmp_pd_mask(_mm512_loadu_pd(x + k),
                                                           _mm512_loadu_pd(x + k - 1), _CMP_LT_OQ);
        if (down)
            return k + (size_t)__builtin_ctz(down);
    }
    return next_inversion_portable(x, k, hi);
}
#endif

static size_t next_inversion(ds_scan scan, const double *x, size_t k, size_t hi)
{
#if defined(HAVE_X86_VECTORS)
    if (scan == DS_SCAN_AVX512)
        return next_inversion_avx512(x, k, hi);
#endif
    (void)scan;
    return next_inversion_portable(x, k, hi);
}

void ds_bp_insertion_sort(ds_disks *d, size_t lo, size_t hi, ds_scan scan)
{
    const double *x = d->x;
    for (size_t k = next_inversion(scan, x, lo + 1, hi); k < hi;
         k = next_inversion(scan, x, k + 1, hi)) {
        const ds_disk_record held = ds_disks_load(d, k);
        size_t j = k;
        do {
            ds_disks_copy(d, j, d, j - 1);
            --j;
        } while (j > lo && held.x < x[j - 1]);
        ds_disks_store(d, j, held);
    }
}

/* Merges the sorted runs order[lo, mid) and order[mid, hi) by x into
 * scratch, the left run first on equal x (stable), and copies back. */
static void merge_runs(const double *x, uint32_t *order, uint32_t *scratch, size_t lo, size_t mid,
                       size_t hi)
{
    size_t a = lo, b = mid, w = lo;
    while (a < mid && b < hi)
        scratch[w++] = x[order[b]] < x[order[a]] ? order[b++] : order[a++];
    while (a < mid)
        scratch[w++] = order[a++];
    while (b < hi)
        scratch[w++] = order[b++];
    memcpy(order + lo, scratch + lo, (hi - lo) * sizeof *order);
}

ds_status ds_bp_sort(ds_disks *d, ds_scan scan)
{
    const size_t n = d->n;
    uint32_t *order = malloc((n ? n : 1) * sizeof *order);
    uint32_t *scratch = malloc((n ? n : 1) * sizeof *scratch);
    ds_status st = order && scratch ? DS_OK : DS_ERR_NOMEM;
    if (st == DS_OK) {
        for (size_t k = 0; k < n; ++k)
            order[k] = (uint32_t)k;
        /* Bottom-up merge sort: runs of 1, 2, 4, ... */
        for (size_t width = 1; width < n; width *= 2)
            for (size_t lo = 0; lo + width < n; lo += 2 * width)
                merge_runs(d->x, order, scratch, lo, lo + width,
                           lo + 2 * width < n ? lo + 2 * width : n);
        st = ds_disks_permute(d, order);
    }
    free(order);
    free(scratch);
    if (st != DS_OK) /* no memory for the copy: the slow way, in place */
        ds_bp_insertion_sort(d, 0, n, scan);
    return DS_OK;
}
