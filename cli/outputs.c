/* SPDX-License-Identifier: MIT */
/* The paths a run names, checked before any work (docs/cli.md, "Nothing
 * lost, nothing mixed"): no two files the same, no output over a frame
 * (judged by what the paths name, not how they are spelt: links, hard or
 * symbolic, dangling or not), every output in a directory that exists or
 * that --out will make; the --out directory made; and the frames an
 * earlier run left there. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

/* Symbolic links followed in one path before the rest is taken as
 * written: the kernel's own limit (Linux's MAXSYMLINKS), past which
 * opening the path fails anyway. */
#define LINKS_MAX 40

/* The absolute location a path names, found as the kernel finds it:
 * component by component, every symbolic link followed, and "." and ".."
 * taken on the links' targets. realpath() stops at the first name that
 * does not exist, but an output is written through a dangling link (to
 * its target) and a frame file or a directory --out makes does not exist
 * yet: past such a name the rest is added as written, so two names of one
 * future file give one string. */
static void resolve(const char *path, char *out, size_t cap)
{
    char todo[PATH_CAP], rest[PATH_CAP], done[PATH_CAP] = "", next[PATH_CAP];
    path_printf(todo, sizeof todo, "%s", path);
    if (todo[0] != '/' && !getcwd(done, sizeof done))
        die(EXIT_RUN, "cannot resolve '%s': the current directory: %s", path, strerror(errno));
    if (strcmp(done, "/") == 0)
        done[0] = '\0'; /* done holds no trailing '/': "" is the root */
    int links = 0;
    const char *p = todo;
    for (;;) {
        p += strspn(p, "/");
        if (!*p)
            break;
        const size_t len = strcspn(p, "/");
        const char *after = p + len;
        if (len == 1 && p[0] == '.') {
            p = after;
            continue;
        }
        if (len == 2 && p[0] == '.' && p[1] == '.') {
            char *slash = strrchr(done, '/');
            if (slash)
                *slash = '\0';
            p = after;
            continue;
        }
        path_printf(next, sizeof next, "%s/%.*s", done, (int)len, p);
        struct stat st;
        char target[PATH_CAP];
        ssize_t got;
        if (links < LINKS_MAX && lstat(next, &st) == 0 && S_ISLNK(st.st_mode) &&
            (got = readlink(next, target, sizeof target - 1)) > 0) {
            /* The link's target, then what followed the link. */
            target[got] = '\0';
            ++links;
            path_printf(rest, sizeof rest, "%s/%s", target, after);
            memcpy(todo, rest, strlen(rest) + 1);
            if (target[0] == '/')
                done[0] = '\0';
            p = todo;
            continue;
        }
        memcpy(done, next, strlen(next) + 1);
        p = after;
    }
    path_printf(out, cap, "%s", *done ? done : "/");
}

int frame_number(const char *base)
{
    if (strlen(base) != strlen("frame_0000.txt") || strncmp(base, "frame_", 6) != 0 ||
        strcmp(base + 10, ".txt") != 0)
        return -1;
    int k = 0;
    for (int i = 6; i < 10; ++i) {
        if (base[i] < '0' || base[i] > '9')
            return -1;
        k = 10 * k + (base[i] - '0');
    }
    return k;
}

static int is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Refuses an --out that cannot become a directory, as mkdir would, before
 * anything is made. */
static void check_out_dir(const char *path)
{
    char buf[PATH_CAP];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        die(EXIT_USAGE, "--out path is too long");
    memcpy(buf, path, len + 1);
    for (size_t k = 1; k <= len; ++k) {
        if (buf[k] != '/' && buf[k] != '\0')
            continue;
        char saved = buf[k];
        buf[k] = '\0';
        struct stat st;
        int exists = stat(buf, &st) == 0;
        buf[k] = saved;
        if (!exists)
            return; /* this part and the rest are made */
        if (S_ISDIR(st.st_mode))
            continue;
        if (k == len || strspn(path + k, "/") == len - k)
            die(EXIT_RUN, "'%s' is not a directory", path);
        size_t next = k + 1;
        while (next < len && buf[next] != '/')
            ++next;
        die(EXIT_RUN, "cannot create directory '%.*s': %s", (int)next, path, strerror(ENOTDIR));
    }
}

/* A path the run is given, and what it names: the file by device and
 * inode if one is there now (through every link: each name of a file,
 * hard link or symbolic, gives the same pair), and its resolved location,
 * which is all a file the run will make has. */
typedef struct named {
    const char *option;
    const char *path;
    int output; /* written by the run; else read (--restart, --from) */
    char canon[PATH_CAP];
    int exists;
    dev_t dev;
    ino_t ino;
    nlink_t links;
} named;

static void look_up(named *f)
{
    resolve(f->path, f->canon, sizeof f->canon);
    struct stat st;
    f->exists = stat(f->path, &st) == 0;
    if (f->exists) {
        f->dev = st.st_dev;
        f->ino = st.st_ino;
        f->links = st.st_nlink;
    }
}

static int same_file(const named *a, const named *b)
{
    return strcmp(a->canon, b->canon) == 0 ||
           (a->exists && b->exists && a->dev == b->dev && a->ino == b->ino);
}

/* /dev/null takes any number of outputs, by whatever name. */
static int is_dev_null(const named *f)
{
    struct stat st;
    return strcmp(f->canon, "/dev/null") == 0 ||
           (f->exists && stat("/dev/null", &st) == 0 && st.st_dev == f->dev && st.st_ino == f->ino);
}

/* dir/name, with no "//" when dir ends with '/'. */
static void join(char *out, size_t cap, const char *dir, const char *name)
{
    const size_t l = strlen(dir);
    path_printf(out, cap, "%s%s%s", dir, l && dir[l - 1] == '/' ? "" : "/", name);
}

/* The frame file of --out that f names, by its location or as another
 * name (a hard link) of a frame file there now; its name into frame.
 * Returns 0 if it names none. The run writes frame_kkkk.txt for any k
 * its --frames and a restart allow, so every such name counts. */
static int names_a_frame(const named *f, const char *out_dir, const char *out_canon, char *frame,
                         size_t cap)
{
    char dir[PATH_CAP];
    const char *base;
    split_path(f->canon, dir, sizeof dir, &base);
    if (strcmp(dir, out_canon) == 0 && frame_number(base) >= 0) {
        path_printf(frame, cap, "%s", base);
        return 1;
    }
    if (!f->exists || f->links < 2)
        return 0; /* one name only: its location said it all */
    DIR *d = opendir(out_dir);
    int found = 0;
    for (struct dirent *e; d && !found && (e = readdir(d));) {
        char path[PATH_CAP];
        struct stat st;
        if (frame_number(e->d_name) < 0)
            continue;
        join(path, sizeof path, out_dir, e->d_name);
        found = stat(path, &st) == 0 && st.st_dev == f->dev && st.st_ino == f->ino;
        if (found)
            path_printf(frame, cap, "%s", e->d_name);
    }
    if (d)
        closedir(d);
    return found;
}

/* f is the frames.json the run writes beside its frames. */
static int names_frames_json(const named *f, const char *out_canon)
{
    char dir[PATH_CAP];
    const char *base;
    split_path(f->canon, dir, sizeof dir, &base);
    return strcmp(dir, out_canon) == 0 && strcmp(base, "frames.json") == 0;
}

/* An output's directory exists, or --out makes it: it is --out or one of
 * the parents --out creates. */
static int dir_usable(const char *dir, const char *dir_canon, const char *out_canon)
{
    struct stat st;
    if (stat(dir, &st) == 0)
        return S_ISDIR(st.st_mode);
    const size_t l = strlen(dir_canon);
    return strcmp(dir_canon, out_canon) == 0 ||
           (strncmp(out_canon, dir_canon, l) == 0 && out_canon[l] == '/');
}

/* The directory as written, then the one a symbolic link leads to (an
 * output is written through the link). */
static void check_output_dir(const named *f, const char *out_canon)
{
    char dir[PATH_CAP], dir_canon[PATH_CAP];
    const char *base;
    split_path(f->path, dir, sizeof dir, &base);
    resolve(dir, dir_canon, sizeof dir_canon);
    if (!dir_usable(dir, dir_canon, out_canon))
        die(EXIT_RUN, "cannot write %s %s: '%s' is not a directory", f->option, f->path, dir);
    split_path(f->canon, dir, sizeof dir, &base);
    if (!dir_usable(dir, dir, out_canon))
        die(EXIT_RUN, "cannot write %s %s: it leads to %s, and '%s' is not a directory", f->option,
            f->path, f->canon, dir);
}

void check_paths(const options *o)
{
    check_out_dir(o->out_dir);
    char out_canon[PATH_CAP], frame[PATH_CAP];
    resolve(o->out_dir, out_canon, sizeof out_canon);
    named files[] = {{"--stats", o->stats_path, 1, "", 0, 0, 0, 0},
                     {"--trajectory", o->trajectory_path, 1, "", 0, 0, 0, 0},
                     {"--gsd", o->gsd_path, 1, "", 0, 0, 0, 0},
                     {"--checkpoint", o->checkpoint_path, 1, "", 0, 0, 0, 0},
                     {"--restart", o->restart_path, 0, "", 0, 0, 0, 0},
                     {"--from", o->from_path, 0, "", 0, 0, 0, 0}};
    const size_t count = sizeof files / sizeof files[0];
    for (size_t i = 0; i < count; ++i) {
        named *f = &files[i];
        if (!f->path)
            continue;
        if (f->output && is_dir(f->path))
            die(EXIT_USAGE, "%s needs a file name, got directory '%s'", f->option, f->path);
        look_up(f);
        if (strcmp(f->canon, out_canon) == 0)
            die(EXIT_USAGE, "%s %s is the --out directory: give it a file name", f->option,
                f->path);
        if (f->output && names_frames_json(f, out_canon))
            die(EXIT_USAGE,
                "%s %s would replace the run's frames.json in the --out directory '%s': choose "
                "another name",
                f->option, f->path, o->out_dir);
        if (!names_a_frame(f, o->out_dir, out_canon, frame, sizeof frame))
            continue;
        if (f->output)
            die(EXIT_USAGE,
                "%s %s would replace the frame file %s in the --out directory '%s': choose "
                "another name",
                f->option, f->path, frame, o->out_dir);
        die(EXIT_USAGE,
            "%s %s is the frame file %s in the --out directory '%s', which this run writes: "
            "copy it elsewhere first",
            f->option, f->path, frame, o->out_dir);
    }
    /* Two names of one file: the later write would replace the earlier, or
     * an output its own input. --restart and --checkpoint may be the same
     * file (the checkpoint is read first and replaced atomically), and
     * /dev/null takes anything. */
    for (size_t i = 0; i < count; ++i)
        for (size_t j = i + 1; j < count; ++j) {
            const named *a = &files[i], *b = &files[j];
            if (!a->path || !b->path || !same_file(a, b) || is_dev_null(a))
                continue;
            if (strcmp(a->option, "--checkpoint") == 0 && strcmp(b->option, "--restart") == 0)
                continue;
            if (strcmp(a->path, b->path) == 0)
                die(EXIT_USAGE, "%s and %s both name %s: give each its own file", a->option,
                    b->option, b->path);
            die(EXIT_USAGE, "%s %s and %s %s name the same file: give each its own file", a->option,
                a->path, b->option, b->path);
        }
    for (size_t i = 0; i < count; ++i)
        if (files[i].path && files[i].output)
            check_output_dir(&files[i], out_canon);
}

void make_out_dir(const char *path)
{
    char buf[PATH_CAP];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        die(EXIT_USAGE, "--out path is too long");
    memcpy(buf, path, len + 1);
    for (size_t k = 1; k <= len; ++k) {
        if (buf[k] != '/' && buf[k] != '\0')
            continue;
        char saved = buf[k];
        buf[k] = '\0';
        if (mkdir(buf, 0777) == 0)
            note_created_dir(buf);
        else if (errno != EEXIST)
            die(EXIT_RUN, "cannot create directory '%s': %s", buf, strerror(errno));
        buf[k] = saved;
    }
    if (!is_dir(path))
        die(EXIT_RUN, "'%s' is not a directory", path);
}

/* Frame files numbered after last: another run's (a run writes frames
 * 0 .. last, a restart its checkpoint's frame + 1 .. last after the
 * frames before, which are its own); last -1: every frame file. */
static long other_frames(const char *dir, long last, long *lo, long *hi, int remove)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0; /* not there yet: made by this run */
    long count = 0;
    *lo = MAX_FRAMES;
    *hi = -1;
    struct dirent *e;
    while ((e = readdir(d))) {
        int k = frame_number(e->d_name);
        if (k < 0 || k <= last)
            continue;
        char path[PATH_CAP];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat st;
        if (lstat(path, &st) != 0 || S_ISDIR(st.st_mode))
            continue;
        if (remove && unlink(path) != 0)
            die(EXIT_RUN, "cannot remove %s (--overwrite): %s", path, strerror(errno));
        ++count;
        *lo = k < *lo ? k : *lo;
        *hi = k > *hi ? k : *hi;
    }
    closedir(d);
    return count;
}

/* "out/", or "the current directory". */
static void dir_words(const char *dir, char *where, size_t cap)
{
    if (strcmp(dir, ".") == 0)
        snprintf(where, cap, "the current directory");
    else
        path_printf(where, cap, "%s%s", dir, dir[strlen(dir) - 1] == '/' ? "" : "/");
}

int check_other_runs(const options *o, long first, long last, const char *json)
{
    char where[PATH_CAP], why[256], reason[300] = "";
    const char *dir = o->out_dir;
    dir_words(dir, where, sizeof where);
    const int other = frames_json_compare(dir, json, why, sizeof why);
    if (other && first > 0)
        die(EXIT_RUN, "cannot restart from %s into %s: its frames.json %s: give another --out",
            o->restart_path, where, why);
    long lo = 0, hi = 0;
    /* Another run's frames.json: every frame beside it is that run's. */
    long count = other_frames(dir, other ? -1 : last, &lo, &hi, 0);
    if (o->overwrite)
        return other;
    if (other == 2 && count == 0)
        die(EXIT_RUN, "%sframes.json %s; move it or pass --overwrite",
            strcmp(dir, ".") == 0 ? "" : where, why);
    if (count == 0)
        return other;
    if (other)
        snprintf(reason, sizeof reason, " (its frames.json %s)", why);
    if (count == 1)
        die(EXIT_RUN, "%s holds frame_%04ld.txt from another run%s; remove it or pass --overwrite",
            where, lo, reason);
    if (count == 2)
        die(EXIT_RUN,
            "%s holds frame_%04ld.txt and frame_%04ld.txt from another run%s; remove them or pass "
            "--overwrite",
            where, lo, hi, reason);
    if (count == hi - lo + 1)
        die(EXIT_RUN,
            "%s holds frame_%04ld.txt ... frame_%04ld.txt from another run%s; remove them or pass "
            "--overwrite",
            where, lo, hi, reason);
    die(EXIT_RUN,
        "%s holds %ld frame files from another run, frame_%04ld.txt ... frame_%04ld.txt%s; remove "
        "them or pass --overwrite",
        where, count, lo, hi, reason);
}

void remove_other_runs(const options *o, long last, int other_json)
{
    long lo = 0, hi = 0;
    if (!o->overwrite)
        return;
    (void)other_frames(o->out_dir, other_json ? -1 : last, &lo, &hi, 1);
    char path[PATH_CAP];
    join(path, sizeof path, o->out_dir, "frames.json");
    if (other_json && unlink(path) != 0 && errno != ENOENT)
        die(EXIT_RUN, "cannot remove %s (--overwrite): %s", path, strerror(errno));
}
