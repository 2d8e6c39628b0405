/* SPDX-License-Identifier: MIT */
/* Large arrays that the event-driven integrator reads at random, one
 * cache line here and one there: backed by 2 MB pages where the system
 * offers them, so that each access does not also miss the TLB (with 4 KB
 * pages, a 16 MB array is 4096 pages, twice what the second-level TLB of
 * a current x86 core holds). Freed with free(). Not installed. */
#ifndef DS_LARGE_ALLOC_H
#define DS_LARGE_ALLOC_H

#include <stddef.h>

/* bytes of memory aligned to 64 (a cache line), or NULL. From 4 MB up the
 * block is aligned to 2 MB and the kernel asked to back it with huge
 * pages (madvise, where it exists; a hint it may ignore). */
void *ds_large_alloc(size_t bytes);

#endif
