/* SPDX-License-Identifier: MIT */
/* Extended XYZ trajectories: what ds_xyz_format writes reads back as
 * the simulation (parsed here, in C, always), `disks --trajectory` holds
 * exactly the frames it writes as text, and a third-party reader, ASE's
 * ase.io.read, sees the same frames, kinds, positions, radii, velocities
 * and masses when a python3 with ASE is installed (Debian: python3-ase).
 * Run from the top directory (make test does). */
#include "test_util.h"

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef DS_TEST_DISKS
#define DS_TEST_DISKS "disks"
#endif

/* ------------------------------------------------------------------ */
/* A strict reader of the frames we write                              */
/* ------------------------------------------------------------------ */

/* One frame as the header's comment on ds_xyz_format describes it. */
typedef struct xyz_frame {
    size_t count;
    double time, box, box_y, height;
    int periodic;         /* pbc="T T F" or "T F F" (a channel), and lines end with ix iy */
    int periodic_y;       /* pbc="T T F" */
    ds_frame_disk *disks; /* x, y, r, vx, vy */
    double *momenta;      /* px, py of each disk */
    double *mass;         /* of each disk (the two mass columns agree) */
    char (*kind)[16];     /* each disk's kind's name */
    long *image;          /* ix, iy of each disk when periodic, else NULL */
    int sheared;          /* the comment ends with shear_offset= */
    double shear_offset;  /* its value (0 when not sheared) */
} xyz_frame;

/* Reads one number followed by a space or a newline; fails the test if
 * there is none. */
static double number(const char **p)
{
    char *end;
    double v = strtod(*p, &end);
    if (end == *p || (*end != ' ' && *end != '\n' && *end != '"'))
        fail_msg("expected a number at \"%.40s\"", *p);
    *p = end + (*end == ' ' || *end == '\n');
    return v;
}

/* A whole number, as number() reads one. */
static long integer(const char **p)
{
    const double v = number(p);
    assert_true(v == floor(v));
    return (long)v;
}

static void expect(const char **p, const char *text)
{
    if (strncmp(*p, text, strlen(text)) != 0)
        fail_msg("expected \"%s\" at \"%.60s\"", text, *p);
    *p += strlen(text);
}

static int next_is(const char **p, const char *text)
{
    if (strncmp(*p, text, strlen(text)) != 0)
        return 0;
    *p += strlen(text);
    return 1;
}

/* Parses every frame of text, strictly in the form the header documents
 * (nothing else is accepted); returns how many (at most max). */
static size_t parse_trajectory(const char *text, xyz_frame *frames, size_t max)
{
    const char *p = text;
    size_t n = 0;
    while (*p) {
        assert_true(n < max);
        xyz_frame *f = &frames[n++];
        f->count = (size_t)number(&p);
        expect(&p, "Lattice=\"");
        f->box = number(&p);
        expect(&p, "0 0 0 ");
        f->box_y = number(&p);
        expect(&p, "0 0 0 ");
        f->height = number(&p);
        expect(&p, "\" Properties=type:S:1:pos:R:3:radius:R:1:velo:R:3:momenta:R:3:mass:R:1:"
                   "masses:R:1");
        const int images = next_is(&p, ":map_shift:I:3");
        expect(&p, " Time=");
        f->time = number(&p);
        expect(&p, "pbc=\"");
        f->periodic_y = next_is(&p, "T T F");
        f->periodic = f->periodic_y || next_is(&p, "T F F");
        if (!f->periodic)
            expect(&p, "F F F");
        expect(&p, "\"");
        f->sheared = next_is(&p, " shear_offset=");
        f->shear_offset = f->sheared ? number(&p) : 0.0;
        if (!f->sheared)
            expect(&p, "\n");
        assert_int_equal(images, f->periodic); /* the image column iff periodic */
        f->disks = malloc(f->count * sizeof *f->disks);
        f->momenta = malloc(2 * f->count * sizeof *f->momenta);
        f->mass = malloc(f->count * sizeof *f->mass);
        f->kind = malloc(f->count * sizeof *f->kind);
        assert_true(f->disks && f->momenta && f->mass && f->kind);
        f->image = f->periodic ? malloc(2 * f->count * sizeof *f->image) : NULL;
        assert_true(!f->periodic || f->image);
        for (size_t i = 0; i < f->count; ++i) {
            ds_frame_disk *d = &f->disks[i];
            const size_t name = strcspn(p, " \n");
            assert_true(name > 0 && name < 16 && p[name] == ' ');
            memcpy(f->kind[i], p, name);
            f->kind[i][name] = '\0';
            p += name + 1;
            d->x = number(&p);
            d->y = number(&p);
            assert_true(number(&p) == 0.0); /* z */
            d->r = number(&p);
            d->vx = number(&p);
            d->vy = number(&p);
            assert_true(number(&p) == 0.0); /* vz */
            f->momenta[2 * i] = number(&p);
            f->momenta[2 * i + 1] = number(&p);
            assert_true(number(&p) == 0.0); /* pz */
            f->mass[i] = number(&p);
            assert_true(number(&p) == f->mass[i]); /* mass and masses */
            if (f->periodic) {
                f->image[2 * i] = integer(&p);
                f->image[2 * i + 1] = integer(&p);
                assert_true(integer(&p) == 0); /* along z */
            }
            assert_true(p[-1] == '\n');
        }
    }
    return n;
}

static void free_frames(xyz_frame *frames, size_t n)
{
    for (size_t k = 0; k < n; ++k) {
        free(frames[k].disks);
        free(frames[k].momenta);
        free(frames[k].mass);
        free(frames[k].kind);
        free(frames[k].image);
    }
}

/* The rest of f from where it is, NUL-terminated; closes f. */
static char *read_all(FILE *f)
{
    assert_non_null(f);
    long start = ftell(f);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    long size = ftell(f) - start;
    assert_int_equal(fseek(f, start, SEEK_SET), 0);
    char *text = malloc((size_t)size + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)size, f), (size_t)size);
    text[size] = '\0';
    fclose(f);
    return text;
}

static char *slurp(const char *path) { return read_all(fopen(path, "rb")); }

/* Six decimals are written: a value read back is within half a unit of
 * the sixth decimal (5e-7), plus the rounding of the double itself. */
static int within_six_decimals(double got, double want) { return fabs(got - want) <= 5e-7 + 1e-12; }

/* ------------------------------------------------------------------ */
/* The library's writer                                                */
/* ------------------------------------------------------------------ */

static void test_an_xyz_frame_reads_back_as_the_simulation(void **state)
{
    (void)state;
    ds_sim *sim = test_create(300, 4.0, 9, DS_BROADPHASE_SAP);
    ds_sim_run(sim, 500, NULL); /* slots permuted by the sort: output must not be */
    size_t cap = ds_xyz_get_size(sim), len = 0;
    char *buf = malloc(cap + 1);
    assert_non_null(buf);
    assert_int_equal(ds_xyz_format(sim, buf, cap, &len, NULL), DS_OK);
    buf[len] = '\0';
    xyz_frame f;
    assert_int_equal(parse_trajectory(buf, &f, 1), 1);
    assert_int_equal(f.count, 300);
    assert_true(f.box == 1000.0 && f.box_y == 1000.0);
    assert_true(f.height == 8.0); /* 2R: the flat layer the disks fill */
    assert_false(f.periodic);
    assert_true(within_six_decimals(f.time, 0.5));
    ds_disk want[300];
    assert_int_equal(ds_sim_get_disks(sim, want, NULL), DS_OK);
    for (size_t i = 0; i < 300; ++i) {
        assert_true(within_six_decimals(f.disks[i].x, want[i].x));
        assert_true(within_six_decimals(f.disks[i].y, want[i].y));
        assert_true(within_six_decimals(f.disks[i].vx, want[i].vx));
        assert_true(within_six_decimals(f.disks[i].vy, want[i].vy));
        assert_true(f.disks[i].r == 4.0);
        assert_string_equal(f.kind[i], "A"); /* one kind, the default name */
        assert_true(f.mass[i] == 1.0);
    }
    free_frames(&f, 1);
    free(buf);
    ds_sim_destroy(sim);
}

/* The header's comment on ds_xyz_format, claim by claim, on what
 * it must describe beyond one square box of one radius: a mixture of
 * named kinds, masses by area, in a box taller than wide, with walls and
 * periodic, after the disks have crossed the periodic box's sides. The
 * parser above accepts only the documented form; here each number is
 * checked against the simulation. */
static void test_the_documented_xyz_form_is_what_is_written(void **state)
{
    (void)state;
    enum { N = 24 };
    const ds_species kinds[2] = {{12, 3.0, 0.0, "small"}, {12, 4.5, 0.0, "large"}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    for (int b = 0; b < DS_BOUNDARY_COUNT; ++b) {
        /* Along x a channel is periodic too: images along x, 0 along y. */
        const int periodic = b != DS_BOUNDARY_WALLS;
        ds_params p = ds_params_default(N, 3.0);
        p.box = 160.0;
        p.box_y = 230.0;
        p.seed = 5;
        p.boundary = (ds_boundary)b;
        ds_sim *sim = NULL;
        assert_int_equal(ds_sim_create(&p, &mixture, &sim, NULL), DS_OK);
        ds_sim_run(sim, 3000, NULL); /* t = 3: at speeds near 100 many disks cross a side */
        size_t cap = ds_xyz_get_size(sim), len = 0;
        char *buf = malloc(cap + 1);
        assert_non_null(buf);
        assert_int_equal(ds_xyz_format(sim, buf, cap, &len, NULL), DS_OK);
        buf[len] = '\0';
        xyz_frame f;
        assert_int_equal(parse_trajectory(buf, &f, 1), 1);
        assert_int_equal(f.count, N);
        assert_int_equal(f.periodic, periodic);
        assert_int_equal(f.periodic_y, b == DS_BOUNDARY_PERIODIC);
        /* Lx, Ly and H = 2 r_max in the shortest text that reads back. */
        assert_true(f.box == ds_sim_get_box_width(sim) && f.box_y == ds_sim_get_box_height(sim));
        assert_true(f.height == 2.0 * ds_sim_get_radius_max(sim) && f.height == 9.0);
        assert_true(within_six_decimals(f.time, ds_sim_get_time(sim)));
        ds_disk want[N];
        int32_t image[2 * N];
        double mass[N];
        uint32_t kind[N];
        assert_int_equal(ds_sim_get_disks(sim, want, NULL), DS_OK);
        assert_int_equal(ds_sim_get_images(sim, image, NULL), DS_OK);
        assert_int_equal(ds_sim_get_masses(sim, mass, NULL), DS_OK);
        assert_int_equal(ds_sim_get_kinds(sim, kind, NULL), DS_OK);
        int crossed = 0;
        for (size_t i = 0; i < N; ++i) {
            assert_true(f.disks[i].r == radius_of(sim, i)); /* each its own, exactly */
            assert_true(f.mass[i] == mass[i] && (i < 12 ? mass[i] == 1.0 : mass[i] == 2.25));
            assert_string_equal(f.kind[i], ds_sim_get_kind_name(sim, kind[i]));
            assert_string_equal(f.kind[i], i < 12 ? "small" : "large");
            assert_true(within_six_decimals(f.momenta[2 * i], mass[i] * want[i].vx));
            assert_true(within_six_decimals(f.momenta[2 * i + 1], mass[i] * want[i].vy));
            assert_true(within_six_decimals(f.disks[i].x, want[i].x));
            assert_true(within_six_decimals(f.disks[i].y, want[i].y));
            assert_true(within_six_decimals(f.disks[i].vx, want[i].vx));
            assert_true(within_six_decimals(f.disks[i].vy, want[i].vy));
            if (periodic) {
                assert_int_equal(f.image[2 * i], image[2 * i]);
                assert_int_equal(f.image[2 * i + 1], image[2 * i + 1]);
                assert_true(b == DS_BOUNDARY_PERIODIC || image[2 * i + 1] == 0);
                crossed += image[2 * i] != 0 || image[2 * i + 1] != 0;
            }
        }
        assert_true(!periodic || crossed > 0); /* the image column was put to the test */
        free_frames(&f, 1);
        free(buf);
        ds_sim_destroy(sim);
    }
}

/* A sheared box's frames end their comment line with shear_offset=, the
 * images' offset unwrapped in the shortest form that reads back
 * (ds_sim_get_shear_offset, to the bit), so that pos + map_shift x the
 * sides + iy shear_offset along x is ds_sim_get_unwrapped (to the six
 * decimals of the positions); the cell stays rectangular. An unsheared
 * box writes no such key. */
static void test_a_sheared_frame_names_its_images_offset(void **state)
{
    (void)state;
    enum { N = 60 };
    ds_params p = ds_params_default(N, 5.0);
    p.box = 200.0;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    for (int sheared = 0; sheared < 2; ++sheared) {
        if (sheared)
            assert_int_equal(ds_sim_set_shear(sim, 1.7, NULL), DS_OK);
        ds_sim_run(sim, 3000, NULL); /* t = 3: many disks cross the top or bottom */
        size_t cap = ds_xyz_get_size(sim), len = 0;
        char *buf = malloc(cap + 1);
        assert_non_null(buf);
        assert_int_equal(ds_xyz_format(sim, buf, cap, &len, NULL), DS_OK);
        buf[len] = '\0';
        xyz_frame f;
        assert_int_equal(parse_trajectory(buf, &f, 1), 1);
        assert_int_equal(f.sheared, sheared);
        assert_true(f.box == 200.0 && f.box_y == 200.0); /* Lattice="Lx 0 0 0 Ly 0 ...": no tilt */
        if (sheared) {
            assert_true(f.shear_offset == ds_sim_get_shear_offset(sim));
            assert_true(f.shear_offset > 200.0); /* past a width: the unwrapped one */
            double xy[2 * N];
            assert_int_equal(ds_sim_get_unwrapped(sim, xy, NULL), DS_OK);
            int crossed = 0;
            for (size_t i = 0; i < N; ++i) {
                const double x = f.disks[i].x + (double)f.image[2 * i] * f.box +
                                 (double)f.image[2 * i + 1] * f.shear_offset;
                assert_true(fabs(x - xy[2 * i]) <= 5e-7 + 1e-12 * fabs(xy[2 * i]));
                crossed += f.image[2 * i + 1] != 0;
            }
            assert_true(crossed > 0); /* the offset was put to the test */
        }
        free_frames(&f, 1);
        free(buf);
    }
    ds_sim_destroy(sim);
}

static void test_frames_written_one_after_another_make_a_trajectory(void **state)
{
    (void)state;
    ds_sim *sim = test_create(40, 7.5, 3, DS_BROADPHASE_STRIPS);
    FILE *out = tmpfile();
    assert_non_null(out);
    ds_disk last[40];
    for (int k = 0; k < 3; ++k) {
        if (k > 0)
            ds_sim_run(sim, 250, NULL);
        assert_int_equal(ds_xyz_write(sim, out, NULL), DS_OK);
    }
    assert_int_equal(ds_sim_get_disks(sim, last, NULL), DS_OK);
    rewind(out);
    char *text = read_all(out);
    xyz_frame f[4];
    assert_int_equal(parse_trajectory(text, f, 4), 3);
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(f[k].count, 40);
        assert_true(within_six_decimals(f[k].time, 0.25 * k));
        assert_true(f[k].disks[0].r == 7.5);
    }
    for (size_t i = 0; i < 40; ++i)
        assert_true(within_six_decimals(f[2].disks[i].x, last[i].x));
    free_frames(f, 3);
    free(text);
    ds_sim_destroy(sim);
}

static void test_formatting_reports_the_bytes_needed(void **state)
{
    (void)state;
    ds_sim *sim = test_create(25, 5.0, 1, DS_BROADPHASE_AUTO);
    size_t need = 0, len = 0, cap = ds_xyz_get_size(sim);
    assert_int_equal(ds_xyz_format(sim, NULL, 0, &need, NULL), DS_ERR_ARG);
    char *buf = malloc(cap);
    assert_non_null(buf);
    assert_int_equal(ds_xyz_format(sim, buf, cap, &len, NULL), DS_OK);
    assert_int_equal(need, len);
    assert_true(len <= cap);
    assert_int_equal(ds_xyz_format(sim, buf, len - 1, &need, NULL), DS_ERR_ARG);
    assert_int_equal(need, len);
    free(buf);
    ds_sim_destroy(sim);
}

static void test_bad_arguments_and_a_full_disk_are_errors(void **state)
{
    (void)state;
    ds_sim *sim = test_create(50, 5.0, 1, DS_BROADPHASE_SAP);
    size_t len = 99;
    char buf[8];
    assert_int_equal(ds_xyz_format(NULL, buf, sizeof buf, &len, NULL), DS_ERR_ARG);
    assert_int_equal(len, 0);
    assert_int_equal(ds_xyz_format(sim, NULL, 10, &len, NULL), DS_ERR_ARG);
    assert_int_equal(ds_xyz_write(NULL, stdout, NULL), DS_ERR_ARG);
    assert_int_equal(ds_xyz_write(sim, NULL, NULL), DS_ERR_ARG);
    assert_int_equal(ds_xyz_get_size(NULL), 0);
    FILE *full = fopen("/dev/full", "w");
    if (full) { /* Linux: writes fail with ENOSPC, seen at the flush */
        assert_int_equal(ds_xyz_write(sim, full, NULL), DS_ERR_IO);
        fclose(full);
    }
    ds_sim_destroy(sim);
}

/* ------------------------------------------------------------------ */
/* disks --trajectory                                                  */
/* ------------------------------------------------------------------ */

static char workdir[64];

static int make_workdir(void **state)
{
    (void)state;
    snprintf(workdir, sizeof workdir, "/tmp/ds_test_xyz_XXXXXX");
    return mkdtemp(workdir) ? 0 : -1;
}

static int remove_workdir(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", workdir);
    return system(cmd) == 0 ? 0 : -1;
}

#define RUN_FRAMES 5
#define RUN_DISKS 60

/* Runs disks once per test group: RUN_FRAMES frames with velocities in
 * workdir/run and the same frames in workdir/run.xyz. */
static const char *disks_trajectory(void)
{
    static char path[128];
    snprintf(path, sizeof path, "%s/run.xyz", workdir);
    if (access(path, F_OK) == 0)
        return path;
    char cmd[512];
    snprintf(cmd, sizeof cmd,
             "./%s %d 5 --frames %d --steps-per-frame 30 --velocities --quiet --out %s/run "
             "--trajectory %s",
             DS_TEST_DISKS, RUN_DISKS, RUN_FRAMES, workdir, path);
    assert_int_equal(system(cmd), 0);
    return path;
}

static void test_disks_trajectory_holds_exactly_its_frames(void **state)
{
    (void)state;
    char *text = slurp(disks_trajectory());
    xyz_frame f[RUN_FRAMES + 1];
    assert_int_equal(parse_trajectory(text, f, RUN_FRAMES + 1), RUN_FRAMES);
    for (int k = 0; k < RUN_FRAMES; ++k) {
        char path[128];
        snprintf(path, sizeof path, "%s/run/frame_%04d.txt", workdir, k);
        ds_frame frame;
        assert_int_equal(ds_frame_read(path, &frame, NULL), DS_OK);
        assert_int_equal(f[k].count, frame.count);
        assert_true(within_six_decimals(f[k].time, k * 30 * 0.001));
        /* The same six-decimal text in both files: the same doubles. */
        for (size_t i = 0; i < frame.count; ++i)
            assert_memory_equal(&f[k].disks[i], &frame.disks[i], sizeof frame.disks[i]);
        ds_frame_free(&frame);
    }
    free_frames(f, RUN_FRAMES);
    free(text);
    /* Written through a temporary renamed at the end: none is left. */
    DIR *d = opendir(workdir);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (e->d_name[0] == '.' && strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
            fail_msg("temporary %s left behind", e->d_name);
    closedir(d);
}

/* ------------------------------------------------------------------ */
/* ASE reads it                                                        */
/* ------------------------------------------------------------------ */

/* The first python3 that can import ase: Debian's own (python3-ase) before
 * whatever python3 comes first on PATH (pyenv, a venv) and may lack it. */
static const char *python_with_ase(void)
{
    static const char *const candidates[] = {"/usr/bin/python3", "python3"};
    for (size_t k = 0; k < 2; ++k) {
        char cmd[256];
        snprintf(cmd, sizeof cmd, "%s -c 'import ase.io' >/dev/null 2>&1", candidates[k]);
        if (system(cmd) == 0)
            return candidates[k];
    }
    return NULL;
}

/* Prints what ase.io.read(path, index=':') found, one line per frame and
 * per atom, every float with repr (the shortest text that reads back):
 * the symbol, the kind, the position, radius, mass and velocity as ASE
 * has them (get_masses(), get_velocities()). */
static const char ase_script[] =
    "import sys, ase.io\n"
    "frames = ase.io.read(sys.argv[1], index=':')\n"
    "print(len(frames))\n"
    "for a in frames:\n"
    "    print(repr(float(a.info['Time'])), len(a), *(repr(float(v)) for v in a.cell.lengths()),\n"
    "          ''.join('T' if p else 'F' for p in a.pbc))\n"
    "    for s, k, p, r, m, v in zip(a.get_chemical_symbols(), a.arrays['type'], a.positions,\n"
    "                                a.arrays['radius'], a.get_masses(), a.get_velocities()):\n"
    "        print(s, k, *(repr(float(x)) for x in (p[0], p[1], p[2], r, m, v[0], v[1], v[2])))\n";

static void test_ase_reads_the_trajectory_disks_writes(void **state)
{
    (void)state;
    const char *python = python_with_ase();
    if (!python) {
        print_message("skipped: no python3 that can import ase (Debian: python3-ase)\n");
        skip();
    }
    const char *path = disks_trajectory();
    char *text = slurp(path);
    xyz_frame f[RUN_FRAMES + 1];
    assert_int_equal(parse_trajectory(text, f, RUN_FRAMES + 1), RUN_FRAMES);

    char script[128], cmd[512];
    snprintf(script, sizeof script, "%s/read_with_ase.py", workdir);
    FILE *s = fopen(script, "w");
    assert_non_null(s);
    assert_int_equal(fputs(ase_script, s) >= 0, 1);
    assert_int_equal(fclose(s), 0);
    snprintf(cmd, sizeof cmd, "%s %s %s 2>&1", python, script, path);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    char line[512];
    assert_non_null(fgets(line, sizeof line, p));
    if (atoi(line) != RUN_FRAMES)
        fail_msg("ASE read %s as \"%s\", expected %d frames", path, line, RUN_FRAMES);
    /* ASE parses the same decimal text with a correctly rounded conversion,
     * so every number must be the very double the C reader got. */
    for (int k = 0; k < RUN_FRAMES; ++k) {
        double time, lx, ly, lz;
        size_t count;
        char pbc[8];
        assert_non_null(fgets(line, sizeof line, p));
        assert_int_equal(sscanf(line, "%lf %zu %lf %lf %lf %7s", &time, &count, &lx, &ly, &lz, pbc),
                         6);
        assert_true(time == f[k].time);
        assert_int_equal(count, RUN_DISKS);
        assert_true(lx == 1000.0 && ly == 1000.0 && lz == 10.0);
        assert_string_equal(pbc, "FFF");
        for (size_t i = 0; i < count; ++i) {
            char species[8], kind[16];
            double x, y, z, r, m, vx, vy, vz;
            assert_non_null(fgets(line, sizeof line, p));
            assert_int_equal(sscanf(line, "%7s %15s %lf %lf %lf %lf %lf %lf %lf %lf", species, kind,
                                    &x, &y, &z, &r, &m, &vx, &vy, &vz),
                             10);
            const ds_frame_disk *d = &f[k].disks[i];
            assert_string_equal(species, "X");
            assert_string_equal(kind, "A");
            assert_true(x == d->x && y == d->y && z == 0.0);
            assert_true(r == 5.0 && m == 1.0);
            /* get_velocities() is momenta / masses: m = 1, the same text. */
            assert_true(vx == d->vx && vy == d->vy && vz == 0.0);
        }
    }
    assert_null(fgets(line, sizeof line, p));
    assert_int_equal(pclose(p), 0);
    free_frames(f, RUN_FRAMES);
    free(text);
}

int main(void)
{
    const struct CMUnitTest library[] = {
        cmocka_unit_test(test_an_xyz_frame_reads_back_as_the_simulation),
        cmocka_unit_test(test_a_sheared_frame_names_its_images_offset),
        cmocka_unit_test(test_the_documented_xyz_form_is_what_is_written),
        cmocka_unit_test(test_frames_written_one_after_another_make_a_trajectory),
        cmocka_unit_test(test_formatting_reports_the_bytes_needed),
        cmocka_unit_test(test_bad_arguments_and_a_full_disk_are_errors),
    };
    const struct CMUnitTest command[] = {
        cmocka_unit_test(test_disks_trajectory_holds_exactly_its_frames),
        cmocka_unit_test(test_ase_reads_the_trajectory_disks_writes),
    };
    int failed = cmocka_run_group_tests_name("xyz, library", library, NULL, NULL);
    failed += cmocka_run_group_tests_name("xyz, disks --trajectory", command, make_workdir,
                                          remove_workdir);
    return failed ? 1 : 0;
}
