/* SPDX-License-Identifier: MIT */
/* The disks command's one header: what its files share. options.c reads
 * the command line; start.c checks the request; outputs.c checks and
 * makes the directories; files.c writes files so that no partial one is
 * ever seen; report.c says what went wrong; disks.c runs. The command
 * uses the library only through disk_sim.h, and only it prints. */
#ifndef DISKS_CLI_H
#define DISKS_CLI_H

#include <signal.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "disk_sim.h"

enum { EXIT_RUN = 1, EXIT_USAGE = 2 };
#define MAX_FRAMES 10000 /* frame_NNNN.txt has four digits */

typedef struct options {
    size_t n;
    double radius;
    uint64_t seed;
    long frames;
    uint64_t steps_per_frame;
    const char *out_dir;
    const char *stats_path;
    const char *trajectory_path;
    int quiet, velocities;
    ds_broadphase broadphase;
    ds_integrator integrator;
    ds_placement placement;
    ds_boundary boundary;
    double box_y; /* 0: square */
} options;

/* gcc and clang check die's format and know it does not return. */
#if defined(__GNUC__)
#define DIES __attribute__((noreturn, format(printf, 2, 3)))
#else
#define DIES
#endif

/* report.c: "disks: " and the message on one line of stderr, then exit. */
void die(int code, const char *fmt, ...) DIES;

/* options.c */
options parse_args(int argc, char **argv);

/* start.c */
void check_request(const ds_params *p);

/* files.c */
void block_signals(sigset_t *old);
int write_file_atomic(const char *dir, const char *name, const char *data, size_t len,
                      const char **why);
int is_special_file(const char *path);
int write_file_in_place(const char *path, const char *data, size_t len, const char **why);

typedef struct trajectory {
    FILE *f;
    const char *path;
    char *buf;
    size_t cap;
} trajectory;

void trajectory_open(trajectory *t, const char *path, const char *dir, const char *base,
                     const ds_sim *sim);
void trajectory_append(trajectory *t, const ds_sim *sim);
void trajectory_close(trajectory *t);

/* outputs.c */
void make_dirs(const char *path);
const char *output_split(const char *option, const char *path, char *dir, size_t dir_cap);

#endif
