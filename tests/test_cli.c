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
#define MAX_ARGS 24
#define MAX_CASES 128
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
        if (lstat(full, &st) == 0 && S_ISDIR(st.st_mode))
            continue; /* --out directories are created before the failure */
        const char *slash = strrchr(after[i], '/');
        const char *base = slash ? slash + 1 : after[i];
        ds_frame frame;
        if (base[0] == '.')
            snprintf(o->problem, sizeof o->problem, "temporary file '%s' left behind", after[i]);
        else if (c->exit_code == 2)
            snprintf(o->problem, sizeof o->problem, "a usage error wrote '%s'", after[i]);
        else if (!is_frame_name(base))
            snprintf(o->problem, sizeof o->problem, "unexpected file '%s' left behind", after[i]);
        else if (ds_read_frame(full, &frame, NULL) != DS_OK)
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

/* Starts disks writing frames and a trajectory as fast as it can, waits
 * for a few frames, interrupts it and checks that only complete frames
 * remain (the trajectory's temporary removed, none renamed into place). Whether the
 * signal lands inside a write is luck, so it is tried several times; the
 * invariant must hold every time. */
static void interrupt_a_run(int sig)
{
    char dir[] = "/tmp/ds_test_cli_XXXXXX";
    assert_non_null(mkdtemp(dir));
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
        alarm(CASE_TIMEOUT_SECONDS);
        execl(disks_path, disks_path, "3000", "2", "--frames", "10000", "--steps-per-frame", "1",
              "--quiet", "--out", "out", "--trajectory", "t.xyz", (char *)NULL);
        _exit(126);
    }
    /* Poll (no timing is asserted: the alarm above bounds a stuck run). */
    char third[PATH_MAX];
    snprintf(third, sizeof third, "%s/out/frame_0003.txt", dir);
    int ws = 0;
    pid_t done = 0;
    while (access(third, F_OK) != 0 && (done = waitpid(pid, &ws, WNOHANG)) == 0)
        nanosleep(&(struct timespec){0, 1000000}, NULL);
    if (done == 0) {
        kill(pid, sig);
        while ((done = waitpid(pid, &ws, 0)) < 0 && errno == EINTR)
            ;
    }
    /* Say what happened when the run did not end by the signal: a disks
     * error before it (exit status; stderr went to /dev/null, so rerun the
     * command by hand), or the child lost to waitpid. */
    if (done != pid)
        fail_msg("signal %d: waitpid returned %d (%s)", sig, (int)done, strerror(errno));
    if (!WIFSIGNALED(ws))
        fail_msg("signal %d: disks exited with status %d, not by the signal", sig,
                 WIFEXITED(ws) ? WEXITSTATUS(ws) : -1);
    assert_int_equal(WTERMSIG(ws), sig);

    cli_case run = {"interrupted", 1, "", "-", "", 0};
    outcome o;
    memset(&o, 0, sizeof o);
    check_leftovers(&run, dir, NULL, 0, &o);
    remove_tree(dir);
    if (o.problem[0])
        fail_msg("after signal %d: %s", sig, o.problem);
    assert_true(o.frames >= 4);
}

static void test_an_interrupted_run_leaves_only_complete_frames(void **state)
{
    (void)state;
    for (int k = 0; k < 3; ++k) {
        interrupt_a_run(SIGINT);
        interrupt_a_run(SIGTERM);
    }
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
    char text[4096];
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

    static struct CMUnitTest tests[MAX_CASES + 5];
    size_t n = 0;
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_a_good_run_writes_only_complete_frames);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_one_disk_of_almost_half_the_box_runs);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_help_documents_the_exit_statuses);
    tests[n++] =
        (struct CMUnitTest)cmocka_unit_test(test_an_interrupted_run_leaves_only_complete_frames);
    tests[n++] = (struct CMUnitTest)cmocka_unit_test(test_the_cli_doc_table_lists_every_case);
    for (size_t i = 0; i < case_count; ++i) {
        struct CMUnitTest t = cmocka_unit_test_prestate(test_bad_input_case, &cases[i]);
        t.name = cases[i].name;
        tests[n++] = t;
    }
    return _cmocka_run_group_tests("test_cli", tests, n, NULL, NULL);
}
