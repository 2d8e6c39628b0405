# disksim: plain make. `make` builds libdisksim.a and disks; `make test`
# builds and runs the cmocka suite. Honours CC, CFLAGS, CPPFLAGS, LDFLAGS.

CC      ?= cc
CFLAGS  ?= -O2 -g
WARN    := -std=c99 -Wall -Wextra -Wpedantic
CPPFLAGS += -Iinclude
LDLIBS  += -lm
AR      ?= ar

ifeq ($(SANITIZE),1)
  CFLAGS  += -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
  LDFLAGS += -fsanitize=address,undefined
endif

LIB_SRC := src/rng.c src/timer.c src/status.c src/placement.c src/collision.c \
           src/broad_phase.c src/broad_phase_strips.c src/frame_io.c src/sim.c
LIB_OBJ := $(LIB_SRC:src/%.c=build/%.o)

.PHONY: all test clean
all: libdisksim.a disks

build:
	@mkdir -p build

build/%.o: src/%.c include/disk_sim.h src/sim_internal.h | build
	$(CC) $(WARN) $(CPPFLAGS) $(CFLAGS) -c $< -o $@

libdisksim.a: $(LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $^

disks: build/disks.o libdisksim.a
	$(CC) $(CFLAGS) $(LDFLAGS) -o $@ $^ $(LDLIBS)

# ---------------------------------------------------------------- tests
CMOCKA_CFLAGS := $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS   := $(shell pkg-config --libs cmocka 2>/dev/null || echo -lcmocka)
TEST_SRC := $(wildcard tests/test_*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=build/tests/%)

build/tests/%: tests/%.c tests/test_util.h libdisksim.a include/disk_sim.h src/sim_internal.h
	@mkdir -p build/tests
	$(CC) $(WARN) $(CPPFLAGS) -Isrc $(CMOCKA_CFLAGS) $(CFLAGS) $(LDFLAGS) -o $@ $< \
	    libdisksim.a $(CMOCKA_LIBS) $(LDLIBS)

test: all $(TEST_BIN)
	@fail=0; for t in $(TEST_BIN); do \
	    echo "== $$t"; ./$$t || fail=1; \
	done; \
	if [ $$fail -ne 0 ]; then echo "make test: some tests FAILED"; exit 1; fi; \
	echo "make test: all test programs passed"

clean:
	rm -rf build libdisksim.a disks
