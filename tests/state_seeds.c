/* SPDX-License-Identifier: MIT */
/* Writes small checkpoints of every integrator, boundary and broad phase
 * into the directory given: the seeds of the checkpoint fuzzer
 * (tests/fuzz_state.c, make fuzz). */
#include <stdio.h>

#include "disk_sim.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s DIR\n", argv[0]);
        return 2;
    }
    static const struct {
        ds_integrator integrator;
        ds_broadphase broadphase;
    } kinds[] = {{DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_SAP},
                 {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_STRIPS},
                 {DS_INTEGRATOR_TIME_STEP, DS_BROADPHASE_BRUTE},
                 {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_CELLS},
                 {DS_INTEGRATOR_EVENT_DRIVEN, DS_BROADPHASE_BRUTE}};
    int written = 0;
    for (int k = 0; k < 5; ++k)
        for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
            ds_params p = ds_params_default(6, 60.0);
            p.box_y = 600.0;
            p.integrator = kinds[k].integrator;
            p.broadphase = kinds[k].broadphase;
            p.boundary = (ds_boundary)b;
            ds_sim *sim = NULL;
            if (ds_sim_create(&p, NULL, &sim, NULL) != DS_OK)
                return 1;
            ds_sim_run(sim, 5, NULL);
            char path[4096];
            snprintf(path, sizeof path, "%s/seed-%s-%s-%s.state", argv[1],
                     ds_integrator_name(p.integrator), ds_broadphase_name(p.broadphase),
                     ds_boundary_name(p.boundary));
            FILE *f = fopen(path, "wb");
            if (!f || ds_checkpoint_save(sim, f, NULL) != DS_OK || fclose(f) != 0)
                return 1;
            ds_sim_destroy(sim);
            ++written;
        }
    printf("state_seeds: %d checkpoints in %s\n", written, argv[1]);
    return 0;
}
