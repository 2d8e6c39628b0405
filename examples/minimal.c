/* SPDX-License-Identifier: MIT */
/* The smallest complete program on libdisksim: create a simulation, run it,
 * print the classic exercise's figure (time spent on disk-disk collisions).
 *
 *   cc minimal.c $(pkg-config --cflags --libs disksim) -o minimal && ./minimal
 */
#include <stdio.h>

#include <disk_sim.h>

int main(void)
{
    /* 400 disks of radius 5; box 1000, speed 100, dt 0.001 by default. */
    ds_params params = ds_default_params(400, 5.0);
    ds_sim *sim = NULL;
    ds_status status = ds_create(&params, &sim);
    if (status != DS_OK) {
        /* The library never prints: what went wrong comes back as a status. */
        fprintf(stderr, "ds_create: %s\n", ds_status_str(status));
        return 1;
    }

    ds_run(sim, 49900); /* 499 frames x 100 steps, as disks 400 5 */

    printf("libdisksim %s: %zu disks, %.1f simulated seconds\n", ds_version(), ds_count(sim),
           ds_time(sim));
    printf("collision processing time: %.6f s, %llu collisions\n", ds_collision_seconds(sim),
           (unsigned long long)ds_collision_count(sim));
    ds_destroy(sim);
    return 0;
}
