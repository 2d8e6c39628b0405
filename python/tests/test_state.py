# SPDX-License-Identifier: MIT
"""The state as arrays: copies out, copies in, checked before anything
changes."""
import pickle

import numpy as np
import pytest

import disksim


def test_positions_and_velocities_are_fresh_float64_arrays_in_generation_order():
    s = disksim.Sim(400, 5)
    p = s.positions
    v = s.velocities
    assert p.shape == v.shape == (400, 2)
    assert p.dtype == v.dtype == np.float64
    assert p.flags.c_contiguous and p.flags.writeable and p.flags.owndata
    assert s.positions is not p and np.array_equal(s.positions, p)
    # Generation order: every disk starts at speed 100.
    assert np.allclose(np.hypot(v[:, 0], v[:, 1]), 100)


def test_changing_an_array_changes_nothing_in_the_simulation():
    s = disksim.Sim(400, 5)
    before = s.positions
    p = s.positions
    p[:] = 0
    v = s.velocities
    v *= 2
    assert np.array_equal(s.positions, before)
    assert s.kinetic_energy == pytest.approx(400 * 100**2 / 2)


def test_set_state_copies_its_arguments():
    s = disksim.Sim(400, 5)
    p = s.positions + 0.5
    v = s.velocities
    s.set_state(p, v)
    p[:] = 1e6
    v[:] = 0
    assert np.array_equal(s.positions, disksim.Sim(400, 5).positions + 0.5)


def test_set_state_sets_every_disk_exactly_and_keeps_velocities_when_none():
    s = disksim.Sim(400, 5)
    rng = np.random.default_rng(1)
    v_new = rng.normal(0, 50, (400, 2))
    p_new = s.positions[::-1].copy()  # the same centres, in reverse order
    v_old = s.velocities
    s.set_state(p_new)
    assert np.array_equal(s.positions, p_new) and np.array_equal(s.velocities, v_old)
    s.set_state(p_new, v_new)
    assert np.array_equal(s.velocities, v_new)
    assert s.kinetic_energy == pytest.approx(0.5 * (v_new**2).sum(), rel=1e-12)


@pytest.mark.parametrize("integrator", ["step", "event"])
def test_set_state_then_run_is_the_simulation_of_that_state(integrator):
    # Time, steps and observables go on; the disks move from the new state.
    s = disksim.Sim(50, 5, integrator=integrator)
    s.run(10)
    p = np.column_stack([np.linspace(100, 900, 50), np.full(50, 500.0)])
    v = np.zeros((50, 2))
    v[:, 1] = 10
    s.set_state(p, v)
    s.run(1000)  # 1 time unit at speed 10 along y, far from every wall
    assert s.steps == 1010
    assert np.allclose(s.positions[:, 0], p[:, 0]) and np.allclose(s.positions[:, 1], 510)


def test_any_array_like_of_numbers_is_taken():
    s = disksim.Sim(3, 1)
    s.set_state([[10, 10], [20, 20], [30, 30]], [[1, 0], [0, 1], [0, 0]])  # lists of ints
    assert s.positions.tolist() == [[10, 10], [20, 20], [30, 30]]
    s.set_state(np.array([[10, 20, 30], [10, 20, 40]], dtype=np.float32).T)  # strided, float32
    assert s.positions.tolist() == [[10, 10], [20, 20], [30, 40]]
    s.set_state(np.asfortranarray(s.positions * 2))
    assert s.positions.tolist() == [[20, 20], [40, 40], [60, 80]]


def test_a_refused_state_changes_nothing():
    s = disksim.Sim(400, 5)
    before = s.positions
    overlapping = s.positions
    overlapping[7] = overlapping[3] + [1, 0]
    with pytest.raises(disksim.ArgumentError) as info:
        s.set_state(overlapping)
    assert info.value.status == "DS_ERR_OVERLAP" and "disks 3 and 7 overlap" in str(info.value)
    outside = s.positions
    outside[5] = [2, 500]
    with pytest.raises(disksim.ArgumentError, match="disk 5 at"):
        s.set_state(outside)
    fast = s.velocities
    fast[9] = [1e13, 0]
    with pytest.raises(disksim.ArgumentError, match="disk 9 moves"):
        s.set_state(s.positions, fast)
    not_finite = s.positions
    not_finite[2, 1] = np.nan
    with pytest.raises(disksim.ArgumentError, match="disk 2 has a value that is not a finite"):
        s.set_state(not_finite)
    assert np.array_equal(s.positions, before)


def test_a_periodic_state_takes_any_centre_inside_the_box():
    s = disksim.Sim(2, 5, boundary="periodic")
    s.set_state([[0, 0], [999.999, 500]])
    with pytest.raises(disksim.ArgumentError, match="outside the periodic box"):
        s.set_state([[1000, 0], [500, 500]])


def test_unwrapped_centres_follow_a_free_disk_across_the_seams():
    # Box 10, disk 0 from (8, 7.5) with velocity (1, -0.5): it crosses the
    # far x edge at t = 2 and y = 0 at t = 15; disk 1 rests 3 / sqrt 5 >
    # 2R off its line, so neither collides. Unwrapped is x0 + v t to the
    # header's rounding bound, (s + 2) eps (box + |x|) after s steps.
    for integrator in ("step", "event"):
        s = disksim.Sim(2, 0.5, box=10, boundary="periodic", integrator=integrator,
                        dt=0.01, speed=1)
        s.set_state([[8.0, 7.5], [5.0, 2.5]], [[1.0, -0.5], [0.0, 0.0]])
        assert np.array_equal(s.unwrapped, s.positions)
        s.run(2000)  # t = 20
        u = s.unwrapped
        assert u.shape == (2, 2) and u.dtype == np.float64
        bound = 2002 * np.finfo(float).eps * (10 + 28)
        assert abs(u[0, 0] - 28.0) <= bound and abs(u[0, 1] - (-2.5)) <= bound
        assert np.array_equal(u[1], [5.0, 2.5])
        assert 0 <= s.positions[0, 0] < 10 and 0 <= s.positions[0, 1] < 10
        assert s.collision_count == 0


def test_image_counts_are_the_crossings_of_each_disk_and_unwrap_it():
    # The free disk above, x from 8 at speed 1 in a box of 10: it crosses x
    # = 10 at t = 2, 12 and 22 (images +3 at t = 25); y from 7.5 at -0.5
    # crosses y = 0 at t = 15 (images -1). The other rests.
    for integrator in ("step", "event"):
        s = disksim.Sim(2, 0.5, box=10, boundary="periodic", integrator=integrator,
                        dt=0.01, speed=1)
        s.set_state([[8.0, 7.5], [5.0, 2.5]], [[1.0, -0.5], [0.0, 0.0]])
        assert np.array_equal(s.images, [[0, 0], [0, 0]])
        s.run(2500)
        images = s.images
        assert images.dtype == np.int32 and images.shape == (2, 2)
        assert np.array_equal(images, [[3, -1], [0, 0]])
        # unwrapped is position + images * box, one rounding of the sum
        assert np.array_equal(s.unwrapped, s.positions + images * [s.box, s.box_y])
        t = pickle.loads(pickle.dumps(s))  # checkpoints carry them
        assert np.array_equal(t.images, images)
        s.set_state(s.positions)  # a new state starts in the box
        assert not s.images.any()


def test_image_counts_are_zero_with_walls_and_along_a_channels_y():
    s = disksim.Sim(100, 5)
    s.run(300)
    assert np.array_equal(s.images, np.zeros((100, 2), np.int32))
    c = disksim.Sim(100, 5, boundary="channel", speed=1000)
    c.run(2000)  # 2 time units: a disk crosses the box twice at speed 1000
    assert c.images[:, 0].any() and not c.images[:, 1].any()


def test_unwrapped_is_the_position_with_walls():
    s = disksim.Sim(100, 5)
    s.run(300)
    assert np.array_equal(s.unwrapped, s.positions)


@pytest.mark.parametrize("integrator", disksim.INTEGRATORS)
@pytest.mark.parametrize("speed", [1e-200, 5e-324])
def test_any_allowed_speed_gives_finite_velocities(integrator, speed):
    # Below ~1e-162 the centre of mass's sums underflowed and every
    # velocity came out NaN (the event-driven step then never returned).
    s = disksim.Sim(20, 5, speed=speed, boundary="periodic", integrator=integrator)
    assert np.isfinite(s.velocities).all()
    s.run(10)
    assert s.steps == 10 and np.isfinite(s.positions).all()
