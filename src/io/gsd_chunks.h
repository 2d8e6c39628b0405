/* SPDX-License-Identifier: MIT */
/* The chunks of a GSD frame as the HOOMD schema names them, filled from a
 * simulation (gsd_chunks.c), for the GSD writer (gsd.c), which lays them
 * out in the file. Private to io/. Not installed. */
#ifndef DS_GSD_CHUNKS_H
#define DS_GSD_CHUNKS_H

#include "core/core.h"

/* The element types of the GSD file layer (gsd_type) the chunks use. */
enum {
    DS_GSD_UINT8 = 1,
    DS_GSD_UINT32 = 3,
    DS_GSD_UINT64 = 4,
    DS_GSD_INT8 = 5,
    DS_GSD_INT32 = 7,
    DS_GSD_FLOAT = 9,
    DS_GSD_DOUBLE = 10
};

/* What one frame logs (log/disksim/<name>), computed once per frame: the
 * columns of the command's --stats after frame, named as there. */
typedef struct ds_gsd_log {
    double time, kinetic_energy, px, py, pressure, virial_pressure, psi6, area_fraction;
    uint64_t collisions, wall_reflections;
} ds_gsd_log;

/* The log of sim now: DS_ERR_NOMEM (field "out") without memory for psi6. */
ds_status ds_gsd_log_of(const ds_sim *sim, ds_gsd_log *log, ds_error *err);

/* One chunk: its name, element type, whether every frame has it (the
 * others are in frame 0, and in a later frame only where they differ from
 * frame 0's: the schema reads a chunk a frame lacks from frame 0, N being
 * the same), and how its bytes are made: little-endian into w, *rows x
 * *cols elements (GSD's N x M). */
typedef struct ds_gsd_chunk {
    const char *name;
    uint8_t type;
    int every;
    void (*fill)(const ds_sim *sim, const ds_gsd_log *log, ds_state_writer *w, uint64_t *rows,
                 uint32_t *cols);
} ds_gsd_chunk;

/* Every chunk, in the order of the file's name list: a chunk's id is its
 * row. GSD sorts the index by frame, then id, so a frame's chunks are
 * written in this order. */
#define DS_GSD_CHUNK_COUNT 22
extern const ds_gsd_chunk ds_gsd_chunks[DS_GSD_CHUNK_COUNT];

/* Bytes the largest chunk of sim takes. */
size_t ds_gsd_chunk_cap(const ds_sim *sim);

#endif
