/* SPDX-License-Identifier: MIT */
/* The event-driven integrator's cell grid: its shape (cells at least 2R
 * wide, never more than a few per disk), where a coordinate falls, and
 * that every disk added is found in its cell, slots and overflow list
 * alike, and gone once removed. */
#include "test_util.h"

#include "event/cells.h"

/* The disks of cell, in any order, into out; returns how many. */
static size_t cell_disks(const ds_cells *cells, uint32_t cell, uint32_t *out)
{
    size_t count = 0;
    const uint32_t *slot = ds_cells_slots(cells, cell);
    for (int k = 0; k < DS_CELL_SLOTS; ++k)
        if (slot[k] != cells->empty)
            out[count++] = slot[k];
    for (uint32_t d = ds_cells_overflow(cells, cell); d != cells->empty; d = cells->next[d])
        out[count++] = d;
    return count;
}

static int holds(const ds_cells *cells, uint32_t cell, uint32_t disk)
{
    uint32_t found[64];
    const size_t count = cell_disks(cells, cell, found);
    int times = 0;
    for (size_t k = 0; k < count; ++k)
        times += found[k] == disk;
    return times;
}

/* Whether the cell's disks fill its first `count` slots and the rest are
 * empty: the pair tests read a cell as four slots and a count. */
static int packed(const ds_cells *cells, uint32_t cell, int count)
{
    const uint32_t *slot = ds_cells_slots(cells, cell);
    for (int k = 0; k < DS_CELL_SLOTS; ++k)
        if ((slot[k] != cells->empty) != (k < count))
            return 0;
    return 1;
}

static void test_cells_are_at_least_a_diameter_wide(void **state)
{
    (void)state;
    ds_cells cells;
    /* 1000 / 10 = 100 exactly: rounding must not make them a hair narrower,
     * so there are 99. */
    assert_int_equal(ds_cells_init(&cells, 10000, 1000.0, 1000.0, 10.0, UINT32_MAX), DS_OK);
    assert_int_equal(cells.nx, 99);
    assert_int_equal(cells.ny, 99);
    assert_true(cells.wx >= 10.0 && cells.wy >= 10.0);
    ds_cells_free(&cells);
    /* A rectangle gets its own count per side. */
    assert_int_equal(ds_cells_init(&cells, 10000, 1000.0, 500.0, 10.0, UINT32_MAX), DS_OK);
    assert_int_equal(cells.nx, 99);
    assert_int_equal(cells.ny, 49);
    ds_cells_free(&cells);
}

static void test_a_dilute_gas_gets_a_few_cells_per_disk_not_millions(void **state)
{
    (void)state;
    ds_cells cells;
    /* R = 0.01: cells of 0.02 would be 2.5e9; 100 disks need ~400. */
    assert_int_equal(ds_cells_init(&cells, 100, 1000.0, 1000.0, 0.02, UINT32_MAX), DS_OK);
    assert_true((size_t)cells.nx * cells.ny <= 4 * 100 + 64);
    ds_cells_free(&cells);
    /* A long channel, 1e6 x 4 with 5,000 disks of R = 0.5: 1e6 cells of
     * 2R along it would fit, and sqrt(4 n) shared out by aspect would be
     * 70,700; a disk's column is 16 bits, so 65,535 at most. */
    assert_int_equal(ds_cells_init(&cells, 5000, 1e6, 4.0, 1.0, UINT32_MAX), DS_OK);
    assert_int_equal(cells.nx, DS_CELLS_MAX_SIDE);
    assert_true(cells.wx >= 1.0);
    ds_cells_free(&cells);
    /* max_side_cells = 1: one cell, everyone's candidate (brute force). */
    assert_int_equal(ds_cells_init(&cells, 100, 1000.0, 1000.0, 2.0, 1), DS_OK);
    assert_int_equal(cells.nx, 1);
    assert_int_equal(cells.ny, 1);
    ds_cells_free(&cells);
}

static void test_coordinates_map_to_their_cell_and_clamp_at_the_edges(void **state)
{
    (void)state;
    ds_cells cells;
    assert_int_equal(ds_cells_init(&cells, 100, 1000.0, 1000.0, 100.0, UINT32_MAX), DS_OK);
    assert_int_equal(cells.nx, 9);
    assert_int_equal(ds_cells_column(&cells, 0.0), 0);
    assert_int_equal(ds_cells_column(&cells, 112.0), 1);
    assert_int_equal(ds_cells_row(&cells, 999.999), 8);
    assert_int_equal(ds_cells_column(&cells, 1000.0), 8); /* the far edge */
    assert_int_equal(ds_cells_column(&cells, -1e-13), 0); /* rounded past 0 */
    assert_int_equal(ds_cells_row(&cells, 2000.0), 8);
    ds_cells_free(&cells);
}

static void test_disks_added_are_found_once_and_removed_cleanly(void **state)
{
    (void)state;
    /* Up to 40 disks in one cell: four in slots, the rest overflowing;
     * removal in a scrambled order refills the slots from the overflow. */
    const uint32_t n = 40;
    ds_cells cells;
    assert_int_equal(ds_cells_init(&cells, n, 30.0, 30.0, 5.0, UINT32_MAX), DS_OK);
    assert_true(cells.nx >= 3 && cells.ny >= 3);
    const uint32_t cell = ds_cells_index(&cells, 1, 1);
    for (uint32_t d = 0; d < n; ++d) {
        ds_cells_add(&cells, cell, d);
        uint32_t found[64];
        assert_int_equal(cell_disks(&cells, cell, found), d + 1);
        for (uint32_t e = 0; e <= d; ++e)
            assert_int_equal(holds(&cells, cell, e), 1);
    }
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t d = (k * 17) % n; /* 17 is prime to 40 */
        ds_cells_remove(&cells, cell, d);
        assert_int_equal(holds(&cells, cell, d), 0);
        uint32_t found[64];
        assert_int_equal(cell_disks(&cells, cell, found), n - k - 1);
        /* The overflow list is used only while all four slots are taken. */
        if (ds_cells_overflow(&cells, cell) != cells.empty)
            for (int s = 0; s < DS_CELL_SLOTS; ++s)
                assert_true(ds_cells_slots(&cells, cell)[s] != cells.empty);
        assert_true(packed(&cells, cell, n - k - 1 < DS_CELL_SLOTS ? (int)(n - k - 1) : 4));
    }
    /* Other cells were never touched. */
    for (uint32_t c = 0; c < cells.nx * cells.ny; ++c) {
        uint32_t found[64];
        assert_int_equal(cell_disks(&cells, c, found), 0);
    }
    ds_cells_free(&cells);
}

static void test_a_cell_keeps_its_disks_in_its_first_slots_whatever_leaves(void **state)
{
    (void)state;
    ds_cells cells;
    assert_int_equal(ds_cells_init(&cells, 8, 30.0, 30.0, 5.0, UINT32_MAX), DS_OK);
    const uint32_t cell = ds_cells_index(&cells, 2, 1);
    /* Four disks, then taken out in each of the 24 orders, one disk put
     * back after the second removal: every slot freed in the middle is
     * filled from the end. */
    for (int order = 0; order < 24; ++order) {
        uint32_t left[4] = {0, 1, 2, 3}, taken[4];
        int perm = order;
        for (int k = 4; k > 0; --k) { /* the order-th permutation */
            const int pick = perm % k;
            perm /= k;
            taken[4 - k] = left[pick];
            left[pick] = left[k - 1];
        }
        for (uint32_t d = 0; d < 4; ++d)
            ds_cells_add(&cells, cell, d);
        assert_true(packed(&cells, cell, 4));
        int count = 4;
        for (int k = 0; k < 4; ++k) {
            ds_cells_remove(&cells, cell, taken[k]);
            assert_int_equal(holds(&cells, cell, taken[k]), 0);
            assert_true(packed(&cells, cell, --count));
            if (k == 1) {
                ds_cells_add(&cells, cell, 7);
                assert_true(packed(&cells, cell, ++count));
            }
        }
        ds_cells_remove(&cells, cell, 7);
        assert_true(packed(&cells, cell, 0));
    }
    ds_cells_free(&cells);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cells_are_at_least_a_diameter_wide),
        cmocka_unit_test(test_a_dilute_gas_gets_a_few_cells_per_disk_not_millions),
        cmocka_unit_test(test_coordinates_map_to_their_cell_and_clamp_at_the_edges),
        cmocka_unit_test(test_disks_added_are_found_once_and_removed_cleanly),
        cmocka_unit_test(test_a_cell_keeps_its_disks_in_its_first_slots_whatever_leaves),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
