/* SPDX-License-Identifier: MIT */
/* What `disks --help` prints: every option the command reads
 * (options.c), each with its range and default. docs/cli.md and
 * man/disks.1 document the same options (tests/check_docs.sh compares
 * them with this text). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>

#include "cli.h"

/* Two strings: C99 promises a literal of 4095 characters only
 * (-Woverlength-strings), and the help is longer. */
static const char usage_first[] =
    "usage: disks N R [options]\n"
    "       disks N --area-fraction ETA [options]\n"
    "       disks --restart FILE [options]\n"
    "       disks [N R] --from FRAME [options]\n"
    "Simulates N hard disks of radius R in the box [0,L] x [0,H] (1000 x 1000\n"
    "unless told) and writes frame_0000.txt, frame_0001.txt, ... with one line\n"
    "\"x y R\" per disk.\n"
    "\n"
    "options:\n"
    "  --seed S             random seed, 0..2^64-1 (default %u)\n"
    "  --frames F           frames to write, 1..10000 (default 500)\n"
    "  --steps-per-frame K  steps of dt = 0.001 between frames (default 100)\n"
    "  --out DIR            directory for the frames, created if missing (default .)\n"
    "  --overwrite          remove the frames of another run from DIR instead of\n"
    "                       refusing to mix them with this run's\n"
    "  --velocities         write \"x y R vx vy\" lines instead of \"x y R\"\n"
    "  --stats FILE         write one CSV row of observables per frame to FILE\n"
    "  --trajectory FILE    also write every frame to FILE, one extended XYZ trajectory\n"
    "  --gsd FILE           also write every frame to FILE, one GSD trajectory (HOOMD)\n"
    "  --checkpoint FILE    write an exact checkpoint to FILE at the end, and when\n"
    "                       stopped by a signal (INT, TERM, HUP)\n"
    "  --checkpoint-every K also every K frames\n"
    "  --restart FILE       continue the run a checkpoint saved: N, R, the box, the\n"
    "                       integrator and the frame number come from FILE\n"
    "  --from FRAME         start at time 0 from the disks of FRAME, a frame written\n"
    "                       with --velocities (N and R from it)\n"
    "  --lattice            start on a triangular lattice instead of at random\n"
    "  --boundary B         walls (the default), periodic (nearest image along both\n"
    "                       axes) or channel (periodic along x, walls at y = 0 and\n"
    "                       y = box_y)\n"
    "  --periodic           the same as --boundary periodic\n"
    "  --box L              width of the box, 0 < L <= 1e9 (default 1000)\n"
    "  --box-y H            height of the box, 0 < H <= 1e9 (default L, square)\n"
    "  --area-fraction ETA  instead of R: the R at which the disks cover ETA of the\n"
    "                       box (0 < ETA < 1; with --mixture, R of the small ones)\n"
    "  --speed V            every disk's starting speed (default 100)\n"
    "  --dt DT              the time step, and the time between frames' steps with\n"
    "                       the event-driven integrator; with chain a step carries\n"
    "                       N x speed x DT of chain displacement (default 0.001)\n"
    "  --mixture RATIO:FRACTION\n"
    "                       a binary mixture: a FRACTION (0..1) of the disks have\n"
    "                       radius RATIO x R, the rest R (e.g. 1.4:0.5)\n"
    "  --mass M             equal (every disk mass 1, the default) or area (mass\n"
    "                       (r/R)^2)\n"
    "  --grow RATE          compress: every radius grows as r (1 + RATE t)\n"
    "                       (event-driven, periodic); until Z passes 1e6, or:\n"
    "  --until-eta ETA      stop growing at area fraction ETA, then run on\n"
    "  --until-z Z          stop growing, and the run, once Z passes Z (1 < Z <= 1e9)\n"
    "  --measure-after T    discard the start: the pressures and the wall counts of\n"
    "                       --stats and the report are averaged from the first frame\n"
    "                       at time >= T on\n";
static const char usage_rest[] =
    "  --restitution E      granular disks: each collision keeps E (0 < E <= 1) of\n"
    "                       the pair's normal approach speed (default 1, elastic)\n"
    "  --wall-restitution E the same at the walls\n"
    "  --contact-time T     the TC model's contact time: a collision within T of a\n"
    "                       disk's previous one is elastic (event; default 1e-4 of\n"
    "                       the time to cross a diameter at the initial speed)\n"
    "  --drive S            white-noise kicks at every step's end: each velocity\n"
    "                       component's variance grows by S per unit time\n"
    "  --gravity G          a field of magnitude G pulling down, toward y = 0 (box\n"
    "                       units per time squared); needs walls along y (walls or\n"
    "                       channel)\n"
    "  --thermostat KIND    a heat bath: andersen (each disk's velocity redrawn from\n"
    "                       Maxwell-Boltzmann at Poisson times: the canonical\n"
    "                       ensemble) or isokinetic (every velocity scaled to the\n"
    "                       temperature at each step's end); none (the default)\n"
    "  --temperature KT     its temperature, an energy: mass 1 at speed v is v^2 / 2\n"
    "                       (default: the start's, 5000 at the default speed 100)\n"
    "  --thermostat-rate NU andersen's collisions with the bath per disk per unit\n"
    "                       time (default 0.1 sqrt(KT) / (2 R))\n"
    "  --pressure BP        Monte Carlo moves of the box at the reduced pressure\n"
    "                       beta P sigma^2 (sigma the largest diameter; periodic)\n"
    "  --barostat-every K   a move of the box every K steps (default 10)\n"
    "  --barostat-step D    the largest change of ln(area) a move proposes (default\n"
    "                       1 / (4 N))\n"
    "  --barostat-aspect    also moves of the box's aspect at fixed area (crystals)\n"
    "  --integrator I       step (the fixed time step, default), event (exact\n"
    "                       event-driven dynamics) or chain (event-chain Monte Carlo:\n"
    "                       equilibrium sampling without dynamics)\n"
    "  --broadphase B       step: sap, strips, brute or auto; event and chain:\n"
    "                       cells, brute or auto (default auto)\n"
    "  -q, --quiet          print nothing but errors and warnings\n"
    "  -h, --help           show this help and exit\n"
    "  --version            show the version and exit\n"
    "\n"
    "exit status: 0 success, 1 run-time error (placement, I/O, a file that does not\n"
    "fit), 2 usage error; stopped by a signal, the signal's (128 + its number)\n";

void print_usage(void)
{
    printf(usage_first, (unsigned)DS_DEFAULT_SEED);
    fputs(usage_rest, stdout);
}
