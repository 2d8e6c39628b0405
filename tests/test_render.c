/* SPDX-License-Identifier: MIT */
/* tools/render, tested from the outside: each backend's binary renders
 * hand-written frames and the PNGs are read back with libpng. Expected
 * pixel positions come from the renderer's own layout (render_layout.c),
 * expected colours from its colour map; what is tested is that the image
 * shows them where the frame says, with y up and antialiased edges. */
#include "test_util.h"

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <png.h>

#include "render_colormap.h"
#include "render_font.h"
#include "render_layout.h"

/* ------------------------------------------------------------------ */
/* Helpers                                                             */
/* ------------------------------------------------------------------ */

typedef struct image {
    int width, height;
    unsigned char *rgb;
} image;

typedef struct rgb8 {
    int r, g, b;
} rgb8;

static char scratch[64];

static int make_scratch(void **state)
{
    (void)state;
    snprintf(scratch, sizeof scratch, "/tmp/test_render_XXXXXX");
    return mkdtemp(scratch) ? 0 : -1;
}

static int remove_scratch(void **state)
{
    (void)state;
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", scratch);
    return system(cmd) == 0 ? 0 : -1;
}

static char *path_in(const char *dir, const char *name)
{
    static char buf[4][512];
    static int next;
    char joined[sizeof buf[0]]; /* dir may be one of buf's entries */
    if ((size_t)snprintf(joined, sizeof joined, "%s/%s", dir, name) >= sizeof joined)
        fail_msg("path too long: %s/%s", dir, name);
    char *p = buf[next++ % 4];
    memcpy(p, joined, sizeof joined);
    return p;
}

/* A fresh empty directory under the scratch directory. */
static const char *fresh_dir(const char *name)
{
    char *dir = path_in(scratch, name);
    char cmd[600];
    snprintf(cmd, sizeof cmd, "rm -rf %s && mkdir -p %s", dir, dir);
    assert_int_equal(system(cmd), 0);
    return dir;
}

static void write_bytes(const char *path, const char *bytes, size_t len)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, len, f), len);
    assert_int_equal(fclose(f), 0);
}

static void write_text(const char *path, const char *text)
{
    write_bytes(path, text, strlen(text));
}

/* Runs "BINARY ARGS", stderr kept in scratch/stderr.txt; the exit status. */
static int run(const char *binary, const char *args)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s %s >%s/stdout.txt 2>%s/stderr.txt", binary, args, scratch,
             scratch);
    int st = system(cmd);
    assert_true(WIFEXITED(st));
    return WEXITSTATUS(st);
}

static const char *last_stderr(void)
{
    static char text[4096];
    FILE *f = fopen(path_in(scratch, "stderr.txt"), "rb");
    assert_non_null(f);
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    return text;
}

static image read_png(const char *path)
{
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path))
        fail_msg("cannot read %s: %s", path, png.message);
    png.format = PNG_FORMAT_RGB;
    image img = {(int)png.width, (int)png.height, malloc(PNG_IMAGE_SIZE(png))};
    assert_non_null(img.rgb);
    if (!png_image_finish_read(&png, NULL, img.rgb, 0, NULL))
        fail_msg("cannot decode %s: %s", path, png.message);
    return img;
}

/* The pixel whose centre is nearest (px, py), in the renderer's pixel
 * coordinates: origin bottom-left, y up (the PNG stores the top row first). */
static rgb8 pixel(const image *img, double px, double py)
{
    int col = (int)floor(px), row = img->height - 1 - (int)floor(py);
    assert_true(col >= 0 && col < img->width && row >= 0 && row < img->height);
    const unsigned char *p = img->rgb + 3 * ((size_t)row * (size_t)img->width + (size_t)col);
    rgb8 c = {p[0], p[1], p[2]};
    return c;
}

static rgb8 to8(rc_rgb c)
{
    rgb8 o = {(int)lround(c.r * 255.0), (int)lround(c.g * 255.0), (int)lround(c.b * 255.0)};
    return o;
}

/* Colours match within one 8-bit step: GL converts floats to bytes with
 * its own rounding, which may differ from lround by one. */
static int near(rgb8 a, rgb8 b)
{
    return abs(a.r - b.r) <= 1 && abs(a.g - b.g) <= 1 && abs(a.b - b.b) <= 1;
}

static void assert_colour(rgb8 got, rc_rgb want, const char *what)
{
    rgb8 w = to8(want);
    if (!near(got, w))
        fail_msg("%s: got (%d,%d,%d), want (%d,%d,%d)", what, got.r, got.g, got.b, w.r, w.g, w.b);
}

/* Renders text as DIR/frame_0000.txt into a PNG at size px; returns it. */
static image render_text(const char *binary, const char *text, int size, const char *extra)
{
    const char *dir = fresh_dir("frame");
    write_text(path_in(dir, "frame_0000.txt"), text);
    char args[1024];
    snprintf(args, sizeof args, "--quiet --size %d %s %s", size, extra ? extra : "",
             path_in(dir, "frame_0000.txt"));
    int st = run(binary, args);
    if (st != 0)
        fail_msg("render exited with %d: %s", st, last_stderr());
    return read_png(path_in(dir, "frame_0000.png"));
}

static size_t count_files(const char *dir)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    size_t n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += e->d_name[0] != '.';
    closedir(d);
    return n;
}

/* ------------------------------------------------------------------ */
/* The colour map (no GL needed)                                       */
/* ------------------------------------------------------------------ */

static void test_viridis_gets_lighter_from_slow_to_fast(void **state)
{
    (void)state;
    /* Perceptual maps order speeds by lightness; Rec. 709 luma is a fair
     * stand-in for lightness and must rise at every step of 1/64. */
    double previous = -1.0;
    for (int k = 0; k <= 64; ++k) {
        rc_rgb c = rc_viridis(k / 64.0);
        double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        assert_true(luma > previous);
        previous = luma;
    }
    /* Matplotlib's end points, within the fit's documented 0.015. */
    rc_rgb lo = rc_viridis(0.0), hi = rc_viridis(1.0);
    assert_true(fabs(lo.r - 0.267) < 0.015 && fabs(lo.g - 0.005) < 0.015 &&
                fabs(lo.b - 0.329) < 0.015);
    assert_true(fabs(hi.r - 0.993) < 0.015 && fabs(hi.g - 0.906) < 0.015 &&
                fabs(hi.b - 0.144) < 0.015);
}

static void test_speed_scale_is_two_and_a_half_rms_speeds(void **state)
{
    (void)state;
    ds_frame_disk d[2] = {{0, 0, 1, 100, 0}, {0, 0, 1, 0, -100}};
    ds_frame f = {d, 2, 5};
    assert_true(rc_speed_scale(&f) == 250.0);
    d[0].vx = 0.0;
    d[1].vy = 0.0;
    assert_true(rc_speed_scale(&f) == 1.0); /* all at rest: any scale, not 0 */
}

/* ------------------------------------------------------------------ */
/* One backend: drawing                                                */
/* ------------------------------------------------------------------ */

static void test_image_has_the_requested_size(void **state)
{
    image img = render_text(*state, "500 500 10\n", 123, NULL);
    assert_int_equal(img.width, 123);
    assert_int_equal(img.height, 123);
    free(img.rgb);
    img = render_text(*state, "500 500 10\n", 800, NULL);
    assert_int_equal(img.width, 800); /* the default is --size 800 */
    free(img.rgb);
}

static void test_disk_centres_have_the_disk_colour_and_empty_space_the_background(void **state)
{
    image img = render_text(*state, "250 250 100\n750 600 50\n", 200, NULL);
    rl_layout l;
    rl_make(&l, 200, 1000.0, 0);
    assert_colour(pixel(&img, rl_px(&l, 250), rl_py(&l, 250)), RC_DISK, "centre of disk 1");
    assert_colour(pixel(&img, rl_px(&l, 750), rl_py(&l, 600)), RC_DISK, "centre of disk 2");
    assert_colour(pixel(&img, rl_px(&l, 600), rl_py(&l, 150)), RC_BACKGROUND, "empty box");
    assert_colour(pixel(&img, 1, 1), RC_BACKGROUND, "margin outside the box");
    free(img.rgb);
}

static void test_y_axis_points_up(void **state)
{
    image img = render_text(*state, "500 850 60\n", 200, NULL);
    rl_layout l;
    rl_make(&l, 200, 1000.0, 0);
    assert_colour(pixel(&img, rl_px(&l, 500), rl_py(&l, 850)), RC_DISK, "disk near the top");
    assert_colour(pixel(&img, rl_px(&l, 500), rl_py(&l, 150)), RC_BACKGROUND, "its mirror image");
    /* And the disk is in the top rows of the PNG file itself. */
    assert_true(rl_py(&l, 850) > 0.75 * 200);
    free(img.rgb);
}

/* A disk of radius 76 px, every pixel around its rim: full colour a pixel
 * inside the rim, background a pixel outside, and a blend of the two for
 * pixels whose centre is within a quarter pixel of the rim (so between a
 * quarter and three quarters of the pixel is covered). Polygons without
 * antialiasing would give only the two pure colours. */
static void test_disk_edges_are_antialiased(void **state)
{
    const int size = 400;
    image img = render_text(*state, "500 500 200\n", size, NULL);
    rl_layout l;
    rl_make(&l, size, 1000.0, 0);
    const double cx = rl_px(&l, 500), cy = rl_py(&l, 500), r = 200 * l.scale;
    int inside = 0, outside = 0, blended = 0;
    rgb8 disk = to8(RC_DISK), bg = to8(RC_BACKGROUND);
    for (int y = (int)(cy - r - 2); y <= (int)(cy + r + 2); ++y)
        for (int x = (int)(cx - r - 2); x <= (int)(cx + r + 2); ++x) {
            double d = hypot(x + 0.5 - cx, y + 0.5 - cy);
            rgb8 c = pixel(&img, x + 0.5, y + 0.5);
            if (d <= r - 1.0 && d >= r - 2.0) {
                assert_true(near(c, disk));
                ++inside;
            } else if (d >= r + 1.0) {
                assert_true(near(c, bg));
                ++outside;
            } else if (fabs(d - r) < 0.25) {
                /* Red goes from 42 (disk) to 255 (background). */
                if (!(c.r > disk.r + 40 && c.r < bg.r - 40))
                    fail_msg("pixel %d,%d at %.3f px from the rim: red %d", x, y, d - r, c.r);
                ++blended;
            }
        }
    /* The rim is 2 pi 76 = 478 px long: about that many pixels in each
     * one-pixel band, half as many in the half-pixel band. */
    if (!(inside > 400 && outside > 400 && blended > 150))
        fail_msg("inside %d, outside %d, blended %d", inside, outside, blended);
    free(img.rgb);
}

static void test_box_outline_is_drawn_on_the_box_edges(void **state)
{
    image img = render_text(*state, "100 100 5\n", 400, NULL);
    rl_layout l;
    rl_make(&l, 400, 1000.0, 0);
    const double mid = rl_px(&l, 500);
    const double edges[4][2] = {
        {rl_px(&l, 0), mid}, {rl_px(&l, 1000), mid}, {mid, rl_py(&l, 0)}, {mid, rl_py(&l, 1000)}};
    for (int k = 0; k < 4; ++k) {
        /* The outline straddles the edge; a step of outline + 1 px either
         * side of it is clear. */
        const double dx = k < 2 ? l.outline + 1.0 : 0.0, dy = k < 2 ? 0.0 : l.outline + 1.0;
        const double x = edges[k][0], y = edges[k][1];
        assert_colour(pixel(&img, x - 0.25 * l.outline + 0.01, y - 0.25 * l.outline + 0.01),
                      RC_OUTLINE, "on the box edge");
        assert_colour(pixel(&img, x + dx, y + dy), RC_BACKGROUND, "beside the edge");
        assert_colour(pixel(&img, x - dx, y - dy), RC_BACKGROUND, "beside the edge");
    }
    free(img.rgb);
}

static void test_speeds_colour_slow_and_fast_disks_differently(void **state)
{
    image img = render_text(*state, "300 500 60 10 0\n700 500 60 0 -240\n", 400, "--vmax 250");
    rl_layout l;
    rl_make(&l, 400, 1000.0, 1);
    rgb8 slow = pixel(&img, rl_px(&l, 300), rl_py(&l, 500));
    rgb8 fast = pixel(&img, rl_px(&l, 700), rl_py(&l, 500));
    assert_colour(slow, rc_viridis(10.0 / 250.0), "slow disk");
    assert_colour(fast, rc_viridis(240.0 / 250.0), "fast disk");
    assert_true(abs(slow.r - fast.r) + abs(slow.g - fast.g) + abs(slow.b - fast.b) > 200);
    /* The legend's bar shows the map: its middle is the middle colour. */
    assert_colour(pixel(&img, l.bar_x + 0.5 * l.bar_w, l.bar_y + 0.5 * l.bar_h), rc_viridis(0.5),
                  "legend middle");
    free(img.rgb);
}

static void test_dir_renders_every_frame_of_a_disks_run(void **state)
{
    char frames[512], pngs[512];
    snprintf(frames, sizeof frames, "%s", fresh_dir("run"));
    snprintf(pngs, sizeof pngs, "%s", fresh_dir("pngs"));
    char args[1200];
    snprintf(args, sizeof args, "20 5 --frames 6 --quiet --velocities --out %s", frames);
    assert_int_equal(run(RENDER_DISKS, args), 0);
    snprintf(args, sizeof args, "--quiet -j 3 --size 64 --dir %s --out %s", frames, pngs);
    assert_int_equal(run(*state, args), 0);
    assert_int_equal(count_files(pngs), 6); /* no temporary left behind */
    for (int k = 0; k < 6; ++k) {
        char name[32];
        snprintf(name, sizeof name, "frame_%04d.png", k);
        image img = read_png(path_in(pngs, name));
        assert_int_equal(img.width, 64);
        free(img.rgb);
    }
    /* Without --out the PNGs go next to the frames (and frames.json). */
    snprintf(args, sizeof args, "--quiet --size 64 --dir %s", frames);
    assert_int_equal(run(*state, args), 0);
    assert_int_equal(count_files(frames), 13);
}

static void test_version_names_the_backend_and_the_gl_renderer(void **state)
{
    assert_int_equal(run(*state, "--version"), 0);
    FILE *f = fopen(path_in(scratch, "stdout.txt"), "rb");
    assert_non_null(f);
    char text[1024];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    assert_non_null(strstr(text, "backend"));
    assert_non_null(strstr(text, "GL renderer: "));
}

/* ------------------------------------------------------------------ */
/* One backend: the run's box, periodic images, labels                 */
/* ------------------------------------------------------------------ */

/* A fresh directory whose path stays (path_in's buffers are reused). */
static const char *kept_dir(char *keep, size_t cap, const char *name)
{
    snprintf(keep, cap, "%s", fresh_dir(name));
    return keep;
}

/* Runs disks with args in a fresh directory dir/name; its path. */
static const char *disks_run(const char *name, const char *args)
{
    static char dir[512];
    snprintf(dir, sizeof dir, "%s", fresh_dir(name));
    char full[1200];
    snprintf(full, sizeof full, "%s --quiet --out %s", args, dir);
    if (run(RENDER_DISKS, full) != 0)
        fail_msg("disks %s: %s", full, last_stderr());
    return dir;
}

/* Renders args (which name the frames) at size px into the PNG out. */
static image render_png(const char *binary, const char *args, int size, const char *out)
{
    char full[2048];
    snprintf(full, sizeof full, "--quiet --size %d %s", size, args);
    int st = run(binary, full);
    if (st != 0)
        fail_msg("render %s exited with %d: %s", full, st, last_stderr());
    return read_png(out);
}

/* The outline crosses the middle of the box's top edge (within half its
 * width of the edge), and the image is background half an outline and a
 * pixel beyond it. */
static void assert_top_edge(const image *img, const rl_layout *l, const char *what)
{
    const double x = rl_px(l, 0.5 * l->box), y = rl_py(l, l->box_y);
    if (!near(pixel(img, x, y - 0.25 * l->outline + 0.01), to8(RC_OUTLINE)) ||
        !near(pixel(img, x, y + 0.5 * l->outline + 1.0), to8(RC_BACKGROUND)))
        fail_msg("%s: no box edge at y = %g px", what, y);
}

/* disks --box-y 500 writes frames.json; the renderer draws that box with
 * no option: the edge at height 500, nothing where a square box's top
 * half would be. */
static void test_a_run_is_drawn_in_its_own_box_from_frames_json(void **state)
{
    const char *dir = disks_run("rect", "40 5 --box-y 500 --frames 1");
    char args[1200], out[600];
    snprintf(out, sizeof out, "%s", path_in(dir, "frame_0000.png"));
    snprintf(args, sizeof args, "--dir %s", dir);
    image img = render_png(*state, args, 200, out);
    assert_string_equal(last_stderr(), "");
    rl_layout l, square;
    rl_make_rect(&l, 200, 1000.0, 500.0, 0);
    rl_make(&square, 200, 1000.0, 0);
    assert_top_edge(&img, &l, "the run's 1000 x 500 box");
    assert_colour(pixel(&img, rl_px(&square, 500), rl_py(&square, 1000) - 0.5 * square.outline),
                  RC_BACKGROUND, "where a square box's top edge would be");
    free(img.rgb);
    /* Options still win, and the contradiction is said. */
    snprintf(args, sizeof args, "--box-y 1000 --dir %s", dir);
    img = render_png(*state, args, 200, out);
    assert_top_edge(&img, &square, "--box-y 1000");
    if (!strstr(last_stderr(), "frames.json gives the box 1000 x 500; drawn 1000 x 1000 as the "
                               "options say"))
        fail_msg("stderr: %s", last_stderr());
    free(img.rgb);
}

/* A frame whose frames.json is another run's is refused, not drawn in
 * that run's box. */
static void test_a_frame_that_is_not_its_frames_json_runs_is_refused(void **state)
{
    char keep[512];
    const char *dir = kept_dir(keep, sizeof keep, "foreign");
    write_text(path_in(dir, "frames.json"), "{\"n\": 3, \"box\": [1000, 500]}\n");
    write_text(path_in(dir, "frame_0000.txt"), "100 100 5\n200 200 5\n");
    char args[600];
    snprintf(args, sizeof args, "--quiet %s", path_in(dir, "frame_0000.txt"));
    assert_int_equal(run(*state, args), 1);
    if (!strstr(last_stderr(), "frame_0000.txt: 2 disks, but ") ||
        !strstr(last_stderr(), "frames.json says n = 3: not that run's frame"))
        fail_msg("stderr: %s", last_stderr());
    assert_int_equal(count_files(dir), 2); /* no PNG */
}

/* In a periodic box a disk across an edge is drawn on both sides and
 * clipped to the box; in a channel only across the x edges; with walls
 * it hangs over the edge as before. Disk 1 crosses the left edge, disk 2
 * the top edge, disk 3 the corner. */
static void test_a_disk_across_a_periodic_edge_is_drawn_on_both_sides(void **state)
{
    const char *text = "15 500 40\n500 985 40\n10 10 40\n";
    rl_layout l;
    rl_make(&l, 400, 1000.0, 0);
    const rgb8 disk = to8(RC_DISK), bg = to8(RC_BACKGROUND);
#define AT(x, y) near(pixel(&img, rl_px(&l, x), rl_py(&l, y)), disk)
#define OFF(x, y) near(pixel(&img, rl_px(&l, x), rl_py(&l, y)), bg)
    image img = render_text(*state, text, 400, "--periodic");
    assert_true(AT(15, 500) && AT(990, 500) && OFF(-15, 500));             /* across x, clipped */
    assert_true(AT(500, 985) && AT(500, 10) && OFF(500, 1015));            /* across y, clipped */
    assert_true(AT(10, 10) && AT(990, 10) && AT(10, 990) && AT(990, 990)); /* the corner */
    free(img.rgb);
    /* The same from a frames.json that says so, with no option. */
    char keep[512];
    const char *dir = kept_dir(keep, sizeof keep, "periodic");
    write_text(path_in(dir, "frames.json"), "{\"box\": [1000, 1000], \"boundary\": \"periodic\"}");
    write_text(path_in(dir, "frame_0000.txt"), text);
    char args[600], out[600];
    snprintf(args, sizeof args, "%s", path_in(dir, "frame_0000.txt"));
    snprintf(out, sizeof out, "%s", path_in(dir, "frame_0000.png"));
    img = render_png(*state, args, 400, out);
    assert_true(AT(990, 500) && OFF(-15, 500) && AT(500, 10) && AT(990, 990));
    free(img.rgb);
    img = render_text(*state, text, 400, "--boundary channel");
    assert_true(AT(990, 500) && OFF(-15, 500));                  /* periodic along x */
    assert_true(OFF(500, 10) && AT(500, 1015) && OFF(990, 990)); /* walls along y */
    free(img.rgb);
    img = render_text(*state, text, 400, NULL);
    assert_true(OFF(990, 500) && AT(-15, 500) && OFF(500, 10) && AT(500, 1015));
    free(img.rgb);
#undef AT
#undef OFF
}

/* disks --trajectory writes extended XYZ: one PNG per frame, named from
 * the file and the frame's index, in the box its Lattice gives, periodic
 * by its pbc (the image column is not drawn). */
static void test_an_extended_xyz_trajectory_gives_a_png_per_frame(void **state)
{
    const char *pngs = fresh_dir("xyz-pngs");
    char out[600], xyz[600], args[1400];
    snprintf(out, sizeof out, "%s", pngs);
    snprintf(xyz, sizeof xyz, "%s", path_in(scratch, "run.xyz"));
    snprintf(args, sizeof args, "30 5 --periodic --box-y 500 --frames 3 --trajectory %s", xyz);
    disks_run("xyz-frames", args);
    snprintf(args, sizeof args, "--out %s %s", out, xyz);
    image img = render_png(*state, args, 200, path_in(out, "run_0002.png"));
    assert_int_equal(count_files(out), 3); /* run_0000.png ... run_0002.png */
    rl_layout l;
    rl_make_rect(&l, 200, 1000.0, 500.0, 1); /* velo: speed colours and their legend */
    assert_top_edge(&img, &l, "the Lattice's 1000 x 500 box");
    free(img.rgb);
}

/* The columns are found by the Properties= header, in any order: a file
 * as ASE writes it (momenta, not drawn) and one with velo before pos. */
static void test_an_xyz_file_is_read_by_its_properties_header(void **state)
{
    char keep[512];
    const char *dir = kept_dir(keep, sizeof keep, "ase");
    /* Written by ase.io.write (ASE 3.22.1) from Atoms with a radius array
     * and velocities, one disk across the left edge of a periodic box. */
    write_text(path_in(dir, "ase.xyz"),
               "2\n"
               "Lattice=\"1000.0 0.0 0.0 0.0 500.0 0.0 0.0 0.0 10.0\" "
               "Properties=species:S:1:pos:R:3:radius:R:1:momenta:R:3 Time=1.5 pbc=\"T T F\"\n"
               "X       10.00000000     250.00000000       0.00000000      40.00000000       "
               "1.00000000       2.00000000       0.00000000\n"
               "X      700.00000000     300.00000000       0.00000000      25.00000000       "
               "3.00000000       4.00000000       0.00000000\n");
    char args[600];
    snprintf(args, sizeof args, "%s", path_in(dir, "ase.xyz"));
    image img = render_png(*state, args, 400, path_in(dir, "ase_0000.png"));
    rl_layout l;
    rl_make_rect(&l, 400, 1000.0, 500.0, 0);
    assert_colour(pixel(&img, rl_px(&l, 700), rl_py(&l, 300)), RC_DISK, "disk 2");
    assert_colour(pixel(&img, rl_px(&l, 990), rl_py(&l, 250)), RC_DISK, "disk 1's image");
    assert_colour(pixel(&img, rl_px(&l, 500), rl_py(&l, 250)), RC_BACKGROUND, "between");
    free(img.rgb);
    write_text(path_in(dir, "order.xyz"),
               "2\n"
               "Properties=velo:R:2:species:S:1:radius:R:1:pos:R:2 pbc=\"F F F\" "
               "Lattice=\"1000 0 0 0 1000 0 0 0 1\"\n"
               "10 0 X 60 300 500\n"
               "0 -240 X 60 700 500\n");
    snprintf(args, sizeof args, "--vmax 250 %s", path_in(dir, "order.xyz"));
    img = render_png(*state, args, 400, path_in(dir, "order_0000.png"));
    rl_make(&l, 400, 1000.0, 1);
    assert_colour(pixel(&img, rl_px(&l, 300), rl_py(&l, 500)), rc_viridis(10.0 / 250.0), "slow");
    assert_colour(pixel(&img, rl_px(&l, 700), rl_py(&l, 500)), rc_viridis(240.0 / 250.0), "fast");
    free(img.rgb);
}

/* The label's text as drawn: every font pixel of every character is the
 * outline's colour where the glyph has it and the background elsewhere. */
static void assert_label(const image *img, const rl_layout *l, const char *want)
{
    const double px = l->text_px;
    for (size_t k = 0; want[k]; ++k) {
        const unsigned char *rows = rf_glyph(want[k]);
        for (int row = 0; row < RF_HEIGHT; ++row)
            for (int col = 0; col < RF_WIDTH; ++col) {
                const int on = rows[row] & (1u << (RF_WIDTH - 1 - col));
                const double x = l->label_x + ((double)k * (RF_WIDTH + 1) + col + 0.5) * px;
                const double y = l->label_y + (RF_HEIGHT - 1 - row + 0.5) * px;
                if (!near(pixel(img, x, y), to8(on ? RC_OUTLINE : RC_BACKGROUND)))
                    fail_msg("label \"%s\": character %zu, row %d, column %d is not %s", want, k,
                             row, col, on ? "drawn" : "blank");
            }
    }
}

/* --label time: k steps_per_frame dt from frames.json (or an XYZ Time=);
 * --label frame: the frame's number. */
static void test_a_label_shows_the_time_or_the_frame_number(void **state)
{
    const char *dir = disks_run("label", "10 5 --frames 4 --steps-per-frame 50 --dt 0.002");
    char args[1200], out[600];
    snprintf(out, sizeof out, "%s", path_in(dir, "frame_0003.png"));
    rl_layout l;
    rl_make_view(&l, 400, 1000.0, 1000.0, 0, 1);
    snprintf(args, sizeof args, "--label time %s", path_in(dir, "frame_0003.txt"));
    image img = render_png(*state, args, 400, out);
    assert_label(&img, &l, "t = 0.3");
    free(img.rgb);
    snprintf(args, sizeof args, "--label frame %s", path_in(dir, "frame_0003.txt"));
    img = render_png(*state, args, 400, out);
    assert_label(&img, &l, "frame 3");
    free(img.rgb);
    /* Without a label nothing is there. */
    snprintf(args, sizeof args, "%s", path_in(dir, "frame_0003.txt"));
    img = render_png(*state, args, 400, out);
    rl_layout plain;
    rl_make(&plain, 400, 1000.0, 0);
    assert_colour(pixel(&img, plain.x0 + 0.5, plain.size - 0.5), RC_BACKGROUND, "no label");
    free(img.rgb);
    /* An XYZ frame's Time=. */
    char xyz[512];
    snprintf(xyz, sizeof xyz, "%s", path_in(scratch, "label.xyz"));
    write_text(xyz,
               "1\nLattice=\"1000 0 0 0 1000 0 0 0 1\" Properties=species:S:1:pos:R:3:radius:R:1 "
               "Time=12.5 pbc=\"F F F\"\nX 500 500 0 20\n");
    snprintf(args, sizeof args, "--label time %s", xyz);
    img = render_png(*state, args, 400, path_in(scratch, "label_0000.png"));
    assert_label(&img, &l, "t = 12.5");
    free(img.rgb);
    /* A frame with no time is refused before anything is drawn. */
    char keep[512];
    const char *bare = kept_dir(keep, sizeof keep, "label-bare");
    write_text(path_in(bare, "frame_0001.txt"), "500 500 20\n");
    snprintf(args, sizeof args, "--label time %s", path_in(bare, "frame_0001.txt"));
    assert_int_equal(run(*state, args), 1);
    if (!strstr(last_stderr(), "--label time: ") || !strstr(last_stderr(), "use --label frame"))
        fail_msg("stderr: %s", last_stderr());
    assert_int_equal(count_files(bare), 1);
}

/* Runs disks with args writing r.gsd and r.xyz of the same frames into
 * a fresh directory dir/name (its frames in dir/name/o); then renders
 * each at size px with both_args, the GSD file with gsd_args too, into
 * dir/name/gsd and dir/name/xyz. The directory's path. */
static const char *gsd_and_xyz(const char *binary, const char *name, const char *args,
                               const char *both_args, const char *gsd_args, int size)
{
    static char dir[512];
    snprintf(dir, sizeof dir, "%s", fresh_dir(name));
    char full[2048];
    snprintf(full, sizeof full, "%s --quiet --out %s/o --gsd %s/r.gsd --trajectory %s/r.xyz", args,
             dir, dir, dir);
    if (run(RENDER_DISKS, full) != 0)
        fail_msg("disks %s: %s", full, last_stderr());
    snprintf(full, sizeof full, "--quiet --size %d %s %s --out %s/gsd %s/r.gsd", size, both_args,
             gsd_args, dir, dir);
    if (run(binary, full) != 0)
        fail_msg("render %s: %s", full, last_stderr());
    snprintf(full, sizeof full, "--quiet --size %d %s --out %s/xyz %s/r.xyz", size, both_args, dir,
             dir);
    if (run(binary, full) != 0)
        fail_msg("render %s: %s", full, last_stderr());
    return dir;
}

/* Frame k's PNGs from the GSD file and from the XYZ file of gsd_and_xyz. */
static void gsd_and_xyz_pngs(const char *dir, int k, image *gsd, image *xyz)
{
    char png[600], name[32];
    snprintf(name, sizeof name, "r_%04d.png", k);
    snprintf(png, sizeof png, "%s/gsd/%s", dir, name);
    *gsd = read_png(png);
    snprintf(png, sizeof png, "%s/xyz/%s", dir, name);
    *xyz = read_png(png);
    assert_int_equal(gsd->width, xyz->width);
    assert_int_equal(gsd->height, xyz->height);
}

/* A run started from centres and velocities a float holds exactly
 * (multiples of 1/8 under 1024): its GSD file (floats about the box's
 * centre) and its XYZ file (six decimals) hold the same numbers, so
 * frame 0 must be the same image to the byte: the box, y up, the centres
 * moved from HOOMD's box about the origin, radii from diameters, speeds,
 * the time. Periodic with a disk across each edge (GSD says no boundary:
 * periodic, as the XYZ's pbc says), and walls by --boundary walls. */
static void test_a_gsd_frame_is_drawn_as_its_xyz_twin_to_the_byte(void **state)
{
    static const struct {
        const char *name, *start, *args, *gsd_args;
    } runs[] = {
        {"gsd-exact-periodic",
         "100.5 200.25 20 1.5 -0.5\n700.125 300.75 20 -2 1\n15 250 20 0.25 0.75\n"
         "500 490 20 0 -3\n990.5 12 20 3 3\n",
         "--periodic --box-y 500", ""},
        {"gsd-exact-walls",
         "100.5 200.25 20 1.5 -0.5\n700.125 300.75 20 -2 1\n25 250 20 0.25 0.75\n"
         "500 470 20 0 -3\n970.5 22 20 3 3\n",
         "--box-y 500", "--boundary walls"},
    };
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; ++k) {
        char args[1200], start[600];
        snprintf(start, sizeof start, "%s", path_in(scratch, "gsd-start.txt"));
        write_text(start, runs[k].start);
        snprintf(args, sizeof args, "--from %s --frames 1 %s", start, runs[k].args);
        const char *dir =
            gsd_and_xyz(*state, runs[k].name, args, "--label time", runs[k].gsd_args, 300);
        image gsd, xyz;
        gsd_and_xyz_pngs(dir, 0, &gsd, &xyz);
        if (memcmp(gsd.rgb, xyz.rgb, (size_t)gsd.width * (size_t)gsd.height * 3) != 0)
            fail_msg("%s: the GSD file's frame 0 is not drawn as the XYZ file's", runs[k].name);
        rl_layout l;
        rl_make_view(&l, 300, 1000.0, 500.0, 1, 1);
        assert_label(&gsd, &l, "t = 0");
        free(gsd.rgb);
        free(xyz.rgb);
    }
}

/* Whether pixel (x, y) is within 1.5 px of the rim of a disk of frame
 * (lines "x y R"), or of its image across a periodic edge. */
static int on_a_rim(const char *frame, const rl_layout *l, int x, int y)
{
    FILE *f = fopen(frame, "r");
    assert_non_null(f);
    double cx, cy, r;
    int near_rim = 0;
    while (!near_rim && fscanf(f, "%lf %lf %lf", &cx, &cy, &r) == 3)
        for (int i = -1; i <= 1; ++i)
            for (int j = -1; j <= 1; ++j) {
                const double d = hypot(x + 0.5 - rl_px(l, cx + i * l->box),
                                       y + 0.5 - rl_py(l, cy + j * l->box_y));
                near_rim |= fabs(d - r * l->scale) < 1.5;
            }
    fclose(f);
    return near_rim;
}

/* disks --gsd and --trajectory of the same runs (periodic, a mixture in
 * a rectangular box, walls): every frame drawn from the GSD file is the
 * XYZ file's image but where GSD's floats move a rim. A centre there is
 * a float about the box's centre, within 2^-24 x 500 = 3e-5 of the
 * double (and the XYZ's within 5e-7): at 400 px a rim moves by under
 * 2e-5 px, which can turn a rim pixel's coverage across a rounding step
 * of its 8-bit level, never by more than one level. */
static void test_a_gsd_run_is_drawn_as_its_xyz_twin(void **state)
{
    static const struct {
        const char *name, *args, *gsd_args;
        double box_y;
    } runs[] = {
        {"gsd-periodic", "200 5 --periodic --frames 3", "", 1000.0},
        {"gsd-mixture", "150 5 --periodic --box-y 500 --mixture 1.4:0.5 --frames 3", "", 500.0},
        {"gsd-walls", "200 5 --frames 3", "--boundary walls", 1000.0},
    };
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; ++k) {
        const char *dir =
            gsd_and_xyz(*state, runs[k].name, runs[k].args, "", runs[k].gsd_args, 400);
        rl_layout l;
        rl_make_rect(&l, 400, 1000.0, runs[k].box_y, 1);
        size_t differing = 0;
        for (int frame = 0; frame < 3; ++frame) {
            image gsd, xyz;
            gsd_and_xyz_pngs(dir, frame, &gsd, &xyz);
            char text[600];
            snprintf(text, sizeof text, "%s/o/frame_%04d.txt", dir, frame);
            for (int y = 0; y < gsd.height; ++y)
                for (int x = 0; x < gsd.width; ++x) {
                    const rgb8 a = pixel(&gsd, x + 0.5, y + 0.5), b = pixel(&xyz, x + 0.5, y + 0.5);
                    if (a.r == b.r && a.g == b.g && a.b == b.b)
                        continue;
                    ++differing;
                    if (!near(a, b) || !on_a_rim(text, &l, x, y))
                        fail_msg("%s frame %d, pixel (%d,%d): GSD (%d,%d,%d), XYZ (%d,%d,%d)",
                                 runs[k].name, frame, x, y, a.r, a.g, a.b, b.r, b.g, b.b);
                }
            free(gsd.rgb);
            free(xyz.rgb);
        }
        print_message("%s: %zu rim pixels of 3 frames differ by one level\n", runs[k].name,
                      differing);
    }
}

/* --out F.png writes that one file for one frame, and with more frames
 * is refused, making nothing; a failed render leaves no directory it
 * made. */
static void test_out_names_one_png_or_a_directory(void **state)
{
    char keep[512];
    const char *dir = kept_dir(keep, sizeof keep, "out-png");
    char one[600], args[1600];
    write_text(path_in(dir, "frame_0000.txt"), "500 500 20\n");
    write_text(path_in(dir, "frame_0001.txt"), "500 500 20\n");
    snprintf(one, sizeof one, "%s", path_in(dir, "one.png"));
    snprintf(args, sizeof args, "--out %s %s", one, path_in(dir, "frame_0000.txt"));
    image img = render_png(*state, args, 64, one);
    assert_int_equal(img.width, 64);
    free(img.rgb);
    struct stat st;
    assert_int_equal(stat(one, &st), 0);
    assert_true(S_ISREG(st.st_mode));
    snprintf(args, sizeof args, "--quiet --out %s --dir %s", path_in(dir, "two.png"), dir);
    assert_int_equal(run(*state, args), 2);
    if (!strstr(last_stderr(), "names one PNG, but there are 2 frames: give --out a directory"))
        fail_msg("stderr: %s", last_stderr());
    assert_int_equal(count_files(dir), 3); /* the frames and one.png: no two.png */
    /* A render that fails removes the --out directory it made. */
    write_text(path_in(dir, "bad.txt"), "1 2 -3\n");
    snprintf(args, sizeof args, "--quiet --out %s %s", path_in(dir, "made"),
             path_in(dir, "bad.txt"));
    assert_int_equal(run(*state, args), 1);
    assert_int_not_equal(stat(path_in(dir, "made"), &st), 0);
}

/* ------------------------------------------------------------------ */
/* One backend: bad input                                              */
/* ------------------------------------------------------------------ */

/* Renders the files named in args (relative to scratch/bad) into
 * scratch/bad-out: must fail with `message` on stderr and write nothing. */
static void expect_failure(const char *binary, const char *args, const char *message)
{
    const char *out = fresh_dir("bad-out");
    char full[1500];
    snprintf(full, sizeof full, "--quiet --size 64 --out %s %s", out, args);
    int st = run(binary, full);
    const char *err = last_stderr();
    if (st == 0 || !strstr(err, message))
        fail_msg("render %s: status %d, stderr \"%s\", want \"%s\"", args, st, err, message);
    assert_int_equal(count_files(out), 0);
}

static const char *bad_file(const char *name, const char *bytes, size_t len)
{
    const char *dir = path_in(scratch, "bad");
    mkdir(dir, 0777);
    char *p = path_in(dir, name);
    write_bytes(p, bytes, len);
    return p;
}

static void test_a_short_line_is_reported_with_file_and_line(void **state)
{
    char text[2048] = "";
    for (int k = 0; k < 36; ++k)
        strcat(text, "500 500 5\n");
    strcat(text, "1 2\n");
    const char *p = bad_file("frame_0012.txt", text, strlen(text));
    expect_failure(*state, p, "frame_0012.txt:37: expected 3 or 5 numbers");
}

static void test_an_empty_file_is_refused(void **state)
{
    expect_failure(*state, bad_file("empty.txt", "", 0), "empty.txt: empty frame");
}

static void test_nan_and_infinity_are_refused(void **state)
{
    const char nan_text[] = "1 2 3\nnan 5 5\n", inf_text[] = "1 2 inf\n";
    expect_failure(*state, bad_file("nan.txt", nan_text, strlen(nan_text)),
                   "nan.txt:2: number is not finite");
    expect_failure(*state, bad_file("inf.txt", inf_text, strlen(inf_text)),
                   "inf.txt:1: number is not finite");
}

static void test_a_negative_radius_is_refused(void **state)
{
    const char text[] = "1 2 3\n4 5 -3\n";
    expect_failure(*state, bad_file("neg.txt", text, strlen(text)),
                   "neg.txt:2: radius must be positive");
}

static void test_binary_garbage_is_refused(void **state)
{
    const char bytes[] = {'\x7f', 'E', 'L', 'F', '\x02', '\0', '\x01', '\xff', '\n'};
    expect_failure(*state, bad_file("garbage.txt", bytes, sizeof bytes), "garbage.txt:1: ");
}

static void test_cyclic_map_closes_on_itself_without_jumps(void **state)
{
    (void)state;
    rc_rgb a = rc_cyclic(0.0), b = rc_cyclic(1.0), c = rc_cyclic(-1.0);
    assert_true(fabs(a.r - b.r) < 1e-6 && fabs(a.g - b.g) < 1e-6 && fabs(a.b - b.b) < 1e-6);
    assert_true(fabs(a.r - c.r) < 1e-6 && fabs(a.g - c.g) < 1e-6 && fabs(a.b - c.b) < 1e-6);
    /* Every step of 1/256 moves each channel by little (no seam, no jump),
     * and the colours stay inside the sRGB cube unclipped. */
    rc_rgb prev = rc_cyclic(0.0);
    for (int k = 1; k <= 256; ++k) {
        rc_rgb now = rc_cyclic(k / 256.0);
        assert_true(now.r > 0.0f && now.r < 1.0f && now.g > 0.0f && now.g < 1.0f && now.b > 0.0f &&
                    now.b < 1.0f);
        assert_true(fabs(now.r - prev.r) < 0.03 && fabs(now.g - prev.g) < 0.03 &&
                    fabs(now.b - prev.b) < 0.03);
        prev = now;
    }
    /* Opposite orientations are far apart in colour. */
    rc_rgb half = rc_cyclic(0.5);
    assert_true(fabs(a.r - half.r) + fabs(a.g - half.g) + fabs(a.b - half.b) > 0.6);
    /* psi6 = 1 (bonds along x) is the middle of the map at full
     * brightness; no order at all is that colour at 0.3. */
    rc_rgb one = rc_psi6(1.0, 0.0), none = rc_psi6(0.0, 0.0);
    assert_true(fabs(one.r - half.r) < 1e-6 && fabs(one.g - half.g) < 1e-6);
    assert_true(fabs(none.r - 0.3f * half.r) < 1e-6 && fabs(none.b - 0.3f * half.b) < 1e-6);
}

/* --colour size: the small disk at the map's bottom, the large one at its
 * top, a disk of a size between at its place between; one size alone is
 * the middle colour. */
static void test_size_colours_disks_by_their_radius(void **state)
{
    image img = render_text(*state, "250 500 40 0 0\n500 500 70 0 0\n750 500 100 0 0\n", 400,
                            "--colour size");
    rl_layout l;
    rl_make(&l, 400, 1000.0, 1);
    assert_colour(pixel(&img, rl_px(&l, 250), rl_py(&l, 500)), rc_viridis(0.0), "small disk");
    assert_colour(pixel(&img, rl_px(&l, 500), rl_py(&l, 500)), rc_viridis(0.5), "middle disk");
    assert_colour(pixel(&img, rl_px(&l, 750), rl_py(&l, 500)), rc_viridis(1.0), "large disk");
    free(img.rgb);
    img = render_text(*state, "500 500 40\n", 400, "--color size");
    assert_colour(pixel(&img, rl_px(&l, 500), rl_py(&l, 500)), rc_viridis(0.5), "one size");
    free(img.rgb);
}

static void test_psi6_colours_a_hexagon_by_its_orientation(void **state)
{
    /* Six disks touching a seventh, the whole turned by 0.1 rad: every
     * one of the seven has |psi6| = 1 at phase 0.6. A lone disk far away
     * has no neighbour, psi6 = 0. */
    char text[1024];
    size_t len = (size_t)snprintf(text, sizeof text, "500 500 40\n150 150 40\n");
    for (int k = 0; k < 6; ++k)
        len += (size_t)snprintf(text + len, sizeof text - len, "%.6f %.6f 40\n",
                                500.0 + 80.0 * cos(0.1 + k * 3.14159265358979 / 3.0),
                                500.0 + 80.0 * sin(0.1 + k * 3.14159265358979 / 3.0));
    image img = render_text(*state, text, 400, "--colour psi6");
    rl_layout l;
    rl_make(&l, 400, 1000.0, 1);
    assert_colour(pixel(&img, rl_px(&l, 500), rl_py(&l, 500)), rc_psi6(cos(0.6), sin(0.6)),
                  "centre of the hexagon");
    assert_colour(pixel(&img, rl_px(&l, 500 + 80 * cos(0.1)), rl_py(&l, 500 + 80 * sin(0.1))),
                  rc_psi6(cos(0.6), sin(0.6)), "a disk of the ring");
    assert_colour(pixel(&img, rl_px(&l, 150), rl_py(&l, 150)), rc_psi6(0.0, 0.0), "the lone disk");
    /* The legend's bar is the cyclic map: its middle is orientation 0. */
    /* The bar's slice at a row shows the map at the slice's middle. */
    const double row = floor(0.5 * l.bar_h);
    assert_colour(pixel(&img, l.bar_x + 0.5 * l.bar_w, l.bar_y + row + 0.5),
                  rc_cyclic((row + 0.5) / l.bar_h), "legend middle");
    free(img.rgb);
    /* --color is the same option. */
    img = render_text(*state, text, 400, "--color psi6");
    assert_colour(pixel(&img, rl_px(&l, 150), rl_py(&l, 150)), rc_psi6(0.0, 0.0), "--color");
    free(img.rgb);
}

static void test_psi6_counts_neighbours_across_a_periodic_edge(void **state)
{
    /* Two disks touching across the left/right edge: bonded only when the
     * box is periodic (a lone pair's bond gives |psi6| = 1). */
    const char *text = "30 500 40\n970 500 40\n";
    rl_layout l;
    rl_make(&l, 400, 1000.0, 1);
    image img = render_text(*state, text, 400, "--colour psi6 --periodic");
    assert_colour(pixel(&img, rl_px(&l, 30), rl_py(&l, 500)), rc_psi6(1.0, 0.0), "periodic");
    free(img.rgb);
    img = render_text(*state, text, 400, "--colour psi6");
    assert_colour(pixel(&img, rl_px(&l, 30), rl_py(&l, 500)), rc_psi6(0.0, 0.0), "walls");
    free(img.rgb);
}

static void test_a_tall_box_is_drawn_with_its_own_height(void **state)
{
    /* A 500 x 1000 box: as tall as a square box would be, half as wide. */
    image img = render_text(*state, "250 900 40\n", 400, "--box 500 --box-y 1000");
    rl_layout l, square;
    rl_make_rect(&l, 400, 500.0, 1000.0, 0);
    rl_make(&square, 400, 1000.0, 0);
    assert_true(fabs(l.scale - square.scale) < 1e-12);
    assert_colour(pixel(&img, rl_px(&l, 250), rl_py(&l, 900)), RC_DISK, "disk near the top");
    assert_colour(pixel(&img, rl_px(&l, 250), rl_py(&l, 100)), RC_BACKGROUND, "its mirror image");
    /* The right edge of the box is drawn at x = 500, centred in the image. */
    const double right = rl_px(&l, 500.0), mid = rl_py(&l, 500.0);
    assert_colour(pixel(&img, right - 0.25 * l.outline + 0.01, mid), RC_OUTLINE, "right edge");
    assert_colour(pixel(&img, rl_px(&l, 750.0), mid), RC_BACKGROUND, "beyond the right edge");
    assert_true(fabs(rl_px(&l, 250.0) - 200.0) <= 1.0);
    free(img.rgb);
}

static void test_bad_colour_requests_are_refused(void **state)
{
    /* path_in's buffers are reused: keep the frame's path. */
    char frame[512];
    snprintf(frame, sizeof frame, "%s", path_in(fresh_dir("colour"), "frame_0000.txt"));
    write_text(frame, "500 500 10\n");
    char args[1024];
    snprintf(args, sizeof args, "--colour hue %s", frame);
    assert_int_equal(run(*state, args), 2);
    assert_non_null(strstr(last_stderr(), "--colour must be speed, psi6 or size, got 'hue'"));
    snprintf(args, sizeof args, "--quiet --colour speed %s", frame);
    assert_int_equal(run(*state, args), 1);
    assert_non_null(strstr(last_stderr(), "--colour speed needs frames of"));
    /* A periodic box too small for the psi6 cutoff is named. */
    snprintf(args, sizeof args, "--quiet --colour psi6 --periodic --box 50 %s", frame);
    assert_int_equal(run(*state, args), 1);
    if (!strstr(last_stderr(), "narrower than 2.8 diameters"))
        fail_msg("stderr: %s", last_stderr());
}

static void test_a_missing_file_is_refused(void **state)
{
    expect_failure(*state, path_in(scratch, "no_such_frame.txt"),
                   "no_such_frame.txt: cannot open: No such file or directory");
}

static void test_a_bad_frame_among_good_ones_fails_the_run(void **state)
{
    const char *good = bad_file("frame_0001.txt", "1 2 3\n", 6);
    char args[1200];
    snprintf(args, sizeof args, "-j 1 %s %s", good, path_in(scratch, "bad/neg.txt"));
    const char text[] = "1 2 3\n4 5 -3\n";
    bad_file("neg.txt", text, strlen(text));
    const char *out = fresh_dir("bad-out");
    char full[1500];
    snprintf(full, sizeof full, "--quiet --out %s %s", out, args);
    assert_int_not_equal(run(*state, full), 0);
    assert_non_null(strstr(last_stderr(), "neg.txt:2: radius must be positive"));
    /* The good frame rendered before the bad one is complete, the bad one
     * has no file at all. */
    assert_int_equal(count_files(out), 1);
    free(read_png(path_in(out, "frame_0001.png")).rgb);
}

static void test_directories_that_cannot_be_read_are_refused(void **state)
{
    char args[600];
    snprintf(args, sizeof args, "--dir %s", path_in(scratch, "no_such_dir"));
    expect_failure(*state, args, "no_such_dir: cannot open directory: No such file or directory");
    /* A file where a directory should be. */
    snprintf(args, sizeof args, "--dir %s", bad_file("plain.txt", "1 2 3\n", 6));
    expect_failure(*state, args, "plain.txt: cannot open directory: Not a directory");
    /* A directory where a frame should be. */
    expect_failure(*state, fresh_dir("a_dir.txt"), "a_dir.txt: read error: Is a directory");
    /* A directory with no frames. */
    snprintf(args, sizeof args, "--dir %s", fresh_dir("no_frames"));
    expect_failure(*state, args, "no_frames: no frame_*.txt files");
    /* Permissions: only meaningful when not root, who reads anything. */
    if (geteuid() != 0) {
        const char *locked = fresh_dir("locked");
        assert_int_equal(chmod(locked, 0), 0);
        snprintf(args, sizeof args, "--dir %s", locked);
        expect_failure(*state, args, "locked: cannot open directory: Permission denied");
        chmod(locked, 0755);
    }
}

static void test_an_output_directory_that_is_a_file_is_refused(void **state)
{
    const char *frame = bad_file("frame_0002.txt", "1 2 3\n", 6);
    char args[1200];
    snprintf(args, sizeof args, "--quiet --out %s %s", frame, frame);
    assert_int_equal(run(*state, args), 1);
    assert_non_null(strstr(last_stderr(), "frame_0002.png: cannot create: Not a directory"));
}

/* ------------------------------------------------------------------ */
/* Movies (--movie, through ffmpeg)                                    */
/* ------------------------------------------------------------------ */

static int have_ffmpeg(void)
{
    return system("command -v ffmpeg >/dev/null 2>&1 && command -v ffprobe >/dev/null 2>&1") == 0;
}

#define SKIP_WITHOUT_FFMPEG()                                                                      \
    do {                                                                                           \
        if (!have_ffmpeg()) {                                                                      \
            print_message("skipped: no ffmpeg and ffprobe on PATH (Debian: ffmpeg)\n");            \
            skip();                                                                                \
        }                                                                                          \
    } while (0)

/* What ffprobe says about the video stream, as "key=value" lines. */
typedef struct probe {
    char codec[32], pix_fmt[32], rate[32];
    int width, height, frames;
} probe;

static probe ffprobe(const char *movie)
{
    char cmd[1024], line[256];
    snprintf(cmd, sizeof cmd,
             "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
             "stream=codec_name,pix_fmt,width,height,nb_read_frames,r_frame_rate "
             "-of default=noprint_wrappers=1 '%s'",
             movie);
    probe pr;
    memset(&pr, 0, sizeof pr);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    while (fgets(line, sizeof line, p)) {
        line[strcspn(line, "\n")] = '\0';
        sscanf(line, "codec_name=%31s", pr.codec);
        sscanf(line, "pix_fmt=%31s", pr.pix_fmt);
        sscanf(line, "r_frame_rate=%31s", pr.rate);
        sscanf(line, "width=%d", &pr.width);
        sscanf(line, "height=%d", &pr.height);
        sscanf(line, "nb_read_frames=%d", &pr.frames);
    }
    assert_int_equal(pclose(p), 0);
    return pr;
}

static void test_a_movie_is_h264_yuv420p_with_every_frame(void **state)
{
    SKIP_WITHOUT_FFMPEG();
    char frames[512], out[512], args[1400];
    snprintf(frames, sizeof frames, "%s", fresh_dir("movie-run"));
    snprintf(out, sizeof out, "%s", fresh_dir("movie-out"));
    snprintf(args, sizeof args, "20 5 --frames 12 --quiet --velocities --out %s", frames);
    assert_int_equal(run(RENDER_DISKS, args), 0);
    snprintf(args, sizeof args, "--quiet -j 3 --size 96 --fps 30 --movie %s --dir %s",
             path_in(out, "run.mp4"), frames);
    if (run(*state, args) != 0)
        fail_msg("render --movie: %s", last_stderr());
    probe pr = ffprobe(path_in(out, "run.mp4"));
    assert_string_equal(pr.codec, "h264");
    assert_string_equal(pr.pix_fmt, "yuv420p");
    assert_string_equal(pr.rate, "30/1");
    assert_int_equal(pr.frames, 12);
    assert_int_equal(pr.width, 96);
    assert_int_equal(pr.height, 96);
    assert_int_equal(count_files(out), 1);     /* the movie, no temporary */
    assert_int_equal(count_files(frames), 13); /* the frames and frames.json: no PNG */
}

/* yuv420p stores colour for 2 x 2 pixel blocks: an odd size is padded. */
static void test_an_odd_size_makes_an_even_movie(void **state)
{
    SKIP_WITHOUT_FFMPEG();
    const char *dir = fresh_dir("movie-odd");
    write_text(path_in(dir, "frame_0000.txt"), "500 500 100\n");
    char args[1400];
    snprintf(args, sizeof args, "--quiet --size 65 --movie %s %s", path_in(dir, "odd.mp4"),
             path_in(dir, "frame_0000.txt"));
    if (run(*state, args) != 0)
        fail_msg("render --movie --size 65: %s", last_stderr());
    probe pr = ffprobe(path_in(dir, "odd.mp4"));
    assert_int_equal(pr.width, 66);
    assert_int_equal(pr.height, 66);
    assert_int_equal(pr.frames, 1);
}

/* Workers finish frames in any order; the movie must not. Frame k shows
 * one disk at x = 100 + 70 k: decoded, frame k is dark there and light
 * where the disks of frames k - 1 and k + 1 were. */
static void test_movie_frames_keep_their_order_with_many_workers(void **state)
{
    SKIP_WITHOUT_FFMPEG();
    enum { FRAMES = 12, SIZE = 160 };
    const char *dir = fresh_dir("movie-order");
    char dir_copy[512], name[32], text[64], args[1400], cmd[1400];
    snprintf(dir_copy, sizeof dir_copy, "%s", dir);
    for (int k = 0; k < FRAMES; ++k) {
        snprintf(name, sizeof name, "frame_%04d.txt", k);
        snprintf(text, sizeof text, "%d 500 40\n", 100 + 70 * k);
        write_text(path_in(dir_copy, name), text);
    }
    snprintf(args, sizeof args, "--quiet -j 4 --size %d --movie %s --dir %s", SIZE,
             path_in(dir_copy, "order.mp4"), dir_copy);
    if (run(*state, args) != 0)
        fail_msg("render --movie -j 4: %s", last_stderr());
    snprintf(cmd, sizeof cmd, "ffmpeg -v error -i '%s' -f rawvideo -pix_fmt rgb24 pipe:1",
             path_in(dir_copy, "order.mp4"));
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    static unsigned char rgb[SIZE * SIZE * 3];
    rl_layout l;
    rl_make(&l, SIZE, 1000.0, 0);
    /* Brightness (r + g + b) of the pixel at frame coordinates (x, 500):
     * the disk colour sums to ~330, the background to 765; a disk of 5.6 px
     * radius keeps its centre far from either after lossy coding. */
    for (int k = 0; k < FRAMES; ++k) {
        assert_int_equal(fread(rgb, 1, sizeof rgb, p), sizeof rgb);
        for (int d = k - 1; d <= k + 1; ++d) {
            if (d < 0 || d >= FRAMES)
                continue;
            int col = (int)floor(rl_px(&l, 100 + 70 * d));
            int row = SIZE - 1 - (int)floor(rl_py(&l, 500));
            const unsigned char *px = rgb + 3 * ((size_t)row * SIZE + (size_t)col);
            int sum = px[0] + px[1] + px[2];
            if (d == k ? sum > 500 : sum < 650)
                fail_msg("movie frame %d at the disk of frame %d: brightness %d", k, d, sum);
        }
    }
    assert_int_equal(fread(rgb, 1, 1, p), 0); /* no frame more */
    assert_int_equal(pclose(p), 0);
}

/* The name says the format: .gif a GIF, .mp4 an MP4; any other name is
 * refused before anything is rendered. */
static void test_a_movie_is_the_format_its_name_says(void **state)
{
    SKIP_WITHOUT_FFMPEG();
    const char *dir = fresh_dir("movie-kinds");
    char dir_copy[512], args[1400];
    snprintf(dir_copy, sizeof dir_copy, "%s", dir);
    for (int k = 0; k < 3; ++k) {
        char name[32], text[32];
        snprintf(name, sizeof name, "frame_%04d.txt", k);
        snprintf(text, sizeof text, "%d 500 60\n", 200 + 300 * k);
        write_text(path_in(dir_copy, name), text);
    }
    const struct {
        const char *name, *magic;
        size_t at;
    } kinds[] = {{"m.gif", "GIF89a", 0}, {"m.GIF", "GIF89a", 0}, {"m.mp4", "ftyp", 4}};
    for (size_t k = 0; k < 3; ++k) {
        snprintf(args, sizeof args, "--quiet --size 96 --movie %s --dir %s",
                 path_in(dir_copy, kinds[k].name), dir_copy);
        if (run(*state, args) != 0)
            fail_msg("render --movie %s: %s", kinds[k].name, last_stderr());
        FILE *f = fopen(path_in(dir_copy, kinds[k].name), "rb");
        assert_non_null(f);
        char head[16] = "";
        assert_int_equal(fread(head, 1, sizeof head, f), sizeof head);
        fclose(f);
        if (memcmp(head + kinds[k].at, kinds[k].magic, strlen(kinds[k].magic)) != 0)
            fail_msg("%s does not hold \"%s\" at byte %zu", kinds[k].name, kinds[k].magic,
                     kinds[k].at);
        assert_int_equal(ffprobe(path_in(dir_copy, kinds[k].name)).frames, 3);
    }
    assert_int_equal(count_files(dir_copy), 6);
    snprintf(args, sizeof args, "--quiet --movie %s --dir %s", path_in(dir_copy, "m.avi"),
             dir_copy);
    assert_int_equal(run(*state, args), 2);
    if (!strstr(last_stderr(), "m.avi: the name must end in .mp4 (H.264) or .gif"))
        fail_msg("stderr: %s", last_stderr());
    assert_int_equal(count_files(dir_copy), 6); /* no m.avi, no temporary */
}

/* Runs the renderer with PATH holding only an empty directory. */
static void test_a_movie_without_ffmpeg_names_the_package(void **state)
{
    const char *dir = fresh_dir("movie-noffmpeg");
    char dir_copy[512], args[1400];
    snprintf(dir_copy, sizeof dir_copy, "%s", dir);
    write_text(path_in(dir_copy, "frame_0000.txt"), "500 500 10\n");
    assert_int_equal(mkdir(path_in(dir_copy, "empty"), 0755), 0);
    snprintf(args, sizeof args, "--quiet --movie %s %s", path_in(dir_copy, "m.mp4"),
             path_in(dir_copy, "frame_0000.txt"));
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "PATH=%s %s %s >%s/stdout.txt 2>%s/stderr.txt",
             path_in(dir_copy, "empty"), (const char *)*state, args, scratch, scratch);
    int st = system(cmd);
    assert_true(WIFEXITED(st));
    assert_int_equal(WEXITSTATUS(st), 1);
    const char *err = last_stderr();
    if (!strstr(err, "ffmpeg is not on PATH") || !strstr(err, "apt-get install ffmpeg") ||
        strchr(err, '\n') != err + strlen(err) - 1)
        fail_msg("stderr: \"%s\"", err);
    assert_int_equal(count_files(dir_copy), 2); /* the frame and empty/: no movie */
}

static void test_a_bad_frame_leaves_no_movie(void **state)
{
    SKIP_WITHOUT_FFMPEG();
    const char *dir = fresh_dir("movie-bad");
    char dir_copy[512], args[1400];
    snprintf(dir_copy, sizeof dir_copy, "%s", dir);
    for (int k = 0; k < 6; ++k) {
        char name[32];
        snprintf(name, sizeof name, "frame_%04d.txt", k);
        write_text(path_in(dir_copy, name), k == 4 ? "1 2 -3\n" : "500 500 10\n");
    }
    snprintf(args, sizeof args, "--quiet -j 2 --size 64 --movie %s --dir %s",
             path_in(dir_copy, "m.mp4"), dir_copy);
    assert_int_equal(run(*state, args), 1);
    assert_non_null(strstr(last_stderr(), "frame_0004.txt:1: radius must be positive"));
    assert_int_equal(count_files(dir_copy), 6); /* the frames: no movie, no temporary */
}

/* ------------------------------------------------------------------ */
/* Backends agree                                                      */
/* ------------------------------------------------------------------ */

#if defined(RENDER_osmesa) && defined(RENDER_egl)
/* Both backends run the same shaders on the same rasterizer (llvmpipe on
 * Mesa), so the images are expected to be identical. The tolerance allows
 * what a different rasterizer could legitimately change: pixels on an
 * antialiased edge (within 1.5 px of a disk's rim) may differ by 2 steps. */
static void test_osmesa_and_egl_draw_the_same_image(void **state)
{
    (void)state;
    const char text[] = "250 250 100 10 0\n750 600 50 -200 30\n510.3 500.7 3.3 0 90\n"
                        "990 10 8 5 5\n";
    image a = render_text(RENDER_osmesa, text, 300, NULL);
    image b = render_text(RENDER_egl, text, 300, NULL);
    assert_int_equal(a.width, b.width);
    assert_int_equal(a.height, b.height);
    rl_layout l;
    rl_make(&l, 300, 1000.0, 1);
    size_t differing = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            rgb8 pa = pixel(&a, x + 0.5, y + 0.5), pb = pixel(&b, x + 0.5, y + 0.5);
            if (pa.r == pb.r && pa.g == pb.g && pa.b == pb.b)
                continue;
            ++differing;
            int on_edge = 0;
            for (const char *s = text; *s;) {
                double dx, dy, r;
                assert_int_equal(sscanf(s, "%lf %lf %lf", &dx, &dy, &r), 3);
                double d = hypot(x + 0.5 - rl_px(&l, dx), y + 0.5 - rl_py(&l, dy));
                on_edge |= fabs(d - r * l.scale) < 1.5;
                s = strchr(s, '\n') + 1;
            }
            if (!on_edge || abs(pa.r - pb.r) > 2 || abs(pa.g - pb.g) > 2 || abs(pa.b - pb.b) > 2)
                fail_msg("pixel (%d,%d): osmesa (%d,%d,%d), egl (%d,%d,%d)", x, y, pa.r, pa.g, pa.b,
                         pb.r, pb.g, pb.b);
        }
    print_message("osmesa and egl: %zu of %d pixels differ\n", differing, a.width * a.height);
    free(a.rgb);
    free(b.rgb);
}
#endif

/* ------------------------------------------------------------------ */

#define BACKEND_TESTS(binary)                                                                      \
    cmocka_unit_test_prestate(test_image_has_the_requested_size, binary),                          \
        cmocka_unit_test_prestate(                                                                 \
            test_disk_centres_have_the_disk_colour_and_empty_space_the_background, binary),        \
        cmocka_unit_test_prestate(test_y_axis_points_up, binary),                                  \
        cmocka_unit_test_prestate(test_disk_edges_are_antialiased, binary),                        \
        cmocka_unit_test_prestate(test_box_outline_is_drawn_on_the_box_edges, binary),             \
        cmocka_unit_test_prestate(test_speeds_colour_slow_and_fast_disks_differently, binary),     \
        cmocka_unit_test_prestate(test_psi6_colours_a_hexagon_by_its_orientation, binary),         \
        cmocka_unit_test_prestate(test_size_colours_disks_by_their_radius, binary),                \
        cmocka_unit_test_prestate(test_psi6_counts_neighbours_across_a_periodic_edge, binary),     \
        cmocka_unit_test_prestate(test_a_tall_box_is_drawn_with_its_own_height, binary),           \
        cmocka_unit_test_prestate(test_bad_colour_requests_are_refused, binary),                   \
        cmocka_unit_test_prestate(test_dir_renders_every_frame_of_a_disks_run, binary),            \
        cmocka_unit_test_prestate(test_version_names_the_backend_and_the_gl_renderer, binary),     \
        cmocka_unit_test_prestate(test_a_short_line_is_reported_with_file_and_line, binary),       \
        cmocka_unit_test_prestate(test_an_empty_file_is_refused, binary),                          \
        cmocka_unit_test_prestate(test_nan_and_infinity_are_refused, binary),                      \
        cmocka_unit_test_prestate(test_a_negative_radius_is_refused, binary),                      \
        cmocka_unit_test_prestate(test_binary_garbage_is_refused, binary),                         \
        cmocka_unit_test_prestate(test_a_missing_file_is_refused, binary),                         \
        cmocka_unit_test_prestate(test_a_bad_frame_among_good_ones_fails_the_run, binary),         \
        cmocka_unit_test_prestate(test_directories_that_cannot_be_read_are_refused, binary),       \
        cmocka_unit_test_prestate(test_an_output_directory_that_is_a_file_is_refused, binary),     \
        cmocka_unit_test_prestate(test_a_run_is_drawn_in_its_own_box_from_frames_json, binary),    \
        cmocka_unit_test_prestate(test_a_frame_that_is_not_its_frames_json_runs_is_refused,        \
                                  binary),                                                         \
        cmocka_unit_test_prestate(test_a_disk_across_a_periodic_edge_is_drawn_on_both_sides,       \
                                  binary),                                                         \
        cmocka_unit_test_prestate(test_an_extended_xyz_trajectory_gives_a_png_per_frame, binary),  \
        cmocka_unit_test_prestate(test_an_xyz_file_is_read_by_its_properties_header, binary),      \
        cmocka_unit_test_prestate(test_a_gsd_frame_is_drawn_as_its_xyz_twin_to_the_byte, binary),  \
        cmocka_unit_test_prestate(test_a_gsd_run_is_drawn_as_its_xyz_twin, binary),                \
        cmocka_unit_test_prestate(test_a_label_shows_the_time_or_the_frame_number, binary),        \
        cmocka_unit_test_prestate(test_out_names_one_png_or_a_directory, binary)

#define MOVIE_TESTS(binary)                                                                        \
    cmocka_unit_test_prestate(test_a_movie_is_h264_yuv420p_with_every_frame, binary),              \
        cmocka_unit_test_prestate(test_an_odd_size_makes_an_even_movie, binary),                   \
        cmocka_unit_test_prestate(test_movie_frames_keep_their_order_with_many_workers, binary),   \
        cmocka_unit_test_prestate(test_a_movie_without_ffmpeg_names_the_package, binary),          \
        cmocka_unit_test_prestate(test_a_bad_frame_leaves_no_movie, binary),                       \
        cmocka_unit_test_prestate(test_a_movie_is_the_format_its_name_says, binary)

/* The movie code is the same in every backend's binary: tested with one. */
#ifdef RENDER_osmesa
#define MOVIE_BINARY RENDER_osmesa
#else
#define MOVIE_BINARY RENDER_egl
#endif

int main(void)
{
    const struct CMUnitTest colours[] = {
        cmocka_unit_test(test_viridis_gets_lighter_from_slow_to_fast),
        cmocka_unit_test(test_cyclic_map_closes_on_itself_without_jumps),
        cmocka_unit_test(test_speed_scale_is_two_and_a_half_rms_speeds),
    };
    int failed = cmocka_run_group_tests_name("render colour map", colours, NULL, NULL);
#ifdef RENDER_osmesa
    const struct CMUnitTest osmesa[] = {BACKEND_TESTS((void *)RENDER_osmesa)};
    failed +=
        cmocka_run_group_tests_name("render, osmesa backend", osmesa, make_scratch, remove_scratch);
#endif
#ifdef RENDER_egl
    const struct CMUnitTest egl[] = {BACKEND_TESTS((void *)RENDER_egl)};
    failed += cmocka_run_group_tests_name("render, egl backend", egl, make_scratch, remove_scratch);
#endif
    const struct CMUnitTest movie[] = {MOVIE_TESTS((void *)MOVIE_BINARY)};
    failed += cmocka_run_group_tests_name("render --movie", movie, make_scratch, remove_scratch);
#if defined(RENDER_osmesa) && defined(RENDER_egl)
    const struct CMUnitTest both[] = {
        cmocka_unit_test(test_osmesa_and_egl_draw_the_same_image),
    };
    failed +=
        cmocka_run_group_tests_name("render, backends agree", both, make_scratch, remove_scratch);
#else
    print_message("render: one backend only, the cross-backend comparison is skipped\n");
#endif
    return failed ? 1 : 0;
}
