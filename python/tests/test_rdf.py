# SPDX-License-Identifier: MIT
"""g(r): disksim.rdf and Sim.rdf, the pair counts of pair_histogram over
those of an ideal gas of the same n in the same box, walls or not.

The statistical tests draw their frames from fixed seeds, so each either
always passes or always fails; the tolerances say how often a run with
other seeds would fail by chance."""
import math
import os
import subprocess

import numpy as np
import pytest

import disksim

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def ideal_probability(edges, a, b, walls_x, walls_y):
    """F(r1) - F(r0) of each bin: two uniform points of an a x b rectangle
    r0 to r1 apart (rdf's docstring derives F)."""
    r = np.asarray(edges, float)
    F = (math.pi * a * b * r**2 - 4 / 3 * (a * walls_y + b * walls_x) * r**3
         + walls_x * walls_y * r**4 / 2) / (a * b) ** 2
    return np.diff(F)


# The box (1000 x 800), the centres' rectangle in it (100 from each wall),
# and the largest r where F holds: half a periodic side, or a side the
# walls leave.
BOXES = {"walls": ((800.0, 600.0), 600.0), "periodic": ((1000.0, 800.0), 400.0),
         "channel": ((1000.0, 600.0), 500.0)}


@pytest.mark.parametrize("boundary", list(BOXES))
def test_an_ideal_gas_has_g_1_at_every_r_walls_or_not(boundary):
    # 4000 frames of 50 independent, uniform centres in the rectangle they
    # fill. Frames are independent, so the mean of g over them has the
    # standard error of the frames' spread over sqrt(4000) (known to 1%);
    # 4.5 of them: 30 bins fail by chance once in 10^4 runs. (Not the
    # Poisson error of the counts: with walls, pairs that share a centre
    # near a wall lose partners together, which makes the counts spread
    # more, and the frames' spread includes that.)
    (a, b), reach = BOXES[boundary]
    walls = {"walls": (1, 1), "periodic": (0, 0), "channel": (0, 1)}[boundary]
    rng = np.random.default_rng(36)
    lo = 100.0 * np.array(walls)  # the centres keep 100 from a wall
    frames = []
    for _ in range(4000):
        xy = lo + rng.uniform(0.0, 1.0, (50, 2)) * [a, b]
        r, g = disksim.rdf(xy, reach, 10, box=1000.0, box_y=800.0, boundary=boundary,
                           radius=100.0)
        frames.append(g)
    frames = np.array(frames)
    mean, error = frames.mean(0), frames.std(0, ddof=1) / math.sqrt(len(frames))
    assert np.all(np.abs(mean - 1.0) < 4.5 * error), (mean, error)
    assert np.allclose(r, (np.arange(10) + 0.5) * reach / 10, rtol=0, atol=1e-12 * reach)
    # The edge correction is what makes it so: the usual normalisation,
    # pi (r1^2 - r0^2) / (a b), leaves g well below 1 at the far bins.
    naive = np.pi * np.diff((np.arange(11) * reach / 10) ** 2) / (a * b)
    exact = ideal_probability(np.arange(11) * reach / 10, a, b, *walls)
    if boundary != "periodic":
        assert np.abs(mean * exact / naive - 1.0)[-1] > 20 * error[-1]


def test_a_sim_of_tiny_disks_is_an_ideal_gas_in_a_periodic_box():
    # 4000 disks of radius 0.01 placed at random in a periodic box: centres
    # independent and uniform but for the 2e-4 of the box the first disks
    # take from the last. In a periodic box the pairs sharing a centre are
    # independent of each other (every centre sees the same shell), so a
    # bin's count has the variance of C(n, 2) independent pairs, p (1 - p)
    # each: 4.5 of its standard errors, 20 bins fail by chance once in 10^4.
    n = 4000
    s = disksim.Sim(n, 0.01, boundary="periodic", speed=1.0, seed=36)
    r, g = s.rdf(500.0, 20)
    p = ideal_probability(np.arange(21) * 25.0, 1000.0, 1000.0, 0, 0)
    error = np.sqrt((1 - p) / (n * (n - 1) / 2 * p))
    assert np.all(np.abs(g - 1.0) < 4.5 * error), (g, error)


def test_a_sim_with_walls_normalises_in_the_rectangle_its_centres_reach():
    # Sim.rdf is disksim.rdf of its positions with its radius (a mixture's
    # mean radius), box and boundary.
    s = disksim.Sim(400, 10.0, integrator="event", seed=3)
    s.run(500)
    r, g = s.rdf(900.0, 45)
    r2, g2 = disksim.rdf(s.positions, 900.0, 45, radius=10.0)
    assert np.array_equal(r, r2) and np.array_equal(g, g2)
    m = disksim.Sim(400, 8.0, species=[(200, 8.0), (200, 12.0)], boundary="channel", seed=4)
    r, g = m.rdf(400.0, 40)
    r2, g2 = disksim.rdf(m.positions, 400.0, 40, boundary="channel", radius=10.0)
    assert np.array_equal(g, g2)


def henderson_contact(eta):
    """Henderson's g(sigma) for hard disks, from his equation of state
    Z = (1 + eta^2 / 8) / (1 - eta)^2 and Z = 1 + 2 eta g(sigma)."""
    return ((1 + eta**2 / 8) / (1 - eta) ** 2 - 1) / (2 * eta)


def test_hard_disks_have_g_0_inside_contact_and_hendersons_contact_value():
    # 1024 disks at area fraction 0.3, event-driven, periodic: 400 frames one
    # time unit (about ten collisions a disk) apart, in 40 blocks of 10. g
    # in bins of sigma / 50 from sigma to 1.2 sigma, fitted by a quadratic
    # in r - sigma in each block: its value at sigma is the contact value.
    eta, n = 0.3, 1024
    radius = math.sqrt(eta * 1e6 / (n * math.pi))
    sigma = 2 * radius
    s = disksim.Sim(n, radius, integrator="event", boundary="periodic", placement="lattice",
                    seed=36)
    s.run(3000)  # the lattice melts (psi6 ~ 1/sqrt(n) long before)
    frames = []
    for _ in range(400):
        s.run(1000)
        r, g = s.rdf(1.2 * sigma, 60)
        frames.append(g)
    frames = np.array(frames)
    # no pair closer than contact, ever (the event-driven dynamics is exact)
    assert not frames[:, :50].any() and np.all(r[:50] + 0.5 * sigma / 50 <= sigma * (1 + 1e-12))
    blocks = frames.reshape(40, 10, -1).mean(1)
    x = r[50:60] - sigma
    contact = np.polyfit(x, blocks[:, 50:60].T, 2)[-1]
    value, error = contact.mean(), contact.std(ddof=1) / math.sqrt(len(contact))
    # 4 standard errors (once in 10^4 by chance; measured 1.777 +- 0.013),
    # plus 0.005 for what is not statistical: the quadratic's bias from g's
    # third derivative, X^3 g''' / 120 over X = 0.2 sigma, below 0.002
    # (cubic to quintic fits of 1500 frames out to 1.5 sigma put |g'''|
    # below 20 / sigma^3); Henderson's own error at 0.3, his Z 0.0006 above
    # the virial series' 2.0632, so 0.001 in g = (Z - 1) / (2 eta); and the
    # O(1/n) of a finite canonical system, 0.001 at n = 1024.
    expected = henderson_contact(eta)  # 1.7730
    assert abs(value - expected) < 4 * error + 0.005, (value, error, expected)
    assert error < 0.02  # and the measure is worth the name


def tools_gr():
    path = os.environ.get("DISKSIM_GR") or os.path.join(TOP, "tools", "gr")
    if not os.access(path, os.X_OK):
        pytest.skip("no tools/gr at %s (run make first)" % path)
    return path


@pytest.mark.parametrize("boundary", ["periodic", "walls"])
def test_g_of_a_frame_is_tools_grs_over_the_same_pairs(tmp_path, boundary):
    # The same frame file, read by both: periodic, the same normalisation,
    # so the same g to the 9 significant digits tools/gr prints (half a
    # unit of the 9th is at most 5e-9 of the value); with walls tools/gr
    # divides by the pairs of (box - 2R)^2 without the edges' correction,
    # so the pairs counted, g times the ideal count, are the same.
    gr = tools_gr()
    s = disksim.Sim(500, 5.0, integrator="event", boundary=boundary, seed=8)
    s.run(300)
    s.write_frame(tmp_path / "frame.txt")
    args = [gr, "--dr", "0.5", "--rmax", "100", str(tmp_path / "frame.txt")]
    if boundary == "periodic":
        args.insert(1, "--periodic")
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    theirs = np.loadtxt(out.splitlines(), comments="#")
    frame = disksim.read_frame(tmp_path / "frame.txt")
    r, g = disksim.rdf(frame.positions, 100.0, 200, boundary=boundary, radius=5.0)
    assert np.allclose(r, theirs[:, 0], rtol=1e-9, atol=0)
    pairs = 500 * 499 / 2
    edges = np.arange(201) * 0.5
    if boundary == "periodic":
        assert np.allclose(g, theirs[:, 1], rtol=1e-8, atol=0)
    else:
        ours = g * pairs * ideal_probability(edges, 990.0, 990.0, 1, 1)
        counted = theirs[:, 1] * pairs * np.pi * np.diff(edges**2) / 990.0**2
        assert np.allclose(ours, counted, rtol=1e-8, atol=0)
        assert np.array_equal(np.round(ours), disksim.pair_histogram(frame.positions, 0.5, 200))


REFUSALS = [
    (dict(r_max=600.0, boundary="periodic"), "r_max = 600 must be > 0 and at most 500"),
    (dict(r_max=999.0, radius=5.0), "at most 990"),
    (dict(r_max=0.0), "r_max = 0 must be > 0"),
    (dict(r_max=math.nan), "r_max = nan"),
    (dict(r_max=10.0, radius=-1.0), "radius = -1 must be finite and >= 0"),
    (dict(r_max=10.0, radius=600.0), "box = 1000 leaves the centres no room"),
    (dict(r_max=10.0, bins=0), "bins = 0"),
    (dict(r_max=10.0, positions=[[1.0, 1.0]]), "g(r) needs at least two centres"),
]


@pytest.mark.parametrize("change, words", REFUSALS, ids=[w for _, w in REFUSALS])
def test_a_range_beyond_where_the_normalisation_holds_is_refused(change, words):
    arguments = dict(positions=np.full((3, 2), 500.0), bins=10)
    arguments.update(change)
    positions, r_max, bins = (arguments.pop(k) for k in ("positions", "r_max", "bins"))
    with pytest.raises(disksim.ArgumentError) as info:
        disksim.rdf(positions, r_max, bins, **arguments)
    assert words in str(info.value)
