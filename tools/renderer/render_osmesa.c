/* SPDX-License-Identifier: MIT */
/* OSMesa backend: Mesa renders straight into a buffer we own, so reading
 * the pixels back is only a glFinish. OSMesa was removed from Mesa in 25.1;
 * render_egl.c is the backend for systems that no longer ship it. */
#include <stdio.h>
#include <stdlib.h>

#include <GL/osmesa.h>

#include "render_backend.h"

struct rb_context {
    OSMesaContext osmesa;
    unsigned char *rgba;
};

const char *rb_name(void) { return "osmesa"; }

int rb_open(char *err, size_t errlen)
{
    (void)err;
    (void)errlen;
    return 0;
}

void rb_close(void) {}

rb_context *rb_create(int width, int height, char *err, size_t errlen)
{
    rb_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    ctx->rgba = malloc((size_t)width * (size_t)height * 4);
    /* No depth, stencil or accumulation buffer: disks are drawn in order
     * with blending, nothing needs depth testing. */
    ctx->osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    if (!ctx->rgba || !ctx->osmesa) {
        snprintf(err, errlen, ctx->rgba ? "OSMesaCreateContextExt failed" : "out of memory");
        rb_destroy(ctx);
        return NULL;
    }
    if (!OSMesaMakeCurrent(ctx->osmesa, ctx->rgba, GL_UNSIGNED_BYTE, width, height)) {
        snprintf(err, errlen, "OSMesaMakeCurrent failed for a %dx%d image", width, height);
        rb_destroy(ctx);
        return NULL;
    }
    return ctx;
}

const unsigned char *rb_pixels(rb_context *ctx, char *err, size_t errlen)
{
    (void)err;
    (void)errlen;
    glFinish();
    return ctx->rgba;
}

void rb_destroy(rb_context *ctx)
{
    if (!ctx)
        return;
    if (ctx->osmesa)
        OSMesaDestroyContext(ctx->osmesa);
    free(ctx->rgba);
    free(ctx);
}

/* OSMesa keeps every framebuffer it made in a list of its own that nothing
 * frees (Mesa 22.3), so a sanitizer build would report them as leaks at
 * exit: they are Mesa's, ours are still checked. */
#if defined(__SANITIZE_ADDRESS__)
#define RB_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RB_LSAN 1
#endif
#endif
#ifdef RB_LSAN
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libOSMesa.so\n"; }
#endif
