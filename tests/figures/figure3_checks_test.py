"""The Figure 3 checks (scripts/figures/figure3_checks.py) on curves whose answer is known: a
physically right drop passes, and each deliberately wrong one (a sinking sphere, a sphere that does
not bounce, one still bouncing at the end, a coupling that injects energy) fails the check meant to
catch it. Run by ctest with Debian's python3."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "figures"))

from drop_log import DropLog  # noqa: E402
from figure3_checks import (archimedes_depth, deformable_checks, fluid_checks, free_surface,  # noqa: E402
                            hertz_indentation, rigid_checks, sampled_radius)

DT = 1e-3
RADIUS = 0.2
SPACING = 0.04


def drop(kind, z, fz, duration):
    """A sphere-drop log as DropLog would read it, from a centre height and a vertical force curve."""
    log = DropLog.__new__(DropLog)
    log.time = np.arange(0.0, duration, DT)
    n = len(log.time)
    log.z = np.asarray(z, dtype=float)[:n]
    log.vz = np.gradient(log.z, DT)
    log.force = np.zeros((n, 3))
    log.force[:, 2] = np.asarray(fz, dtype=float)[:n]
    log.block_kind = kind
    log.spacing = SPACING
    log.gravity = 9.81
    log.radius = RADIUS
    log.start_height = 0.45
    log.block_top = 0.2
    log.fluid_density = 1000.0
    log.young_modulus = 2e5
    log.poisson_ratio = 0.3
    # 485 lattice sites of (4 cm)^3 sample a ball of radius 0.195 m; a density of 500 kg/m^3.
    log.lattice_sites = 485
    log.mass = 500.0 * 4.0 / 3.0 * np.pi * sampled_radius(log) ** 3
    log.haptic_time = log.time
    log.coupling_force = np.zeros((n, 3))
    log.max_injected_energy = 0.0
    log.last_particles = None
    return log


def free_fall_then(t, z_contact, after):
    """Free fall from 0.45 m until the sphere reaches z_contact, then `after(t - t_contact)`."""
    t_contact = np.sqrt(2.0 * (0.45 - z_contact) / 9.81)
    return np.where(t < t_contact, 0.45 - 0.5 * 9.81 * t ** 2, after(np.maximum(t - t_contact, 0.0))), t_contact


def pulse(t, centre, width, height):
    return height * np.exp(-0.5 * ((t - centre) / (width / 2.355)) ** 2)


def by_name(checks):
    return {c["name"]: c for c in checks}


class Formulas(unittest.TestCase):
    def test_archimedes_half_density_floats_at_the_equator(self):
        # d^2 (3R - d) = 4 R^3 / 2 has the root d = R: half the volume submerged.
        self.assertAlmostEqual(archimedes_depth(0.2, 0.5), 0.2, places=12)
        # A neutrally buoyant sphere sinks to d = 2R, where d^2 (3R - d) is flat: bisection finds it
        # to the square root of the rounding error.
        self.assertAlmostEqual(archimedes_depth(0.2, 1.0), 0.4, places=6)
        self.assertLess(archimedes_depth(0.2, 0.25), 0.2)

    def test_hertz_indentation_by_hand(self):
        # W = 100 N, R = 0.25 m, E = 1e5 Pa, nu = 0: d = (300 / (4e5 * 0.5))^(2/3) = 1.5^(2/3) / 100^(2/3).
        self.assertAlmostEqual(hertz_indentation(100.0, 0.25, 1e5, 0.0), (300.0 / 2e5) ** (2.0 / 3.0), places=15)


class RigidChecks(unittest.TestCase):
    def bouncing(self, restitution, width):
        t = np.arange(0.0, 1.5, DT)
        z_contact = 0.4
        impact_speed = np.sqrt(2 * 9.81 * 0.05)
        z, t_contact = free_fall_then(t, z_contact, lambda s: z_contact + np.maximum(
            restitution * impact_speed * s - 0.5 * 9.81 * s ** 2, 0.0))
        return drop("rigid", z, pulse(t, t_contact, width, 2500.0), 1.5)

    def test_a_sharp_bounce_passes(self):
        self.assertTrue(all(c["passed"] for c in rigid_checks(self.bouncing(0.8, 0.012))))

    def test_a_dead_stop_is_no_bounce(self):
        checks = by_name(rigid_checks(self.bouncing(0.0, 0.012)))
        self.assertFalse(checks["rebound fraction"]["passed"])

    def test_a_slow_push_is_no_sharp_impact(self):
        checks = by_name(rigid_checks(self.bouncing(0.8, 0.08)))
        self.assertFalse(checks["impact peak width"]["passed"])


class FluidChecks(unittest.TestCase):
    def floating(self, z_end, support):
        """Falls to the surface, dips 12 cm deeper within 0.4 s, then relaxes to z_end."""
        t = np.arange(0.0, 3.0, DT)
        z, t_contact = free_fall_then(t, 0.4, lambda s: z_end + (0.4 - z_end) * np.exp(-s / 0.3)
                                      - 0.12 * np.sin(np.pi * np.clip(s / 0.4, 0.0, 1.0)))
        return drop("fluid", z, np.where(t > t_contact, support, 0.0), 3.0)

    def with_surface(self, log, surface):
        # A top layer of fluid particles half a spacing below the surface, in the tank's corners.
        corners = np.array([[x, y, surface - 0.5 * SPACING] for x in (-0.23, 0.23) for y in (-0.23, 0.23)])
        below = corners - [0.0, 0.0, SPACING]
        log.last_particles = {"time": log.time[-1], "block": np.vstack([corners, below])}
        return log

    def test_floating_at_archimedes_depth_passes(self):
        radius = 0.1949594845
        depth = archimedes_depth(radius, 0.5)
        surface = 0.24
        log = self.floating(surface - depth + radius, 0.0)
        log.force[:, 2] = np.where(log.time > 0.2, log.weight, 0.0)
        checks = by_name(fluid_checks(self.with_surface(log, surface)))
        for name in ("penetration below the initial surface", "rise after the deepest point", "floating depth",
                     "settled support / weight"):
            self.assertTrue(checks[name]["passed"], checks[name])

    def test_a_splashed_droplet_does_not_move_the_surface(self):
        radius = 0.1949594845
        surface = 0.24
        log = self.with_surface(self.floating(surface - archimedes_depth(radius, 0.5) + radius, 0.0), surface)
        droplet = np.array([[0.23, 0.23, surface + 0.3]])
        log.last_particles["block"] = np.vstack([log.last_particles["block"], droplet])
        self.assertAlmostEqual(free_surface(log, (0.0, 0.0), radius), surface, places=12)

    def test_a_sinking_sphere_fails(self):
        t = np.arange(0.0, 3.0, DT)
        z = np.maximum(0.45 - 0.5 * 9.81 * t ** 2, 0.2)  # falls and lies on the tank floor
        log = self.with_surface(drop("fluid", z, np.zeros_like(t), 3.0), 0.24)
        checks = by_name(fluid_checks(log))
        self.assertFalse(checks["rise after the deepest point"]["passed"])
        self.assertFalse(checks["floating depth"]["passed"])

    def test_no_snapshot_cannot_pass(self):
        checks = by_name(fluid_checks(self.floating(0.24, 150.0)))
        self.assertFalse(checks["floating depth"]["passed"])


class DeformableChecks(unittest.TestCase):
    def resting(self, amplitude_at_end):
        t = np.arange(0.0, 3.0, DT)
        z, t_contact = free_fall_then(t, 0.4, lambda s: 0.4 + 0.03 * np.abs(np.sin(np.pi * s / 0.35))
                                      * np.exp(-s / 0.4) + amplitude_at_end * np.sin(2 * np.pi * s / 0.3))
        log = drop("deformable", z, pulse(t, t_contact + 0.02, 0.04, 1100.0), 3.0)
        rest = log.block_top + RADIUS - hertz_indentation(log.weight, RADIUS, 2e5, 0.3)
        settle = t > 2.0
        log.z = np.where(settle, rest + amplitude_at_end * np.sin(2 * np.pi * t / 0.3), log.z)
        log.vz = np.gradient(log.z, DT)
        return log

    def rigid_reference(self):
        t = np.arange(0.0, 1.5, DT)
        t_contact = np.sqrt(2 * 0.05 / 9.81)
        return drop("rigid", np.full_like(t, 0.4), pulse(t, t_contact, 0.012, 2500.0), 1.5)

    def test_resting_on_top_passes(self):
        checks = deformable_checks(self.resting(0.0), self.rigid_reference())
        self.assertTrue(all(c["passed"] for c in checks), [c for c in checks if not c["passed"]])

    def test_still_bouncing_fails(self):
        checks = by_name(deformable_checks(self.resting(0.02), self.rigid_reference()))
        self.assertFalse(checks["settled speed / impact speed"]["passed"])

    def test_energy_from_the_coupling_fails(self):
        log = self.resting(0.0)
        log.max_injected_energy = 1.0
        checks = by_name(deformable_checks(log, self.rigid_reference()))
        self.assertFalse(checks["max energy injected by the coupling"]["passed"])


if __name__ == "__main__":
    unittest.main()
