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
    ds_params params = ds_params_default(400, 5.0);
    ds_sim *sim = NULL;
    ds_error err;
    if (ds_sim_create(&params, NULL, &sim, &err) != DS_OK) {
        /* The library never prints: what went wrong comes back as a status
         * and, in err, the field at fault, its value, the limit and why. */
        fprintf(stderr, "ds_sim_create: %s\n", err.message);
        return 1;
    }

    ds_sim_run(sim, 49900, NULL); /* 499 frames x 100 steps, as disks 400 5 */

    printf("libdisksim %s: %zu disks, %.1f simulated seconds\n", ds_version(),
           ds_sim_get_count(sim), ds_sim_get_time(sim));
    printf("collision processing time: %.6f s, %llu collisions\n",
           ds_sim_get_collision_seconds(sim), (unsigned long long)ds_sim_get_collision_count(sim));
    ds_sim_destroy(sim);
    return 0;
}
