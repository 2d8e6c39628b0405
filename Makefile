# SPDX-License-Identifier: MIT
# disksim: plain make. `make` builds libdisksim.a and disks; `make test`
# builds and runs the cmocka suite. Honours CC, CFLAGS, CPPFLAGS, LDFLAGS.

CC      ?= cc
CFLAGS  ?= -O2 -g
# pkg-config is optional: without it cmocka is linked as -lcmocka and the
# renderer is skipped with a note that names it, never a shell error.
PKG_CONFIG ?= pkg-config
HAVE_PKG_CONFIG := $(shell command -v $(PKG_CONFIG) >/dev/null 2>&1 && echo y)
WARN    := -std=c99 -Wall -Wextra -Wpedantic
CPPFLAGS += -Iinclude -Isrc
LDLIBS  += -lm
AR      ?= ar

# SANITIZE=1 rebuilds everything with AddressSanitizer and UBSan in its own
# directory (build-san/, giving build-san/libdisksim.a and build-san/disks),
# so no uninstrumented object is ever reused and the plain build is left
# alone. Any other BUILD=dir likewise keeps objects and outputs inside dir
# (CI uses that for its -Werror builds under gcc and clang).
ifeq ($(SANITIZE),1)
  BUILD   ?= build-san
  # gcc leaves float-cast-overflow out of "undefined": (uint64_t)2e19 is UB.
  CFLAGS  += -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer \
             -fno-sanitize-recover=all
  LDFLAGS += -fsanitize=address,undefined,float-cast-overflow
  # Mesa never frees its per-process driver state: only that is suppressed.
  export LSAN_OPTIONS := suppressions=$(CURDIR)/tests/lsan.supp:print_suppressions=0
  # OSMesa's llvmpipe renders with a pool of threads; LeakSanitizer stops
  # every thread at a program's exit, and its tracer once crashed there
  # (signal 11, "LeakSanitizer has encountered a fatal error") in the
  # sanitized renderer's test. One rasterizer thread draws the same pixels.
  export LP_NUM_THREADS := 0
endif
BUILD ?= build
OUT   := $(if $(filter build,$(BUILD)),,$(BUILD)/)
LIB   := $(OUT)libdisksim.a
DISKS := $(OUT)disks

# The library is every file of the folders of src/ (docs/architecture.md):
# core/ (what every part shares: the disk arrays, the grid, the box),
# timestep/, event/ and chain/ (the integrators), init/ (placement), observe/
# (observables), io/ (text formats), and sim/ (the public API of the
# simulation, over the parts). The command is every file of cli/.
LIB_DIRS := core timestep event chain protocols init observe io sim
LIB_SRC := $(sort $(foreach d,$(LIB_DIRS),$(wildcard src/$(d)/*.c)))
LIB_OBJ := $(LIB_SRC:src/%.c=$(BUILD)/%.o)

.PHONY: all test clean
all: $(LIB) $(DISKS)

$(BUILD):
	@mkdir -p $(BUILD)

# Objects record the flags they were built with: a changed CC, CFLAGS or
# LDFLAGS (a sanitizer, -Werror) rebuilds them instead of mixing old and new.
FLAGS_STAMP := $(BUILD)/flags.stamp
FLAGS_NOW   := $(CC) $(CFLAGS) $(CPPFLAGS) $(LDFLAGS)
$(shell mkdir -p $(BUILD); [ "$$(cat $(FLAGS_STAMP) 2>/dev/null)" = "$(FLAGS_NOW)" ] || \
    echo "$(FLAGS_NOW)" > $(FLAGS_STAMP))

# The public headers: disk_sim.h and the headers it includes, one per
# concept (include/disksim/).
PUB_HDR := include/disk_sim.h $(sort $(wildcard include/disksim/*.h))
LIB_HDR := $(PUB_HDR) $(wildcard src/*/*.h)
$(BUILD)/%.o: src/%.c $(LIB_HDR) $(FLAGS_STAMP) | $(BUILD)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

CLI_OBJ := $(patsubst cli/%.c,$(BUILD)/cli/%.o,$(sort $(wildcard cli/*.c)))
$(BUILD)/cli/%.o: cli/%.c $(PUB_HDR) $(wildcard cli/*.h) $(FLAGS_STAMP) | $(BUILD)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $^

$(DISKS): $(CLI_OBJ) $(LIB)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# ---------------------------------------------------------------- tests
CMOCKA_CFLAGS := $(if $(HAVE_PKG_CONFIG),$(shell $(PKG_CONFIG) --cflags cmocka 2>/dev/null))
CMOCKA_LIBS   := $(or $(if $(HAVE_PKG_CONFIG),$(shell $(PKG_CONFIG) --libs cmocka 2>/dev/null)),-lcmocka)
# test_render needs GL and libpng: its own rule, in the renderer section.
TEST_SRC := $(filter-out tests/test_render.c,$(wildcard tests/test_*.c))
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
# test_cli runs the disks and render of this build (relative to the top).
TEST_DEFS := -DDS_TEST_DISKS='"$(DISKS)"' -DDS_TEST_RENDER='"$(OUT)tools/render"' \
             -DDS_TEST_GR='"$(OUT)tools/gr"'

$(BUILD)/tests/%: tests/%.c tests/test_util.h $(LIB) $(LIB_HDR)
	@mkdir -p $(BUILD)/tests
	$(CC) $(WARN) $(CPPFLAGS) $(TEST_DEFS) $(CMOCKA_CFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ $< \
	    $(LIB) $(CMOCKA_LIBS) $(LDLIBS)

# test_alloc_failure counts the library's allocations and fails each in
# turn through the linker (--wrap, GNU ld and lld): its own link flags.
ALLOC_WRAP := -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=posix_memalign \
              -Wl,--wrap=aligned_alloc
$(BUILD)/tests/test_alloc_failure: tests/test_alloc_failure.c tests/test_util.h $(LIB) $(LIB_HDR)
	@mkdir -p $(BUILD)/tests
	$(CC) $(WARN) $(CPPFLAGS) $(CMOCKA_CFLAGS) $(CFLAGS) $(LDFLAGS) $(ALLOC_WRAP) -o $@ $< \
	    $(LIB) $(CMOCKA_LIBS) $(LDLIBS)

# After the C programs: the sweeps' scripts on small sweeps
# (tests/eos_sweep.sh and tests/analysis_sweeps.sh, seconds), the plot
# scripts (tests/plots.sh: PDF beside PNG, the state point), and the Python module's pytest
# suite (python-test, below), which says in one line what it lacks instead
# when a Python package is missing.
test: all $(TEST_BIN)
	@fail=0; for t in $(TEST_BIN); do \
	    echo "== $$t"; ./$$t || fail=1; \
	done; \
	echo "== tests/eos_sweep.sh"; \
	PRESSURE="$(CURDIR)/$(OUT)tools/pressure" sh tests/eos_sweep.sh || fail=1; \
	echo "== tests/analysis_sweeps.sh"; \
	DISKS="$(CURDIR)/$(DISKS)" TRANSPORT="$(CURDIR)/$(OUT)tools/transport" \
	    sh tests/analysis_sweeps.sh || fail=1; \
	echo "== tests/plots.sh"; \
	DISKS="$(CURDIR)/$(DISKS)" GR="$(CURDIR)/$(OUT)tools/gr" sh tests/plots.sh || fail=1; \
	echo "== tests/migrate.sh"; \
	PYTHON="$(PYTHON)" CC="$(CC)" CFLAGS="$(CFLAGS)" LDFLAGS="$(LDFLAGS)" sh tests/migrate.sh $(LIB) || fail=1; \
	$(MAKE) --no-print-directory python-test || fail=1; \
	if [ $$fail -ne 0 ]; then echo "make test: some tests FAILED"; exit 1; fi; \
	echo "make test: all test programs passed"

# ---------------------------------------------------------------- docs
# Docs that cannot rot, checked by `make test` (and alone by `make
# check-docs`): tests/check_docs.sh checks that the links of README.md and
# docs/ resolve, that every option the programs print in --help is in their
# man page and docs/ page and no other option is, that example commands use
# real options, that the README's library example is examples/minimal.c,
# that the API is named in man/disk_sim.3 and docs/library.md, and that the
# man pages render without a warning. It prints what is wrong and fails.
.PHONY: check-docs
check-docs: all
	sh tests/check_docs.sh $(DISKS) $(OUT)tools/render $(OUT)tools/gr $(OUT)tools/pressure \
	    $(OUT)tools/transport $(OUT)tools/rheology
test: check-docs

# The structure docs/architecture.md promises (tests/check_structure.sh):
# no two files of the library calling each other round a circle, no file
# above 500 lines, no function above 80 without a "Long:" reason.
.PHONY: check-structure
check-structure: $(LIB)
	sh tests/check_structure.sh $(BUILD)
test: check-structure

# ---------------------------------------------------------------- hardening
.PHONY: fuzz check-symbols bad-input-table

# libFuzzer over the frame reader, seeded from tests/corpus/ (crashes are
# written there as crash-<sha1>: commit them, test_frame_corpus replays them).
# The library sources are compiled into the harness so they are instrumented.
FUZZ_CC      ?= clang
FUZZ_SECONDS ?= 30
build-fuzz/fuzz_frame: tests/fuzz_frame.c $(LIB_SRC) $(LIB_HDR)
	@mkdir -p build-fuzz/found
	$(FUZZ_CC) $(WARN) $(CPPFLAGS) -g -O1 -fsanitize=fuzzer,address,undefined \
	    -fno-sanitize-recover=all -o $@ tests/fuzz_frame.c $(LIB_SRC) -lm

# The checkpoint loader likewise (tests/fuzz_state.c), seeded with small
# checkpoints of every integrator, boundary and broad phase that
# tests/state_seeds.c writes; crashes go to tests/corpus-state/.
build-fuzz/fuzz_state: tests/fuzz_state.c $(LIB_SRC) $(LIB_HDR)
	@mkdir -p build-fuzz/state-found
	$(FUZZ_CC) $(WARN) $(CPPFLAGS) -g -O1 -fsanitize=fuzzer,address,undefined \
	    -fno-sanitize-recover=all -o $@ tests/fuzz_state.c $(LIB_SRC) -lm

build-fuzz/state_seeds: tests/state_seeds.c $(LIB)
	@mkdir -p build-fuzz/state-seeds
	$(CC) $(WARN) $(CPPFLAGS) $(CFLAGS) -o $@ $< $(LIB) $(LDLIBS)

fuzz: fuzz-frame fuzz-state
.PHONY: fuzz-frame fuzz-state
fuzz-state: build-fuzz/fuzz_state build-fuzz/state_seeds
	./build-fuzz/state_seeds build-fuzz/state-seeds
	@mkdir -p tests/corpus-state
	./build-fuzz/fuzz_state -max_total_time=$(FUZZ_SECONDS) -max_len=8192 -timeout=10 \
	    -rss_limit_mb=1024 -print_final_stats=1 -artifact_prefix=tests/corpus-state/ \
	    build-fuzz/state-found build-fuzz/state-seeds tests/corpus-state

fuzz-frame: build-fuzz/fuzz_frame
	./build-fuzz/fuzz_frame -max_total_time=$(FUZZ_SECONDS) -max_len=2048 -timeout=10 \
	    -rss_limit_mb=1024 -print_final_stats=1 -artifact_prefix=tests/corpus/ \
	    -dict=tests/fuzz_frame.dict \
	    build-fuzz/found tests/corpus

# Library hygiene: every exported symbol starts with ds_, the shared
# library exports exactly the functions of the public headers, and the
# library never prints or ends the process (it returns a ds_status instead).
check-symbols: $(LIB) $(OUT)$(SHLIB) $(BUILD)/exports.map
	@bad=$$(nm -g --defined-only $(LIB) | awk 'NF == 3 && $$3 !~ /^ds_/ { print $$3 }'); \
	if [ -n "$$bad" ]; then echo "check-symbols: exported without ds_ prefix:" $$bad; exit 1; fi; \
	nm -D --defined-only $(OUT)$(SHLIB) | awk '$$2 == "T" { print $$3 }' | sort > $(BUILD)/exported; \
	sed -n 's/^    \(ds_[a-z0-9_]*\);$$/\1/p' $(BUILD)/exports.map | sort > $(BUILD)/declared; \
	if ! cmp -s $(BUILD)/declared $(BUILD)/exported; then \
	    echo "check-symbols: $(SHLIB) exports other functions than the public headers declare:"; \
	    diff $(BUILD)/declared $(BUILD)/exported; exit 1; fi; \
	calls=$$(nm -u $(LIB) | awk '{ print $$2 }' | grep -E '^(exit|_exit|_Exit|abort|__assert_fail|printf|vprintf|fprintf|vfprintf|puts|fputs|putchar|fputc|perror)$$' | sort -u); \
	if [ -n "$$calls" ]; then echo "check-symbols: the library calls" $$calls; exit 1; fi; \
	echo "check-symbols: $$(nm -g --defined-only $(LIB) | awk 'NF == 3' | wc -l) symbols of $(LIB), all ds_*; $(SHLIB) exports the $$(wc -l < $(BUILD)/declared) public functions; no printing or exit"

# Regenerates the "Bad input" table of docs/cli.md from tests/cli_cases.txt.
bad-input-table: all $(BUILD)/tests/test_cli
	sh tests/bad_input_table.sh $(BUILD)/tests/test_cli docs/cli.md

clean:
	rm -rf build build-san build-fuzz build-werror-gcc build-werror-clang build-plain libdisksim.a disks

# ---------------------------------------------------------------- bench
# `make bench` prints the table of docs/performance.md (under a minute
# on 2 cores; run it on an otherwise idle machine).
.PHONY: bench
BENCH_SRC := tools/benchmark/bench.c tools/benchmark/bench_events.c tools/benchmark/bench_chain.c \
             tools/benchmark/bench_stats.c
$(OUT)tools/bench: $(BENCH_SRC) tools/benchmark/bench.h $(LIB) $(PUB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) $(LDFLAGS) -o $@ $(BENCH_SRC) $(LIB) $(LDLIBS)

bench: $(OUT)tools/bench
	./$(OUT)tools/bench

# tools/pressure: Z with block-average errors for one system (public API
# only), run by tools/analysis/pressure_vs_dt.sh and tools/analysis/eos.sh. Built by `make`.
all: $(OUT)tools/pressure
$(OUT)tools/pressure: tools/analysis/pressure.c tools/analysis/analysis_util.h $(LIB) $(PUB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# tools/gr: g(r) of one frame file (public API only), plotted by
# tools/analysis/plot_gr.plt. Built by `make`.
all: $(OUT)tools/gr
$(OUT)tools/gr: tools/analysis/gr.c $(BUILD)/tools/frames_json.o $(LIB) $(PUB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude -Itools/common $(CFLAGS) $(LDFLAGS) -o $@ $< \
	    $(BUILD)/tools/frames_json.o $(LIB) $(LDLIBS)

# tools/transport: diffusion, mean-squared displacement and velocity
# autocorrelation of one periodic system (public API only), plotted by
# tools/analysis/plot_transport.plt. Built by `make`.
all: $(OUT)tools/transport
$(OUT)tools/transport: tools/analysis/transport.c tools/analysis/analysis_util.h $(LIB) $(PUB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# tools/rheology: the shear viscosity from a sheared flow (Lees-Edwards,
# public API only), the other way to tools/transport's Helfand moments.
# Built by `make`.
all: $(OUT)tools/rheology
$(OUT)tools/rheology: tools/analysis/rheology.c tools/analysis/analysis_util.h $(LIB) $(PUB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# tools/decorrelation: integrated autocorrelation times of psi6 and Z in
# CPU seconds for one algorithm (public API only), run by
# tools/analysis/decorrelation.sh. Built by `make`.
all: $(OUT)tools/decorrelation
$(OUT)tools/decorrelation: tools/analysis/decorrelation.c tools/analysis/analysis_util.h $(LIB) $(PUB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

clean: clean-bench
clean-bench:
	rm -f tools/bench tools/pressure tools/gr tools/transport tools/rheology tools/decorrelation

# ---------------------------------------------------------------- packaging
# The shared library beside the static one, disksim.pc, `make examples`,
# `make install` and `make uninstall` (PREFIX, default /usr/local, and
# DESTDIR for staging). The version, the .pc Version and the soname all come
# from the DS_VERSION_* macros in disksim/base.h, the one place they are written.
VERSION   := $(shell sed -n 's/^.define DS_VERSION_STRING "\(.*\)"/\1/p' include/disksim/base.h)
SOVERSION := $(shell sed -n 's/^.define DS_VERSION_MAJOR \([0-9]*\).*/\1/p' include/disksim/base.h)
SONAME    := libdisksim.so.$(SOVERSION)
SHLIB     := libdisksim.so.$(VERSION)
PIC_OBJ   := $(LIB_SRC:src/%.c=$(BUILD)/pic/%.o)
EXAMPLES  := $(OUT)examples/minimal $(OUT)examples/stream_frames $(OUT)examples/speeds

PREFIX       ?= /usr/local
BINDIR       = $(PREFIX)/bin
LIBDIR       = $(PREFIX)/lib
INCLUDEDIR   = $(PREFIX)/include
DATADIR      = $(PREFIX)/share
MANDIR       = $(DATADIR)/man
PKGCONFIGDIR = $(LIBDIR)/pkgconfig
INSTALL      ?= install
# The gnuplot scripts, wherever they live in the tree (share/disksim/).
PLT_FILES     = $(wildcard animate_disk.plt tools/analysis/*.plt)
# The documentation, where a package puts it (share/doc/disksim/): the
# front page, changelog and licence, and the manual in docs/ with its
# pictures, so the pages' relative links work in the installed copy.
DOCDIR        = $(DATADIR)/doc/disksim
DOC_FILES     = README.md CHANGELOG.md LICENSE
DOC_PAGES     = $(wildcard docs/*.md docs/*.png)

.PHONY: examples install uninstall clean-packaging FORCE
all: $(OUT)libdisksim.so disksim.pc
clean: clean-packaging

# Position-independent copies of the library objects: the static library
# keeps the plain ones, which are a little faster without -fPIC.
$(BUILD)/pic/%.o: src/%.c $(LIB_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) $(CPPFLAGS) $(CFLAGS) -fPIC -c $< -o $@

# Internal functions shared between src/ files are also named ds_*, so the
# export list is every function declared in the public headers, no more.
$(BUILD)/exports.map: $(PUB_HDR) | $(BUILD)
	{ echo '{ global:'; \
	  sed -n '/^[a-z]/s/^[^(]*[ *]\(ds_[a-z0-9_]*\)(.*/    \1;/p' $(PUB_HDR) | sort -u; \
	  echo '  local: *; };'; } > $@

$(OUT)$(SHLIB): $(PIC_OBJ) $(BUILD)/exports.map
	$(CC) $(CFLAGS) $(LDFLAGS) -shared -Wl,-soname,$(SONAME) \
	    -Wl,--version-script,$(BUILD)/exports.map -o $@ $(PIC_OBJ) -lm

$(OUT)$(SONAME): $(OUT)$(SHLIB)
	ln -sf $(SHLIB) $@

$(OUT)libdisksim.so: $(OUT)$(SONAME)
	ln -sf $(SONAME) $@

# Regenerated when PREFIX changes (FORCE), but rewritten only if different,
# so `make install PREFIX=/usr` after `make` installs the right paths.
disksim.pc: disksim.pc.in $(PUB_HDR) FORCE
	@sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@LIBDIR@|$(LIBDIR)|g' \
	     -e 's|@INCLUDEDIR@|$(INCLUDEDIR)|g' -e 's|@VERSION@|$(VERSION)|g' \
	     disksim.pc.in > $@.tmp
	@if cmp -s $@.tmp $@; then rm -f $@.tmp; else mv -f $@.tmp $@; \
	     echo "disksim.pc: prefix $(PREFIX), version $(VERSION)"; fi

FORCE:

examples: $(EXAMPLES)

$(OUT)examples/%: examples/%.c $(PUB_HDR) $(LIB)
	@mkdir -p $(dir $@)
	$(CC) $(WARN) -Iinclude $(CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# The analysis commands, installed under names that cannot clash with
# other packages' (bin/disks-*), each with its man page: the programs of
# tools/analysis/*.c and the sweeps a user runs (docs/sweeps.md). The
# scripts those sweeps run in turn, and the gnuplot scripts, go to
# share/disksim/.
ANALYSIS_PROGRAMS = gr pressure transport rheology
ANALYSIS_SCRIPTS  = eos.sh:disks-eos eos.sbatch:disks-eos-slurm \
                    diffusion_sweep.sh:disks-diffusion jamming.sh:disks-jamming
ANALYSIS_HELPERS  = eos_point.sh eos_gather.sh sweep_dir.sh
ANALYSIS_MAN      = disks-gr disks-pressure disks-transport disks-rheology disks-eos disks-diffusion \
                    disks-jamming
ANALYSIS_BIN      = $(ANALYSIS_PROGRAMS:%=disks-%) $(foreach s,$(ANALYSIS_SCRIPTS),$(lastword $(subst :, ,$(s))))
# In the checkout each script finds the others beside itself and the
# programs in tools/; installed, it finds them where make install puts them.
# Every script says which lines this rewrites (docs/install.md).
INSTALL_PATHS = sed -e 's|^\( *\)scripts=\$$(cd .*|\1scripts=$(DATADIR)/disksim|' \
                    -e 's|\$$scripts/\.\./pressure|$(BINDIR)/disks-pressure|' \
                    -e 's|\$$scripts/\.\./transport|$(BINDIR)/disks-transport|' \
                    -e 's|\$$scripts/\.\./\.\./disks|$(BINDIR)/disks|' \
                    -e 's|"\$$scripts/eos\.sbatch"|"$(BINDIR)/disks-eos-slurm"|'

# disks-render and its man page are installed when the renderer has been
# built (`make render`). The man pages name the gnuplot scripts by their
# path under the default prefix; the installed copies name them where they
# really are.
install: all
	$(INSTALL) -d $(DESTDIR)$(BINDIR) $(DESTDIR)$(LIBDIR) $(DESTDIR)$(PKGCONFIGDIR) \
	    $(DESTDIR)$(INCLUDEDIR)/disksim $(DESTDIR)$(MANDIR)/man1 $(DESTDIR)$(DATADIR)/disksim \
	    $(DESTDIR)$(MANDIR)/man3 $(DESTDIR)$(DOCDIR)/docs
	$(INSTALL) -m 755 $(DISKS) $(DESTDIR)$(BINDIR)/disks
	if [ -x $(OUT)tools/render ]; then \
	    $(INSTALL) -m 755 $(OUT)tools/render $(DESTDIR)$(BINDIR)/disks-render && \
	    $(INSTALL) -m 644 man/disks-render.1 $(DESTDIR)$(MANDIR)/man1/disks-render.1; fi
	$(INSTALL) -m 644 $(LIB) $(DESTDIR)$(LIBDIR)/libdisksim.a
	$(INSTALL) -m 755 $(OUT)$(SHLIB) $(DESTDIR)$(LIBDIR)/$(SHLIB)
	ln -sf $(SHLIB) $(DESTDIR)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(LIBDIR)/libdisksim.so
	$(INSTALL) -m 644 include/disk_sim.h $(DESTDIR)$(INCLUDEDIR)/disk_sim.h
	$(INSTALL) -m 644 $(wildcard include/disksim/*.h) $(DESTDIR)$(INCLUDEDIR)/disksim/
	$(INSTALL) -m 644 disksim.pc $(DESTDIR)$(PKGCONFIGDIR)/disksim.pc
	for page in disks $(ANALYSIS_MAN); do \
	    sed 's|/usr/local/share/disksim|$(DATADIR)/disksim|g' man/$$page.1 \
	        > $(DESTDIR)$(MANDIR)/man1/$$page.1 && \
	    chmod 644 $(DESTDIR)$(MANDIR)/man1/$$page.1 || exit 1; \
	done
	ln -sf disks-eos.1 $(DESTDIR)$(MANDIR)/man1/disks-eos-slurm.1
	for p in $(ANALYSIS_PROGRAMS); do \
	    $(INSTALL) -m 755 $(OUT)tools/$$p $(DESTDIR)$(BINDIR)/disks-$$p || exit 1; done
	for s in $(ANALYSIS_SCRIPTS); do \
	    $(INSTALL_PATHS) tools/analysis/$${s%%:*} > $(DESTDIR)$(BINDIR)/$${s##*:} && \
	    chmod 755 $(DESTDIR)$(BINDIR)/$${s##*:} || exit 1; done
	for h in $(ANALYSIS_HELPERS); do \
	    $(INSTALL_PATHS) tools/analysis/$$h > $(DESTDIR)$(DATADIR)/disksim/$$h && \
	    chmod 644 $(DESTDIR)$(DATADIR)/disksim/$$h || exit 1; done
	$(INSTALL) -m 644 man/disk_sim.3 $(DESTDIR)$(MANDIR)/man3/disk_sim.3
	$(if $(PLT_FILES),$(INSTALL) -m 644 $(PLT_FILES) $(DESTDIR)$(DATADIR)/disksim/)
	$(INSTALL) -m 644 $(DOC_FILES) $(DESTDIR)$(DOCDIR)/
	$(if $(DOC_PAGES),$(INSTALL) -m 644 $(DOC_PAGES) $(DESTDIR)$(DOCDIR)/docs/)

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/disks $(DESTDIR)$(BINDIR)/disks-render \
	    $(DESTDIR)$(LIBDIR)/libdisksim.a $(DESTDIR)$(LIBDIR)/libdisksim.so \
	    $(DESTDIR)$(LIBDIR)/$(SONAME) $(DESTDIR)$(LIBDIR)/$(SHLIB) \
	    $(DESTDIR)$(INCLUDEDIR)/disk_sim.h $(DESTDIR)$(PKGCONFIGDIR)/disksim.pc \
	    $(addprefix $(DESTDIR)$(INCLUDEDIR)/,$(patsubst include/%,%,$(wildcard include/disksim/*.h))) \
	    $(DESTDIR)$(MANDIR)/man1/disks.1 $(DESTDIR)$(MANDIR)/man1/disks-render.1 \
	    $(DESTDIR)$(MANDIR)/man3/disk_sim.3 \
	    $(addprefix $(DESTDIR)$(BINDIR)/,$(ANALYSIS_BIN)) \
	    $(ANALYSIS_MAN:%=$(DESTDIR)$(MANDIR)/man1/%.1) $(DESTDIR)$(MANDIR)/man1/disks-eos-slurm.1 \
	    $(addprefix $(DESTDIR)$(DATADIR)/disksim/,$(ANALYSIS_HELPERS)) \
	    $(addprefix $(DESTDIR)$(DATADIR)/disksim/,$(notdir $(PLT_FILES))) \
	    $(addprefix $(DESTDIR)$(DOCDIR)/,$(DOC_FILES)) \
	    $(addprefix $(DESTDIR)$(DOCDIR)/docs/,$(notdir $(DOC_PAGES)))
	rmdir $(DESTDIR)$(DATADIR)/disksim 2>/dev/null || true
	rmdir $(DESTDIR)$(INCLUDEDIR)/disksim 2>/dev/null || true
	rmdir $(DESTDIR)$(DOCDIR)/docs $(DESTDIR)$(DOCDIR) 2>/dev/null || true

clean-packaging:
	rm -f libdisksim.so libdisksim.so.* disksim.pc disksim.pc.tmp \
	    examples/minimal examples/stream_frames examples/speeds

# ---------------------------------------------------------------- renderer
# tools/render (frames to PNG, tools/render*.c) draws through one small
# backend interface with two implementations: OSMesa (pkg-config osmesa) and
# surfaceless EGL (egl + gl). Each backend gets its own binary,
# $(BUILD)/tools/render-osmesa and -egl, because libOSMesa and libGL both
# export the gl* functions and one binary cannot link both; tools/render is
# a copy of the one BACKEND names: OSMesa when present, else EGL, or forced
# with BACKEND=osmesa|egl. `make all` and `make test` build every backend
# pkg-config finds (test_render compares them) and skip the renderer with a
# one-line note when there is none.
RENDER_PKGS_osmesa := osmesa libpng
RENDER_PKGS_egl    := egl gl libpng
RENDER_BACKENDS := $(if $(HAVE_PKG_CONFIG),$(strip $(foreach b,osmesa egl,$(if $(shell \
    $(PKG_CONFIG) --exists $(RENDER_PKGS_$(b)) 2>/dev/null && echo y),$(b)))))
BACKEND ?= $(firstword $(RENDER_BACKENDS))
RENDER_HINT := the renderer needs libpng-dev and libosmesa6-dev, or libegl-dev libgl-dev libegl-mesa0
RENDER_COMMON := render render_draw render_layout render_colormap render_font render_png \
                 render_movie render_request render_inputs render_xyz render_gsd frames_json
RENDER_CFLAGS := $(if $(HAVE_PKG_CONFIG),$(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null))
RENDER_BIN := $(RENDER_BACKENDS:%=$(BUILD)/tools/render-%)
RENDER_OBJ := $(foreach o,$(RENDER_COMMON) render_osmesa render_egl,$(BUILD)/tools/$(o).o)
.SECONDARY: $(RENDER_OBJ) # kept between builds, not intermediate
RENDER_DEPS := $(PUB_HDR) $(wildcard tools/renderer/*.h) tools/common/frames_json.h

.PHONY: render render-skipped clean-render
ifneq ($(RENDER_BACKENDS),)
all: render $(RENDER_BIN)
TEST_BIN += $(BUILD)/tests/test_render
test: $(BUILD)/tests/test_render $(RENDER_BIN)
else
all: render-skipped
test: render-skipped
endif

$(BUILD)/tools/%.o: tools/renderer/%.c $(RENDER_DEPS)
	@mkdir -p $(BUILD)/tools
	$(CC) $(WARN) -Iinclude -Itools/common $(RENDER_CFLAGS) $(CFLAGS) -c $< -o $@

# What the tools share: frames.json's reader (render, gr).
$(BUILD)/tools/frames_json.o: tools/common/frames_json.c tools/common/frames_json.h $(PUB_HDR)
	@mkdir -p $(BUILD)/tools
	$(CC) $(WARN) -Iinclude $(CFLAGS) -c $< -o $@

$(BUILD)/tools/render-%: $(RENDER_COMMON:%=$(BUILD)/tools/%.o) $(BUILD)/tools/render_%.o $(LIB)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $^ $(shell $(PKG_CONFIG) --libs $(RENDER_PKGS_$*)) -lpthread $(LDLIBS)

# A copy, refreshed whenever it differs, so switching BACKEND takes effect.
ifneq ($(BACKEND),)
render: $(BUILD)/tools/render-$(BACKEND)
	@cmp -s $< $(OUT)tools/render || { mkdir -p $(OUT)tools && cp -f $< $(OUT)tools/render && \
	    echo "$(OUT)tools/render: $(BACKEND) backend"; }
else
render:
	@echo "make render: $(RENDER_HINT)"; exit 1
endif

clean: clean-render
clean-render:
	rm -f tools/render

render-skipped:
	@echo "renderer skipped: $(if $(HAVE_PKG_CONFIG),pkg-config finds neither osmesa nor egl+gl with libpng,$(PKG_CONFIG) is not installed (Debian: pkg-config)) ($(RENDER_HINT))"

# The test runs each backend's binary (their paths are compiled in) and
# links the GL-free parts (colour map, layout) to compute expected pixels.
$(BUILD)/tests/test_render: tests/test_render.c tests/test_util.h $(LIB) $(RENDER_DEPS) \
                            $(BUILD)/tools/render_colormap.o $(BUILD)/tools/render_layout.o \
                            $(BUILD)/tools/render_font.o
	@mkdir -p $(BUILD)/tests
	$(CC) $(WARN) $(CPPFLAGS) -Itools/renderer $(RENDER_CFLAGS) $(CMOCKA_CFLAGS) $(CFLAGS) $(LDFLAGS) \
	    $(foreach b,$(RENDER_BACKENDS),-DRENDER_$(b)='"$(BUILD)/tools/render-$(b)"') \
	    -DRENDER_DISKS='"./$(DISKS)"' -o $@ $< $(BUILD)/tools/render_colormap.o \
	    $(BUILD)/tools/render_layout.o $(BUILD)/tools/render_font.o $(LIB) $(CMOCKA_LIBS) \
	    $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null) $(LDLIBS)

# ---------------------------------------------------------------- python
# The Python module disksim (python/, docs/python.md), a C extension over
# disk_sim.h that compiles the library's sources itself (setup.py at the
# top, the one build definition, which pip uses too). `make python` builds
# it in place, python/disksim/_disksim*.so, for PYTHONPATH=python; `make
# test` then runs its pytest suite. Debian's own python3 by default (its
# python3-numpy, python3-dev, python3-setuptools and python3-pytest), not
# whichever python3 comes first on PATH; without them the suite is skipped
# with a one-line note naming the packages.
PYTHON ?= $(if $(wildcard /usr/bin/python3),/usr/bin/python3,python3)
PY_JOBS ?= 2
PY_MISSING = $$($(PYTHON) python/check_deps.py $(1) 2>/dev/null || echo python3)
PY_EXT = $(shell $(PYTHON) -c 'import sysconfig; print(sysconfig.get_config_var("EXT_SUFFIX"))' 2>/dev/null)
PY_SRC := $(wildcard python/src/*.c python/src/*.h) setup.py python/disksim/__init__.py
# SANITIZE=1 builds the module with the sanitizers into $(BUILD)/python/lib
# (an instrumented module cannot replace the plain one in place) and runs
# the suite with AddressSanitizer's runtime preloaded into python3, leak
# checking off (CPython keeps its objects at exit).
ifeq ($(SANITIZE),1)
  PY_LIB    := $(BUILD)/python/lib
  PY_MODULE  = $(PY_LIB)/disksim/_disksim$(PY_EXT)
  PY_WHERE  := --build-lib $(PY_LIB)
  PY_ASAN    = $(shell $(CC) -print-file-name=libasan.so)
  PY_RUN     = $(if $(filter /%,$(PY_ASAN)),LD_PRELOAD=$(PY_ASAN) ASAN_OPTIONS=detect_leaks=0)
else
  PY_LIB    := python
  PY_MODULE  = python/disksim/_disksim$(PY_EXT)
  PY_WHERE  := --inplace
  PY_RUN    :=
endif

.PHONY: python python-deps python-test clean-python
python: $(PY_MODULE)

python-deps:
	@missing=$(call PY_MISSING,build); if [ -n "$$missing" ]; then \
	    echo "make python: $(PYTHON) lacks $$missing (Debian packages)"; exit 1; fi

# setuptools recompiles every file when it builds: make decides when.
$(PY_MODULE): $(PY_SRC) $(LIB_SRC) $(LIB_HDR) $(FLAGS_STAMP) | python-deps
	CC="$(CC)" CFLAGS="$(CFLAGS)" LDFLAGS="$(LDFLAGS)" $(PYTHON) setup.py -q \
	    build_ext $(PY_WHERE) --force --parallel $(PY_JOBS) --build-temp $(BUILD)/python/temp
	$(if $(filter 1,$(SANITIZE)),cp python/disksim/__init__.py $(PY_LIB)/disksim/)

# The suite runs the disks of this build (test_frames compares its frames)
# and its tools/pressure and tools/gr (test_example, test_rdf).
python-test: $(DISKS) $(OUT)tools/pressure $(OUT)tools/gr
	@missing=$(call PY_MISSING,test); if [ -n "$$missing" ]; then \
	    echo "python tests skipped: $(PYTHON) lacks $$missing (Debian packages)"; exit 0; fi; \
	$(MAKE) -s --no-print-directory python && echo "== pytest python/tests" && \
	    PYTHONPATH=$(PY_LIB) DISKSIM_DISKS="$(CURDIR)/$(DISKS)" \
	    DISKSIM_PRESSURE="$(CURDIR)/$(OUT)tools/pressure" DISKSIM_GR="$(CURDIR)/$(OUT)tools/gr" \
	    $(PY_RUN) \
	    $(PYTHON) -m pytest -q -p no:cacheprovider python/tests

# The packaging, offline in a venv (tests/python_packaging.sh): pip install
# . from the top and ./python, pip wheel ., the sdist and a wheel from it
# alone, the stubs checked by mypy, the checkout left as it was. Five
# builds of the library, about 30 s on two cores: .ci/run runs it, not make
# test. Needs python3-venv, python3-wheel, python3-build and python3-mypy.
.PHONY: python-packaging
python-packaging:
	PYTHON="$(PYTHON)" sh tests/python_packaging.sh

clean: clean-python
clean-python:
	rm -rf python/build python/disksim.egg-info python/disksim/_disksim*.so \
	    python/disksim/__pycache__ python/tests/__pycache__
