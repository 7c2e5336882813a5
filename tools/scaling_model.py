#!/usr/bin/env python3
"""The scaling model of docs/scaling.md: the time of one step of a domain-decomposed run as the
work of a rank's own particles plus the exchange of its halo, from figures measured on one
machine (talus-bench, talus-comm-bench). Prints the table of docs/scaling.md.

usage: scaling_model.py [--particle-us 0.16] [--ghost-us 0.10] [--latency-us 2.0]
                        [--cross-us 3.0] [--cross-ghost-us 0.13]

A rank owns a cube of side L (in bounding diameters d) of number density n on a 3-D grid of
ranks; its halo is the shell of thickness r_g = 1.15 d (the largest diameter plus the 15 % skin)
around it on both sides along two axes and on the upper side only along the pair list's slab
axis (the half shell of Talus's staged halo, rank_grid.h), with Newton's third law across ranks
(forward positions, reverse forces). Per step: n L^3 particles at t_p each,
n ((L + 2 r_g)^2 (L + r_g) - L^3) ghosts at t_g each (pack, send, unpack, forward and reverse),
and 10 messages (5 passes each way: two along each of two axes, one along the slab axis) at
the latency.
"""
import argparse

R_GHOST = 1.15  # d: the largest diameter plus the skin


def rank_cube(particles, ranks, density):
    """Side L (d) of one rank's cube and its halo fraction (ghosts per owned particle)."""
    local = particles / ranks
    side = (local / density) ** (1.0 / 3.0)
    return side, (1.0 + 2.0 * R_GHOST / side) ** 2 * (1.0 + R_GHOST / side) - 1.0


def efficiency(particles, ranks, density, particle_us, ghost_us, latency_us, messages=10):
    side, halo = rank_cube(particles, ranks, density)
    local = particles / ranks
    work = local * particle_us
    exchange = local * halo * ghost_us + messages * latency_us
    return side, halo, local * halo, work / (work + exchange)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--particle-us", type=float, default=0.16, help="us per sphere-step, one core (chute32k_1t)")
    ap.add_argument("--ghost-us", type=float, default=0.10, help="us per ghost-step, forward + reverse (talus-comm-bench)")
    ap.add_argument("--latency-us", type=float, default=2.0, help="us per message between nodes")
    ap.add_argument("--cross-us", type=float, default=3.0, help="us per cross-step, one core (crosspile_flow_1t)")
    ap.add_argument("--cross-ghost-us", type=float, default=0.13, help="us per cross ghost-step (orientation too)")
    a = ap.parse_args()
    # Spheres of a dense flow: volume fraction 0.58, n = 0.58 / (pi/6) per d^3. Crosses of
    # Huet et al. 2021 (two 27 x 2 x 3 mm cuboids, 312 mm^3) at volume fraction 0.3, counted
    # per cube of their 27 mm bounding diameter: 0.3 * 27^3 / 312.
    spheres = 0.58 / (3.141592653589793 / 6.0)
    crosses = 0.3 * 27.0 ** 3 / 312.0
    cases = [("spheres", 1e6, spheres, a.particle_us, a.ghost_us), ("spheres", 1e8, spheres, a.particle_us, a.ghost_us),
             ("crosses", 1e5, crosses, a.cross_us, a.cross_ghost_us)]
    print("| system | ranks | particles per rank | side L (d) | ghosts per particle | ghosts per rank | efficiency |")
    print("|---|---|---|---|---|---|---|")
    for kind, n, density, t_p, t_g in cases:
        for ranks in (64, 1024):
            side, halo, ghosts, e = efficiency(n, ranks, density, t_p, t_g, a.latency_us)
            print("| %.0e %s | %d | %.0f | %.1f | %.2f | %.0f | %.2f |" % (n, kind, ranks, n / ranks, side, halo, ghosts, e))


if __name__ == "__main__":
    main()
