#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The measurements of docs/physics.md's granular gases, through the Python
module: each subcommand runs its simulations and prints a table (tab
separated, a header line starting with #) that tools/analysis/plot_granular.plt
plots. Run from the top of the source tree after `make python`, with
PYTHONPATH=python; long ones under `nice`.

  haff E SEEDS N        a freely cooling gas at area fraction 0.05 (periodic):
                        T / T0 and T over Haff's law against t / tau
  clusters E N ETA OUT  the same at lower E, larger N: T over Haff's law and
                        the density's clumping against t / tau, frames to OUT
  driven E N T [DT]     the steady state of white-noise driving: T against the
                        theory's, a2 against van Noije and Ernst's, the powers
  collisions E N T      the same state's collisions: their rate and the energy
                        each loses against molecular chaos's, the pairs at contact
  barometric            a dilute elastic gas under gravity: n(y) and its fit
  sediment OUT          a dense inelastic gas falling to the floor, frames to OUT
"""
import math
import sys

import numpy as np

import disksim

CHI = lambda eta: (1.0 - 7.0 * eta / 16.0) / (1.0 - eta) ** 2  # Henderson's g(sigma)


def periodic_gas(n, eta, r=5.0, dt=0.01, seed=1):
    box = math.sqrt(n * math.pi * r * r / eta)
    return disksim.Sim(n, r, integrator="event", boundary="periodic", box=box, dt=dt,
                       seed=seed), box


def enskog_frequency(n, r, box, eta, temperature):
    """Collisions per disk per unit time, 2 sigma n chi sqrt(pi T / m)."""
    return 2.0 * (2.0 * r) * (n / box**2) * CHI(eta) * math.sqrt(math.pi * temperature)


def haff(e, seeds, n):
    """T(t) of freely cooling gases, averaged over seeds, at t = k tau / 4."""
    eta, r, points = 0.05, 5.0, 12
    ratio = np.zeros((seeds, points))
    for seed in range(seeds):
        s, box = periodic_gas(n, eta, r, seed=100 + seed)
        s.run(500)  # ~8 collisions a disk: Maxwell-Boltzmann
        s.set_restitution(e)
        t0, temp0 = s.time, s.temperature
        tau = 4.0 / ((1.0 - e * e) * enskog_frequency(n, r, box, eta, temp0))
        for k in range(points):
            s.run(int(round((t0 + (k + 1) * tau / 4.0) / s.dt)) - s.steps)
            x = (s.time - t0) / tau
            ratio[seed, k] = s.temperature * (1.0 + x) ** 2 / temp0
    print(f"# e {e}, n {n}, area fraction {eta}, {seeds} seeds: t/tau, T/T0 (Haff), "
          "T/T_Haff mean, its standard error")
    print("0\t1\t1\t0")
    for k in range(points):
        x = (k + 1) / 4.0
        m, err = ratio[:, k].mean(), ratio[:, k].std(ddof=1) / math.sqrt(seeds)
        print(f"{x:.2f}\t{1.0 / (1.0 + x) ** 2:.6f}\t{m:.5f}\t{err:.5f}")


def clumping(positions, box, cells):
    """The variance of the disks' counts in cells x cells boxes over their
    mean: 1 for a uniform random gas, growing as clusters form."""
    index = np.floor(positions / (box / cells)).astype(int) % cells
    counts = np.bincount(index[:, 0] * cells + index[:, 1], minlength=cells * cells)
    return counts.var() / counts.mean()


def clusters(e, n, eta, out):
    r = 5.0
    s, box = periodic_gas(n, eta, r, dt=0.01, seed=3)
    s.run(300)
    s.set_restitution(e)
    t0, temp0 = s.time, s.temperature
    tau = 4.0 / ((1.0 - e * e) * enskog_frequency(n, r, box, eta, temp0))
    cells = int(box / (8.0 * r))  # boxes of 8 radii a side
    print(f"# e {e}, n {n}, area fraction {eta}, box {box:.1f}, tau {tau:.4g}: t/tau, "
          "collisions per disk, T/T_Haff, clumping (cells of 8 R), frame")
    frame, x = 0, 0.0
    while x < 200.0:
        x = (s.time - t0) / tau
        ratio = s.temperature * (1.0 + x) ** 2 / temp0
        s.write_frame(f"{out}/frame_{frame:04d}.txt", velocities=True)
        print(f"{x:.3f}\t{2.0 * s.collision_count / n:.1f}\t{ratio:.4f}\t"
              f"{clumping(s.positions, box, cells):.3f}\t{frame}", flush=True)
        frame += 1
        # frames evenly spaced in ln(1 + t / tau), the HCS's own clock
        target = t0 + tau * (math.exp(math.log1p(x) + 0.1) - 1.0)
        s.run(max(1, int(round(target / s.dt)) - s.steps))


def sonine_white_noise(e, d=2):
    """van Noije and Ernst (1998): a2 of the heated (white-noise) state."""
    return 16.0 * (1 - e) * (1 - 2 * e * e) / (73 + 56 * d - 24 * d * e - 105 * e + 30 * (1 - e) * e * e)


def driven_gas(e, n, temperature, dt=0.01, eta=0.05, r=5.0):
    """A gas at area fraction eta driven by the strength for which the
    theory's T is temperature, run five of the energy's relaxation times
    1 / zeta into its steady state: the simulation, its box, the strength."""
    s, box = periodic_gas(n, eta, r, dt=dt, seed=7)
    a2 = sonine_white_noise(e)
    # m S (N - 1) / N = zeta T, zeta = (1 - e^2) omega_E(T) (1 + 3 a2 / 16) / 2
    zeta = (1 - e * e) * enskog_frequency(n, r, box, eta, temperature) * (1 + 3 * a2 / 16) / 2
    strength = zeta * temperature * n / (n - 1)
    s.set_restitution(e)
    s.set_drive(strength)
    s.run(int(5.0 / zeta / s.dt))
    s.reset_observables()
    return s, box, strength


def driven(e, n, temperature, dt=0.01):
    """The steady state of a driven gas at area fraction 0.05, the strength
    chosen for the theory's T; blocks of 2000 steps (10 time units at the
    default dt, about 10 collisions a disk at T = 2000)."""
    blocks = 40
    s, _, strength = driven_gas(e, n, temperature, dt)
    a2 = sonine_white_noise(e)
    temps, moments, inputs, losses = [], [], [], []
    for _ in range(blocks):
        bt, ba = 0.0, 0.0
        e_in, e_lost, t_start = s.energy_input, s.energy_lost, s.time
        for _ in range(20):
            s.run(50)
            v2 = (s.velocities**2).sum(axis=1)
            bt += s.temperature / 20
            ba += ((v2**2).mean() / (2 * v2.mean() ** 2) - 1) / 20
        temps.append(bt)
        moments.append(ba)
        inputs.append((s.energy_input - e_in) / (s.time - t_start))
        losses.append((s.energy_lost - e_lost) / (s.time - t_start))
    t, a, p_in, p_lost = (np.array(q) for q in (temps, moments, inputs, losses))
    stderr = lambda q: q.std(ddof=1) / math.sqrt(blocks)
    # the balance's error: the blocks' input less loss, which is dK/dt over each
    print(f"{e}\t{strength:.6g}\t{temperature}\t{t.mean():.2f}\t{stderr(t):.2f}"
          f"\t{a2:.5f}\t{a.mean():.5f}\t{stderr(a):.5f}"
          f"\t{s.power_input:.6g}\t{s.power_lost:.6g}\t{stderr(p_in - p_lost):.4g}", flush=True)


def approaching_pairs(positions, velocities, box, reach):
    """The pairs of a periodic square box closer than reach (minimum
    image): their distances and their radial speeds dr/dt (< 0 approaching)."""
    x, y = positions[:, 0], positions[:, 1]
    dx = x[None, :] - x[:, None]
    dx -= box * np.round(dx / box)
    i, j = np.nonzero(np.triu(np.abs(dx) < reach, 1))  # a strip first: few pairs
    dx = dx[i, j]
    dy = y[j] - y[i]
    dy -= box * np.round(dy / box)
    dist = np.hypot(dx, dy)
    near = dist < reach
    i, j, dx, dy, dist = i[near], j[near], dx[near], dy[near], dist[near]
    g = velocities[j] - velocities[i]
    return dist, (g[:, 0] * dx + g[:, 1] * dy) / dist


def collisions(e, n, temperature):
    """Why the driven gas's T departs from the theory's: the steady state
    balances (N - 1) m S = (N / 2) omega <Delta E>, omega = k omega_E(T)
    and <Delta E> = l (1 - e^2) T, so T^(3/2) k l is fixed, and the theory
    (first Sonine, molecular chaos) takes k l = 1 + 3 a2 / 16. Measured
    over the blocks of `driven`: k from the collisions counted, l from the
    energy lost (each collision loses (1 - e^2) m (g.n)^2 / 4, so l is
    <(g.n)^2> over collisions / (4 T / m)); the same under molecular chaos
    for the measured velocities (random pairs: omega = n sigma chi pi
    <|g_x|>, <(g.n)^2> = <|g_x|^3> / <|g_x|>); and the pairs closer than
    sigma + sigma / 40 that are heading for their contact: their density
    against Henderson's chi and their mean approach speed against chaos's
    2 sqrt(T / (pi m)), whose product is the collision rate's factor, and
    the collisions' mean |g.n| (the pairs weighted by their speed, as they
    cross the shell) against a Maxwell gas's sqrt(pi T / m) and chaos's."""
    eta, r, blocks, frames, every = 0.05, 5.0, 40, 100, 20
    s, box, strength = driven_gas(e, n, temperature)
    a2 = sonine_white_noise(e)
    sigma, shell = 2.0 * r, 2.0 * r / 40.0
    chi, density = CHI(eta), n / box**2
    # pairs per frame in the shell for g = 1: (N / 2) n 2 pi (sigma + shell / 2) shell
    ideal = 0.5 * n * density * 2.0 * math.pi * (sigma + 0.5 * shell) * shell
    rng = np.random.default_rng(11)
    rows = []
    for _ in range(blocks):
        c0, lost0, t0 = s.collision_count, s.energy_lost, s.time
        temp = k_chaos = l_chaos = hit_chaos = 0.0
        shell_all, shell_in, speed_in, flux, flux_speed = 0, 0, 0.0, 0.0, 0.0
        for _ in range(frames):
            s.run(every)
            v, tf = s.velocities, s.temperature
            temp += tf / frames
            half = rng.permutation(n)
            g = np.abs(v[half[: n // 2]] - v[half[n // 2 : 2 * (n // 2)]]).ravel()
            k_chaos += g.mean() / (2.0 * math.sqrt(tf / math.pi)) / frames
            l_chaos += (g**3).mean() / g.mean() / (4.0 * tf) / frames
            hit_chaos += (g**2).mean() / g.mean() / math.sqrt(math.pi * tf) / frames
            dist, speed = approaching_pairs(s.positions, v, box, sigma + shell)
            shell_all += len(dist)
            shell_in += int((speed < 0).sum())
            approach = -speed[speed < 0]
            speed_in += approach.sum() / (2.0 * math.sqrt(tf / math.pi))
            # the pairs cross the shell in proportion to their speed: the
            # collisions' mean |g.n| against sqrt(pi T / m), a Maxwell gas's
            flux += approach.sum()
            flux_speed += (approach**2).sum() / math.sqrt(math.pi * tf)
        count = s.collision_count - c0
        omega = 2.0 * count / n / (s.time - t0)
        rows.append((temp, omega / enskog_frequency(n, r, box, eta, temp), k_chaos,
                     (s.energy_lost - lost0) / count / ((1 - e * e) * temp), l_chaos,
                     shell_all / (frames * ideal * chi), 2.0 * shell_in / (frames * ideal * chi),
                     speed_in / max(shell_in, 1), flux_speed / max(flux, 1e-300), hit_chaos))
    q = np.array(rows)
    mean, err = q.mean(axis=0), q.std(axis=0, ddof=1) / math.sqrt(blocks)
    t, k, kc, l, lc = mean[:5]
    # T / T_theory = [P / P_theory (1 + 3 a2 / 16) / (k l)]^(2/3), in parts:
    # the input's noise (the power that came in, which the loss matched,
    # against its mean (N - 1) m S), the distribution's (chaos with the
    # measured velocities against the first Sonine theory's), and the
    # correlations' in the rate and in the loss
    theory = 1.0 + 3.0 * a2 / 16.0
    parts = [(s.power_lost / ((n - 1) * strength)) ** (2 / 3), (theory / (kc * lc)) ** (2 / 3),
             (kc / k) ** (2 / 3), (lc / l) ** (2 / 3)]
    cells = [f"{e}", f"{t:.1f}", f"{err[0]:.1f}", f"{temperature * np.prod(parts):.1f}"]
    for j in (1, 2, 3, 4):
        cells += [f"{mean[j]:.4f}", f"{err[j]:.4f}"]
    cells += [f"{100 * (p - 1):+.2f}" for p in parts]
    for j in (5, 6, 7, 8, 9):
        cells += [f"{mean[j]:.3f}", f"{err[j]:.3f}"]
    print("\t".join(cells), flush=True)


def barometric():
    n, r, box, g = 400, 0.5, 400.0, 30.0
    s = disksim.Sim(n, r, integrator="event", box=box, dt=0.25, seed=2)
    s.set_gravity(0.0, -g)
    e0 = s.kinetic_energy + s.potential_energy
    s.run(200)
    bins, heights, kt, frames = 40, np.zeros(40), 0.0, 4000
    for _ in range(frames):
        s.run(1)
        heights += np.histogram(s.positions[:, 1], bins=bins, range=(0.0, box))[0]
        kt += s.kinetic_energy / n / frames
    drift = (s.kinetic_energy + s.potential_energy - e0) / e0
    # the fit: the rate whose truncated mean on [r, box - r] is the mean height
    centres = (np.arange(bins) + 0.5) * box / bins
    mean = (heights * centres).sum() / heights.sum()
    lo, hi = 1e-6, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        d = box - 2 * r
        m = r + 1 / mid - d * math.exp(-mid * d) / (1 - math.exp(-mid * d))
        lo, hi = (mid, hi) if m > mean else (lo, mid)
    # and a straight line through ln n(y), the bins at the walls left out (a
    # centre keeps R from a wall, so they hold less), weighted by the counts
    inner = slice(1, bins - 1)
    slope = np.polyfit(centres[inner], np.log(heights[inner]), 1, w=np.sqrt(heights[inner]))[0]
    print(f"# n {n}, R {r}, box {box}, g {g}, kT {kt:.2f}: m g / kT {g / kt:.6g}, fitted "
          f"{lo:.6g} (ratio {lo * kt / g:.4f}) from the mean height, {-slope:.6g} (ratio "
          f"{-slope * kt / g:.4f}) from ln n(y); (E - E0) / E0 {drift:.2e} after "
          f"{s.collision_count} collisions, {s.wall_count} wall turns")
    print("# y, disks per unit height (time-averaged), the barometric law with m g / kT")
    norm = heights.sum() / frames  # the disks counted, n
    z = (math.exp(-g / kt * r) - math.exp(-g / kt * (box - r))) / (g / kt)
    for c, h in zip(centres, heights):
        print(f"{c:.1f}\t{h / frames / (box / bins):.5f}\t{norm * math.exp(-g / kt * c) / z:.5f}")


def sediment(out):
    n, r, g = 1500, 10.0, 100.0
    s = disksim.Sim(n, r, integrator="event", box=1000.0, box_y=1000.0, dt=0.01, seed=5)
    s.set_restitution(0.9, 0.9)
    s.set_contact_time(1e-3)
    s.set_gravity(0.0, -g)
    print(f"# n {n}, R {r}, g {g}, e 0.9, contact time 1e-3: t, kinetic, potential, "
          "collisions, psi6, frame")
    for frame in range(16):
        s.write_frame(f"{out}/frame_{frame:04d}.txt")
        print(f"{s.time:.2f}\t{s.kinetic_energy:.6g}\t{s.potential_energy:.6g}\t"
              f"{s.collision_count}\t{s.psi6:.3f}\t{frame}", flush=True)
        s.run(100)


if __name__ == "__main__":
    what, args = sys.argv[1], sys.argv[2:]
    if what == "haff":
        haff(float(args[0]), int(args[1]), int(args[2]))
    elif what == "clusters":
        clusters(float(args[0]), int(args[1]), float(args[2]), args[3])
    elif what == "driven":
        if args[0] == "header":
            print("# e, S, T theory, T, error, a2 van Noije-Ernst, a2, error, power in, power lost, "
                  "the error of their difference")
        else:
            driven(float(args[0]), int(args[1]), float(args[2]), *map(float, args[3:4]))
    elif what == "collisions":
        if args[0] == "header":
            print("# e, T, error, T from the parts, k = omega / omega_E(T), error, k under "
                  "molecular chaos, error, l = <(g.n)^2>_coll / (4 T / m), error, l under chaos, "
                  "error, T's excess (%) from the input's noise, the distribution, the rate's "
                  "correlations, the loss's correlations; at contact: g / chi, error, g of "
                  "approaching pairs / chi, error, their mean approach speed / chaos's, error, "
                  "the collisions' <|g.n|> / sqrt(pi T / m), error, the same under chaos, error")
        else:
            collisions(float(args[0]), int(args[1]), float(args[2]))
    elif what == "barometric":
        barometric()
    elif what == "sediment":
        sediment(args[0])
    else:
        sys.exit(__doc__)
