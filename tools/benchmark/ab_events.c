/* Two builds of the library in one process (tools/benchmark/ab.sh): this file is
 * compiled once per build with AB_SIDE set to its symbol prefix (A_ or
 * B_), the prefix tools/benchmark/ab.sh gives every global symbol of that build's
 * libdisksim.a, and once with AB_MAIN for the program that alternates
 * them. Each side builds the same system (area fraction 0.5, walls,
 * event-driven, relaxed ~1 collision per disk), then the rounds time ~10^6
 * collisions on each side in turn, which side goes first alternating, so
 * that both see the same state of a shared, noisy machine. Prints each
 * side's median ns per collision and the median of the per-round ratios
 * B / A with its quartiles. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#if defined(AB_SIDE)
#include "disk_sim.h"

#define AB_CAT2(a, b) a##b
#define AB_CAT(a, b) AB_CAT2(a, b)
#define AB(x) AB_CAT(AB_SIDE, x)

/* The public calls, under this build's prefix. */
ds_params AB(ds_default_params)(size_t n, double radius);
ds_status AB(ds_create)(const ds_params *params, ds_sim **out);
void AB(ds_run)(ds_sim *sim, unsigned long steps);
uint64_t AB(ds_collision_count)(const ds_sim *sim);
double AB(ds_collision_seconds)(const ds_sim *sim);
void AB(ds_destroy)(ds_sim *sim);

void *AB(ab_make)(size_t n);
double AB(ab_round)(void *sim, size_t n);
void AB(ab_done)(void *sim);

/* Collisions per step at area fraction 0.5 (as tools/benchmark/bench_events.c). */
static double per_step(size_t n) { return 3.1e-4 * pow((double)n, 1.5); }

void *AB(ab_make)(size_t n)
{
    ds_params p = AB(ds_default_params)(n, sqrt(0.5 * 1e6 / ((double)n * 3.14159265358979)));
    p.integrator = DS_EVENT_DRIVEN;
    ds_sim *sim = NULL;
    if (AB(ds_create)(&p, &sim) != DS_OK)
        return NULL;
    AB(ds_run)(sim, (unsigned long)(0.5 * (double)n / per_step(n)) + 2);
    return sim;
}

double AB(ab_round)(void *s, size_t n)
{
    ds_sim *sim = s;
    unsigned long steps = (unsigned long)(1e6 / per_step(n));
    steps = steps < 4 ? 4 : steps;
    const uint64_t c0 = AB(ds_collision_count)(sim);
    const double s0 = AB(ds_collision_seconds)(sim);
    AB(ds_run)(sim, steps);
    return 1e9 * (AB(ds_collision_seconds)(sim) - s0) / (double)(AB(ds_collision_count)(sim) - c0);
}

void AB(ab_done)(void *sim) { AB(ds_destroy)(sim); }

#elif defined(AB_MAIN)
void *A_ab_make(size_t n);
double A_ab_round(void *sim, size_t n);
void A_ab_done(void *sim);
void *B_ab_make(size_t n);
double B_ab_round(void *sim, size_t n);
void B_ab_done(void *sim);

#define MAX_ROUNDS 1000

static int compare(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    const size_t n = argc > 1 ? strtoul(argv[1], NULL, 10) : 0;
    const int rounds = argc > 2 ? atoi(argv[2]) : 0;
    if (n < 2 || rounds < 1 || rounds > MAX_ROUNDS) {
        fprintf(stderr, "usage: %s N ROUNDS (N >= 2, 1 <= ROUNDS <= %d)\n", argv[0], MAX_ROUNDS);
        return 2;
    }
    void *a = A_ab_make(n), *b = B_ab_make(n);
    if (!a || !b) {
        fprintf(stderr, "%s: could not create the systems\n", argv[0]);
        return 1;
    }
    static double na[MAX_ROUNDS], nb[MAX_ROUNDS], ratio[MAX_ROUNDS];
    for (int r = 0; r < rounds; ++r) {
        if (r % 2) {
            nb[r] = B_ab_round(b, n);
            na[r] = A_ab_round(a, n);
        } else {
            na[r] = A_ab_round(a, n);
            nb[r] = B_ab_round(b, n);
        }
        ratio[r] = nb[r] / na[r];
    }
    qsort(na, (size_t)rounds, sizeof *na, compare);
    qsort(nb, (size_t)rounds, sizeof *nb, compare);
    qsort(ratio, (size_t)rounds, sizeof *ratio, compare);
    printf("N = %zu, %d rounds: A %.0f ns per collision, B %.0f (medians); B / A %.3f "
           "(quartiles %.3f, %.3f)\n",
           n, rounds, na[rounds / 2], nb[rounds / 2], ratio[rounds / 2], ratio[rounds / 4],
           ratio[(3 * rounds) / 4]);
    A_ab_done(a);
    B_ab_done(b);
    return 0;
}
#endif
