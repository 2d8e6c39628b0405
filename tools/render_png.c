#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <setjmp.h>
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

/* The body, separate so that no local of rp_write is modified between
 * setjmp and longjmp (which would make its value indeterminate). */
static int encode(FILE *file, const unsigned char *rgba, int width, int height, png_bytep *rows,
                  png_failure *f)
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
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    /* Encoding is most of the renderer's time. Frames are long runs of
     * one colour, which zlib's run-length strategy finds without hashing:
     * with no row filter and a large buffer it is a quarter faster than
     * level 1 with the "up" filter, and the files are smaller (65 kB for
     * 400 disks at 800 px). */
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_compression_level(png, 1);
    png_set_compression_strategy(png, Z_RLE);
    png_set_compression_buffer_size(png, (size_t)1 << 18);
    png_write_info(png, info);
    png_set_filler(png, 0, PNG_FILLER_AFTER); /* drop the alpha byte */
    for (int y = 0; y < height; ++y)          /* PNG rows go top first */
        rows[y] = (png_bytep)(rgba + (size_t)(height - 1 - y) * (size_t)width * 4);
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
    if (!tmp || !rows) {
        free(tmp);
        free(rows);
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
        int enc = encode(file, rgba, width, height, rows, &f);
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
    free(tmp);
    free(rows);
    return rc;
}
