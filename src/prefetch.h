/* A hint to bring the cache line holding *p in: a no-op where the compiler
 * has no way to say it. Never faults, whatever the address. */
#ifndef DS_PREFETCH_H
#define DS_PREFETCH_H

static inline void ds_prefetch(const void *p)
{
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

#endif
