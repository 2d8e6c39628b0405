# SPDX-License-Identifier: MIT
"""Sim.freud_box and Sim.freud_points: the system as freud and HOOMD-blue
take it, a box centred on the origin and (n, 3) points with z = 0. freud
is not in Debian, so nothing here imports it: the box is checked against
what freud.box.Box.from_box and hoomd.Box.from_box read from a dict (the
keys Lx, Ly, Lz, xy, xz, yz and dimensions), the points against the
library's positions and against freud's wrap, which leaves a point inside
its box where it is."""
import numpy as np
import pytest

import disksim


def from_box(box):
    """What freud.box.Box.from_box (freud 2.x) reads from a dict, as
    (Lx, Ly, Lz, xy, xz, yz, is2D); hoomd.Box.from_box reads the same six."""
    Lz = box.get("Lz", 0)
    dimensions = box.get("dimensions", None)
    dimensions = dimensions if dimensions is not None else (2 if Lz == 0 else 3)
    return (box["Lx"], box["Ly"], Lz, box.get("xy", 0), box.get("xz", 0), box.get("yz", 0),
            dimensions == 2)


def freud_wrap(points, Lx, Ly):
    """freud's Box.wrap for an orthorhombic 2D box: the image of each point
    in [-L/2, L/2), from its fractional coordinate (x + L/2) / L."""
    L = np.array([Lx, Ly, 1.0])
    image = np.floor((points + L / 2) / L)
    image[:, 2] = 0
    return points - image * L


@pytest.mark.parametrize("boundary", ["walls", "periodic", "channel"])
def test_the_box_is_a_two_dimensional_box_of_the_sims_sides(boundary):
    s = disksim.Sim(300, 5, boundary=boundary, box=1000.0, box_y=600.0)
    box = s.freud_box()
    assert box == {"Lx": 1000.0, "Ly": 600.0, "Lz": 0.0, "xy": 0.0, "xz": 0.0, "yz": 0.0,
                   "dimensions": 2}
    assert from_box(box) == (1000.0, 600.0, 0.0, 0.0, 0.0, 0.0, True)
    box["Lx"] = 1.0  # a new dict each call
    assert s.freud_box()["Lx"] == 1000.0


@pytest.mark.parametrize("boundary", ["walls", "periodic", "channel"])
def test_the_points_are_the_centres_moved_by_half_a_side_with_z_zero(boundary):
    s = disksim.Sim(300, 5, boundary=boundary, box_y=600.0, integrator="event")
    s.run(3000)  # 3 time units at speed 100: many disks have crossed a seam
    points = s.freud_points()
    assert points.shape == (300, 3) and points.dtype == np.float64
    assert np.array_equal(points[:, 2], np.zeros(300))
    # exactly the library's positions less half of each side
    assert np.array_equal(points[:, :2], s.positions - [500.0, 300.0])
    if boundary == "periodic":
        assert (points[:, :2] >= [-500.0, -300.0]).all() and (points[:, :2] < [500, 300]).all()
    assert not np.shares_memory(points, s.freud_points())


def test_periodic_points_are_in_the_centred_box_and_freuds_wrap_keeps_them():
    s = disksim.Sim(3, 5, boundary="periodic", box_y=600.0, integrator="event")
    # centres on the edges of the library's box, 0 and the largest double
    # below a side: they become -L/2 and the largest below +L/2
    below_x, below_y = np.nextafter(1000.0, 0.0), np.nextafter(600.0, 0.0)
    s.set_state([[0.0, 0.0], [below_x, 300.0], [500.0, below_y]])
    half = np.array([500.0, 300.0])
    points = s.freud_points()
    assert np.array_equal(points[0, :2], -half)
    assert points[1, 0] == below_x - 500.0 < 500.0 and points[2, 1] == below_y - 300.0 < 300.0
    for _ in range(2):
        assert (points[:, :2] >= -half).all() and (points[:, :2] < half).all()
        assert np.array_equal(freud_wrap(points, 1000.0, 600.0), points)
        s.run(7000)  # 7 time units at speed 100: each crosses a seam or two
        points = s.freud_points()
    assert np.abs(s.images).sum() > 0


def test_with_walls_the_points_keep_a_radius_from_the_centred_walls():
    s = disksim.Sim(300, 5)
    s.run(3000)
    points = s.freud_points()
    assert (np.abs(points[:, :2]) <= 500.0 - 5.0 + 1e-9).all()


def test_a_closed_sim_has_no_freud_view():
    s = disksim.Sim(10, 1)
    s.close()
    for call in (s.freud_box, s.freud_points):
        with pytest.raises(disksim.Error, match="closed"):
            call()
