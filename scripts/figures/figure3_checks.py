"""The shape checks of Figure 3 (Cirio et al. 2011): each measures a quantity from the sphere-drop
run logs and compares it with a physical expectation fixed before the measurement. A check is a
dict: name, medium, measured, expected, tolerance, unit, passed, and how it was measured."""
import numpy as np

CONTACT_FRACTION = 0.05  # the sphere is in contact while the upward force exceeds 5 % of its weight
SETTLE_WINDOW = 0.5      # [s] the last half second is the settled state


def check(medium, name, measured, expected, tolerance, unit, passed, how):
    return {"medium": medium, "name": name, "measured": float(measured), "expected": expected,
            "tolerance": tolerance, "unit": unit, "passed": bool(passed), "how": how}


def first_contact(log):
    """(start, peak, end) sample indices of the first contact episode: from the first sample whose
    upward force exceeds CONTACT_FRACTION of the weight to the first one after it that does not
    (the last sample if contact never ends), with the force's maximum in between."""
    touching = log.fz > CONTACT_FRACTION * log.weight
    if not touching.any():
        return None
    start = int(np.argmax(touching))
    after = np.flatnonzero(~touching[start:])
    end = start + int(after[0]) if after.size else len(touching) - 1
    peak = start + int(np.argmax(log.fz[start:end + 1]))
    return start, peak, end


def peak_width(log, peak):
    """Full width at half maximum of the force peak at `peak` [s], by linear interpolation of the
    half-maximum crossings on each side."""
    t, f = log.time, log.fz
    half = 0.5 * f[peak]
    left = peak
    while left > 0 and f[left] > half:
        left -= 1
    right = peak
    while right < len(f) - 1 and f[right] > half:
        right += 1
    t_left = np.interp(half, [f[left], f[left + 1]], [t[left], t[left + 1]])
    t_right = np.interp(half, [f[right], f[right - 1]], [t[right], t[right - 1]])
    return t_right - t_left


def rebound_fraction(log, contact):
    """How far the sphere climbs back after its first impact, as a fraction of how far it fell:
    (highest point after the impact's lowest one, before the next contact) minus the lowest point,
    over (release height minus the lowest point)."""
    start, _, end = contact
    lowest = start + int(np.argmin(log.z[start:end + 1]))
    touching = log.fz > CONTACT_FRACTION * log.weight
    later = np.flatnonzero(touching[end + 1:])
    stop = end + 1 + int(later[0]) if later.size else len(log.z)
    highest = log.z[lowest:stop].max()
    return (highest - log.z[lowest]) / (log.z[0] - log.z[lowest])


def sampled_radius(log):
    """The sphere as sampled: N lattice sites of volume dx^3 make a ball of this radius [m]."""
    return np.cbrt(3.0 * log.lattice_sites * log.spacing ** 3 / (4.0 * np.pi))


def archimedes_depth(radius, density_ratio):
    """Depth d of a floating sphere's lowest point below the free surface: the submerged cap's
    volume pi d^2 (3R - d) / 3 equals the sphere's volume times rho_s / rho_f, i.e.
    d^2 (3R - d) = 4 R^3 rho_s / rho_f (Archimedes). Bisection on [0, 2R]."""
    target = 4.0 * radius ** 3 * density_ratio
    lo, hi = 0.0, 2.0 * radius
    for _ in range(60):
        d = 0.5 * (lo + hi)
        lo, hi = (d, hi) if d * d * (3.0 * radius - d) < target else (lo, d)
    return 0.5 * (lo + hi)


def free_surface(log, centre_xy, radius):
    """Height of the fluid's free surface away from the sphere [m], from the last snapshot: the
    particles beyond the sphere's meniscus (more than R + 2 dx from its axis) in columns of side
    dx, the median of the columns' top particles plus half a spacing (each particle stands for a
    cell of side dx). The median ignores a splashed droplet above the surface."""
    x = log.last_particles["block"]
    away = np.hypot(x[:, 0] - centre_xy[0], x[:, 1] - centre_xy[1]) > radius + 2.0 * log.spacing
    if not away.any():
        return None
    tops = {}
    for column, height in zip(map(tuple, np.floor(x[away, :2] / log.spacing).astype(int)), x[away, 2]):
        tops[column] = max(tops.get(column, -np.inf), height)
    return float(np.median(list(tops.values()))) + 0.5 * log.spacing


def hertz_indentation(load, radius, young_modulus, poisson_ratio):
    """Hertz's indentation of an elastic half-space by a rigid sphere under a load W [m]:
    d = (3 W / (4 E* sqrt(R)))^(2/3) with E* = E / (1 - nu^2) (Johnson, Contact Mechanics, 1985, eq. 4.23)."""
    effective_modulus = young_modulus / (1.0 - poisson_ratio ** 2)
    return (3.0 * load / (4.0 * effective_modulus * np.sqrt(radius))) ** (2.0 / 3.0)


def rigid_checks(rigid):
    contact = first_contact(rigid)
    if contact is None:
        return [check("rigid", "impact", 0.0, "> 0", None, "N", False, "the sphere never touched the block")]
    _, peak, _ = contact
    fall_time = np.sqrt(2.0 * (rigid.start_height - rigid.radius - rigid.block_top) / rigid.gravity)
    return [
        check("rigid", "impact peak / weight", rigid.fz[peak] / rigid.weight, ">= 3", None, "1",
              rigid.fz[peak] >= 3.0 * rigid.weight,
              "largest upward interaction force of the first contact over m g: an impact, not a resting load"),
        check("rigid", "impact peak width", peak_width(rigid, peak), f"<= {0.2 * fall_time:.4g}", None, "s",
              peak_width(rigid, peak) <= 0.2 * fall_time,
              "full width at half maximum of the first force peak, against a fifth of the free-fall time "
              "sqrt(2 h / g) from the release height: a short, sharp impact"),
        check("rigid", "rebound fraction", rebound_fraction(rigid, contact), ">= 0.1", None, "1",
              rebound_fraction(rigid, contact) >= 0.1,
              "climb after the first impact's lowest point over the fall to it: the sphere bounces"),
    ]


def deformable_checks(deformable, rigid):
    contact = first_contact(deformable)
    if contact is None:
        return [check("deformable", "impact", 0.0, "> 0", None, "N", False, "the sphere never touched the block")]
    _, peak, _ = contact
    checks = []
    rigid_contact = first_contact(rigid) if rigid is not None else None
    if rigid_contact is not None:
        r_peak = rigid_contact[1]
        checks += [
            check("deformable", "peak time - rigid peak time", deformable.time[peak] - rigid.time[r_peak], "> 0",
                  None, "s", deformable.time[peak] > rigid.time[r_peak], "the softer block's force peaks later"),
            check("deformable", "peak / rigid peak", deformable.fz[peak] / rigid.fz[r_peak], "< 1", None, "1",
                  deformable.fz[peak] < rigid.fz[r_peak], "and lower"),
            check("deformable", "peak width / rigid peak width",
                  peak_width(deformable, peak) / peak_width(rigid, r_peak), "> 1", None, "1",
                  peak_width(deformable, peak) > peak_width(rigid, r_peak), "and lasts longer (half-maximum widths)"),
        ]
    settled = deformable.settled(0.5)
    speed = np.sqrt(np.mean(deformable.vz[settled] ** 2))
    impact_speed = np.sqrt(2.0 * deformable.gravity * (deformable.start_height - deformable.radius - deformable.block_top))
    gap = np.mean(deformable.z[settled]) - deformable.radius - deformable.block_top
    indentation = hertz_indentation(deformable.weight, deformable.radius, deformable.young_modulus,
                                    deformable.poisson_ratio)
    checks += [
        check("deformable", "rebound fraction", rebound_fraction(deformable, contact), ">= 0.05", None, "1",
              rebound_fraction(deformable, contact) >= 0.05,
              "climb after the first impact's lowest point over the fall to it: the block pushes the sphere back up"),
        check("deformable", "settled speed / impact speed", speed / impact_speed, "<= 0.05", None, "1",
              speed <= 0.05 * impact_speed,
              "RMS vertical speed over the last 0.5 s against the impact speed sqrt(2 g h): at rest"),
        check("deformable", "settled indentation", -gap, f"{indentation:.3g} +/- {deformable.spacing:.3g}", None, "m",
              abs(-gap - indentation) <= deformable.spacing,
              "block's top minus the sphere's lowest point (centre - R, mean over the last 0.5 s), against Hertz's "
              "d = (3 W / (4 E* sqrt(R)))^(2/3), E* = E / (1 - nu^2), within one particle spacing (SPH contact "
              "acts across about a spacing): the sphere rests on top, neither sunk in nor hovering"),
        check("deformable", "max energy injected by the coupling", deformable.max_injected_energy,
              f"<= {0.01 * deformable.weight * (deformable.start_height - deformable.radius - deformable.block_top):.3g}",
              None, "J",
              deformable.max_injected_energy
              <= 0.01 * deformable.weight * (deformable.start_height - deformable.radius - deformable.block_top),
              "passivity observer's maximum (work of the coupling on proxy and handle), against 1 % of the "
              "drop's potential energy m g h: the coupling injects no energy"),
    ]
    return checks


def fluid_checks(fluid):
    checks = []
    settled = fluid.settled(0.5)
    radius = sampled_radius(fluid)
    density_ratio = fluid.mass / (4.0 / 3.0 * np.pi * radius ** 3) / fluid.fluid_density
    lowest = fluid.z - radius
    deepest = int(np.argmin(lowest))
    checks.append(check("fluid", "penetration below the initial surface", fluid.block_top - lowest[deepest],
                        f">= {fluid.spacing:.3g}", None, "m", fluid.block_top - lowest[deepest] >= fluid.spacing,
                        "initial free surface minus the sphere's lowest point at its deepest: the sphere goes in"))
    rise = fluid.z[deepest:].max() - fluid.z[deepest]
    checks.append(check("fluid", "rise after the deepest point", rise, f">= {fluid.spacing:.3g}", None, "m",
                        rise >= fluid.spacing, "the sphere comes back up"))
    if fluid.last_particles is None:
        checks.append(check("fluid", "floating depth", 0.0, "snapshot", None, "m", False,
                            "the log has no particle snapshot to find the free surface"))
    else:
        centre = np.mean(fluid.z[settled])
        surface = free_surface(fluid, (0.0, 0.0), radius)
        expected = archimedes_depth(radius, density_ratio)
        depth = surface - (centre - radius) if surface is not None else float("nan")
        checks.append(check("fluid", "floating depth", depth, expected, 0.10, "m",
                            surface is not None and abs(depth - expected) <= 0.10 * expected,
                            "free surface (top particle layer away from the sphere, last snapshot) minus the sphere's "
                            "lowest point (mean over the last 0.5 s), against Archimedes d^2 (3R - d) = 4 R^3 "
                            "rho_s / rho_f with the sampled radius; 10 % covers a sphere of a few spacings"))
    coupling_z = np.interp(fluid.time[settled], fluid.haptic_time, fluid.coupling_force[:, 2])
    support = np.mean(fluid.fz[settled] + coupling_z)
    checks.append(check("fluid", "settled support / weight", support / fluid.weight, 1.0, 0.05, "1",
                        abs(support / fluid.weight - 1.0) <= 0.05,
                        "mean vertical interaction plus coupling force over the last 0.5 s against m g: floating "
                        "in balance; 5 % allows for the remaining bobbing"))
    return checks
