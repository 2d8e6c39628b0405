/* SPDX-License-Identifier: MIT */
/* Writing files so that no reader ever sees a partial one: a temporary in
 * the same directory, written, checked and renamed; a trajectory appended
 * as the run goes into a temporary renamed at the end; signals held while
 * a file is written. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* Writes len bytes to f and closes it, checking every step (fwrite into
 * stdio's buffer succeeds even on a full disk; only the flush and the
 * close tell). Returns 0, or the errno of the first failure. */
static int write_and_close(FILE *f, const char *data, size_t len)
{
    size_t put = fwrite(data, 1, len, f);
    int failed = put != len || fflush(f) != 0 || ferror(f);
    int saved = failed ? (errno ? errno : EIO) : 0;
    if (fclose(f) != 0 && !saved)
        saved = errno ? errno : EIO;
    return saved;
}

/* Writes len bytes to dir/name via a temporary file and rename(), so a
 * reader never sees a half-written file. Returns 0 or sets *why. */
static int write_file_atomic_now(const char *dir, const char *name, const char *data, size_t len,
                                 const char **why)
{
    char final_path[4200], tmp_path[4200];
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
    int saved = write_and_close(f, data, len);
    if (!saved && rename(tmp_path, final_path) != 0)
        saved = errno ? errno : EIO;
    if (saved) {
        unlink(tmp_path);
        *why = strerror(saved);
        return -1;
    }
    return 0;
}

/* Ctrl-C, kill and hang-up wait while a file is written: the signal is
 * delivered once the temporary is renamed or removed, so an interrupted run
 * leaves complete frames and no temporary (only SIGKILL can still strand
 * one, as a hidden .frame_NNNN.txt.XXXXXX). */
int write_file_atomic(const char *dir, const char *name, const char *data, size_t len,
                      const char **why)
{
    sigset_t block, old;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, &old);
    int rc = write_file_atomic_now(dir, name, data, len, why);
    sigprocmask(SIG_SETMASK, &old, NULL);
    return rc;
}

/* --stats may name a device, a pipe or a symbolic link (/dev/full, a FIFO,
 * /dev/stdout): renaming a temporary over it would replace the device node
 * or the link itself, so only a regular file (or a new name) is replaced;
 * anything else is written in place, with the same error checks. */
int is_special_file(const char *path)
{
    struct stat st;
    return lstat(path, &st) == 0 && !S_ISREG(st.st_mode);
}

int write_file_in_place(const char *path, const char *data, size_t len, const char **why)
{
    FILE *f = fopen(path, "wb");
    if (!f) {
        *why = strerror(errno);
        return -1;
    }
    int saved = write_and_close(f, data, len);
    if (saved)
        *why = strerror(saved);
    return saved ? -1 : 0;
}
/* --trajectory: every frame appended as the run goes (a trajectory can be
 * far larger than --stats, which is held in memory), into a temporary file
 * in the same directory renamed over FILE at the end, or written in place
 * for a device, pipe or link (see is_special_file). Until the rename the
 * temporary is removed by every way the run can end early: an error (die
 * exits, and exit runs remove_pending), or Ctrl-C, kill or hang-up. */

static char pending_tmp[4200]; /* the temporary not yet renamed, "" if none */

static void remove_pending(void)
{
    if (pending_tmp[0])
        unlink(pending_tmp);
}

static void remove_pending_and_die(int sig)
{
    remove_pending(); /* unlink is async-signal-safe */
    signal(sig, SIG_DFL);
    raise(sig);
}

void block_signals(sigset_t *old)
{
    sigset_t block;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    sigaddset(&block, SIGHUP);
    sigprocmask(SIG_BLOCK, &block, old);
}

void trajectory_open(trajectory *t, const char *path, const char *dir, const char *base,
                     const ds_sim *sim)
{
    t->path = path;
    t->cap = ds_xyz_frame_size(sim);
    if (!(t->buf = malloc(t->cap)))
        die(EXIT_RUN, "out of memory for --trajectory");
    if (is_special_file(path)) {
        if (!(t->f = fopen(path, "wb")))
            die(EXIT_RUN, "cannot write %s: %s", path, strerror(errno));
        return;
    }
    char tmp[sizeof pending_tmp];
    snprintf(tmp, sizeof tmp, "%s/.%s.XXXXXX", dir, base);
    sigset_t old;
    block_signals(&old);
    int fd = mkstemp(tmp);
    if (fd >= 0) {
        memcpy(pending_tmp, tmp, sizeof tmp);
        atexit(remove_pending);
        const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
        for (size_t k = 0; k < 3; ++k) {
            struct sigaction sa, was;
            memset(&sa, 0, sizeof sa);
            sa.sa_handler = remove_pending_and_die;
            sigemptyset(&sa.sa_mask);
            /* A signal ignored on purpose (nohup) stays ignored. */
            if (sigaction(sigs[k], NULL, &was) == 0 && was.sa_handler != SIG_IGN)
                sigaction(sigs[k], &sa, NULL);
        }
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
    if (fd < 0)
        die(EXIT_RUN, "cannot write %s: %s", path, strerror(errno));
    fchmod(fd, 0644);
    if (!(t->f = fdopen(fd, "wb")))
        die(EXIT_RUN, "cannot write %s: %s", path, strerror(errno));
}

void trajectory_append(trajectory *t, const ds_sim *sim)
{
    size_t len = 0;
    ds_format_xyz_frame(sim, t->buf, t->cap, &len);
    /* Flushed every frame, so a full disk is reported at once. */
    if (fwrite(t->buf, 1, len, t->f) != len || fflush(t->f) != 0 || ferror(t->f))
        die(EXIT_RUN, "cannot write %s: %s", t->path, strerror(errno ? errno : EIO));
}

void trajectory_close(trajectory *t)
{
    int saved = fclose(t->f) != 0 ? (errno ? errno : EIO) : 0;
    free(t->buf);
    if (!saved && pending_tmp[0]) {
        sigset_t old;
        block_signals(&old);
        if (rename(pending_tmp, t->path) != 0)
            saved = errno ? errno : EIO;
        else
            pending_tmp[0] = '\0';
        sigprocmask(SIG_SETMASK, &old, NULL);
    }
    if (saved)
        die(EXIT_RUN, "cannot write %s: %s", t->path, strerror(saved));
}
