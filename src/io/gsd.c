/* SPDX-License-Identifier: MIT */
/* GSD trajectories, the binary format HOOMD-blue writes and OVITO, VMD,
 * freud, MDAnalysis and gsd's Python module read, written from its
 * published specification: the GSD file layer 2.0 (a 256-byte header, a
 * list of chunk names, an index of 32-byte entries, the chunks' bytes)
 * and the HOOMD schema 1.4 (what the chunks are called and hold).
 *
 * The layout: the header at 0, the name list right after it (every name
 * this writer uses, so it never moves), then the index block, then the
 * chunks of frame after frame. A frame's chunks go to the end of the file
 * first and their index entries after them, so that a reader never
 * finds an entry pointing at bytes not yet written: after every frame the
 * file is a valid GSD file of the whole frames written. When the index
 * block fills up, a block twice the size is written at the end with every
 * entry, and only then does the header point at it (the old block stays,
 * unused). Every number is little-endian, as GSD files are on every
 * machine that writes them today. A stream that holds a file this writer
 * wrote is gone on with: its index and frame 0's chunks are read back,
 * and frames are appended as if it had never been closed. */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/gsd_chunks.h"
#include "io/io.h"

#define GSD_MAGIC 0x65DF65DF65DF65DFull
#define GSD_HEADER_BYTES 256
#define GSD_ENTRY_BYTES 32
#define GSD_NAME_BLOCK 64                   /* the name list is allocated in blocks of 64 bytes */
#define GSD_INDEX_FIRST 256u                /* entries of the first index block: 8 KiB */
#define GSD_FILE_VERSION (2u << 16)         /* 2.0, as 0xaaaabbbb */
#define GSD_HOOMD_VERSION ((1u << 16) | 4u) /* hoomd schema 1.4 */
#define GSD_APPLICATION "disksim " DS_VERSION_STRING

typedef struct gsd_entry {
    uint64_t frame, rows, location;
    uint32_t cols;
    uint16_t id;
    uint8_t type;
} gsd_entry;

/* frame 0's bytes of a chunk later frames may leave out */
typedef struct gsd_first {
    uint8_t *bytes;
    size_t len;
    uint64_t rows;
    uint32_t cols;
} gsd_first;

typedef struct gsd_writer {
    uint64_t frames;
    uint64_t end;                 /* the end of the file: the next chunk's place */
    uint64_t index_at, index_cap; /* the index block: where, and entries it holds */
    gsd_entry *entries;           /* every entry written, the index's copy */
    size_t count, entries_cap;
    gsd_first first[DS_GSD_CHUNK_COUNT];
    uint8_t *buf; /* one chunk's bytes */
    size_t buf_cap;
    size_t names; /* bytes of the name list */
    int failed;   /* a write failed: the file ends at its last whole frame */
} gsd_writer;

static ds_status refuse_io(gsd_writer *g, ds_error *err, const char *what)
{
    g->failed = 1;
    return ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: the write of %s failed", what);
}

static ds_status refuse_memory(gsd_writer *g, ds_error *err)
{
    g->failed = 1;
    return ds_refuse(err, DS_ERR_NOMEM, "out", NAN, NAN, "out: no memory for the GSD index");
}

/* len bytes at byte at of out: 0 if that fails (fseek takes a long). */
static int put_at(FILE *out, uint64_t at, const void *bytes, size_t len)
{
    return at <= (uint64_t)LONG_MAX && fseek(out, (long)at, SEEK_SET) == 0 &&
           fwrite(bytes, 1, len, out) == len;
}

static void header_bytes(const gsd_writer *g, uint8_t out[GSD_HEADER_BYTES])
{
    memset(out, 0, GSD_HEADER_BYTES);
    ds_state_writer w = {out, 0};
    ds_put_u64(&w, GSD_MAGIC);
    ds_put_u64(&w, g->index_at);
    ds_put_u64(&w, g->index_cap);
    ds_put_u64(&w, GSD_HEADER_BYTES);          /* the name list's place */
    ds_put_u64(&w, g->names / GSD_NAME_BLOCK); /* and its size, in blocks */
    ds_put_u32(&w, GSD_HOOMD_VERSION);
    ds_put_u32(&w, GSD_FILE_VERSION);
    memcpy(out + w.len, GSD_APPLICATION, strlen(GSD_APPLICATION)); /* 64 bytes, NUL-padded */
    memcpy(out + w.len + 64, "hoomd", 5);                          /* then the schema's */
}

static void entry_bytes(const gsd_entry *e, uint8_t out[GSD_ENTRY_BYTES])
{
    ds_state_writer w = {out, 0};
    ds_put_u64(&w, e->frame);
    ds_put_u64(&w, e->rows);
    ds_put_u64(&w, e->location);
    ds_put_u32(&w, e->cols);
    out[w.len] = (uint8_t)(e->id & 0xffu);
    out[w.len + 1] = (uint8_t)(e->id >> 8);
    out[w.len + 2] = e->type;
    out[w.len + 3] = 0; /* flags */
}

/* The entries of g from `from` on, then zeros, up to entry cap (not
 * included), written from byte at. */
static int put_entries(const gsd_writer *g, FILE *out, uint64_t at, size_t from, size_t cap)
{
    uint8_t block[64 * GSD_ENTRY_BYTES];
    for (size_t k = from; k < cap; k += 64) {
        const size_t some = cap - k < 64 ? cap - k : 64;
        memset(block, 0, sizeof block);
        for (size_t j = 0; j < some && k + j < g->count; ++j)
            entry_bytes(&g->entries[k + j], block + j * GSD_ENTRY_BYTES);
        if (!put_at(out, at + (k - from) * GSD_ENTRY_BYTES, block, some * GSD_ENTRY_BYTES))
            return 0;
    }
    return 1;
}

/* The entries from `from` on (this frame's) into the index: in place, or
 * with every entry in a block twice as large at the end of the file,
 * which the header then names. */
static int index_frame(gsd_writer *g, FILE *out, size_t from)
{
    if (g->count <= g->index_cap)
        return put_entries(g, out, g->index_at + from * GSD_ENTRY_BYTES, from, g->count);
    uint64_t cap = g->index_cap;
    while (cap < g->count)
        cap *= 2;
    uint8_t header[GSD_HEADER_BYTES];
    if (!put_entries(g, out, g->end, 0, (size_t)cap) || fflush(out) != 0)
        return 0;
    g->index_at = g->end;
    g->index_cap = cap;
    g->end += cap * GSD_ENTRY_BYTES;
    header_bytes(g, header);
    return put_at(out, 0, header, sizeof header);
}

/* Room for at least need entries in memory: 0 without it. */
static int make_entries(gsd_writer *g, size_t need)
{
    size_t cap = 2 * g->entries_cap + DS_GSD_CHUNK_COUNT;
    if (cap < need)
        cap = need;
    gsd_entry *e = realloc(g->entries, cap * sizeof *e);
    if (!e)
        return 0;
    g->entries = e;
    g->entries_cap = cap;
    return 1;
}

/* Room for a frame's entries, and for one chunk's bytes of sim. */
static int make_room(gsd_writer *g, const ds_sim *sim)
{
    if (g->count + DS_GSD_CHUNK_COUNT > g->entries_cap &&
        !make_entries(g, g->count + DS_GSD_CHUNK_COUNT))
        return 0;
    const size_t need = ds_gsd_chunk_cap(sim);
    if (need > g->buf_cap) {
        uint8_t *b = realloc(g->buf, need);
        if (!b)
            return 0;
        g->buf = b;
        g->buf_cap = need;
    }
    return 1;
}

/* Whether chunk c, just filled into g->buf, goes into this frame (and
 * frame 0's copy kept); 0 with *nomem set without memory for the copy. */
static int keeps(gsd_writer *g, size_t c, size_t len, uint64_t rows, uint32_t cols, int *nomem)
{
    gsd_first *f = &g->first[c];
    if (ds_gsd_chunks[c].every)
        return 1;
    if (g->frames > 0)
        return !(f->len == len && f->rows == rows && f->cols == cols &&
                 memcmp(f->bytes, g->buf, len) == 0);
    free(f->bytes);
    f->bytes = malloc(len);
    *nomem = !f->bytes;
    if (f->bytes)
        memcpy(f->bytes, g->buf, len);
    f->len = len;
    f->rows = rows;
    f->cols = cols;
    return !*nomem;
}

static ds_status write_frame(void *self, FILE *out, unsigned flags, const ds_sim *sim,
                             ds_error *err)
{
    (void)flags; /* velocities are always written */
    gsd_writer *g = self;
    if (g->failed)
        return ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: an earlier write failed");
    ds_gsd_log log;
    const ds_status st = ds_gsd_log_of(sim, &log, err);
    if (st != DS_OK)
        return st;
    if (!make_room(g, sim))
        return refuse_memory(g, err);
    const size_t from = g->count;
    for (size_t c = 0; c < DS_GSD_CHUNK_COUNT; ++c) {
        ds_state_writer w = {g->buf, 0};
        uint64_t rows = 0;
        uint32_t cols = 0;
        int nomem = 0;
        ds_gsd_chunks[c].fill(sim, &log, &w, &rows, &cols);
        if (!keeps(g, c, w.len, rows, cols, &nomem)) {
            if (nomem)
                return refuse_memory(g, err);
            continue;
        }
        if (!put_at(out, g->end, g->buf, w.len))
            return refuse_io(g, err, ds_gsd_chunks[c].name);
        g->entries[g->count++] =
            (gsd_entry){g->frames, rows, g->end, cols, (uint16_t)c, ds_gsd_chunks[c].type};
        g->end += w.len;
    }
    if (!index_frame(g, out, from) || fflush(out) != 0 || ferror(out))
        return refuse_io(g, err, "the index");
    ++g->frames;
    return DS_OK;
}

static void free_writer(gsd_writer *g)
{
    for (size_t c = 0; c < DS_GSD_CHUNK_COUNT; ++c)
        free(g->first[c].bytes);
    free(g->entries);
    free(g->buf);
    free(g);
}

/* Our name list: the chunks' names, each ended by a NUL, then the empty
 * name that ends the list, padded with NULs to whole blocks; *size its
 * bytes. NULL without memory. */
static char *name_list(size_t *size)
{
    size_t names = 1;
    for (size_t c = 0; c < DS_GSD_CHUNK_COUNT; ++c)
        names += strlen(ds_gsd_chunks[c].name) + 1;
    *size = (names + GSD_NAME_BLOCK - 1) / GSD_NAME_BLOCK * GSD_NAME_BLOCK;
    char *list = calloc(1, *size);
    size_t at = 0;
    for (size_t c = 0; list && c < DS_GSD_CHUNK_COUNT; ++c) {
        memcpy(list + at, ds_gsd_chunks[c].name, strlen(ds_gsd_chunks[c].name));
        at += strlen(ds_gsd_chunks[c].name) + 1;
    }
    return list;
}

/* A new file: the header, the name list and an empty index. */
static ds_status start_file(gsd_writer *g, FILE *out, const char *list, ds_error *err)
{
    g->index_at = GSD_HEADER_BYTES + g->names;
    g->index_cap = GSD_INDEX_FIRST;
    g->end = g->index_at + g->index_cap * GSD_ENTRY_BYTES;
    uint8_t header[GSD_HEADER_BYTES];
    header_bytes(g, header);
    if (put_at(out, 0, header, sizeof header) && put_at(out, GSD_HEADER_BYTES, list, g->names) &&
        put_entries(g, out, g->index_at, 0, g->index_cap) && fflush(out) == 0)
        return DS_OK;
    return ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: the write of the header failed");
}

/* ------------------------------------------------------------------ */
/* Going on with a file                                                */
/* ------------------------------------------------------------------ */

/* len bytes at byte at of out into buf: 0 if that fails. */
static int get_at(FILE *out, uint64_t at, void *buf, size_t len)
{
    return at <= (uint64_t)LONG_MAX && fseek(out, (long)at, SEEK_SET) == 0 &&
           fread(buf, 1, len, out) == len;
}

static uint64_t le_at(const uint8_t *p, int bytes)
{
    uint64_t v = 0;
    for (int k = 0; k < bytes; ++k)
        v |= (uint64_t)p[k] << (8 * k);
    return v;
}

/* Bytes of one element of the types the chunks use. */
static uint64_t type_bytes(uint8_t type)
{
    return type == DS_GSD_UINT8 || type == DS_GSD_INT8      ? 1
           : type == DS_GSD_UINT64 || type == DS_GSD_DOUBLE ? 8
                                                            : 4;
}

static ds_status refuse_foreign(ds_error *err, uint64_t size)
{
    return ds_refuse(err, DS_ERR_FORMAT, "out", (double)size, NAN,
                     "out: holds %llu bytes that are not a GSD file of this library's chunks",
                     (unsigned long long)size);
}

/* Whether entry e may follow the entries read so far: one of this
 * writer's chunks, inside the file, in the order the index keeps (by
 * frame, then id; frames from 0 without a gap). */
static int follows(const gsd_writer *g, const gsd_entry *e, uint64_t size)
{
    const gsd_entry *p = g->count ? &g->entries[g->count - 1] : NULL;
    const int in_order =
        p ? (e->frame == p->frame && e->id > p->id) || e->frame == p->frame + 1 : e->frame == 0;
    return in_order && e->id < DS_GSD_CHUNK_COUNT && e->type == ds_gsd_chunks[e->id].type &&
           e->rows <= size && e->cols <= size && e->location <= size &&
           e->rows * e->cols * type_bytes(e->type) <= size - e->location;
}

/* The index's entries into g, up to the first unused one. */
static ds_status read_index(gsd_writer *g, FILE *out, uint64_t size, ds_error *err)
{
    uint8_t block[64 * GSD_ENTRY_BYTES];
    for (uint64_t k = 0; k < g->index_cap; k += 64) {
        const size_t some = g->index_cap - k < 64 ? (size_t)(g->index_cap - k) : 64;
        if (!get_at(out, g->index_at + k * GSD_ENTRY_BYTES, block, some * GSD_ENTRY_BYTES))
            return refuse_foreign(err, size);
        for (size_t j = 0; j < some; ++j) {
            const uint8_t *b = block + j * GSD_ENTRY_BYTES;
            const gsd_entry e = {le_at(b, 8),
                                 le_at(b + 8, 8),
                                 le_at(b + 16, 8),
                                 (uint32_t)le_at(b + 24, 4),
                                 (uint16_t)le_at(b + 28, 2),
                                 b[30]};
            if (e.location == 0)
                return DS_OK;
            if (b[31] != 0 || !follows(g, &e, size))
                return refuse_foreign(err, size);
            if (g->count == g->entries_cap && !make_entries(g, g->count + 1))
                return refuse_memory(g, err);
            g->entries[g->count++] = e;
        }
    }
    return DS_OK;
}

/* Frame 0's bytes of the chunks later frames leave out when equal. */
static ds_status read_first(gsd_writer *g, FILE *out, uint64_t size, ds_error *err)
{
    for (size_t k = 0; k < g->count && g->entries[k].frame == 0; ++k) {
        const gsd_entry *e = &g->entries[k];
        gsd_first *f = &g->first[e->id];
        if (ds_gsd_chunks[e->id].every)
            continue;
        f->len = (size_t)(e->rows * e->cols * type_bytes(e->type));
        f->rows = e->rows;
        f->cols = e->cols;
        if (!(f->bytes = malloc(f->len ? f->len : 1)))
            return refuse_memory(g, err);
        if (!get_at(out, e->location, f->bytes, f->len))
            return refuse_foreign(err, size);
    }
    for (size_t c = 0; g->count > 0 && c < DS_GSD_CHUNK_COUNT; ++c)
        if (!ds_gsd_chunks[c].every && !g->first[c].bytes)
            return refuse_foreign(err, size); /* frame 0 holds every chunk */
    return DS_OK;
}

/* The file of size bytes on out, which this writer began: its frames
 * kept, the next appended at its end, into its index. Something else is
 * DS_ERR_FORMAT; a stream that cannot be read back DS_ERR_ARG. */
static ds_status resume(gsd_writer *g, FILE *out, uint64_t size, const char *list, ds_error *err)
{
    uint8_t h[GSD_HEADER_BYTES];
    const int got = size >= GSD_HEADER_BYTES && get_at(out, 0, h, sizeof h);
    if (!got && ferror(out)) {
        clearerr(out); /* the stream's flag, set by the read this writer tried */
        return ds_refuse(err, DS_ERR_ARG, "out", (double)size, NAN,
                         "out: holds %llu bytes, which a GSD writer goes on with only on a "
                         "stream it can read too (opened r+b or w+b)",
                         (unsigned long long)size);
    }
    if (!got || le_at(h, 8) != GSD_MAGIC || le_at(h + 44, 4) >> 16 != 2 ||
        memcmp(h + 112, "hoomd", 6) != 0 || le_at(h + 24, 8) != GSD_HEADER_BYTES ||
        le_at(h + 32, 8) * GSD_NAME_BLOCK != g->names)
        return refuse_foreign(err, size);
    char *names = malloc(g->names);
    if (!names)
        return refuse_memory(g, err);
    const int ours =
        get_at(out, GSD_HEADER_BYTES, names, g->names) && memcmp(names, list, g->names) == 0;
    free(names);
    g->index_at = le_at(h + 8, 8);
    g->index_cap = le_at(h + 16, 8);
    if (!ours || g->index_cap == 0 || g->index_at > size ||
        g->index_cap > (size - g->index_at) / GSD_ENTRY_BYTES)
        return refuse_foreign(err, size);
    ds_status st = read_index(g, out, size, err);
    if (st == DS_OK)
        st = read_first(g, out, size, err);
    g->frames = g->count ? g->entries[g->count - 1].frame + 1 : 0;
    g->end = size;
    return st;
}

/* A GSD file on out, begun already (this writer's, from its start: an
 * earlier run's, or one a restart goes on with), or a new one: the
 * stream must be able to seek. */
static ds_status open_gsd(FILE *out, unsigned flags, void **self, ds_error *err)
{
    (void)flags;
    const long size = fseek(out, 0, SEEK_END) == 0 ? ftell(out) : -1;
    if (size < 0)
        return ds_refuse(err, DS_ERR_ARG, "out", NAN, NAN,
                         "out: a GSD file is written at chosen places of its stream, which must "
                         "be able to seek: a file, not a pipe");
    gsd_writer *g = calloc(1, sizeof *g);
    char *list = g ? name_list(&g->names) : NULL;
    ds_status st = DS_OK;
    if (!list)
        st = ds_refuse(err, DS_ERR_NOMEM, "out", NAN, NAN, "out: no memory for the writer");
    else if (size == 0)
        st = start_file(g, out, list, err);
    else
        st = resume(g, out, (uint64_t)size, list, err);
    free(list);
    if (st != DS_OK) {
        if (g)
            free_writer(g);
        return st;
    }
    *self = g;
    return DS_OK;
}

/* Every frame is whole and indexed already: the stream is left at the
 * end of the file and flushed. */
static ds_status close_gsd(void *self, FILE *out, ds_error *err)
{
    gsd_writer *g = self;
    const int failed = g->failed;
    const uint64_t end = g->end;
    free_writer(g);
    if (failed)
        return ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: an earlier write failed");
    if (end > (uint64_t)LONG_MAX || fseek(out, (long)end, SEEK_SET) != 0 || fflush(out) != 0)
        return ds_refuse(err, DS_ERR_IO, "out", NAN, NAN, "out: the last flush failed");
    return DS_OK;
}

const ds_writer_ops ds_gsd_writer = {
    .name = "gsd",
    .flags = DS_WRITE_VELOCITIES,
    .open = open_gsd,
    .frame = write_frame,
    .close = close_gsd,
};
