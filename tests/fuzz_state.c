/* SPDX-License-Identifier: MIT */
/* libFuzzer harness for the checkpoint loader: any bytes must give either
 * a simulation that runs or DS_ERR_FORMAT (or DS_ERR_NOMEM) with a reason,
 * never a crash, an out-of-bounds read (ASan), undefined behaviour
 * (UBSan) or a hang. The checksum would turn nearly every mutation away
 * at the door, so the harness writes the right one over the last 8 bytes:
 * the fuzzer then reaches the parser behind it. (tests/test_checkpoint.c
 * checks that a wrong checksum is refused.)
 *
 *   make fuzz FUZZ_SECONDS=30     seeds: checkpoints tests/state_seeds.c writes */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "disk_sim.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *copy = malloc(size ? size : 1);
    if (!copy)
        return 0;
    if (size)
        memcpy(copy, data, size);
    if (size >= 48) {
        uint64_t h = 14695981039346656037ull;
        for (size_t k = 0; k + 8 < size; ++k)
            h = (h ^ copy[k]) * 1099511628211ull;
        for (int k = 0; k < 8; ++k)
            copy[size - 8 + (size_t)k] = (uint8_t)(h >> (8 * k));
    }
    ds_sim *sim = NULL;
    ds_error err;
    const ds_status st = ds_checkpoint_parse(copy, size, &sim, &err);
    if (st == DS_OK) {
        /* A loaded state runs: a few steps, then its own checkpoint. */
        ds_sim_run(sim, 2, NULL);
        ds_sim_destroy(sim);
    } else if (st != DS_ERR_FORMAT && st != DS_ERR_NOMEM) {
        abort();
    } else if (!err.message[0]) {
        abort(); /* every refusal has a reason */
    }
    free(copy);
    return 0;
}
