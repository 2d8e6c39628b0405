/* SPDX-License-Identifier: MIT */
/* Everyday use: the man page renders cleanly and says what `disks --help`
 * says, --version is the header's version, and the progress line appears on
 * a terminal, is erased at the end, and never reaches a pipe or a file.
 * Run from the top directory (make test does). */
#define _XOPEN_SOURCE 700 /* posix_openpt, grantpt, unlockpt, ptsname */
#include "test_util.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef DS_TEST_DISKS
#define DS_TEST_DISKS "disks"
#endif
/* DS_TEST_DISKS is relative to the top directory; the shell needs the ./ */
#define DISKS_COMMAND "./" DS_TEST_DISKS
#define MAN_PAGE "man/disks.1"

/* Runs a shell command and returns everything it wrote to stdout (malloc'd);
 * *status receives its exit status (127 when the shell cannot find it). */
static char *run_capture(const char *command, int *status)
{
    FILE *p = popen(command, "r");
    assert_non_null(p);
    size_t len = 0, cap = 4096;
    char *out = malloc(cap);
    assert_non_null(out);
    size_t got;
    while ((got = fread(out + len, 1, cap - len - 1, p)) > 0) {
        len += got;
        if (cap - len < 2) {
            cap *= 2;
            out = realloc(out, cap);
            assert_non_null(out);
        }
    }
    out[len] = '\0';
    int rc = pclose(p);
    *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    return out;
}

static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    assert_true(size > 0);
    rewind(f);
    char *text = malloc((size_t)size + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)size, f), (size_t)size);
    text[size] = '\0';
    fclose(f);
    return text;
}

static void test_man_page_renders_without_any_groff_warning(void **state)
{
    (void)state;
    int status;
    /* -ww enables every warning class; -z formats without output, so all
     * that reaches the pipe is diagnostics. */
    char *diagnostics = run_capture("groff -man -Tutf8 -ww -z " MAN_PAGE " 2>&1", &status);
    if (status == 127)
        fail_msg("groff is not installed (Debian: groff-base)");
    if (diagnostics[0] != '\0')
        fail_msg("groff warnings for " MAN_PAGE ":\n%s", diagnostics);
    assert_int_equal(status, 0);
    free(diagnostics);
}

static void test_man_page_has_the_sections_a_reader_expects(void **state)
{
    (void)state;
    const char *sections[] = {"NAME",  "SYNOPSIS",    "DESCRIPTION", "OPTIONS",
                              "FILES", "EXIT STATUS", "EXAMPLES"};
    char *page = read_text(MAN_PAGE);
    for (size_t k = 0; k < sizeof sections / sizeof sections[0]; ++k) {
        char heading[64];
        snprintf(heading, sizeof heading, "\n.SH %s\n", sections[k]);
        if (!strstr(page, heading))
            fail_msg(MAN_PAGE " has no section %s", sections[k]);
    }
    free(page);
}

/* Every --option that `disks --help` lists appears in the man page as a
 * roff option (hyphens written \-), so the two cannot drift apart. */
static void test_man_page_describes_every_option_of_help(void **state)
{
    (void)state;
    int status;
    char *help = run_capture(DISKS_COMMAND " --help", &status);
    assert_int_equal(status, 0);
    char *page = read_text(MAN_PAGE);
    int options = 0;
    for (const char *s = help; (s = strstr(s, "--")) != NULL;) {
        char roff[128] = "";
        size_t w = 0;
        while (w + 3 < sizeof roff && (*s == '-' || (*s >= 'a' && *s <= 'z'))) {
            if (*s == '-')
                roff[w++] = '\\';
            roff[w++] = *s++;
        }
        roff[w] = '\0';
        if (!strstr(page, roff))
            fail_msg("disks --help lists %s, which " MAN_PAGE " does not describe", roff);
        ++options;
    }
    assert_true(options >= 10); /* the help really was parsed */
    free(help);
    free(page);
}

static void test_man_page_and_version_option_show_the_header_version(void **state)
{
    (void)state;
    int status;
    char *version = run_capture(DISKS_COMMAND " --version", &status);
    assert_int_equal(status, 0);
    assert_string_equal(version, "disks " DS_VERSION_STRING "\n");
    assert_string_equal(ds_version(), DS_VERSION_STRING);
    char *page = read_text(MAN_PAGE);
    char *th = strstr(page, "\n.TH ");
    assert_non_null(th);
    *strchr(th + 1, '\n') = '\0';
    if (!strstr(th, "\"disksim " DS_VERSION_STRING "\""))
        fail_msg("the .TH line of " MAN_PAGE " does not name disksim " DS_VERSION_STRING ": %s",
                 th + 1);
    free(version);
    free(page);
}

/* Runs disks N=20 R=5 for 4 frames in a fresh directory with stderr on
 * fd and stdout discarded; returns the exit status. */
static int run_disks_with_stderr(int fd, const char *extra)
{
    char dir[] = "/tmp/ds_packaging_XXXXXX";
    assert_non_null(mkdtemp(dir));
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        int devnull = open("/dev/null", O_WRONLY);
        dup2(devnull, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        if (extra)
            execl(DS_TEST_DISKS, DS_TEST_DISKS, "20", "5", "--frames", "4", "--steps-per-frame",
                  "10", "--out", dir, extra, (char *)NULL);
        else
            execl(DS_TEST_DISKS, DS_TEST_DISKS, "20", "5", "--frames", "4", "--steps-per-frame",
                  "10", "--out", dir, (char *)NULL);
        _exit(127);
    }
    int status = 0;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    assert_int_equal(system(cmd), 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* Opens a pseudo-terminal; *slave is the terminal end a program writes to. */
static int open_terminal(int *slave)
{
    int master = posix_openpt(O_RDWR | O_NOCTTY);
    assert_true(master >= 0);
    assert_int_equal(grantpt(master), 0);
    assert_int_equal(unlockpt(master), 0);
    *slave = open(ptsname(master), O_RDWR | O_NOCTTY);
    assert_true(*slave >= 0);
    return master;
}

/* Everything written to the terminal until the last writer closed it. */
static size_t read_terminal(int master, char *buf, size_t cap)
{
    size_t len = 0;
    for (;;) {
        ssize_t got = read(master, buf + len, cap - 1 - len);
        if (got > 0 && len + (size_t)got < cap - 1) {
            len += (size_t)got;
            continue;
        }
        if (got < 0 && errno == EINTR)
            continue;
        break; /* Linux reports EIO once no process holds the terminal end */
    }
    buf[len] = '\0';
    return len;
}

static void test_progress_line_on_a_terminal_is_redrawn_and_erased_at_the_end(void **state)
{
    (void)state;
    int slave;
    int master = open_terminal(&slave);
    /* The terminal buffers what disks writes, so the child never blocks on
     * it before the parent reads: 4 progress lines are a few hundred bytes. */
    assert_int_equal(run_disks_with_stderr(slave, NULL), 0);
    close(slave);
    char out[8192];
    size_t len = read_terminal(master, out, sizeof out);
    close(master);
    assert_non_null(strstr(out, "\rframe 1 of 4"));
    assert_non_null(strstr(out, "\rframe 4 of 4"));
    assert_non_null(strstr(out, "steps/s"));
    assert_non_null(strstr(out, "s left"));
    /* Carriage return then erase-to-end-of-line: the prompt or the summary
     * that follows starts on a clean line. */
    const char *erase = "\r\033[K";
    assert_true(len >= strlen(erase));
    assert_string_equal(out + len - strlen(erase), erase);
    assert_null(strchr(out, '\n')); /* redrawn in place, never scrolled */
}

static void test_no_progress_on_a_terminal_with_quiet(void **state)
{
    (void)state;
    int slave;
    int master = open_terminal(&slave);
    assert_int_equal(run_disks_with_stderr(slave, "--quiet"), 0);
    close(slave);
    char out[8192];
    size_t len = read_terminal(master, out, sizeof out);
    close(master);
    if (len != 0)
        fail_msg("disks --quiet wrote to the terminal: \"%s\"", out);
}

static void test_no_progress_when_stderr_is_a_file(void **state)
{
    (void)state;
    FILE *log = tmpfile();
    assert_non_null(log);
    assert_int_equal(run_disks_with_stderr(fileno(log), NULL), 0);
    assert_int_equal(fseek(log, 0, SEEK_END), 0);
    assert_int_equal(ftell(log), 0); /* a CI log gets no control characters */
    fclose(log);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_man_page_renders_without_any_groff_warning),
        cmocka_unit_test(test_man_page_has_the_sections_a_reader_expects),
        cmocka_unit_test(test_man_page_describes_every_option_of_help),
        cmocka_unit_test(test_man_page_and_version_option_show_the_header_version),
        cmocka_unit_test(test_progress_line_on_a_terminal_is_redrawn_and_erased_at_the_end),
        cmocka_unit_test(test_no_progress_on_a_terminal_with_quiet),
        cmocka_unit_test(test_no_progress_when_stderr_is_a_file),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
