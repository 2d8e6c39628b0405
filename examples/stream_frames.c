/* SPDX-License-Identifier: MIT */
/* Writes every frame of a run to stdout as one stream, for piping into
 * another program instead of filling a directory with frame_NNNN.txt files:
 *
 *   stream_frames N R [FRAMES [STEPS_PER_FRAME]] > run.txt
 *   stream_frames 400 5 | awk '/^# frame/ { k++ } END { print k " frames" }'
 *
 * Each frame is a comment line "# frame K time T", then one "x y R" line per
 * disk in generation order (the frame_NNNN.txt format), then two blank lines.
 * Two blank lines are gnuplot's separator between data blocks, so a saved
 * stream plots frame K with `plot "run.txt" index K using 1:2:3 with circles`,
 * and ds_frame_parse() reads a single block back since it skips comments
 * and blank lines. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include <disk_sim.h>

/* A positive whole number argument, or 0 if it is not one. */
static unsigned long positive_arg(const char *s)
{
    char *end;
    errno = 0;
    unsigned long v = strtoul(s, &end, 10);
    if (*s < '0' || *s > '9' || *end != '\0' || errno == ERANGE)
        return 0;
    return v;
}

int main(int argc, char **argv)
{
    if (argc < 3 || argc > 5) {
        fprintf(stderr, "usage: stream_frames N R [FRAMES [STEPS_PER_FRAME]]\n");
        return 2;
    }
    unsigned long n = positive_arg(argv[1]);
    double radius = strtod(argv[2], NULL);
    unsigned long frames = argc > 3 ? positive_arg(argv[3]) : 500;
    unsigned long steps = argc > 4 ? positive_arg(argv[4]) : 100;
    if (n == 0 || frames == 0 || steps == 0) {
        fprintf(stderr, "stream_frames: N, FRAMES and STEPS_PER_FRAME must be positive "
                        "whole numbers\n");
        return 2;
    }

    ds_params params = ds_params_default((size_t)n, radius);
    ds_sim *sim = NULL;
    ds_status status = ds_sim_create(&params, NULL, &sim, NULL); /* also refuses a bad R */
    if (status != DS_OK) {
        fprintf(stderr, "stream_frames: %s\n", ds_status_name(status));
        return 1;
    }

    for (unsigned long k = 0; k < frames; ++k) {
        if (k > 0)
            ds_sim_run(sim, steps, NULL);
        printf("# frame %lu time %.3f\n", k, ds_sim_get_time(sim));
        status = ds_frame_write(sim, 0, stdout, NULL);
        if (status == DS_OK && fputs("\n\n", stdout) == EOF)
            status = DS_ERR_IO;
        if (status != DS_OK) {
            /* A closed pipe or a full disk: stop rather than simulate for nobody. */
            fprintf(stderr, "stream_frames: frame %lu: %s\n", k, ds_status_name(status));
            ds_sim_destroy(sim);
            return 1;
        }
    }
    ds_sim_destroy(sim);
    return fflush(stdout) == 0 ? 0 : 1;
}
