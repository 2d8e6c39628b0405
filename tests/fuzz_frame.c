/* SPDX-License-Identifier: MIT */
/* libFuzzer harness for the frame reader: any bytes at all must give either
 * a well-formed frame or DS_ERR_FORMAT with a line number inside the input,
 * never a crash, an out-of-bounds read (ASan) or undefined behaviour (UBSan).
 *
 *   make fuzz FUZZ_SECONDS=30     clang -fsanitize=fuzzer,address,undefined
 *
 * tests/test_frame_corpus.c includes this file to replay tests/corpus/
 * (the seeds and every crash ever found) in the ordinary test suite. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "disk_sim.h"

/* Counts the lines of data the way the reader numbers them. */
static size_t count_lines(const uint8_t *data, size_t size)
{
    size_t lines = size ? 1 : 0;
    for (size_t k = 0; k + 1 < size; ++k)
        lines += data[k] == '\n';
    return lines;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* A private copy of exactly size bytes, no terminator: ASan then flags
     * any read past the end, which a NUL-terminated copy would hide. */
    char *text = malloc(size ? size : 1);
    if (!text)
        return 0;
    if (size)
        memcpy(text, data, size);

    ds_frame frame;
    ds_error err;
    ds_status st = ds_frame_parse(text, size, &frame, &err);
    if (st == DS_OK) {
        if (frame.count == 0 || !frame.disks || (frame.columns != 3 && frame.columns != 5))
            abort();
        for (size_t i = 0; i < frame.count; ++i) {
            const ds_frame_disk *d = &frame.disks[i];
            if (!isfinite(d->x) || !isfinite(d->y) || !(d->r > 0.0) || !isfinite(d->r) ||
                !isfinite(d->vx) || !isfinite(d->vy))
                abort();
            if (frame.columns == 3 && (d->vx != 0.0 || d->vy != 0.0))
                abort();
        }
        ds_frame_free(&frame);
    } else {
        /* The error names a real line (or none) and a terminated message,
         * and nothing is left allocated. */
        if (st != DS_ERR_FORMAT && st != DS_ERR_NOMEM)
            abort();
        if (frame.disks || frame.count || err.index > count_lines(data, size))
            abort();
        if (!memchr(err.message, '\0', sizeof err.message) || !err.message[0])
            abort();
    }
    free(text);
    return 0;
}
