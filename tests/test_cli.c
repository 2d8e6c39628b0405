/* SPDX-License-Identifier: MIT */
/* The commands under bad input: each case of tests/cli_cases.txt runs the
 * real binary in a fresh directory and checks the promise of docs/cli.md:
 * one line on stderr naming the bad value, the documented exit status, no
 * crash or hang, and no temporary or partial file left behind.
 *
 *   test_cli            runs every case as a cmocka test
 *   test_cli --table    runs every case and prints the table of docs/cli.md
 *
 * Paths: DS_DISKS / DS_RENDER / DS_CLI_CASES in the environment override
 * the paths the Makefile compiled in (relative to the starting directory). */
/* realpath() is X/Open and setgroups() BSD, not plain POSIX. */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include "test_util.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <limits.h>
#include <signal.h>
#include <grp.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef DS_TEST_DISKS
#define DS_TEST_DISKS "disks"
#endif
#ifndef DS_TEST_RENDER
#define DS_TEST_RENDER "tools/render"
#endif
#ifndef DS_TEST_CLI_DOC
#define DS_TEST_CLI_DOC "docs/cli.md"
#endif
#ifndef DS_TEST_CASES
#define DS_TEST_CASES "tests/cli_cases.txt"
#endif

/* A bad case must fail fast: a run taking this long is a hang. Generous
 * because sanitizers and valgrind slow everything down. */
#define CASE_TIMEOUT_SECONDS 60
#define MAX_ARGS 32
#define MAX_CASES 1024
#define MAX_ENTRIES 512 /* files a case may leave: more is a failure */

typedef struct cli_case {
    char name[128];
    int exit_code;
    char expect[128];
    char setup[512];
    char command[512];
    int line;
} cli_case;

typedef struct outcome {
    int ran; /* 0: skipped, see skip_reason */
    char skip_reason[128];
    int status;        /* exit status, or 128 + signal */
    char err[4096];    /* everything written to stderr */
    char problem[512]; /* first broken promise, "" if none */
    int frames;        /* complete frames left behind */
} outcome;

static void row_start(const cli_case *c, char *out, size_t cap);

static char disks_path[PATH_MAX], render_path[PATH_MAX];
static cli_case cases[MAX_CASES];
static size_t case_count;

/* ------------------------------------------------------------------ */
/* Case file                                                           */
/* ------------------------------------------------------------------ */

static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        ++s;
    size_t l = strlen(s);
    while (l && (s[l - 1] == ' ' || s[l - 1] == '\t' || s[l - 1] == '\n' || s[l - 1] == '\r'))
        s[--l] = '\0';
    return s;
}

static int load_cases(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "test_cli: cannot open %s: %s\n", path, strerror(errno));
        return -1;
    }
    char buf[2048];
    int line = 0;
    while (fgets(buf, sizeof buf, f)) {
        ++line;
        char *s = trim(buf);
        if (!*s || *s == '#')
            continue;
        char *field[5];
        int nf = 0;
        for (char *p = s; nf < 5; ++nf) {
            field[nf] = p;
            char *sep = strstr(p, " | ");
            if (!sep) {
                ++nf;
                break;
            }
            *sep = '\0';
            p = sep + 3;
        }
        if (nf != 5 || case_count == MAX_CASES) {
            fprintf(stderr, "test_cli: %s:%d: expected 5 fields separated by ' | '\n", path, line);
            fclose(f);
            return -1;
        }
        cli_case *c = &cases[case_count++];
        snprintf(c->name, sizeof c->name, "%s", trim(field[0]));
        c->exit_code = atoi(field[1]);
        snprintf(c->expect, sizeof c->expect, "%s", trim(field[2]));
        snprintf(c->setup, sizeof c->setup, "%s", trim(field[3]));
        snprintf(c->command, sizeof c->command, "%s", trim(field[4]));
        c->line = line;
    }
    fclose(f);
    return 0;
}

/* ------------------------------------------------------------------ */
/* Case directory                                                      */
/* ------------------------------------------------------------------ */

/* Decodes \n, \t, \\ and \xHH; returns the byte count. */
static size_t unescape(const char *s, char *out, size_t cap)
{
    size_t n = 0;
    while (*s && n < cap) {
        if (s[0] == '\\' && s[1] == 'n') {
            out[n++] = '\n';
            s += 2;
        } else if (s[0] == '\\' && s[1] == 't') {
            out[n++] = '\t';
            s += 2;
        } else if (s[0] == '\\' && s[1] == '\\') {
            out[n++] = '\\';
            s += 2;
        } else if (s[0] == '\\' && s[1] == 'x' && s[2] && s[3]) {
            char hex[3] = {s[2], s[3], '\0'};
            out[n++] = (char)strtol(hex, NULL, 16);
            s += 4;
        } else {
            out[n++] = *s++;
        }
    }
    return n;
}

static int write_bytes(const char *path, const char *data, size_t len)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    int bad = fwrite(data, 1, len, f) != len;
    return fclose(f) != 0 || bad ? -1 : 0;
}

/* Root ignores permissions, so a permission case run as root drops to this
 * unprivileged user (nobody) in the child instead. */
#define UNPRIVILEGED_ID 65534
#define CANNOT_REACH_AS_NOBODY 123

static int run_disks_in(const char *dir, const char *args, char *err, size_t cap);

/* XORs the byte at offset (from the end if negative) with 0xff, or cuts
 * the file to offset bytes. */
static int damage(const char *path, long offset, int cut)
{
    FILE *f = fopen(path, "r+b");
    if (!f || fseek(f, 0, SEEK_END) != 0)
        return f ? (fclose(f), -1) : -1;
    long size = ftell(f), at = offset < 0 ? size + offset : offset;
    int ok = at >= 0 && at < size;
    if (ok && cut) {
        fclose(f);
        return truncate(path, (off_t)at);
    }
    int c = ok && fseek(f, at, SEEK_SET) == 0 ? fgetc(f) : EOF;
    ok = c != EOF && fseek(f, at, SEEK_SET) == 0 && fputc(c ^ 0xff, f) != EOF;
    return fclose(f) != 0 || !ok ? -1 : 0;
}

/* Applies the setup steps inside dir; sets *fsize, *drop, out_path and
 * path_env for the child. Returns 0, or -1 on a broken setup. */
static int apply_setup(const cli_case *c, const char *dir, long *fsize, int *drop, char *out_path,
                       size_t out_cap, char *path_env, size_t path_cap)
{
    char steps[sizeof c->setup];
    snprintf(steps, sizeof steps, "%s", c->setup);
    if (strcmp(steps, "-") == 0)
        return 0;
    for (char *step = strtok(steps, ","); step; step = strtok(NULL, ",")) {
        step = trim(step);
        char *arg = strchr(step, ':');
        if (!arg)
            return -1;
        *arg++ = '\0';
        char path[PATH_MAX];
        char name[256];
        snprintf(name, sizeof name, "%s", arg);
        char *eq = strchr(name, '=');
        if (eq)
            *eq = '\0';
        snprintf(path, sizeof path, "%s/%s", dir, name);
        if (strcmp(step, "file") == 0) {
            if (write_bytes(path, "not a directory\n", 16) != 0)
                return -1;
        } else if (strcmp(step, "text") == 0) {
            char data[1024];
            size_t len = eq ? unescape(strchr(arg, '=') + 1, data, sizeof data) : 0;
            if (write_bytes(path, data, len) != 0)
                return -1;
        } else if (strcmp(step, "dir") == 0) {
            if (mkdir(path, 0755) != 0)
                return -1;
        } else if (strcmp(step, "fifo") == 0) {
            if (mkfifo(path, 0644) != 0)
                return -1;
        } else if (strcmp(step, "link") == 0 || strcmp(step, "hardlink") == 0) {
            /* NAME=TARGET: TARGET as written (relative to NAME's directory
             * for a symbolic link, to the case directory for a hard one). */
            if (!eq)
                return -1;
            const char *target = strchr(arg, '=') + 1;
            char target_path[PATH_MAX];
            snprintf(target_path, sizeof target_path, "%s/%s", dir, target);
            if (strcmp(step, "link") == 0 ? symlink(target, path) != 0
                                          : link(target_path, path) != 0)
                return -1;
        } else if (strcmp(step, "readonly") == 0 || strcmp(step, "unreadable") == 0) {
            if (mkdir(path, 0) != 0 || chmod(path, strcmp(step, "readonly") == 0 ? 0555 : 0))
                return -1;
            if (geteuid() == 0) {
                /* nobody must reach the case directory but not write ro/. */
                if (chmod(dir, 0777) != 0)
                    return -1;
                *drop = 1;
            }
        } else if (strcmp(step, "stdout") == 0) {
            snprintf(out_path, out_cap, "%s", arg);
        } else if (strcmp(step, "path") == 0) {
            snprintf(path_env, path_cap, "%s", path);
        } else if (strcmp(step, "fsize") == 0) {
            *fsize = atol(arg);
        } else if (strcmp(step, "disks") == 0) {
            char err[1024];
            if (run_disks_in(dir, arg, err, sizeof err) != 0)
                return -1;
        } else if (strcmp(step, "flip") == 0 || strcmp(step, "cut") == 0) {
            char *at = strchr(name, '@');
            if (!at)
                return -1;
            *at = '\0';
            snprintf(path, sizeof path, "%s/%s", dir, name);
            if (damage(path, atol(at + 1), strcmp(step, "cut") == 0) != 0)
                return -1;
        } else {
            return -1;
        }
    }
    return 0;
}

/* Lists the entries below dir (relative paths, directories first). */
static void list_tree(const char *dir, const char *rel, char names[][PATH_MAX], size_t *count)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s%s%s", dir, *rel ? "/" : "", rel);
    DIR *d = opendir(path);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) && *count < MAX_ENTRIES) {
        if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
            continue;
        char child[PATH_MAX];
        snprintf(child, sizeof child, "%s%s%s", rel, *rel ? "/" : "", e->d_name);
        snprintf(names[(*count)++], PATH_MAX, "%s", child);
        char full[PATH_MAX];
        struct stat st;
        if (snprintf(full, sizeof full, "%s/%s", dir, child) < (int)sizeof full &&
            lstat(full, &st) == 0 && S_ISDIR(st.st_mode))
            list_tree(dir, child, names, count);
    }
    closedir(d);
}

static void remove_tree(const char *path)
{
    struct stat st;
    if (lstat(path, &st) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        chmod(path, 0700); /* undo readonly/unreadable setups */
        DIR *d = opendir(path);
        struct dirent *e;
        while (d && (e = readdir(d))) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            char child[PATH_MAX];
            snprintf(child, sizeof child, "%s/%s", path, e->d_name);
            remove_tree(child);
        }
        if (d)
            closedir(d);
        rmdir(path);
    } else {
        unlink(path);
    }
}

static int is_frame_name(const char *base)
{
    unsigned k;
    char tail[8];
    return sscanf(base, "frame_%4u%7s", &k, tail) == 2 && strcmp(tail, ".txt") == 0 &&
           strlen(base) == strlen("frame_0000.txt");
}

/* A whole frames.json, the run's description beside its frames: what
 * disks writes begins and ends so (docs/cli.md, "Frame files"). */
static int is_whole_frames_json(const char *path)
{
    static const char head[] = "{\n  \"disksim_frames\": 1,\n", tail[] = "\n}\n";
    char text[8192];
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(text, 1, sizeof text, f) : 0;
    if (f)
        fclose(f);
    return n > sizeof head && n < sizeof text && memcmp(text, head, sizeof head - 1) == 0 &&
           memcmp(text + n - (sizeof tail - 1), tail, sizeof tail - 1) == 0;
}

/* Judges what the run left in dir beyond the setup's entries. */
static void check_leftovers(const cli_case *c, const char *dir, char before[][PATH_MAX],
                            size_t nbefore, outcome *o)
{
    static char after[MAX_ENTRIES][PATH_MAX];
    size_t nafter = 0;
    list_tree(dir, "", after, &nafter);
    if (nafter == MAX_ENTRIES)
        snprintf(o->problem, sizeof o->problem, "more than %d files left behind", MAX_ENTRIES);
    for (size_t i = 0; i < nafter && !o->problem[0]; ++i) {
        int old = 0;
        for (size_t j = 0; j < nbefore; ++j)
            old |= strcmp(after[i], before[j]) == 0;
        if (old)
            continue;
        char full[PATH_MAX];
        struct stat st;
        snprintf(full, sizeof full, "%s/%s", dir, after[i]);
        if (lstat(full, &st) == 0 && S_ISDIR(st.st_mode)) {
            /* A failed disks may leave the --out it made holding frames,
             * the renderer holding PNGs: never an empty one. */
            DIR *d = opendir(full);
            int entries = 0;
            for (struct dirent *e; d && (e = readdir(d));)
                entries += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
            if (d)
                closedir(d);
            if (c->exit_code == 2)
                snprintf(o->problem, sizeof o->problem, "a usage error made directory '%s'",
                         after[i]);
            else if (entries == 0)
                snprintf(o->problem, sizeof o->problem, "empty directory '%s' left behind",
                         after[i]);
            continue;
        }
        const char *slash = strrchr(after[i], '/');
        const char *base = slash ? slash + 1 : after[i];
        ds_frame frame;
        if (base[0] == '.')
            snprintf(o->problem, sizeof o->problem, "temporary file '%s' left behind", after[i]);
        else if (c->exit_code == 2)
            snprintf(o->problem, sizeof o->problem, "a usage error wrote '%s'", after[i]);
        else if (strcmp(base, "frames.json") == 0 && !is_whole_frames_json(full))
            snprintf(o->problem, sizeof o->problem, "partial frames.json '%s' left behind",
                     after[i]);
        else if (strcmp(base, "frames.json") == 0)
            continue;
        else if (!is_frame_name(base))
            snprintf(o->problem, sizeof o->problem, "unexpected file '%s' left behind", after[i]);
        else if (ds_frame_read(full, &frame, NULL) != DS_OK)
            snprintf(o->problem, sizeof o->problem, "partial frame '%s' left behind", after[i]);
        else {
            ds_frame_free(&frame);
            ++o->frames;
        }
    }
}

/* ------------------------------------------------------------------ */
/* Running                                                             */
/* ------------------------------------------------------------------ */

static void run_case(const cli_case *c, outcome *o)
{
    memset(o, 0, sizeof *o);
    char words[sizeof c->command];
    snprintf(words, sizeof words, "%s", c->command);
    char *argv[MAX_ARGS + 1];
    int argc = 0;
    for (char *w = strtok(words, " "); w && argc < MAX_ARGS; w = strtok(NULL, " "))
        argv[argc++] = strcmp(w, "''") == 0 ? w + 2 : w;
    argv[argc] = NULL;
    const char *program = strcmp(argv[0], "render") == 0 ? render_path : disks_path;
    if (access(program, X_OK) != 0) {
        snprintf(o->skip_reason, sizeof o->skip_reason, "skipped: %.100s is not built", program);
        return;
    }

    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    if (!mkdtemp(dir)) {
        snprintf(o->problem, sizeof o->problem, "mkdtemp: %s", strerror(errno));
        return;
    }
    long fsize = -1;
    int drop = 0;
    char out_path[256] = "/dev/null", path_env[PATH_MAX] = "";
    if (apply_setup(c, dir, &fsize, &drop, out_path, sizeof out_path, path_env, sizeof path_env) !=
        0) {
        snprintf(o->problem, sizeof o->problem, "bad setup '%.400s'", c->setup);
        remove_tree(dir);
        return;
    }
    static char before[MAX_ENTRIES][PATH_MAX];
    size_t nbefore = 0;
    list_tree(dir, "", before, &nbefore);

    int pipefd[2];
    if (pipe(pipefd) != 0) {
        snprintf(o->problem, sizeof o->problem, "pipe: %s", strerror(errno));
        remove_tree(dir);
        return;
    }
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int devnull = open("/dev/null", O_RDWR);
        int out = open(out_path, O_WRONLY);
        dup2(devnull, STDIN_FILENO);
        dup2(out, STDOUT_FILENO);
        dup2(pipefd[1], STDERR_FILENO);
        close(pipefd[0]);
        if (chdir(dir) != 0)
            _exit(125);
        if (path_env[0] && setenv("PATH", path_env, 1) != 0)
            _exit(125);
        if (fsize >= 0) {
            /* Without SIGXFSZ ignored the kernel kills the writer; ignored,
             * the write fails with EFBIG like a full quota. */
            struct rlimit rl = {(rlim_t)fsize, (rlim_t)fsize};
            signal(SIGXFSZ, SIG_IGN);
            setrlimit(RLIMIT_FSIZE, &rl);
        }
        if (drop && (setgroups(0, NULL) != 0 || setgid(UNPRIVILEGED_ID) != 0 ||
                     setuid(UNPRIVILEGED_ID) != 0))
            _exit(124);
        if (drop && access(program, X_OK) != 0)
            _exit(CANNOT_REACH_AS_NOBODY);
        alarm(CASE_TIMEOUT_SECONDS); /* survives exec: SIGALRM ends a hang */
        argv[0] = (char *)program;
        execv(program, argv);
        _exit(126);
    }
    close(pipefd[1]);
    size_t got = 0;
    ssize_t r;
    while ((r = read(pipefd[0], o->err + got, sizeof o->err - 1 - got)) > 0 ||
           (r < 0 && errno == EINTR))
        got += r > 0 ? (size_t)r : 0;
    o->err[got] = '\0';
    close(pipefd[0]);
    int ws = 0;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR)
        ;
    if (drop && WIFEXITED(ws) && WEXITSTATUS(ws) == CANNOT_REACH_AS_NOBODY) {
        /* e.g. a checkout under /root: nobody cannot run the binary. */
        snprintf(o->skip_reason, sizeof o->skip_reason, "skipped: user nobody cannot run %.80s",
                 program);
        remove_tree(dir);
        return;
    }
    o->ran = 1;
    o->status = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);

    const char *nl = strchr(o->err, '\n');
    if (WIFSIGNALED(ws))
        snprintf(o->problem, sizeof o->problem, "killed by signal %d%s", WTERMSIG(ws),
                 WTERMSIG(ws) == SIGALRM ? " (hang)" : "");
    else if (o->status != c->exit_code)
        snprintf(o->problem, sizeof o->problem, "exit status %d, expected %d", o->status,
                 c->exit_code);
    else if (c->exit_code == 0 && o->err[0])
        snprintf(o->problem, sizeof o->problem, "a good run printed on stderr");
    else if (c->exit_code != 0 && (!nl || nl[1] != '\0'))
        snprintf(o->problem, sizeof o->problem, "stderr is not exactly one line");
    else if (!strstr(o->err, c->expect))
        snprintf(o->problem, sizeof o->problem, "stderr does not contain \"%s\"", c->expect);
    if (!o->problem[0])
        check_leftovers(c, dir, before, nbefore, o);
    remove_tree(dir);
}

/* ------------------------------------------------------------------ */
/* cmocka                                                              */
/* ------------------------------------------------------------------ */

static void test_bad_input_case(void **state)
{
    const cli_case *c = *state;
    outcome o;
    run_case(c, &o);
    if (!o.ran && !o.problem[0]) {
        print_message("%s (%s)\n", o.skip_reason, c->name);
        skip();
    }
    if (o.problem[0])
        fail_msg("cli_cases.txt:%d \"%s\": `%s`: %s; stderr was: %s", c->line, c->name, c->command,
                 o.problem, o.err);
}

/* Runs a command that must succeed: exit 0, nothing on stderr, the given
 * number of complete frames and no other file. */
static void expect_a_good_run(const char *command, int frames)
{
    cli_case good = {"a good run", 0, "", "-", "", 0};
    snprintf(good.command, sizeof good.command, "%s", command);
    outcome o;
    run_case(&good, &o);
    assert_int_equal(o.ran, 1);
    if (o.problem[0])
        fail_msg("`%s`: %s", command, o.problem);
    assert_string_equal(o.err, "");
    assert_int_equal(o.frames, frames);
}

/* The control case: the checks above would be hollow if a good run also
 * failed them. */
static void test_a_good_run_writes_only_complete_frames(void **state)
{
    (void)state;
    expect_a_good_run("disks 50 5 --frames 3 --quiet --out out", 3);
}

/* One disk always fits, however large: the many-disk limit of random
 * placement (0.54 of the box) does not apply to it. */
static void test_one_disk_of_almost_half_the_box_runs(void **state)
{
    (void)state;
    expect_a_good_run("disks 1 499.9 --frames 3 --quiet --out out", 3);
}

/* ------------------------------------------------------------------ */
/* Runs that survive: checkpoints, restarts, --from, the outputs        */
/* ------------------------------------------------------------------ */

/* Runs disks with args (separated by spaces) in dir, standard output to
 * /dev/null and standard error into err; returns the exit status, or
 * 128 + the signal that ended it. */
static int run_disks_in(const char *dir, const char *args, char *err, size_t cap)
{
    char words[1024];
    snprintf(words, sizeof words, "%s", args);
    char *argv[MAX_ARGS + 1], *save = NULL;
    int argc = 0;
    argv[argc++] = disks_path;
    for (char *w = strtok_r(words, " ", &save); w && argc < MAX_ARGS;
         w = strtok_r(NULL, " ", &save))
        argv[argc++] = w;
    argv[argc] = NULL;
    int pipefd[2];
    if (pipe(pipefd) != 0)
        return -1;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int devnull = open("/dev/null", O_RDWR);
        dup2(devnull, STDIN_FILENO);
        dup2(devnull, STDOUT_FILENO);
        dup2(pipefd[1], STDERR_FILENO);
        close(pipefd[0]);
        if (chdir(dir) != 0)
            _exit(125);
        alarm(CASE_TIMEOUT_SECONDS);
        execv(disks_path, argv);
        _exit(126);
    }
    close(pipefd[1]);
    size_t got = 0;
    ssize_t r;
    while ((r = read(pipefd[0], err + got, cap - 1 - got)) > 0 || (r < 0 && errno == EINTR))
        got += r > 0 ? (size_t)r : 0;
    err[got] = '\0';
    close(pipefd[0]);
    int ws = 0;
    while (waitpid(pid, &ws, 0) < 0 && errno == EINTR)
        ;
    return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
}

/* A run that must succeed quietly. */
static void must_run(const char *dir, const char *fmt, ...)
{
    char args[1024], err[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(args, sizeof args, fmt, ap);
    va_end(ap);
    int status = run_disks_in(dir, args, err, sizeof err);
    if (status != 0 || err[0])
        fail_msg("`disks %s` in %s: status %d, stderr: %s", args, dir, status, err);
}

/* A whole file, NUL-terminated; NULL if it cannot be read. */
static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 1 << 16, n = 0;
    char *data = malloc(cap);
    for (size_t r; data && (r = fread(data + n, 1, cap - n - 1, f)) > 0;) {
        n += r;
        if (n + 1 == cap) {
            char *grown = realloc(data, cap *= 2);
            if (!grown)
                free(data);
            data = grown;
        }
    }
    fclose(f);
    if (data)
        data[n] = '\0';
    if (len)
        *len = n;
    return data;
}

static char *slurp_in(const char *dir, const char *name, size_t *len)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return slurp(path, len);
}

static const char *path_in_dir(const char *dir, const char *name)
{
    static char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return path;
}

static void write_text_in(const char *dir, const char *name, const char *text)
{
    FILE *f = fopen(path_in_dir(dir, name), "wb");
    assert_non_null(f);
    assert_int_equal(fputs(text, f) >= 0, 1);
    assert_int_equal(fclose(f), 0);
}

static int exists_in(const char *dir, const char *name)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return access(path, F_OK) == 0;
}

/* Fails unless dir/a and dir/b hold the same bytes. */
static void assert_same_files(const char *dir, const char *a, const char *b)
{
    size_t la = 0, lb = 0;
    char *x = slurp_in(dir, a, &la), *y = slurp_in(dir, b, &lb);
    int same = x && y && la == lb && memcmp(x, y, la) == 0;
    free(x);
    free(y);
    if (!same)
        fail_msg("%s and %s differ (in %s)", a, b, dir);
}

static void frame_name(char *out, size_t cap, const char *dir, long k)
{
    snprintf(out, cap, "%s/frame_%04ld.txt", dir, k);
}

/* A run stopped after 5 frames and restarted from its checkpoint for 5
 * more writes what one run of 10 writes, to the byte: the frames, the
 * --stats rows and the trajectory (the restart's files hold its frames:
 * the two parts, joined, are the whole run). */
static void restart_matches_one_run(const char *system)
{
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *run = "--steps-per-frame 20 --velocities --quiet";
    must_run(dir, "200 5 %s --frames 10 %s --out one --stats one.csv --trajectory one.xyz", system,
             run);
    must_run(dir,
             "200 5 %s --frames 5 %s --out two --stats a.csv --trajectory a.xyz "
             "--checkpoint c.ckpt --checkpoint-every 2",
             system, run);
    must_run(dir,
             "--restart c.ckpt --frames 5 %s --out two --stats b.csv --trajectory b.xyz "
             "--checkpoint c.ckpt",
             run);
    for (long k = 0; k < 10; ++k) {
        char a[64], b[64];
        frame_name(a, sizeof a, "one", k);
        frame_name(b, sizeof b, "two", k);
        assert_same_files(dir, a, b);
    }
    assert_false(exists_in(dir, "two/frame_0010.txt"));
    size_t l1, la, lb;
    char *one = slurp_in(dir, "one.csv", &l1), *a = slurp_in(dir, "a.csv", &la),
         *b = slurp_in(dir, "b.csv", &lb);
    assert_non_null(one);
    assert_non_null(a);
    assert_non_null(b);
    const char *rows = strchr(b, '\n') + 1; /* after the header */
    assert_int_equal(la + (lb - (size_t)(rows - b)), l1);
    assert_memory_equal(one, a, la);
    assert_memory_equal(one + la, rows, lb - (size_t)(rows - b));
    free(one);
    free(a);
    free(b);
    one = slurp_in(dir, "one.xyz", &l1);
    a = slurp_in(dir, "a.xyz", &la);
    b = slurp_in(dir, "b.xyz", &lb);
    assert_int_equal(la + lb, l1);
    assert_memory_equal(one, a, la);
    assert_memory_equal(one + la, b, lb);
    free(one);
    free(a);
    free(b);
    /* The end checkpoint is frame 9's: a second restart goes on to 10. */
    must_run(dir, "--restart c.ckpt --frames 1 %s --out two", run);
    assert_true(exists_in(dir, "two/frame_0010.txt"));
    remove_tree(dir);
}

static void test_a_restart_writes_the_frames_of_an_uninterrupted_run(void **state)
{
    (void)state;
    restart_matches_one_run("");
    restart_matches_one_run("--periodic");
    restart_matches_one_run("--integrator event");
    restart_matches_one_run("--integrator event --periodic");
    restart_matches_one_run("--boundary channel --box-y 500");
    restart_matches_one_run("--integrator event --boundary channel --box-y 500");
    /* A mixture's area fraction column too (a load summed the areas in
     * the slots' order, and its last bits moved). */
    restart_matches_one_run("--mixture 1.4:0.5");
    restart_matches_one_run("--mixture 1.4:0.5 --integrator event --periodic");
    /* The checkpoint's heat bath and barostat go on (their random
     * numbers, the box of the trajectory's Lattice) without the options
     * given again. */
    restart_matches_one_run("--integrator event --periodic --thermostat andersen --pressure 30 "
                            "--barostat-every 2 --barostat-aspect");
    restart_matches_one_run("--periodic --thermostat isokinetic --temperature 2000 --pressure 30");
    /* The checkpoint's shear goes on without --shear: the images' offset,
     * the trajectory's shear_offset and the stats' shear columns. */
    restart_matches_one_run("--integrator event --periodic --shear 40 --thermostat isokinetic");
}

/* Starts disks in dir with the given arguments and sends sig once
 * dir/wait_for exists (no timing is asserted: the alarm bounds a stuck
 * run). Returns the wait status. */
static int start_and_signal_n(const char *dir, const char *args, const char *wait_for, int sig,
                              int times)
{
    char words[1024];
    snprintf(words, sizeof words, "%s", args);
    char *argv[MAX_ARGS + 1], *save = NULL;
    int argc = 0;
    argv[argc++] = disks_path;
    for (char *w = strtok_r(words, " ", &save); w && argc < MAX_ARGS;
         w = strtok_r(NULL, " ", &save))
        argv[argc++] = w;
    argv[argc] = NULL;
    fflush(NULL);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        int devnull = open("/dev/null", O_RDWR);
        dup2(devnull, STDOUT_FILENO);
        dup2(devnull, STDERR_FILENO);
        if (chdir(dir) != 0)
            _exit(125);
        /* As from a terminal: a shell starts background jobs with SIGINT
         * ignored, disks keeps an ignored signal ignored (as nohup wants),
         * and the run would then not stop. */
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        signal(SIGHUP, SIG_DFL);
        alarm(CASE_TIMEOUT_SECONDS);
        execv(disks_path, argv);
        _exit(126);
    }
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, wait_for);
    int ws = 0;
    pid_t done = 0;
    while (access(path, F_OK) != 0 && (done = waitpid(pid, &ws, WNOHANG)) == 0)
        nanosleep(&(struct timespec){0, 1000000}, NULL);
    if (done == 0) {
        for (int k = 0; k < times; ++k) {
            if (k > 0)
                nanosleep(&(struct timespec){0, 2000000}, NULL);
            kill(pid, sig);
        }
        while ((done = waitpid(pid, &ws, 0)) < 0 && errno == EINTR)
            ;
    }
    /* Say what happened when the run did not end by the signal: a disks
     * error before it (exit status; rerun the command by hand), or the
     * child lost to waitpid. */
    if (done != pid)
        fail_msg("signal %d: waitpid returned %d (%s)", sig, (int)done, strerror(errno));
    if (!WIFSIGNALED(ws))
        fail_msg("signal %d: `disks %s` exited with status %d, not by the signal", sig, args,
                 WIFEXITED(ws) ? WEXITSTATUS(ws) : -1);
    assert_int_equal(WTERMSIG(ws), sig);
    return ws;
}

static int start_and_signal(const char *dir, const char *args, const char *wait_for, int sig)
{
    return start_and_signal_n(dir, args, wait_for, sig, 1);
}

/* The frames of out/: 0 .. n-1 with none missing, each complete; no
 * temporary anywhere in dir. Returns n. */
static long complete_frames(const char *dir)
{
    static char names[MAX_ENTRIES][PATH_MAX];
    size_t count = 0;
    list_tree(dir, "", names, &count);
    long n = 0;
    for (size_t i = 0; i < count; ++i) {
        const char *slash = strrchr(names[i], '/');
        const char *base = slash ? slash + 1 : names[i];
        if (base[0] == '.')
            fail_msg("temporary file '%s' left behind", names[i]);
        if (strncmp(names[i], "out/", 4) == 0 && strcmp(base, "frames.json") != 0)
            ++n;
    }
    for (long k = 0; k < n; ++k) {
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/out/frame_%04ld.txt", dir, k);
        ds_frame frame;
        if (ds_frame_read(path, &frame, NULL) != DS_OK)
            fail_msg("out/frame_%04ld.txt is missing or partial (%ld frames)", k, n);
        ds_frame_free(&frame);
    }
    return n;
}

/* The trajectory holds exactly the n frames of out/, frame by frame the
 * same centres. */
static void assert_trajectory_holds_the_frames(const char *dir, long n)
{
    char *xyz = slurp_in(dir, "t.xyz", NULL);
    if (!xyz)
        fail_msg("no t.xyz after the interruption");
    char *save = NULL, *line = strtok_r(xyz, "\n", &save);
    long frames = 0;
    while (line) {
        char name[64];
        snprintf(name, sizeof name, "out/frame_%04ld.txt", frames);
        char *text = slurp_in(dir, name, NULL);
        if (!text)
            fail_msg("t.xyz holds more frames than out/ (%ld)", n);
        size_t count = strtoul(line, NULL, 10);
        line = strtok_r(NULL, "\n", &save); /* the comment line */
        char *fsave = NULL, *fline = strtok_r(text, "\n", &fsave);
        for (size_t i = 0; i < count; ++i) {
            line = strtok_r(NULL, "\n", &save);
            char xs[32], ys[32], fx[32], fy[32];
            if (!line || !fline || sscanf(line, "%*s %31s %31s", xs, ys) != 2 ||
                sscanf(fline, "%31s %31s", fx, fy) != 2 || strcmp(xs, fx) != 0 ||
                strcmp(ys, fy) != 0)
                fail_msg("t.xyz frame %ld disk %zu is not %s's", frames, i, name);
            fline = strtok_r(NULL, "\n", &fsave);
        }
        free(text);
        ++frames;
        line = strtok_r(NULL, "\n", &save);
    }
    free(xyz);
    assert_int_equal(frames, n);
}

/* Interrupts a run writing frames, a trajectory, stats and a checkpoint
 * as fast as it can. Whatever frames exist are complete, the trajectory
 * and the stats hold exactly those frames, the checkpoint is the last
 * one's and restarts: its next frames are an uninterrupted run's. (A
 * periodic box: with walls the time step leaves a disk past its wall for
 * a step, which the library's checkpoint loader refuses.) */
static void interrupt_a_run(int sig)
{
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *system = "3000 2 --periodic --steps-per-frame 1 --quiet";
    char args[256];
    snprintf(args, sizeof args,
             "%s --frames 10000 --out out --trajectory t.xyz --stats s.csv --checkpoint c.ckpt",
             system);
    start_and_signal(dir, args, "out/frame_0003.txt", sig);
    long n = complete_frames(dir);
    assert_true(n >= 4);
    assert_trajectory_holds_the_frames(dir, n);
    char *stats = slurp_in(dir, "s.csv", NULL);
    assert_non_null(stats);
    long rows = 0;
    for (const char *p = stats; (p = strchr(p, '\n')); ++p)
        ++rows;
    free(stats);
    assert_int_equal(rows, n + 1);
    /* On from the checkpoint, in the same directory: frames n and n + 1. */
    must_run(dir, "--restart c.ckpt --frames 2 --steps-per-frame 1 --quiet --out out");
    must_run(dir, "%s --frames %ld --out whole", system, n + 2);
    for (long k = 0; k < n + 2; ++k) {
        char a[64], b[64];
        frame_name(a, sizeof a, "out", k);
        frame_name(b, sizeof b, "whole", k);
        assert_same_files(dir, a, b);
    }
    remove_tree(dir);
}

static void test_an_interrupted_run_keeps_its_trajectory_and_writes_its_checkpoint(void **state)
{
    (void)state;
    for (int k = 0; k < (quick_mode() ? 1 : 2); ++k) {
        interrupt_a_run(SIGINT);
        interrupt_a_run(SIGTERM);
    }
    interrupt_a_run(SIGHUP);
}

/* A second Ctrl-C ends the run at once, inside a long frame: the frames
 * written stay, and the trajectory holds exactly them. (Should the frame
 * end between the two signals, the first stops the run as above: the same
 * holds.) */
static void test_a_second_signal_ends_the_run_at_once_keeping_the_trajectory(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    start_and_signal_n(dir,
                       "2000 2 --periodic --steps-per-frame 2000 --quiet --frames 10000 --out out "
                       "--trajectory t.xyz --checkpoint c.ckpt",
                       "out/frame_0001.txt", SIGINT, 2);
    long n = complete_frames(dir);
    assert_true(n >= 2);
    assert_trajectory_holds_the_frames(dir, n);
    remove_tree(dir);
}

/* SIGKILL gives no chance to finish: the checkpoint in place is still a
 * whole one (the last of --checkpoint-every 3), and restarts. */
static void test_a_killed_run_leaves_a_checkpoint_that_restarts(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *system = "500 3 --periodic --steps-per-frame 1 --quiet";
    char args[256];
    snprintf(args, sizeof args,
             "%s --frames 10000 --out out --checkpoint c.ckpt --checkpoint-every 3", system);
    start_and_signal(dir, args, "out/frame_0010.txt", SIGKILL);
    must_run(dir, "--restart c.ckpt --frames 2 --steps-per-frame 1 --quiet --out again");
    long first = -1;
    for (long k = 0; k < 10000 && first < 0; ++k) {
        char name[64];
        frame_name(name, sizeof name, "again", k);
        if (exists_in(dir, name))
            first = k;
    }
    /* Written at frames 3, 6, 9, ...: the restart's first is one after. */
    assert_true(first >= 10);
    assert_int_equal((first - 1) % 3, 0);
    must_run(dir, "%s --frames %ld --out whole", system, first + 2);
    for (long k = first; k < first + 2; ++k) {
        char a[64], b[64];
        frame_name(a, sizeof a, "again", k);
        frame_name(b, sizeof b, "whole", k);
        assert_same_files(dir, a, b);
    }
    remove_tree(dir);
}

/* A restart needs nothing but its checkpoint: a run killed (SIGKILL,
 * nothing of its own handled) after its 10th frame, with --steps-per-frame
 * 200, --velocities, --stats, --trajectory and checkpoints every 4 frames,
 * restarted as `disks --restart c.ckpt`, leaves the frames, the rows and
 * the trajectory of the run that was never stopped, to the byte: the
 * checkpoint gave the spacing, the frames still to write, the format and
 * every path, and the outputs kept their rows up to the checkpoint's
 * frame and dropped the later ones, which the restart wrote again. */
static void test_a_restart_without_options_goes_on_with_the_run(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *run = "500 3 --periodic --frames 60 --steps-per-frame 200 --velocities --quiet";
    char args[256];
    snprintf(args, sizeof args,
             "%s --out two --stats two.csv --trajectory two.xyz --checkpoint c.ckpt "
             "--checkpoint-every 4",
             run);
    start_and_signal(dir, args, "two/frame_0010.txt", SIGKILL);
    assert_false(exists_in(dir, "two/frame_0059.txt"));
    must_run(dir, "--restart c.ckpt");
    must_run(dir, "%s --out one --stats one.csv --trajectory one.xyz", run);
    for (long k = 0; k < 60; ++k) {
        char a[64], b[64];
        frame_name(a, sizeof a, "one", k);
        frame_name(b, sizeof b, "two", k);
        assert_same_files(dir, a, b);
    }
    assert_false(exists_in(dir, "two/frame_0060.txt"));
    assert_same_files(dir, "one.csv", "two.csv");
    assert_same_files(dir, "one.xyz", "two.xyz");
    assert_same_files(dir, "one/frames.json", "two/frames.json");
    /* The run is over: a restart now says so, and with --frames goes on. */
    char err[512];
    assert_int_equal(run_disks_in(dir, "--restart c.ckpt", err, sizeof err), 2); /* usage */
    assert_non_null(strstr(err, "ended at frame 59, its last"));
    must_run(dir, "--restart c.ckpt --frames 2");
    assert_true(exists_in(dir, "two/frame_0061.txt"));
    remove_tree(dir);
}

/* A checkpoint without the command's settings (written by the library for
 * another program, or by disksim 2.x) restarts with the command's
 * defaults, 100 steps a frame: one at step 30 is refused as no whole
 * frame, and with --steps-per-frame 10 goes on after frame 3. */
static void test_a_checkpoint_without_settings_restarts_with_the_defaults(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    ds_params p = ds_params_default(20, 5.0);
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_run(sim, 30, NULL), DS_OK);
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/c.ckpt", dir);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(ds_checkpoint_save(sim, f, NULL), DS_OK);
    fclose(f);
    ds_sim_destroy(sim);
    char err[512];
    assert_int_equal(run_disks_in(dir, "--restart c.ckpt --quiet", err, sizeof err),
                     1); /* run-time */
    assert_non_null(strstr(err, "its step 30 is not a whole number of frames"));
    must_run(dir, "--restart c.ckpt --steps-per-frame 10 --frames 2 --quiet --out o");
    assert_false(exists_in(dir, "o/frame_0003.txt")); /* the checkpoint's own */
    assert_true(exists_in(dir, "o/frame_0004.txt"));
    assert_true(exists_in(dir, "o/frame_0005.txt"));
    assert_false(exists_in(dir, "o/frame_0006.txt"));
    remove_tree(dir);
}

/* --from takes a frame written with --velocities: the new run's frame 0
 * is that frame to the byte, at time 0 (a new run, not a continuation). */
static void test_a_run_starts_from_a_frame_written_with_velocities(void **state)
{
    (void)state;
    const char *systems[] = {"--integrator event", "--integrator event --periodic"};
    for (size_t s = 0; s < 2; ++s) {
        char dir[] = "/tmp/ds_test_cli_XXXXXX";
        assert_non_null(mkdtemp(dir));
        must_run(dir, "200 5 %s --velocities --frames 3 --quiet --out a", systems[s]);
        must_run(dir,
                 "--from a/frame_0002.txt %s --velocities --frames 3 --quiet --out b --stats b.csv",
                 systems[s]);
        assert_same_files(dir, "a/frame_0002.txt", "b/frame_0000.txt");
        assert_true(exists_in(dir, "b/frame_0002.txt"));
        char *stats = slurp_in(dir, "b.csv", NULL);
        assert_non_null(stats);
        assert_non_null(strstr(stats, "\n0,0.000000,"));
        free(stats);
        /* N and R may be given: they must be the frame's. */
        must_run(dir, "200 5 --from a/frame_0002.txt %s --frames 2 --quiet --out c", systems[s]);
        remove_tree(dir);
    }
    /* The first frame of a time-step run: no pair inside 2R yet. */
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "200 5 --velocities --frames 1 --quiet --out a");
    must_run(dir, "--from a/frame_0000.txt --velocities --frames 3 --quiet --out b");
    assert_same_files(dir, "a/frame_0000.txt", "b/frame_0000.txt");
    remove_tree(dir);
}

/* The radii column of a frame: how many disks have radius a, how many b
 * (to the frame's six decimals), and how many neither. */
static void count_radii(const char *dir, const char *name, double a, double b, size_t counts[3])
{
    char *text = slurp_in(dir, name, NULL);
    assert_non_null(text);
    counts[0] = counts[1] = counts[2] = 0;
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        double x, y, r;
        assert_int_equal(sscanf(line, "%lf %lf %lf", &x, &y, &r), 3);
        ++counts[fabs(r - a) < 5e-7 ? 0 : fabs(r - b) < 5e-7 ? 1 : 2];
    }
    free(text);
}

/* The last row of a --stats file, its columns split in place. */
static int last_row(char *csv, char *cols[], int most)
{
    size_t len = strlen(csv);
    while (len && csv[len - 1] == '\n')
        csv[--len] = '\0';
    char *row = strrchr(csv, '\n');
    row = row ? row + 1 : csv;
    int n = 0;
    for (char *c = strtok(row, ","); c && n < most; c = strtok(NULL, ","))
        cols[n++] = c;
    return n;
}

/* --box, --box-y, --speed, --dt and --area-fraction reach the
 * simulation: 500 disks (and a 1.4:0.5 mixture) at area fraction 0.25 in a
 * box of 600 x 450 cover 0.25 of it (to the rounding of a sum of 500
 * areas, 1e-12), every centre inside it (frames print 6 decimals), the kinetic energy is N V^2 / 2
 * for --speed 3 (equal masses; 1e-12 relative: the sum's rounding), and
 * frames of 10 steps of --dt 0.01 are 0.1 apart. */
static void test_the_box_speed_dt_and_area_fraction_options_reach_the_run(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *mixtures[2] = {"", "--mixture 1.4:0.5"};
    for (int m = 0; m < 2; ++m) {
        must_run(dir,
                 "500 --area-fraction 0.25 %s --box 600 --box-y 450 --speed 3 --dt 0.01 "
                 "--steps-per-frame 10 --frames 2 --quiet --overwrite --out o --stats s.csv",
                 mixtures[m]);
        size_t len;
        char *csv = slurp_in(dir, "s.csv", &len);
        assert_non_null(csv);
        char *cols[24];
        assert_int_equal(last_row(csv, cols, 24), 20);
        assert_true(fabs(strtod(cols[1], NULL) - 0.1) < 1e-9);                /* time */
        assert_true(fabs(strtod(cols[2], NULL) / (500 * 4.5) - 1.0) < 1e-12); /* K */
        assert_true(fabs(strtod(cols[10], NULL) - 0.25) < 1e-12);             /* eta */
        free(csv);
        ds_frame f;
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/o/frame_0001.txt", dir);
        assert_int_equal(ds_frame_read(path, &f, NULL), DS_OK);
        assert_int_equal(f.count, 500);
        for (size_t k = 0; k < f.count; ++k) {
            const ds_frame_disk *d = &f.disks[k];
            /* The time step turns a disk a step after it crossed its
             * wall line: it may be up to V dt = 0.03 past it. */
            const double past = 3.0 * 0.01 + 1e-6;
            assert_true(d->x >= d->r - past && d->x <= 600 - d->r + past);
            assert_true(d->y >= d->r - past && d->y <= 450 - d->r + past);
        }
        ds_frame_free(&f);
    }
    remove_tree(dir);
}

/* --mixture 1.4:0.3: 30 of 100 disks have radius 1.4 R, the rest R, in
 * every frame; --mass area changes the motion (the large disks weigh
 * 1.96), not the start. */
static void test_a_mixture_run_writes_its_two_radii(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *system = "100 5 --mixture 1.4:0.3 --integrator event --periodic --frames 3";
    must_run(dir, "%s --quiet --out a --stats a.csv", system);
    must_run(dir, "%s --mass area --quiet --out b", system);
    size_t counts[3];
    for (int k = 0; k < 3; ++k) {
        char name[32];
        snprintf(name, sizeof name, "a/frame_%04d.txt", k);
        count_radii(dir, name, 5.0, 7.0, counts);
        assert_int_equal(counts[0], 70);
        assert_int_equal(counts[1], 30);
        assert_int_equal(counts[2], 0);
    }
    assert_same_files(dir, "a/frame_0000.txt", "b/frame_0000.txt");
    size_t la = 0, lb = 0;
    char *x = slurp_in(dir, "a/frame_0002.txt", &la), *y = slurp_in(dir, "b/frame_0002.txt", &lb);
    assert_true(x && y && !(la == lb && memcmp(x, y, la) == 0));
    free(x);
    free(y);
    /* The area fraction column: pi (70 x 25 + 30 x 49) / 10^6. */
    char *csv = slurp_in(dir, "a.csv", NULL), *cols[24];
    assert_non_null(csv);
    assert_non_null(strstr(csv, ",psi6,area_fraction,granular_temperature,"));
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_true(fabs(strtod(cols[10], NULL) / (3.14159265358979 * 3220e-6) - 1.0) < 1e-12);
    free(csv);
    remove_tree(dir);
}

/* A granular run from the command line: --restitution, --wall-restitution,
 * --gravity and --drive in a channel; the --stats columns after
 * area_fraction are the granular temperature and the energy books, which
 * balance in every row to rounding (kinetic + potential + lost - input is
 * the start's: the event-driven books are exact), and a --restart goes on
 * with the rules its checkpoint holds, its rows those of the run that did
 * not stop. */
static void test_a_granular_run_writes_its_energy_books(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *run = "200 5 --integrator event --boundary channel --restitution 0.8 "
                      "--wall-restitution 0.9 --gravity 100 --drive 20000 --steps-per-frame 50";
    must_run(dir, "%s --frames 7 --quiet --out a --stats a.csv", run);
    must_run(dir, "%s --frames 4 --quiet --out b --stats b.csv --checkpoint c.ckpt", run);
    must_run(dir, "--restart c.ckpt --frames 3 --steps-per-frame 50 --quiet --out b --stats r.csv");
    char *csv = slurp_in(dir, "a.csv", NULL);
    assert_non_null(csv);
    assert_non_null(strstr(csv, ",area_fraction,granular_temperature,energy_lost,energy_input,"
                                "power_lost,power_input,potential_energy,"));
    char *line = strchr(csv, '\n') + 1;
    double start = NAN;
    for (int row = 0; row < 7; ++row) {
        double v[17];
        char *end = line;
        for (int c = 0; c < 17; ++c)
            v[c] = strtod(end + (c > 0), &end);
        const double books = v[2] + v[16] + v[12] - v[13];
        if (row == 0)
            start = books;
        assert_true(fabs(books - start) < 1e-9 * start);
        assert_true(row == 0 || (v[12] > 0.0 && v[13] > 0.0 && v[11] > 0.0));
        line = strchr(line, '\n') + 1;
    }
    /* The restarted rows are the whole run's last three, to the byte. */
    char *whole = strstr(csv, "\n4,"), *restarted = slurp_in(dir, "r.csv", NULL);
    assert_non_null(whole);
    assert_non_null(restarted);
    assert_string_equal(whole + 1, strchr(restarted, '\n') + 1);
    free(restarted);
    free(csv);
    remove_tree(dir);
}

/* --shear RATE from the command line, as the library runs it: the
 * --stats columns are the rate, the shear stress over each row's interval
 * (the change of ds_sim_get_stress_integral's xy part over W H times the
 * interval's time) and the apparent viscosity -P_xy / RATE, to the bit
 * what the library gives with ds_sim_set_thermostat (isokinetic) and
 * ds_sim_set_shear in that order; the first row's interval is none
 * (nan). frames.json names the rate. A run without shear writes rate 0
 * and a viscosity of nan. */
static void test_a_sheared_run_writes_its_stress_and_viscosity(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "200 10 --seed 5 --integrator event --periodic --box 400 --shear -25 "
                  "--thermostat isokinetic --steps-per-frame 40 --frames 4 --quiet --out a "
                  "--stats a.csv");
    ds_params p = ds_params_default(200, 10.0);
    p.seed = 5;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    p.boundary = DS_BOUNDARY_PERIODIC;
    p.box = 400.0;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    assert_int_equal(ds_sim_set_thermostat(sim, DS_THERMOSTAT_ISOKINETIC, 0.0, 0.0, NULL), DS_OK);
    assert_int_equal(ds_sim_set_shear(sim, -25.0, NULL), DS_OK);
    char *csv = slurp_in(dir, "a.csv", NULL);
    assert_non_null(csv);
    assert_non_null(strstr(csv, ",potential_energy,shear_rate,shear_stress,viscosity\n"));
    char *row = strchr(csv, '\n') + 1;
    assert_non_null(strstr(row, ",-25,nan,nan\n")); /* frame 0: no interval yet */
    double s0[3], s1[3], t0 = 0.0;
    ds_sim_get_stress_integral(sim, s0, NULL);
    for (int frame = 1; frame < 4; ++frame) {
        ds_sim_run(sim, 40, NULL);
        ds_sim_get_stress_integral(sim, s1, NULL);
        const double t1 = ds_sim_get_time(sim);
        const double p_xy = (s1[2] - s0[2]) / (400.0 * 400.0 * (t1 - t0));
        t0 = t1;
        char want[128];
        snprintf(want, sizeof want, "\n%d,%s", frame, "");
        row = strstr(row, want);
        assert_non_null(row);
        snprintf(want, sizeof want, ",-25,%.17g,%.17g\n", p_xy, -p_xy / -25.0);
        char *end = strchr(row + 1, '\n');
        assert_non_null(end);
        assert_true(strncmp(end - strlen(want) + 1, want, strlen(want)) == 0);
        memcpy(s0, s1, sizeof s0);
        ++row;
    }
    ds_sim_destroy(sim);
    free(csv);
    char *json = slurp_in(dir, "a/frames.json", NULL);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"shear_rate\": -25\n"));
    free(json);
    must_run(dir, "200 10 --integrator event --periodic --frames 2 --quiet --out b --stats b.csv");
    csv = slurp_in(dir, "b.csv", NULL);
    assert_non_null(csv);
    char *cols[24];
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_string_equal(cols[17], "0");
    assert_true(isfinite(strtod(cols[18], NULL))); /* the stress at rest is there */
    assert_string_equal(cols[19], "nan");
    free(csv);
    remove_tree(dir);
}

/* A sheared run's checkpoint restarts sheared, without --shear given
 * again: `disks --restart` alone writes the frames of the run that did
 * not stop (restart_matches_one_run checks the rows and the trajectory),
 * and --shear 0 stops the images: the rate column is 0 from there on. */
static void test_a_restart_without_shear_goes_on_shearing(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *run = "100 5 --integrator event --periodic --shear 30 --thermostat isokinetic "
                      "--steps-per-frame 50 --velocities --quiet";
    must_run(dir, "%s --frames 8 --out one", run);
    must_run(dir, "%s --frames 4 --out two --checkpoint c.ckpt", run);
    must_run(dir, "--restart c.ckpt --frames 4 --stats two.csv");
    assert_same_files(dir, "one/frame_0007.txt", "two/frame_0007.txt");
    char *csv = slurp_in(dir, "two.csv", NULL), *cols[24];
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_string_equal(cols[17], "30");
    free(csv);
    must_run(dir, "--restart c.ckpt --frames 4 --shear 0 --out three --stats three.csv");
    csv = slurp_in(dir, "three.csv", NULL);
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_string_equal(cols[17], "0");
    assert_string_equal(cols[19], "nan");
    free(csv);
    remove_tree(dir);
}

/* --grow to --until-eta: the growth stops at the target exactly (to
 * rounding: 1e-12), the radii keep their ratio, the run goes on to its
 * last frame with the kinetic energy of the start (the heat taken out
 * when the growth stops; N kT = N m v^2 / 2 at the speed of 100). */
static void test_a_growth_stops_at_its_target_area_fraction(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "64 10 --mixture 1.4:0.5 --integrator event --periodic --grow 1 --until-eta 0.5 "
                  "--frames 50 --quiet --out g --stats g.csv");
    assert_true(exists_in(dir, "g/frame_0049.txt"));
    char *csv = slurp_in(dir, "g.csv", NULL), *cols[24];
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_true(fabs(strtod(cols[10], NULL) - 0.5) < 1e-12);
    assert_true(fabs(strtod(cols[2], NULL) / (64 * 5000.0) - 1.0) < 1e-12);
    free(csv);
    size_t counts[3];
    const double r = sqrt(0.5e6 / (3.14159265358979 * 32 * (1.0 + 1.96)));
    count_radii(dir, "g/frame_0049.txt", r, 1.4 * r, counts);
    assert_int_equal(counts[0], 32);
    assert_int_equal(counts[1], 32);
    remove_tree(dir);
}

/* --measure-after T: the rows after the frame at T average from it on,
 * to the bit what the library gives with ds_sim_reset_observables at that
 * step; and a restart from a checkpoint past T goes on with those
 * averages (it does not reset again), so its last row is the whole run's. */
static void test_measure_after_discards_the_start(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    const char *sys = "100 5 --seed 3 --integrator event --frames 11 --measure-after 0.5 --quiet";
    must_run(dir, "%s --out a --stats a.csv", sys);
    ds_params p = ds_params_default(100, 5.0);
    p.seed = 3;
    p.integrator = DS_INTEGRATOR_EVENT_DRIVEN;
    ds_sim *sim = NULL;
    assert_int_equal(ds_sim_create(&p, NULL, &sim, NULL), DS_OK);
    ds_sim_run(sim, 500, NULL); /* frame 5, t = 0.5: the reset */
    ds_sim_reset_observables(sim);
    ds_sim_run(sim, 500, NULL);
    char want[3][64];
    snprintf(want[0], sizeof want[0], "%llu", (unsigned long long)ds_sim_get_wall_count(sim));
    snprintf(want[1], sizeof want[1], "%.17g", ds_sim_get_pressure(sim));
    snprintf(want[2], sizeof want[2], "%.17g", ds_sim_get_virial_pressure(sim));
    ds_sim_destroy(sim);
    char *csv = slurp_in(dir, "a.csv", NULL), *cols[24];
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_string_equal(cols[6], want[0]);
    assert_string_equal(cols[7], want[1]);
    assert_string_equal(cols[8], want[2]);
    char whole[256];
    snprintf(whole, sizeof whole, "%s,%s,%s", cols[6], cols[7], cols[8]);
    free(csv);

    must_run(dir, "100 5 --seed 3 --integrator event --frames 8 --measure-after 0.5 --quiet "
                  "--out b --checkpoint b.ckpt");
    must_run(dir, "--restart b.ckpt --frames 3 --measure-after 0.5 --quiet --out b --stats b.csv");
    csv = slurp_in(dir, "b.csv", NULL);
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    char restarted[256];
    snprintf(restarted, sizeof restarted, "%s,%s,%s", cols[6], cols[7], cols[8]);
    assert_string_equal(restarted, whole);
    free(csv);
    remove_tree(dir);
}

/* --grow until it jams: the packing at the step that jammed is the run's
 * last frame (fewer frames than asked), with no overlap left (the
 * library's check when its checkpoint is read back), and the checkpoint
 * restarts onto the frames' times. */
static void test_a_growth_that_jams_ends_the_run_with_the_packing(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "16 64 --mixture 1.4:0.5 --integrator event --periodic --grow 0.2 --frames 200 "
                  "--quiet --out j --checkpoint j.ckpt --stats j.csv");
    char name[64];
    long last = -1;
    for (long k = 0; k < 200; ++k) {
        snprintf(name, sizeof name, "j/frame_%04ld.txt", k);
        if (exists_in(dir, name))
            last = k;
        else
            break;
    }
    assert_true(last > 0 && last < 199);
    snprintf(name, sizeof name, "j/frame_%04ld.txt", last + 1);
    assert_false(exists_in(dir, name));
    /* The last frame is the packing when it jammed, between two frames'
     * times (steps of 0.001, 100 to a frame). */
    char *csv = slurp_in(dir, "j.csv", NULL), *cols[24];
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_int_equal(strtol(cols[0], NULL, 10), last);
    const double jammed_at = strtod(cols[1], NULL);
    assert_true(jammed_at > 0.1 * (double)(last - 1) && jammed_at <= 0.1 * (double)last);
    free(csv);
    /* frames.json gives that frame's time, off the frames' spacing. */
    char *json = slurp_in(dir, "j/frames.json", NULL), want[64];
    assert_non_null(json);
    snprintf(want, sizeof want, "\"jammed_frame\": %ld,\n  \"jammed_time\": ", last);
    const char *at = strstr(json, want);
    if (!at)
        fail_msg("j/frames.json has no \"%s\": %s", want, json);
    /* The CSV's time has 6 decimals, frames.json all the digits. */
    assert_true(fabs(strtod(at + strlen(want), NULL) - jammed_at) <= 5e-7);
    free(json);
    /* The restart gets back onto the frames' times. */
    must_run(dir, "--restart j.ckpt --frames 2 --quiet --out j --stats r.csv");
    snprintf(name, sizeof name, "j/frame_%04ld.txt", last + 2);
    assert_true(exists_in(dir, name));
    csv = slurp_in(dir, "r.csv", NULL);
    assert_non_null(csv);
    assert_int_equal(last_row(csv, cols, 24), 20);
    assert_int_equal(strtol(cols[0], NULL, 10), last + 2);
    assert_true(fabs(strtod(cols[1], NULL) - 0.1 * (double)(last + 2)) < 1e-6);
    free(csv);
    remove_tree(dir);
}

/* A checkpoint damaged anywhere, or cut anywhere, is refused with one
 * line naming the library's reason, exit 1, nothing written. */
static void test_a_corrupted_checkpoint_is_refused_with_one_line(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "50 5 --frames 3 --quiet --out o --checkpoint c.ckpt");
    size_t size = 0;
    char *good = slurp_in(dir, "c.ckpt", &size);
    assert_non_null(good);
    assert_true(size > 64);
    const long places[] = {
        0, 7, 8, 12, 16, 31, 32, 40, (long)size / 2, (long)size - 9, (long)size - 1};
    for (size_t k = 0; k < 2 * (sizeof places / sizeof places[0]); ++k) {
        const long at = places[k / 2];
        const int cut = k % 2;
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/bad.ckpt", dir);
        assert_int_equal(write_bytes(path, good, cut ? (size_t)at : size), 0);
        if (!cut)
            assert_int_equal(damage(path, at, 0), 0);
        char err[4096];
        int status =
            run_disks_in(dir, "--restart bad.ckpt --frames 2 --quiet --out r", err, sizeof err);
        const char *nl = strchr(err, '\n');
        if (status != 1 || strncmp(err, "disks: cannot restart from bad.ckpt: ", 37) != 0 || !nl ||
            nl[1] != '\0' || exists_in(dir, "r"))
            fail_msg("checkpoint %s at byte %ld: status %d, stderr: %s", cut ? "cut" : "damaged",
                     at, status, err);
    }
    free(good);
    remove_tree(dir);
}

/* --out makes its directory before any output is opened, so an output may
 * be inside it. */
static void test_outputs_inside_a_new_out_directory_are_written(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "20 5 --frames 3 --quiet --out new/dir --trajectory new/dir/t.xyz "
                  "--stats new/s.csv --checkpoint new/dir/c.ckpt");
    assert_true(exists_in(dir, "new/dir/frame_0002.txt"));
    assert_true(exists_in(dir, "new/dir/c.ckpt"));
    char *xyz = slurp_in(dir, "new/dir/t.xyz", NULL), *stats = slurp_in(dir, "new/s.csv", NULL);
    assert_non_null(xyz);
    assert_non_null(stats);
    long frames = 0;
    for (const char *p = xyz; (p = strstr(p, "\n20\n")); ++p)
        ++frames;
    assert_int_equal(frames + (strncmp(xyz, "20\n", 3) == 0), 3);
    assert_non_null(strstr(stats, "\n2,"));
    free(xyz);
    free(stats);
    remove_tree(dir);
}

/* Frames an earlier, longer run left are refused, not mixed; --overwrite
 * removes them; the same command twice just works. */
static void test_frames_of_another_run_are_refused_unless_overwrite(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "20 5 --frames 5 --quiet --out out");
    must_run(dir, "20 5 --frames 5 --quiet --out out");
    char *before = slurp_in(dir, "out/frame_0004.txt", NULL), err[4096];
    assert_non_null(before);
    int status = run_disks_in(dir, "20 5 --frames 2 --seed 7 --quiet --out out", err, sizeof err);
    assert_int_equal(status, 1);
    assert_string_equal(err, "disks: out/ holds frame_0002.txt ... frame_0004.txt from another "
                             "run; remove them or pass --overwrite\n");
    char *after = slurp_in(dir, "out/frame_0004.txt", NULL);
    assert_non_null(after);
    assert_string_equal(before, after);
    free(before);
    free(after);
    must_run(dir, "20 5 --frames 2 --seed 7 --quiet --out out --overwrite");
    assert_true(exists_in(dir, "out/frame_0001.txt"));
    assert_false(exists_in(dir, "out/frame_0002.txt"));
    assert_false(exists_in(dir, "out/frame_0004.txt"));
    remove_tree(dir);
}

/* frames.json beside the frames says what the frames do not: the box,
 * the boundary, the frame spacing in time, the frame format and the
 * kinds, in the documented text (docs/cli.md). The frames themselves are
 * the same with it. */
static void test_a_run_describes_itself_in_frames_json(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
    must_run(dir, "20 5 --frames 2 --steps-per-frame 7 --dt 0.002 --box-y 500 --periodic "
                  "--mixture 1.4:0.5 --velocities --quiet --out out");
    char *json = slurp_in(dir, "out/frames.json", NULL);
    assert_non_null(json);
    assert_string_equal(json, "{\n"
                              "  \"disksim_frames\": 1,\n"
                              "  \"n\": 20,\n"
                              "  \"radius\": 5,\n"
                              "  \"box\": [1000, 500],\n"
                              "  \"boundary\": \"periodic\",\n"
                              "  \"dt\": 0.002,\n"
                              "  \"steps_per_frame\": 7,\n"
                              "  \"integrator\": \"step\",\n"
                              "  \"velocities\": true,\n"
                              "  \"kinds\": [\"A\", \"B\"]\n"
                              "}\n");
    free(json);
    must_run(dir, "10 5 --frames 1 --boundary channel --integrator event --quiet --out two");
    json = slurp_in(dir, "two/frames.json", NULL);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"boundary\": \"channel\",\n"));
    assert_non_null(strstr(json, "\"integrator\": \"event\",\n  \"velocities\": false\n}\n"));
    free(json);
    remove_tree(dir);
}

/* A directory whose frames.json describes another run holds that run's
 * frames, all of them: refused (not replaced one by one, mixing two runs
 * until the last is written), or removed with --overwrite; a restart into
 * it is refused. A frames.json that is not disksim's is not replaced. */
static void test_frames_described_as_another_runs_are_refused_unless_overwrite(void **state)
{
    (void)state;
    char dir[] = "/tmp/ds_test_cli_XXXXXX", err[4096];
    assert_non_null(mkdtemp(dir));
    must_run(dir, "20 5 --frames 5 --box-y 500 --quiet --out out");
    int status = run_disks_in(dir, "20 5 --frames 5 --quiet --out out", err, sizeof err);
    assert_int_equal(status, 1);
    assert_string_equal(err, "disks: out/ holds frame_0000.txt ... frame_0004.txt from another run "
                             "(its frames.json has box [1000, 500], this run's [1000, 1000]); "
                             "remove them or pass --overwrite\n");
    must_run(dir, "20 5 --frames 2 --quiet --out out --overwrite");
    assert_true(exists_in(dir, "out/frame_0001.txt"));
    assert_false(exists_in(dir, "out/frame_0002.txt"));
    char *json = slurp_in(dir, "out/frames.json", NULL);
    assert_non_null(strstr(json, "\"box\": [1000, 1000],"));
    free(json);
    /* A restart goes on only beside its own run's frames. */
    must_run(dir, "20 5 --frames 4 --quiet --out a --checkpoint c.ckpt");
    status = run_disks_in(dir, "--restart c.ckpt --frames 1 --quiet --out out", err, sizeof err);
    assert_int_equal(status, 0);
    must_run(dir, "20 5 --frames 2 --velocities --quiet --out b");
    status = run_disks_in(dir, "--restart c.ckpt --frames 1 --quiet --out b", err, sizeof err);
    assert_int_equal(status, 1);
    assert_string_equal(err, "disks: cannot restart from c.ckpt into b/: its frames.json has "
                             "velocities true, this run's false: give another --out\n");
    /* Someone else's frames.json. */
    assert_int_equal(mkdir(path_in_dir(dir, "mine"), 0755), 0);
    write_text_in(dir, "mine/frames.json", "{\"not\": \"disksim\"}\n");
    status = run_disks_in(dir, "20 5 --frames 1 --quiet --out mine", err, sizeof err);
    assert_int_equal(status, 1);
    assert_string_equal(err, "disks: mine/frames.json is not a disksim run's description; move it "
                             "or pass --overwrite\n");
    json = slurp_in(dir, "mine/frames.json", NULL);
    assert_string_equal(json, "{\"not\": \"disksim\"}\n");
    free(json);
    remove_tree(dir);
}

/* The table of docs/cli.md is generated from this list (make bad-input-table):
 * a case added, renamed or removed without regenerating it fails here. */
static void test_the_cli_doc_table_lists_every_case(void **state)
{
    (void)state;
    const char *path = getenv("DS_CLI_DOC");
    FILE *f = fopen(path && *path ? path : DS_TEST_CLI_DOC, "r");
    if (!f) {
        print_message("skipped: no %s to check\n", DS_TEST_CLI_DOC);
        skip();
    }
    static char text[1 << 18];
    size_t len = fread(text, 1, sizeof text - 1, f);
    text[len] = '\0';
    fclose(f);
    const char *begin = strstr(text, "<!-- bad-input-table:");
    const char *end = begin ? strstr(begin, "<!-- end bad-input-table -->") : NULL;
    assert_non_null(begin);
    assert_non_null(end);
    size_t rows = 0;
    for (const char *p = strstr(begin, "\n| "); p && p < end; p = strstr(p + 1, "\n| "))
        ++rows;
    for (size_t i = 0; i < case_count; ++i) {
        char row[1024];
        row_start(&cases[i], row, sizeof row);
        const char *hit = strstr(begin, row);
        if (!hit || hit > end)
            fail_msg(DS_TEST_CLI_DOC
                     " has no row for cli_cases.txt:%d \"%s\": run make bad-input-table",
                     cases[i].line, cases[i].name);
    }
    /* Rows = header + one per case: no row for a case that was removed. */
    assert_int_equal(rows, case_count + 1);
}

static void test_help_documents_the_exit_statuses(void **state)
{
    (void)state;
    char cmd[PATH_MAX + 32];
    snprintf(cmd, sizeof cmd, "'%s' --help", disks_path);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    char text[16384]; /* all of it (4.4 kB), or disks dies of SIGPIPE */
    size_t n = fread(text, 1, sizeof text - 1, p);
    text[n] = '\0';
    assert_int_equal(pclose(p), 0);
    assert_non_null(strstr(text, "1 run-time error"));
    assert_non_null(strstr(text, "2 usage error"));
}

/* ------------------------------------------------------------------ */
/* The table of docs/cli.md                                            */
/* ------------------------------------------------------------------ */

/* Appends s to out as table cell text: one line, '|' escaped, no '`'. */
static void append_cell(char *out, size_t cap, const char *s)
{
    size_t n = strlen(out);
    for (; *s && *s != '\n' && n + 3 < cap; ++s) {
        if (*s == '|')
            out[n++] = '\\';
        out[n++] = *s == '`' ? '\'' : *s;
    }
    out[n] = '\0';
}

/* "| case | `command` |": the part of a row that does not depend on where
 * the test runs. */
static void row_start(const cli_case *c, char *out, size_t cap)
{
    snprintf(out, cap, "| ");
    append_cell(out, cap, c->name);
    strncat(out, " | `", cap - strlen(out) - 1);
    append_cell(out, cap, c->command);
    strncat(out, "` |", cap - strlen(out) - 1);
}

static int print_table(void)
{
    int bad = 0;
    puts("| Case | Command | Exit | Message on stderr |");
    puts("|---|---|---|---|");
    for (size_t i = 0; i < case_count; ++i) {
        outcome o;
        run_case(&cases[i], &o);
        char row[1024];
        row_start(&cases[i], row, sizeof row);
        if (o.ran) {
            snprintf(row + strlen(row), sizeof row - strlen(row), " %d | `", o.status);
            append_cell(row, sizeof row, o.err);
            strncat(row, "` |", sizeof row - strlen(row) - 1);
        } else {
            strncat(row, " - | ", sizeof row - strlen(row) - 1);
            append_cell(row, sizeof row, o.problem[0] ? o.problem : o.skip_reason);
            strncat(row, " |", sizeof row - strlen(row) - 1);
        }
        puts(row);
        if (o.problem[0]) {
            fprintf(stderr, "test_cli: cli_cases.txt:%d \"%s\": %s\n", cases[i].line, cases[i].name,
                    o.problem);
            bad = 1;
        }
    }
    return bad;
}

static void resolve(char *out, const char *env, const char *fallback)
{
    const char *p = getenv(env);
    if (!p || !*p)
        p = fallback;
    /* Cases run in their own directory: make the path absolute now. */
    if (!realpath(p, out))
        snprintf(out, PATH_MAX, "%s", p);
}

int main(int argc, char **argv)
{
    resolve(disks_path, "DS_DISKS", DS_TEST_DISKS);
    resolve(render_path, "DS_RENDER", DS_TEST_RENDER);
    const char *cases_path = getenv("DS_CLI_CASES");
    if (load_cases(cases_path && *cases_path ? cases_path : DS_TEST_CASES) != 0)
        return 1;
    if (argc > 1 && strcmp(argv[1], "--table") == 0)
        return print_table();

    const struct CMUnitTest first[] = {
        cmocka_unit_test(test_a_good_run_writes_only_complete_frames),
        cmocka_unit_test(test_one_disk_of_almost_half_the_box_runs),
        cmocka_unit_test(test_help_documents_the_exit_statuses),
    };
    const struct CMUnitTest survive[] = {
        cmocka_unit_test(test_a_restart_writes_the_frames_of_an_uninterrupted_run),
        cmocka_unit_test(test_an_interrupted_run_keeps_its_trajectory_and_writes_its_checkpoint),
        cmocka_unit_test(test_a_second_signal_ends_the_run_at_once_keeping_the_trajectory),
        cmocka_unit_test(test_a_killed_run_leaves_a_checkpoint_that_restarts),
        cmocka_unit_test(test_a_restart_without_options_goes_on_with_the_run),
        cmocka_unit_test(test_the_box_speed_dt_and_area_fraction_options_reach_the_run),
        cmocka_unit_test(test_a_checkpoint_without_settings_restarts_with_the_defaults),
        cmocka_unit_test(test_a_run_starts_from_a_frame_written_with_velocities),
        cmocka_unit_test(test_a_corrupted_checkpoint_is_refused_with_one_line),
        cmocka_unit_test(test_outputs_inside_a_new_out_directory_are_written),
        cmocka_unit_test(test_frames_of_another_run_are_refused_unless_overwrite),
        cmocka_unit_test(test_a_run_describes_itself_in_frames_json),
        cmocka_unit_test(test_frames_described_as_another_runs_are_refused_unless_overwrite),
        cmocka_unit_test(test_a_mixture_run_writes_its_two_radii),
        cmocka_unit_test(test_a_granular_run_writes_its_energy_books),
        cmocka_unit_test(test_a_growth_stops_at_its_target_area_fraction),
        cmocka_unit_test(test_a_growth_that_jams_ends_the_run_with_the_packing),
        cmocka_unit_test(test_measure_after_discards_the_start),
        cmocka_unit_test(test_a_sheared_run_writes_its_stress_and_viscosity),
        cmocka_unit_test(test_a_restart_without_shear_goes_on_shearing),
    };
    /* Sized for what goes in: a fixed array overflowed once the cases
     * outgrew its slack (a garbage test name, cases overwritten). */
    const size_t n_first = sizeof first / sizeof first[0];
    const size_t n_survive = sizeof survive / sizeof survive[0];
    struct CMUnitTest *tests = calloc(n_first + n_survive + 1 + case_count, sizeof *tests);
    if (!tests)
        return 1;
    size_t n = 0;
    for (size_t k = 0; k < n_first; ++k)
        tests[n++] = first[k];
    for (size_t k = 0; k < n_survive; ++k)
        tests[n++] = survive[k];
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_the_cli_doc_table_lists_every_case);
    for (size_t i = 0; i < case_count; ++i) {
        struct CMUnitTest t = cmocka_unit_test_prestate(test_bad_input_case, &cases[i]);
        t.name = cases[i].name;
        tests[n++] = t;
    }
    const int failed = _cmocka_run_group_tests("test_cli", tests, n, NULL, NULL);
    free(tests);
    return failed;
}
