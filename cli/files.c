/* SPDX-License-Identifier: MIT */
/* Writing files so that no reader ever sees a partial one, and what the
 * signals do meanwhile.
 *
 * A frame or a checkpoint is written whole to a temporary in its own
 * directory, checked and renamed over its name (a checkpoint also reaches
 * the disk, fsync, before and after the rename). --stats, --trajectory
 * and --gsd grow frame by frame in a temporary, "pending" until it is
 * renamed into place at the end. A device, pipe or symbolic link is
 * written in place.
 *
 * Signals (SIGINT, SIGTERM, SIGHUP) are held while a file is written, so
 * they land between files. Before the frames begin one ends the command
 * at once: the pending temporaries and the directories the run made are
 * removed. While frames are written the first only raises a flag, which
 * the run reads between frames (it finishes the frame, puts everything in
 * place, then ends by the signal); a second ends it at once with the
 * pending files renamed into place as they are, whole frames only, since
 * every append is held too. Only SIGKILL can strand a temporary. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

#define PENDING_MAX 4 /* --stats, --trajectory and --gsd, with room */
#define CREATED_MAX 32

/* Written only with the signals held, read by the handler. */
static char pending_tmp[PENDING_MAX][PATH_CAP], pending_final[PENDING_MAX][PATH_CAP];
static volatile sig_atomic_t pending_used[PENDING_MAX];
static char created[CREATED_MAX][PATH_CAP];
static volatile sig_atomic_t created_count, created_kept;
static volatile sig_atomic_t frames_running, stop_requested;
static const int caught_signals[] = {SIGINT, SIGTERM, SIGHUP};
static int caught[3];

void hold_signals(sigset_t *old)
{
    sigset_t block;
    sigemptyset(&block);
    for (size_t k = 0; k < 3; ++k)
        sigaddset(&block, caught_signals[k]);
    sigprocmask(SIG_BLOCK, &block, old);
}

void release_signals(const sigset_t *old) { sigprocmask(SIG_SETMASK, old, NULL); }

/* Only async-signal-safe calls (unlink, rename, rmdir) from here on. */
static void discard_pending_now(void)
{
    for (size_t k = 0; k < PENDING_MAX; ++k)
        if (pending_used[k])
            unlink(pending_tmp[k]);
    if (!created_kept)
        for (sig_atomic_t k = created_count; k-- > 0;)
            rmdir(created[k]);
}

static void keep_pending_now(void)
{
    for (size_t k = 0; k < PENDING_MAX; ++k)
        if (pending_used[k])
            rename(pending_tmp[k], pending_final[k]);
}

static void on_signal(int sig)
{
    if (frames_running && !stop_requested) {
        stop_requested = sig;
        return;
    }
    if (frames_running)
        keep_pending_now();
    else
        discard_pending_now();
    signal(sig, SIG_DFL);
    raise(sig); /* delivered when the handler returns */
}

/* exit() after a failure: nothing partial stays. After success nothing is
 * pending and the directories hold frames. */
static void discard_pending_at_exit(void) { discard_pending_now(); }

void catch_signals(void)
{
    atexit(discard_pending_at_exit);
    for (size_t k = 0; k < 3; ++k) {
        struct sigaction sa, was;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        /* A signal ignored on purpose (nohup) stays ignored. */
        if (sigaction(caught_signals[k], NULL, &was) == 0 && was.sa_handler != SIG_IGN)
            caught[k] = sigaction(caught_signals[k], &sa, NULL) == 0;
    }
}

void frames_begin(void) { frames_running = 1; }

int stop_signal(void) { return (int)stop_requested; }

void end_by_signal(int sig)
{
    fflush(NULL);
    for (size_t k = 0; k < 3; ++k)
        if (caught[k])
            signal(caught_signals[k], SIG_DFL);
    raise(sig);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, sig);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
    _exit(128 + sig); /* not reached: the signal's default action ends the process */
}

void note_created_dir(const char *path)
{
    if (created_count == CREATED_MAX)
        return; /* left in place if the run fails: rare and harmless */
    sigset_t old;
    hold_signals(&old);
    snprintf(created[created_count], PATH_CAP, "%s", path);
    ++created_count;
    release_signals(&old);
}

void keep_created_dirs(void) { created_kept = 1; }

void path_printf(char *out, size_t cap, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(out, cap, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= cap)
        die(EXIT_USAGE, "a path is too long: '%.60s...'", out);
}

void split_path(const char *path, char *dir, size_t cap, const char **base)
{
    const char *slash = strrchr(path, '/');
    *base = slash ? slash + 1 : path;
    if (!slash)
        snprintf(dir, cap, ".");
    else if (slash == path)
        snprintf(dir, cap, "/");
    else
        snprintf(dir, cap, "%.*s", (int)(slash - path), path);
}

/* Writes len bytes to f and closes it, checking every step (fwrite into
 * stdio's buffer succeeds even on a full disk; only the flush and the
 * close tell); durable, the bytes reach the disk first. Returns 0, or the
 * errno of the first failure. */
static int write_and_close(FILE *f, const void *data, size_t len, int durable)
{
    size_t put = fwrite(data, 1, len, f);
    int failed = put != len || fflush(f) != 0 || ferror(f) || (durable && fsync(fileno(f)) != 0);
    int saved = failed ? (errno ? errno : EIO) : 0;
    if (fclose(f) != 0 && !saved)
        saved = errno ? errno : EIO;
    return saved;
}

/* A directory's entries reach the disk: the rename of a checkpoint
 * survives a crash. File systems that cannot sync a directory say EINVAL. */
static int sync_dir(const char *dir)
{
    int fd = open(dir, O_RDONLY);
    if (fd < 0)
        return errno;
    int saved = fsync(fd) != 0 && errno != EINVAL ? errno : 0;
    close(fd);
    return saved;
}

static int write_file_atomic_now(const char *dir, const char *name, const void *data, size_t len,
                                 int durable, const char **why)
{
    char final_path[PATH_CAP], tmp_path[PATH_CAP];
    snprintf(final_path, sizeof final_path, "%s/%s", dir, name);
    snprintf(tmp_path, sizeof tmp_path, "%s/.%s.XXXXXX", dir, name);
    int fd = mkstemp(tmp_path);
    if (fd < 0) {
        *why = strerror(errno);
        return -1;
    }
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        *why = strerror(errno);
        close(fd);
        unlink(tmp_path);
        return -1;
    }
    fchmod(fd, 0644);
    int saved = write_and_close(f, data, len, durable);
    if (!saved && rename(tmp_path, final_path) != 0)
        saved = errno ? errno : EIO;
    if (saved) {
        unlink(tmp_path);
        *why = strerror(saved);
        return -1;
    }
    if (durable && (saved = sync_dir(dir)) != 0) {
        *why = strerror(saved);
        return -1;
    }
    return 0;
}

int write_file_atomic(const char *dir, const char *name, const void *data, size_t len, int durable,
                      const char **why)
{
    sigset_t old;
    hold_signals(&old);
    int rc = write_file_atomic_now(dir, name, data, len, durable, why);
    release_signals(&old);
    return rc;
}

int probe_dir(const char *dir, const char *name)
{
    char tmp_path[PATH_CAP];
    snprintf(tmp_path, sizeof tmp_path, "%s/.%s.XXXXXX", dir, name);
    sigset_t old;
    hold_signals(&old);
    int fd = mkstemp(tmp_path);
    int saved = fd < 0 ? errno : 0;
    if (fd >= 0) {
        close(fd);
        unlink(tmp_path);
    }
    release_signals(&old);
    return saved;
}

/* A device, a pipe or a symbolic link (/dev/full, a FIFO, /dev/stdout):
 * renaming a temporary over it would replace the device node or the link
 * itself, so only a regular file (or a new name) is replaced; anything
 * else is written in place, with the same error checks. */
int is_special_file(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && !S_ISREG(st.st_mode);
}

int write_file_in_place(const char *path, const void *data, size_t len, const char **why)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        *why = strerror(errno);
        return -1;
    }
    int saved = write_and_close(f, data, len, 0);
    if (saved)
        *why = strerror(saved);
    return saved ? -1 : 0;
}

void output_open(output *out, const char *option, const char *path)
{
    out->option = option;
    out->path = path;
    out->slot = -1;
    if (is_special_file(path)) {
        if (!(out->f = fopen(path, "wb")))
            die(EXIT_RUN, "cannot write %s %s: %s", option, path, strerror(errno));
        return;
    }
    char dir[PATH_CAP];
    const char *base;
    split_path(path, dir, sizeof dir, &base);
    int slot = 0;
    while (slot < PENDING_MAX && pending_used[slot])
        ++slot;
    if (slot == PENDING_MAX)
        die(EXIT_RUN, "cannot write %s %s: too many files at once", option, path);
    char tmp[PATH_CAP];
    path_printf(tmp, sizeof tmp, "%s/.%s.XXXXXX", dir, base);
    sigset_t old;
    hold_signals(&old);
    int fd = mkstemp(tmp);
    if (fd >= 0) {
        memcpy(pending_tmp[slot], tmp, sizeof tmp);
        snprintf(pending_final[slot], PATH_CAP, "%s", path);
        pending_used[slot] = 1;
    }
    release_signals(&old);
    if (fd < 0)
        die(EXIT_RUN, "cannot write %s %s: %s", option, path, strerror(errno));
    out->slot = slot;
    fchmod(fd, 0644);
    /* Read back too: a GSD writer reads the file a restart goes on with. */
    if (!(out->f = fdopen(fd, "w+b")))
        die(EXIT_RUN, "cannot write %s %s: %s", option, path, strerror(errno));
}

void output_write(output *out, const void *data, size_t len)
{
    /* Flushed every frame: a full disk is reported at once, and a signal
     * finds whole frames in the file. */
    errno = 0;
    if (fwrite(data, 1, len, out->f) != len || fflush(out->f) != 0 || ferror(out->f))
        die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path,
            strerror(errno ? errno : EIO));
}

void output_publish(output *out)
{
    if (out->slot < 0)
        return;
    errno = 0;
    int failed = fflush(out->f) != 0 || ferror(out->f);
    sigset_t old;
    hold_signals(&old);
    if (!failed && rename(pending_tmp[out->slot], out->path) == 0) {
        pending_used[out->slot] = 0;
        out->slot = -1; /* written in place from now on */
    } else {
        failed = 1;
    }
    release_signals(&old);
    if (failed)
        die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path,
            strerror(errno ? errno : EIO));
}

void output_close(output *out)
{
    errno = 0;
    int saved = fclose(out->f) != 0 ? (errno ? errno : EIO) : 0;
    out->f = NULL;
    if (!saved && out->slot >= 0) {
        sigset_t old;
        hold_signals(&old);
        if (rename(pending_tmp[out->slot], out->path) != 0)
            saved = errno ? errno : EIO;
        else
            pending_used[out->slot] = 0;
        release_signals(&old);
    }
    if (saved)
        die(EXIT_RUN, "cannot write %s %s: %s", out->option, out->path, strerror(saved));
}
