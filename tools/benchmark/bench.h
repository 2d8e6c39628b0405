/* SPDX-License-Identifier: MIT */
/* What the sections of tools/bench share (bench_stats.c), and the
 * event-driven and event-chain sections (bench_events.c, bench_chain.c)
 * that bench.c runs. */
#ifndef DS_BENCH_H
#define DS_BENCH_H

/* Every section runs in ROUNDS rounds, each running every case of the
 * section once (same seed every time). A shared machine's load drifts:
 * cases of one round see about the same load, so a ratio between two cases
 * is taken within each round, and the table shows medians over rounds
 * (of each case's time, and of each ratio). */
#define ROUNDS 5

/* The median of v[0..count), count odd; v is left sorted. */
double median(double *v, int count);
/* The median over rounds of a[k] / b[k]. */
double median_ratio(const double *a, const double *b);
/* Peak resident set size of this process so far, KB (-1 if unknown). */
long peak_rss_kb(void);

/* Section 5, the event-driven integrator (bench_events.c); 0 on failure. */
int bench_events(void);
/* `bench events N [C]`: one collision-rate case at area fraction 0.5,
 * timed after about C collisions per disk (1 by default). */
int bench_events_one(unsigned long n, double per_disk);

/* Section 6, event-chain Monte Carlo (bench_chain.c); 0 on failure. */
int bench_chain(void);
/* `bench chain N`: one event-chain case at area fraction 0.70, periodic. */
int bench_chain_one(unsigned long n);

#endif
