/* SPDX-License-Identifier: MIT */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "render_movie.h"

extern char **environ;

struct rm_movie {
    pid_t pid;
    int pipe_fd;        /* ffmpeg's standard input */
    int width, height;  /* of the images */
    int even_w, even_h; /* of the movie */
    mode_t mode;
    char path[4096];
};

/* The temporary a signal must remove: one movie per process. */
static char pending[4096 + 8];

static void remove_pending_and_die(int sig)
{
    if (pending[0])
        unlink(pending); /* async-signal-safe, as are signal and raise */
    signal(sig, SIG_DFL);
    raise(sig);
}

static void on_signals(void (*handler)(int))
{
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
    for (size_t k = 0; k < 3; ++k) {
        struct sigaction sa, was;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = handler;
        sigemptyset(&sa.sa_mask);
        /* A signal ignored on purpose (nohup) stays ignored. */
        if (sigaction(sigs[k], NULL, &was) == 0 && was.sa_handler != SIG_IGN)
            sigaction(sigs[k], &sa, NULL);
    }
}

int rm_format_of(const char *path)
{
    const size_t n = strlen(path);
    if (n > 4 && strcasecmp(path + n - 4, ".mp4") == 0)
        return RM_MP4;
    if (n > 4 && strcasecmp(path + n - 4, ".gif") == 0)
        return RM_GIF;
    return -1;
}

int rm_find_ffmpeg(char *found, size_t cap)
{
    const char *path = getenv("PATH");
    for (const char *p = path ? path : ""; *p;) {
        size_t len = strcspn(p, ":");
        /* An empty entry is the current directory, as for the shell. */
        int n = len ? snprintf(found, cap, "%.*s/ffmpeg", (int)len, p)
                    : snprintf(found, cap, "./ffmpeg");
        struct stat st;
        if (n > 0 && (size_t)n < cap && stat(found, &st) == 0 && S_ISREG(st.st_mode) &&
            access(found, X_OK) == 0)
            return 0;
        p += len + (p[len] == ':');
    }
    return -1;
}

rm_movie *rm_open(const char *path, rm_format format, int width, int height, int fps, mode_t mode,
                  char *err, size_t errlen)
{
    char ffmpeg[4096];
    if (rm_find_ffmpeg(ffmpeg, sizeof ffmpeg) != 0) {
        snprintf(err, errlen,
                 "ffmpeg is not on PATH: --movie needs it (Debian: apt-get install "
                 "ffmpeg)");
        return NULL;
    }
    rm_movie *m = calloc(1, sizeof *m);
    if (!m || strlen(path) >= sizeof m->path) {
        snprintf(err, errlen, "%s: %s", path, m ? "path too long" : "out of memory");
        free(m);
        return NULL;
    }
    snprintf(m->path, sizeof m->path, "%s", path);
    m->pipe_fd = -1;
    m->width = width;
    m->height = height;
    /* yuv420p's 2 x 2 blocks; a GIF takes any size. */
    m->even_w = width + (format == RM_MP4 && (width & 1));
    m->even_h = height + (format == RM_MP4 && (height & 1));
    m->mode = mode;

    /* The temporary is made here, so its name is ours alone; ffmpeg
     * overwrites it (-y). Signals that end the run remove it. */
    char tmp[sizeof pending];
    snprintf(tmp, sizeof tmp, "%s.XXXXXX", path);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
        free(m);
        return NULL;
    }
    close(fd);
    memcpy(pending, tmp, sizeof tmp);
    on_signals(remove_pending_and_die);

    /* A write to a pipe ffmpeg has closed must fail with EPIPE, not kill us. */
    signal(SIGPIPE, SIG_IGN);
    int fds[2];
    if (pipe(fds) != 0) {
        snprintf(err, errlen, "%s: pipe: %s", path, strerror(errno));
        rm_abort(m);
        return NULL;
    }
    /* Neither end may stay open in ffmpeg beyond its standard input, or it
     * would never see the end of the input. */
    fcntl(fds[0], F_SETFD, FD_CLOEXEC);
    fcntl(fds[1], F_SETFD, FD_CLOEXEC);
    char size[32], rate[16];
    snprintf(size, sizeof size, "%dx%d", m->even_w, m->even_h);
    snprintf(rate, sizeof rate, "%d", fps);
    /* x264's default quality (crf 23) at preset veryfast: on the 500 frames
     * of `disks 400 5` at 600 px, the default preset (medium) took 1.9x as
     * long for a file 14% smaller, and crf 28 left small disks grey where
     * yuv420p halves the colour resolution. */
    char *mp4[] = {"-c:v",      "libx264",    "-preset", "veryfast", "-pix_fmt", "yuv420p",
                   "-movflags", "+faststart", "-f",      "mp4",      tmp,        NULL};
    /* A GIF has 256 colours a frame: each frame gets its own palette
     * (stats_mode=single, new=1), made and used as the frames stream by;
     * one palette for the whole movie would make ffmpeg hold every frame
     * until the last. No dithering: a frame's few colours (the disks', the
     * rims' blends) are in its palette, and on 100 frames of `disks 400 5`
     * at 600 px dithering took 1.4 times the CPU time for the same size. */
    char *gif[] = {
        "-vf", "split[a][b];[a]palettegen=stats_mode=single[p];[b][p]paletteuse=new=1:dither=none",
        "-f",  "gif",
        tmp,   NULL};
    char *argv[32] = {ffmpeg, "-hide_banner", "-loglevel", "error", "-y",
                      "-f",   "rawvideo",     "-pix_fmt",  "rgb24", "-s",
                      size,   "-framerate",   rate,        "-i",    "pipe:0"};
    char **tail = format == RM_GIF ? gif : mp4;
    size_t k = 0;
    do /* the tail, its NULL included */
        argv[15 + k] = tail[k];
    while (tail[k++]);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    int rc = posix_spawn(&m->pid, ffmpeg, &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[0]);
    m->pipe_fd = fds[1];
    if (rc != 0) {
        snprintf(err, errlen, "%s: cannot run %s: %s", path, ffmpeg, strerror(rc));
        m->pid = 0;
        rm_abort(m);
        return NULL;
    }
    return m;
}

size_t rm_frame_bytes(const rm_movie *m) { return (size_t)m->even_w * (size_t)m->even_h * 3; }

void rm_convert(const rm_movie *m, const unsigned char *rgba, unsigned char *rgb)
{
    const size_t w = (size_t)m->width, row = (size_t)m->even_w * 3;
    for (int y = 0; y < m->even_h; ++y) {
        /* Movie rows go top first; the image's top row is its last. The
         * padding row (odd heights) repeats the bottom row. */
        int source = y < m->height ? m->height - 1 - y : 0;
        const unsigned char *in = rgba + (size_t)source * w * 4;
        unsigned char *out = rgb + (size_t)y * row;
        for (size_t x = 0; x < w; ++x) {
            out[3 * x] = in[4 * x];
            out[3 * x + 1] = in[4 * x + 1];
            out[3 * x + 2] = in[4 * x + 2];
        }
        if (m->even_w != m->width) /* the padding column repeats the last */
            memcpy(out + 3 * w, out + 3 * (w - 1), 3);
    }
}

int rm_write(rm_movie *m, const unsigned char *rgb, char *err, size_t errlen)
{
    size_t left = rm_frame_bytes(m);
    while (left > 0) {
        ssize_t n = write(m->pipe_fd, rgb, left);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            snprintf(err, errlen, "%s: ffmpeg stopped reading frames: %s", m->path,
                     strerror(n < 0 ? errno : EIO));
            return -1;
        }
        rgb += n;
        left -= (size_t)n;
    }
    return 0;
}

/* Closes ffmpeg's input and waits for it; its exit status, or -1. */
static int wait_ffmpeg(rm_movie *m)
{
    if (m->pipe_fd >= 0)
        close(m->pipe_fd);
    m->pipe_fd = -1;
    int ws = 0;
    if (m->pid <= 0)
        return -1;
    while (waitpid(m->pid, &ws, 0) < 0)
        if (errno != EINTR)
            return -1;
    m->pid = 0;
    return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
}

int rm_finish(rm_movie *m, char *err, size_t errlen)
{
    int status = wait_ffmpeg(m), rc = -1;
    if (status != 0)
        snprintf(err, errlen, "%s: ffmpeg failed (exit status %d)", m->path, status);
    else if (chmod(pending, m->mode) != 0 || rename(pending, m->path) != 0)
        snprintf(err, errlen, "%s: cannot rename into place: %s", m->path, strerror(errno));
    else
        rc = 0;
    if (rc != 0)
        unlink(pending);
    pending[0] = '\0';
    free(m);
    return rc;
}

void rm_abort(rm_movie *m)
{
    if (!m)
        return;
    if (m->pid > 0)
        kill(m->pid, SIGKILL);
    wait_ffmpeg(m);
    unlink(pending);
    pending[0] = '\0';
    free(m);
}
