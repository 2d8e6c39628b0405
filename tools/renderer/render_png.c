/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <png.h>
#include <zlib.h> /* Z_RLE; libpng-dev depends on zlib1g-dev */

#include "render_png.h"

/* libpng reports errors by longjmp; the message is kept for the caller. */
typedef struct png_failure {
    jmp_buf jump;
    char message[128];
} png_failure;

static void on_png_error(png_structp png, png_const_charp message)
{
    png_failure *f = png_get_error_ptr(png);
    snprintf(f->message, sizeof f->message, "%s", message);
    longjmp(f->jump, 1);
}

static void on_png_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message; /* nothing a user can act on */
}

/* Frames of one disk colour have few distinct colours (background,
 * outline, the disk colour and its antialiased blends with the background):
 * written as a palette image they are one byte a pixel instead of three, a
 * third of the data for zlib and libpng to go through. Fills index (rows
 * top first) and palette; returns the number of colours, or 0 if there are
 * more than 256 (speed-coloured frames), for a plain RGB image. */
static int palettize(const unsigned char *rgba, int width, int height, unsigned char *index,
                     png_color *palette)
{
    enum { SLOTS = 1024 }; /* power of two, four times the most colours */
    uint32_t key[SLOTS];   /* rgb + 1; 0 marks an empty slot */
    unsigned char value[SLOTS];
    memset(key, 0, sizeof key);
    int colours = 0;
    uint32_t last = 0;
    unsigned char last_index = 0;
    for (int y = 0; y < height; ++y) {
        const unsigned char *p = rgba + (size_t)(height - 1 - y) * (size_t)width * 4;
        unsigned char *out = index + (size_t)y * (size_t)width;
        for (int x = 0; x < width; ++x, p += 4) {
            const uint32_t rgb = ((uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2]) + 1;
            if (rgb != last) { /* most pixels repeat their left neighbour */
                uint32_t h = (rgb * 2654435761u) >> 22;
                while (key[h] && key[h] != rgb)
                    h = (h + 1) & (SLOTS - 1);
                if (!key[h]) {
                    if (colours == 256)
                        return 0;
                    key[h] = rgb;
                    value[h] = (unsigned char)colours;
                    palette[colours].red = p[0];
                    palette[colours].green = p[1];
                    palette[colours].blue = p[2];
                    ++colours;
                }
                last = rgb;
                last_index = value[h];
            }
            out[x] = last_index;
        }
    }
    return colours;
}

/* The body, separate so that no local of rp_write is modified between
 * setjmp and longjmp (which would make its value indeterminate). rows are
 * RGBA (colours == 0) or palette indices. */
static int encode(FILE *file, int width, int height, png_bytep *rows, const png_color *palette,
                  int colours, png_failure *f)
{
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, f, on_png_error, on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        snprintf(f->message, sizeof f->message, "out of memory");
        png_destroy_write_struct(&png, NULL);
        return -1;
    }
    if (setjmp(f->jump)) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8,
                 colours ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (colours)
        png_set_PLTE(png, info, palette, colours);
    /* Encoding is most of the renderer's time. Frames are long runs of
     * one colour, which zlib's run-length strategy finds without hashing:
     * with no row filter and a large buffer it is a quarter faster than
     * level 1 with the "up" filter, and the files are smaller. */
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_compression_level(png, 1);
    png_set_compression_strategy(png, Z_RLE);
    png_set_compression_buffer_size(png, (size_t)1 << 18);
    png_write_info(png, info);
    if (!colours)
        png_set_filler(png, 0, PNG_FILLER_AFTER); /* drop the alpha byte */
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 0;
}

int rp_write(const char *path, const unsigned char *rgba, int width, int height, mode_t mode,
             char *err, size_t errlen)
{
    size_t n = strlen(path);
    char *tmp = malloc(n + 8);
    png_bytep *rows = malloc((size_t)height * sizeof *rows);
    /* Without it the image is simply written as RGB. */
    unsigned char *index = malloc((size_t)width * (size_t)height);
    if (!tmp || !rows) {
        free(tmp);
        free(rows);
        free(index);
        snprintf(err, errlen, "%s: out of memory", path);
        return -1;
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".XXXXXX", 8);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
        free(tmp);
        free(rows);
        free(index);
        return -1;
    }
    /* mkstemp makes the file 0600; give it what a plain fopen would. */
    (void)fchmod(fd, mode);
    FILE *file = fdopen(fd, "wb");
    png_failure f;
    f.message[0] = '\0';
    int rc = -1;
    if (!file) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        close(fd);
    } else {
        png_color palette[256];
        int colours = index ? palettize(rgba, width, height, index, palette) : 0;
        for (int y = 0; y < height; ++y) /* PNG rows go top first */
            rows[y] = colours ? index + (size_t)y * (size_t)width
                              : (png_bytep)(rgba + (size_t)(height - 1 - y) * (size_t)width * 4);
        int enc = encode(file, width, height, rows, palette, colours, &f);
        int write_error = ferror(file);
        int saved = errno;
        if (fclose(file) != 0 && !write_error) {
            write_error = 1;
            saved = errno;
        }
        if (enc != 0)
            snprintf(err, errlen, "%s: %s", path, f.message);
        else if (write_error)
            snprintf(err, errlen, "%s: write failed: %s", path, strerror(saved));
        else if (rename(tmp, path) != 0)
            snprintf(err, errlen, "%s: cannot rename into place: %s", path, strerror(errno));
        else
            rc = 0;
    }
    if (rc != 0)
        unlink(tmp);
    free(index);
    free(tmp);
    free(rows);
    return rc;
}
