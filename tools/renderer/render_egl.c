/* SPDX-License-Identifier: MIT */
/* Surfaceless EGL backend: Mesa's EGL_PLATFORM_SURFACELESS_MESA reaches the
 * same llvmpipe rasterizer as OSMesa (or a GPU driver, if one is there)
 * without a window system. The context has no surface at all; it draws
 * into a framebuffer object and glReadPixels copies the image back. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdio.h>
#include <stdlib.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include "render_backend.h"

struct rb_context {
    EGLContext egl;
    GLuint fbo, color;
    int width, height;
    unsigned char *rgba;
};

/* One display for the process: eglTerminate would pull it from under every
 * thread's context, so it is opened before the workers start and closed
 * after they have all finished. */
static EGLDisplay display = EGL_NO_DISPLAY;
static EGLConfig config;

const char *rb_name(void) { return "egl"; }

int rb_open(char *err, size_t errlen)
{
    display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    EGLint major, minor;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
        snprintf(err, errlen, "cannot open a surfaceless EGL display (is libegl-mesa0 installed?)");
        display = EGL_NO_DISPLAY;
        return -1;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        snprintf(err, errlen, "EGL display %d.%d has no desktop OpenGL", major, minor);
        rb_close();
        return -1;
    }
    /* EGL_SURFACE_TYPE 0: the default (EGL_WINDOW_BIT) would exclude every
     * config of a display that has no windows. */
    const EGLint want[] = {EGL_SURFACE_TYPE,
                           0,
                           EGL_RENDERABLE_TYPE,
                           EGL_OPENGL_BIT,
                           EGL_RED_SIZE,
                           8,
                           EGL_GREEN_SIZE,
                           8,
                           EGL_BLUE_SIZE,
                           8,
                           EGL_NONE};
    EGLint found = 0;
    if (!eglChooseConfig(display, want, &config, 1, &found) || found < 1) {
        snprintf(err, errlen, "no 8-bit RGB OpenGL config on the EGL display");
        rb_close();
        return -1;
    }
    return 0;
}

/* The display is released but not terminated: the process ends right
 * after, and Mesa 22's eglTerminate unloads the driver while a few hundred
 * bytes it allocated are still unfreed, which LeakSanitizer then reports
 * against an unknown module in every sanitizer run. */
void rb_close(void)
{
    eglReleaseThread();
    display = EGL_NO_DISPLAY;
}

rb_context *rb_create(int width, int height, char *err, size_t errlen)
{
    rb_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    ctx->width = width;
    ctx->height = height;
    ctx->rgba = malloc((size_t)width * (size_t)height * 4);
    /* The bound API is per thread, and defaults to OpenGL ES: bind desktop
     * GL again in every worker thread, not only in rb_open. */
    eglBindAPI(EGL_OPENGL_API);
    ctx->egl = eglCreateContext(display, config, EGL_NO_CONTEXT, NULL);
    if (!ctx->rgba || ctx->egl == EGL_NO_CONTEXT) {
        snprintf(err, errlen, ctx->rgba ? "eglCreateContext failed (0x%x)" : "out of memory",
                 (unsigned)eglGetError());
        rb_destroy(ctx);
        return NULL;
    }
    /* EGL_KHR_surfaceless_context: current with no draw or read surface. */
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx->egl)) {
        snprintf(err, errlen, "eglMakeCurrent without a surface failed (0x%x)",
                 (unsigned)eglGetError());
        rb_destroy(ctx);
        return NULL;
    }
    glGenFramebuffers(1, &ctx->fbo);
    glGenRenderbuffers(1, &ctx->color);
    glBindRenderbuffer(GL_RENDERBUFFER, ctx->color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, ctx->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ctx->color);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        snprintf(err, errlen, "framebuffer object of %dx%d is incomplete", width, height);
        rb_destroy(ctx);
        return NULL;
    }
    return ctx;
}

const unsigned char *rb_pixels(rb_context *ctx, char *err, size_t errlen)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, ctx->width, ctx->height, GL_RGBA, GL_UNSIGNED_BYTE, ctx->rgba);
    GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        snprintf(err, errlen, "glReadPixels failed (GL error 0x%x)", (unsigned)e);
        return NULL;
    }
    return ctx->rgba;
}

void rb_destroy(rb_context *ctx)
{
    if (!ctx)
        return;
    if (ctx->egl != EGL_NO_CONTEXT && ctx->egl) {
        if (eglGetCurrentContext() == ctx->egl) {
            glDeleteFramebuffers(1, &ctx->fbo);
            glDeleteRenderbuffers(1, &ctx->color);
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        }
        eglDestroyContext(display, ctx->egl);
    }
    free(ctx->rgba);
    free(ctx);
}
