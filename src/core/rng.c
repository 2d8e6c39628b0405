/* SPDX-License-Identifier: MIT */
/* xorshift64* (Vigna, "An experimental exploration of Marsaglia's xorshift
 * generators, scrambled", 2016): 64-bit state, period 2^64-1, passes BigCrush
 * on the high bits, which are the ones ds_rng_uniform uses. */
#include "disk_sim.h"

/* splitmix64 finaliser: spreads nearby seeds (0, 1, 2...) over the state
 * space so that consecutive seeds give unrelated streams. */
static uint64_t mix_seed(uint64_t z)
{
    z += 0x9E3779B97F4A7C15u;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

void ds_rng_seed(ds_rng *rng, uint64_t seed)
{
    uint64_t s = mix_seed(seed);
    rng->state = s ? s : 0x9E3779B97F4A7C15u; /* xorshift state must not be 0 */
}

uint64_t ds_rng_next(ds_rng *rng)
{
    uint64_t s = rng->state;
    s ^= s >> 12;
    s ^= s << 25;
    s ^= s >> 27;
    rng->state = s;
    return s * 0x2545F4914F6CDD1Du;
}

double ds_rng_uniform(ds_rng *rng, double a, double b)
{
    /* 53 high bits scaled by 2^-53: every value k/2^53, k < 2^53, equally
     * likely, so the result is in [0,1) exactly. */
    double u = (double)(ds_rng_next(rng) >> 11) * (1.0 / 9007199254740992.0);
    double r = a + (b - a) * u;
    return r < b ? r : a; /* (b-a)*u can round up to b when a != 0 */
}
