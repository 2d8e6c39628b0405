/* SPDX-License-Identifier: MIT */
/* GSD trajectories (ds_writer of DS_FORMAT_GSD): the file is what the GSD
 * file layer 2.0 specifies, read here by a strict reader of its own (the
 * header, the name list, the index sorted by frame and id, every entry
 * inside the file), and every chunk is what the HOOMD schema 1.4 names,
 * holding what the simulation says (include/disksim/io.h lists them).
 * The file is valid after every write, its index grows past its first
 * block, and a stream that cannot hold it is refused.
 * python/tests/test_gsd.py reads the same files with the gsd package. */
#include "test_util.h"

#include <float.h>
#include <unistd.h>

/* ------------------------------------------------------------------ */
/* A strict reader of the file layer                                   */
/* ------------------------------------------------------------------ */

typedef struct entry {
    uint64_t frame, rows, location;
    uint32_t cols;
    uint16_t id;
    uint8_t type, flags;
} entry;

typedef struct gsd_file {
    uint8_t *bytes;
    size_t size;
    uint64_t index_at, index_cap;
    const char *names[64];
    size_t name_count;
    entry *entries;
    size_t count;
    uint64_t frames;
} gsd_file;

static uint64_t le(const uint8_t *p, int bytes)
{
    uint64_t v = 0;
    for (int k = 0; k < bytes; ++k)
        v |= (uint64_t)p[k] << (8 * k);
    return v;
}

/* Bytes of the element types the file layer numbers 1 to 10. */
static size_t type_size(uint8_t type)
{
    static const size_t sizes[11] = {0, 1, 2, 4, 8, 1, 2, 4, 8, 4, 8};
    return type <= 10 ? sizes[type] : 0;
}

/* Everything the file layer promises a reader, checked. */
static void parse(gsd_file *g)
{
    const uint8_t *b = g->bytes;
    assert_true(g->size >= 256);
    assert_true(le(b, 8) == 0x65DF65DF65DF65DFull);   /* magic */
    assert_int_equal(le(b + 44, 4), 2u << 16);        /* file layer 2.0 */
    assert_int_equal(le(b + 40, 4), (1u << 16) | 4u); /* hoomd schema 1.4 */
    assert_string_equal((const char *)b + 48, "disksim " DS_VERSION_STRING);
    assert_string_equal((const char *)b + 112, "hoomd");
    g->index_at = le(b + 8, 8);
    g->index_cap = le(b + 16, 8);
    const uint64_t names_at = le(b + 24, 8), names_size = 64 * le(b + 32, 8);
    assert_true(names_at + names_size <= g->size && g->index_at + 32 * g->index_cap <= g->size);
    /* Names ended by NULs, the list by an empty one, the block by a NUL. */
    assert_int_equal(b[names_at + names_size - 1], 0);
    g->name_count = 0;
    for (uint64_t at = names_at; b[at] != 0; at += strlen((const char *)b + at) + 1) {
        assert_true(g->name_count < 64);
        g->names[g->name_count++] = (const char *)b + at;
    }
    g->entries = calloc(g->index_cap + 1, sizeof *g->entries);
    assert_non_null(g->entries);
    g->count = 0;
    for (uint64_t k = 0; k < g->index_cap; ++k) {
        const uint8_t *e = b + g->index_at + 32 * k;
        entry x = {
            le(e, 8), le(e + 8, 8), le(e + 16, 8), (uint32_t)le(e + 24, 4), (uint16_t)le(e + 28, 2),
            e[30],    e[31]};
        if (x.location == 0) {
            for (uint64_t j = k; j < g->index_cap; ++j) /* the rest unused */
                assert_int_equal(le(b + g->index_at + 32 * j + 16, 8), 0);
            break;
        }
        assert_true(type_size(x.type) > 0 && x.flags == 0 && x.id < g->name_count);
        assert_true(x.rows > 0 && x.cols > 0);
        assert_true(x.location + x.rows * x.cols * type_size(x.type) <= g->size);
        assert_true(x.frame < g->index_cap);
        if (g->count > 0) { /* sorted by frame, then by id, each once */
            const entry *p = &g->entries[g->count - 1];
            assert_true(x.frame > p->frame || (x.frame == p->frame && x.id > p->id));
            assert_true(x.frame <= p->frame + 1); /* no frame left out */
        }
        g->entries[g->count++] = x;
    }
    g->frames = g->count ? g->entries[g->count - 1].frame + 1 : 0;
}

static void read_back(gsd_file *g, FILE *f)
{
    assert_int_equal(fflush(f), 0);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    const long size = ftell(f);
    assert_true(size > 0);
    g->size = (size_t)size;
    g->bytes = malloc(g->size);
    assert_non_null(g->bytes);
    rewind(f);
    assert_int_equal(fread(g->bytes, 1, g->size, f), g->size);
    parse(g);
}

static void free_file(gsd_file *g)
{
    free(g->bytes);
    free(g->entries);
}

/* The entry of name in frame, or NULL. */
static const entry *find(const gsd_file *g, uint64_t frame, const char *name)
{
    for (size_t k = 0; k < g->count; ++k)
        if (g->entries[k].frame == frame && strcmp(g->names[g->entries[k].id], name) == 0)
            return &g->entries[k];
    return NULL;
}

/* The chunk of name as the schema reads frame: its own, else frame 0's;
 * fails the test unless it is rows x cols of type. */
static const uint8_t *chunk(const gsd_file *g, uint64_t frame, const char *name, uint8_t type,
                            uint64_t rows, uint32_t cols)
{
    const entry *e = find(g, frame, name);
    if (!e)
        e = find(g, 0, name);
    if (!e)
        fail_msg("no chunk %s in frame %llu or 0", name, (unsigned long long)frame);
    assert_int_equal(e->type, type);
    assert_int_equal(e->rows, rows);
    assert_int_equal(e->cols, cols);
    return g->bytes + e->location;
}

static double f64_at(const uint8_t *p)
{
    const uint64_t bits = le(p, 8);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static float f32_at(const uint8_t *p)
{
    const uint32_t bits = (uint32_t)le(p, 4);
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* ------------------------------------------------------------------ */
/* Writing                                                             */
/* ------------------------------------------------------------------ */

static ds_writer *open_gsd(FILE *f)
{
    ds_writer *w = NULL;
    assert_int_equal(ds_writer_open(DS_FORMAT_GSD, f, 0, &w, NULL), DS_OK);
    return w;
}

/* A mixture of two named kinds, masses by area, in a box taller than
 * wide with boundary b, run until many disks have crossed a side. */
static ds_sim *named_mixture(ds_boundary b)
{
    const ds_species kinds[2] = {{12, 3.0, 0.0, "small"}, {12, 4.5, 0.0, "large_ones"}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    ds_params p = ds_params_default(24, 3.0);
    p.box = 160.0;
    p.box_y = 230.0;
    p.seed = 5;
    p.boundary = b;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, &mixture, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_run(sim, 3000, NULL), DS_OK);
    return sim;
}

/* Disk i's centre along axis as the file must hold it: the float nearest
 * x - L/2 (correctly rounded: within half an ulp), in [-L/2, L/2); or, on
 * a periodic axis where rounding reached +L/2, -L/2 with one more image. */
static void check_centre(float got, int32_t image, double x, double side, int periodic,
                         int32_t want_image)
{
    const float half = (float)side / 2.0f;
    assert_true(got >= -half && got < half);
    if (periodic && got == -half && image == want_image + 1)
        return; /* x was within rounding of the +L/2 side */
    assert_int_equal(image, want_image);
    assert_true(got == (float)(x - 0.5 * side));
}

static void check_particles(const gsd_file *g, uint64_t frame, const ds_sim *sim)
{
    enum { N = 24 };
    ds_disk d[N];
    double r[N], m[N];
    uint32_t kinds[N];
    int32_t image[2 * N];
    assert_int_equal(ds_sim_get_count(sim), N);
    ds_sim_get_disks(sim, d, NULL);
    ds_sim_get_radii(sim, r, NULL);
    ds_sim_get_masses(sim, m, NULL);
    ds_sim_get_kinds(sim, kinds, NULL);
    ds_sim_get_images(sim, image, NULL);
    const uint8_t *typeid = chunk(g, frame, "particles/typeid", 3, N, 1);
    const uint8_t *mass = chunk(g, frame, "particles/mass", 9, N, 1);
    const uint8_t *diameter = chunk(g, frame, "particles/diameter", 9, N, 1);
    const uint8_t *pos = chunk(g, frame, "particles/position", 9, N, 3);
    const uint8_t *vel = chunk(g, frame, "particles/velocity", 9, N, 3);
    const uint8_t *img = chunk(g, frame, "particles/image", 7, N, 3);
    const ds_boundary b = ds_sim_get_boundary(sim);
    const double side[2] = {ds_sim_get_box_width(sim), ds_sim_get_box_height(sim)};
    for (size_t i = 0; i < N; ++i) { /* generation order: HOOMD's tags */
        assert_int_equal(le(typeid + 4 * i, 4), kinds[i]);
        assert_true(f32_at(mass + 4 * i) == (float)m[i]);
        assert_true(f32_at(diameter + 4 * i) == (float)(2.0 * r[i]));
        const double x[2] = {d[i].x, d[i].y}, v[2] = {d[i].vx, d[i].vy};
        for (int a = 0; a < 2; ++a) {
            const int periodic = a == 0 ? b != DS_BOUNDARY_WALLS : b == DS_BOUNDARY_PERIODIC;
            check_centre(f32_at(pos + 12 * i + 4 * a), (int32_t)le(img + 12 * i + 4 * a, 4), x[a],
                         side[a], periodic, image[2 * i + a]);
            assert_true(f32_at(vel + 12 * i + 4 * a) == (float)v[a]);
        }
        assert_true(f32_at(pos + 12 * i + 8) == 0.0f && f32_at(vel + 12 * i + 8) == 0.0f);
        assert_int_equal(le(img + 12 * i + 8, 4), 0);
    }
}

/* The log: the same doubles the library's getters return now. */
static void check_log(const gsd_file *g, uint64_t frame, const ds_sim *sim)
{
    double px, py, psi6 = NAN;
    ds_sim_get_momentum(sim, &px, &py);
    (void)ds_sim_get_psi6(sim, &psi6, NULL);
    const struct {
        const char *name;
        double want;
    } values[] = {
        {"log/disksim/time", ds_sim_get_time(sim)},
        {"log/disksim/kinetic_energy", ds_sim_get_kinetic_energy(sim)},
        {"log/disksim/px", px},
        {"log/disksim/py", py},
        {"log/disksim/pressure", ds_sim_get_pressure(sim)},
        {"log/disksim/virial_pressure", ds_sim_get_virial_pressure(sim)},
        {"log/disksim/psi6", psi6},
        {"log/disksim/area_fraction", ds_sim_get_area_fraction(sim)},
    };
    for (size_t k = 0; k < sizeof values / sizeof values[0]; ++k) {
        const double got = f64_at(chunk(g, frame, values[k].name, 10, 1, 1));
        assert_memory_equal(&got, &values[k].want, sizeof got); /* to the bit, NaN too */
    }
    assert_int_equal(le(chunk(g, frame, "log/disksim/collisions", 4, 1, 1), 8),
                     ds_sim_get_collision_count(sim));
    assert_int_equal(le(chunk(g, frame, "log/disksim/wall_reflections", 4, 1, 1), 8),
                     ds_sim_get_wall_count(sim));
}

static void check_configuration(const gsd_file *g, uint64_t frame, const ds_sim *sim)
{
    assert_int_equal(le(chunk(g, frame, "configuration/step", 4, 1, 1), 8), ds_sim_get_steps(sim));
    assert_int_equal(*chunk(g, frame, "configuration/dimensions", 1, 1, 1), 2);
    const uint8_t *box = chunk(g, frame, "configuration/box", 9, 6, 1);
    const float want[6] = {(float)ds_sim_get_box_width(sim), (float)ds_sim_get_box_height(sim)};
    for (int k = 0; k < 6; ++k) /* Lz = 0: HOOMD's 2D box; no tilt */
        assert_true(f32_at(box + 4 * k) == want[k]);
    assert_int_equal(le(chunk(g, frame, "particles/N", 3, 1, 1), 4), ds_sim_get_count(sim));
}

static void test_every_chunk_holds_what_the_simulation_says(void **state)
{
    (void)state;
    for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
        ds_sim *sim = named_mixture((ds_boundary)b);
        FILE *f = tmpfile();
        assert_non_null(f);
        ds_writer *w = open_gsd(f);
        assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
        assert_int_equal(ds_writer_close(w, NULL), DS_OK);
        gsd_file g;
        read_back(&g, f);
        assert_int_equal(g.frames, 1);
        assert_int_equal(g.count, g.name_count); /* frame 0 holds every chunk */
        /* The kinds' names, a row each, NUL-padded to the longest. */
        const char *types = (const char *)chunk(&g, 0, "particles/types", 5, 2, 11);
        assert_string_equal(types, "small");
        assert_string_equal(types + 11, "large_ones");
        check_configuration(&g, 0, sim);
        check_particles(&g, 0, sim);
        check_log(&g, 0, sim);
        free_file(&g);
        fclose(f);
        ds_sim_destroy(sim);
    }
}

/* Frames after the first hold the step, the positions, the velocities
 * and the log, and what else differs from frame 0: the images of disks
 * that crossed a periodic side, the diameters of a growth. */
static void test_later_frames_hold_what_changed(void **state)
{
    (void)state;
    ds_params p = ds_params_default(60, 8.0);
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    FILE *f = tmpfile();
    assert_non_null(f);
    ds_writer *w = open_gsd(f);
    assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
    assert_int_equal(ds_sim_run(sim, 1, NULL), DS_OK); /* none crosses a side in 0.001 */
    assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
    assert_int_equal(ds_sim_run(sim, 3000, NULL), DS_OK); /* many do in 3 */
    assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_growth(sim, 0.05, 0.3, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_run(sim, 100, NULL), DS_OK);
    assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
    assert_int_equal(ds_writer_close(w, NULL), DS_OK);
    gsd_file g;
    read_back(&g, f);
    assert_int_equal(g.frames, 4);
    const char *every[] = {"configuration/step", "particles/position", "particles/velocity",
                           "log/disksim/time", "log/disksim/psi6"};
    const char *fixed[] = {"configuration/dimensions", "configuration/box", "particles/N",
                           "particles/types",          "particles/typeid",  "particles/mass"};
    for (uint64_t k = 1; k < 4; ++k) {
        for (size_t j = 0; j < sizeof every / sizeof every[0]; ++j)
            assert_non_null(find(&g, k, every[j]));
        for (size_t j = 0; j < sizeof fixed / sizeof fixed[0]; ++j)
            assert_null(find(&g, k, fixed[j]));
    }
    assert_null(find(&g, 1, "particles/image"));
    assert_non_null(find(&g, 2, "particles/image"));
    assert_null(find(&g, 2, "particles/diameter"));
    assert_non_null(find(&g, 3, "particles/diameter")); /* grown */
    const float grown = f32_at(chunk(&g, 3, "particles/diameter", 9, 60, 1));
    assert_true(grown > 16.0f && grown == (float)(2.0 * ds_sim_get_radius_max(sim)));
    check_log(&g, 3, sim);
    free_file(&g);
    fclose(f);
    ds_sim_destroy(sim);
}

/* Each write leaves a valid file of the frames so far, without a close;
 * past the first index block (256 entries: 19 frames here) the index
 * moves to the end of the file and the header follows it. */
static void test_the_file_is_valid_after_every_write(void **state)
{
    (void)state;
    ds_sim *sim = test_create(40, 5.0, 7, DS_BROADPHASE_AUTO);
    FILE *f = tmpfile();
    assert_non_null(f);
    ds_writer *w = open_gsd(f);
    uint64_t first_index = 0;
    for (int k = 0; k < 40; ++k) {
        assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
        gsd_file g;
        read_back(&g, f);
        assert_int_equal(g.frames, (uint64_t)k + 1);
        if (k == 0)
            first_index = g.index_at;
        if (k == 39) {
            assert_true(g.index_at > first_index && g.index_cap > 256);
            check_configuration(&g, 39, sim);
            check_log(&g, 39, sim);
        }
        free_file(&g);
        assert_int_equal(ds_sim_run(sim, 10, NULL), DS_OK);
    }
    assert_int_equal(ds_writer_close(w, NULL), DS_OK);
    /* Closing leaves the stream at the end of the file. */
    const long end = ftell(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    assert_int_equal(ftell(f), end);
    fclose(f);
    ds_sim_destroy(sim);
}

/* A file closed and opened again ("r+b") is gone on with: its frames are
 * kept, the writes append, and frame 0 still decides what a frame leaves
 * out; also past index blocks that moved before and after. */
static void test_a_file_opened_again_is_gone_on_with(void **state)
{
    (void)state;
    char path[] = "/tmp/ds_test_gsd_XXXXXX";
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    ds_sim *sim = named_mixture(DS_BOUNDARY_PERIODIC);
    const int sessions[3] = {3, 25, 20}; /* the index moves in the second and third */
    uint64_t written = 0;
    for (int k = 0; k < 3; ++k) {
        FILE *f = fopen(path, k == 0 ? "wb" : "r+b");
        assert_non_null(f);
        ds_writer *w = open_gsd(f);
        for (int j = 0; j < sessions[k]; ++j, ++written) {
            assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
            assert_int_equal(ds_sim_run(sim, 50, NULL), DS_OK);
        }
        assert_int_equal(ds_writer_close(w, NULL), DS_OK);
        fclose(f);
    }
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    gsd_file g;
    read_back(&g, f);
    assert_int_equal(g.frames, written);
    for (uint64_t k = 1; k < written; ++k) { /* none of frame 0's repeated */
        assert_null(find(&g, k, "particles/types"));
        assert_null(find(&g, k, "particles/mass"));
        assert_non_null(find(&g, k, "particles/position"));
        assert_int_equal(le(chunk(&g, k, "configuration/step", 4, 1, 1), 8), 3000 + 50 * k);
    }
    free_file(&g);
    fclose(f);
    unlink(path);
    ds_sim_destroy(sim);
}

/* A sheared box logs its images' offset every frame, to the bit
 * (log/disksim/shear_offset, ds_sim_get_shear_offset), so that x + ix Lx
 * + iy offset unwraps; its box stays rectangular (no tilt). Unsheared,
 * the offset is 0. */
static void test_a_sheared_run_logs_its_images_offset(void **state)
{
    (void)state;
    ds_params p = ds_params_default(60, 5.0);
    p.box = 200.0;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    FILE *f = tmpfile();
    assert_non_null(f);
    ds_writer *w = open_gsd(f);
    double want[4];
    for (int k = 0; k < 4; ++k) {
        if (k == 1)
            assert_int_equal(ds_sim_set_shear(sim, -2.5, NULL), DS_OK);
        if (k > 0)
            ds_sim_run(sim, 500, NULL);
        want[k] = ds_sim_get_shear_offset(sim);
        assert_int_equal(ds_writer_write(w, sim, NULL), DS_OK);
    }
    assert_int_equal(ds_writer_close(w, NULL), DS_OK);
    gsd_file g;
    read_back(&g, f);
    assert_int_equal(g.frames, 4);
    assert_true(want[0] == 0.0 && want[3] != 0.0);
    for (uint64_t k = 0; k < 4; ++k) {
        const double got = f64_at(chunk(&g, k, "log/disksim/shear_offset", 10, 1, 1));
        assert_memory_equal(&got, &want[k], sizeof got);
    }
    const uint8_t *box = chunk(&g, 0, "configuration/box", 9, 6, 1);
    for (int k = 2; k < 6; ++k)
        assert_true(f32_at(box + 4 * k) == 0.0f);
    free_file(&g);
    fclose(f);
    ds_sim_destroy(sim);
}

/* A file of no frames is a valid file too. */
static void test_a_writer_closed_at_once_leaves_an_empty_trajectory(void **state)
{
    (void)state;
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(ds_writer_close(open_gsd(f), NULL), DS_OK);
    gsd_file g;
    read_back(&g, f);
    assert_int_equal(g.frames, 0);
    assert_int_equal(g.name_count, 22);
    free_file(&g);
    fclose(f);
}

/* GSD places its bytes where its index says: a pipe cannot hold it; a
 * stream holding something else than its file is not gone on with, nor
 * one it cannot read back; a full disk is DS_ERR_IO. */
static void test_a_stream_that_cannot_hold_a_gsd_file_is_refused(void **state)
{
    (void)state;
    int fd[2];
    assert_int_equal(pipe(fd), 0);
    FILE *p = fdopen(fd[1], "wb");
    assert_non_null(p);
    ds_writer *w = (ds_writer *)&w;
    ds_error err;
    assert_int_equal(ds_writer_open(DS_FORMAT_GSD, p, 0, &w, &err), DS_ERR_ARG);
    assert_null(w);
    assert_string_equal(err.field, "out");
    fclose(p);
    close(fd[0]);
    FILE *f = tmpfile();
    assert_non_null(f);
    assert_int_equal(fputc('x', f), 'x');
    assert_int_equal(ds_writer_open(DS_FORMAT_GSD, f, 0, &w, &err), DS_ERR_FORMAT);
    assert_string_equal(err.field, "out");
    fclose(f);
    /* A GSD file on a stream opened for writing only: it cannot be read back. */
    char path[] = "/tmp/ds_test_gsd_XXXXXX";
    const int made = mkstemp(path);
    assert_true(made >= 0);
    close(made);
    f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(ds_writer_close(open_gsd(f), NULL), DS_OK);
    fclose(f);
    f = fopen(path, "ab");
    assert_non_null(f);
    assert_int_equal(ds_writer_open(DS_FORMAT_GSD, f, 0, &w, &err), DS_ERR_ARG);
    assert_false(ferror(f)); /* the writer's failed read leaves no mark */
    fclose(f);
    unlink(path);
    FILE *full = fopen("/dev/full", "wb");
    if (full) { /* Linux: the header's flush fails with ENOSPC */
        assert_int_equal(ds_writer_open(DS_FORMAT_GSD, full, 0, &w, &err), DS_ERR_IO);
        assert_string_equal(err.field, "out");
        fclose(full);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_chunk_holds_what_the_simulation_says),
        cmocka_unit_test(test_later_frames_hold_what_changed),
        cmocka_unit_test(test_the_file_is_valid_after_every_write),
        cmocka_unit_test(test_a_file_opened_again_is_gone_on_with),
        cmocka_unit_test(test_a_sheared_run_logs_its_images_offset),
        cmocka_unit_test(test_a_writer_closed_at_once_leaves_an_empty_trajectory),
        cmocka_unit_test(test_a_stream_that_cannot_hold_a_gsd_file_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
