/* SPDX-License-Identifier: MIT */
/* Large arrays on huge pages (see large_alloc.h). */
#define _DEFAULT_SOURCE /* madvise and MADV_HUGEPAGE (glibc, musl) */
#define _POSIX_C_SOURCE 200112L
#include <stdlib.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "core/large_alloc.h"

#define HUGE_PAGE ((size_t)2 << 20)
#define HUGE_FROM ((size_t)4 << 20)

void *ds_large_alloc(size_t bytes)
{
    const size_t align = bytes >= HUGE_FROM ? HUGE_PAGE : 64;
    /* Whole pages: the kernel backs only whole 2 MB pages with huge ones. */
    const size_t size =
        bytes >= HUGE_FROM ? (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE : (bytes ? bytes : 1);
    void *p = NULL;
    if (size < bytes || posix_memalign(&p, align, size) != 0)
        return NULL;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (align == HUGE_PAGE)
        (void)madvise(p, size, MADV_HUGEPAGE);
#endif
    return p;
}
