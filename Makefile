# disksim: plain make. `make` builds libdisksim.a and disks; `make test`
# builds and runs the cmocka suite. Honours CC, CFLAGS, CPPFLAGS, LDFLAGS.

CC      ?= cc
CFLAGS  ?= -O2 -g
WARN    := -std=c99 -Wall -Wextra -Wpedantic
CPPFLAGS += -Iinclude
LDLIBS  += -lm
AR      ?= ar

# SANITIZE=1 rebuilds everything with AddressSanitizer and UBSan in its own
# directory (build-san/, giving build-san/libdisksim.a and build-san/disks),
# so no uninstrumented object is ever reused and the plain build is left
# alone. Any other BUILD=dir likewise keeps objects and outputs inside dir
# (CI uses that for its -Werror builds under gcc and clang).
ifeq ($(SANITIZE),1)
  BUILD   ?= build-san
  CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
  LDFLAGS += -fsanitize=address,undefined
endif
BUILD ?= build
OUT   := $(if $(filter build,$(BUILD)),,$(BUILD)/)
LIB   := $(OUT)libdisksim.a
DISKS := $(OUT)disks

LIB_SRC := src/rng.c src/timer.c src/status.c src/placement.c src/collision.c \
           src/broad_phase.c src/broad_phase_strips.c src/frame_io.c src/sim.c
LIB_OBJ := $(LIB_SRC:src/%.c=$(BUILD)/%.o)

.PHONY: all test clean
all: $(LIB) $(DISKS)

$(BUILD):
	@mkdir -p $(BUILD)

$(BUILD)/%.o: src/%.c include/disk_sim.h src/sim_internal.h | $(BUILD)
	$(CC) $(WARN) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

$(LIB): $(LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $^

$(DISKS): $(BUILD)/disks.o $(LIB)
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# ---------------------------------------------------------------- tests
CMOCKA_CFLAGS := $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS   := $(shell pkg-config --libs cmocka 2>/dev/null || echo -lcmocka)
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
# test_cli runs the disks of this build (paths relative to the top directory).
TEST_DEFS := -DDS_TEST_DISKS='"$(DISKS)"'

$(BUILD)/tests/%: tests/%.c tests/test_util.h $(LIB) include/disk_sim.h src/sim_internal.h
	@mkdir -p $(BUILD)/tests
	$(CC) $(WARN) $(CPPFLAGS) -Isrc $(TEST_DEFS) $(CMOCKA_CFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ $< \
	    $(LIB) $(CMOCKA_LIBS) $(LDLIBS)

test: all $(TEST_BIN)
	@fail=0; for t in $(TEST_BIN); do \
	    echo "== $$t"; ./$$t || fail=1; \
	done; \
	if [ $$fail -ne 0 ]; then echo "make test: some tests FAILED"; exit 1; fi; \
	echo "make test: all test programs passed"

clean:
	rm -rf build build-san build-fuzz libdisksim.a disks
