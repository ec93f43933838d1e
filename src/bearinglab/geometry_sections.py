"""Cross-sections of grooved bearing rings (layer 1): area, centroid radius, second moment
and width of a ring bounded by two cylinders, less its raceway groove.

:class:`bearinglab.geometry.BallBearing` places the shoulders (``GROOVE_DEPTH_RATIO``) and
takes its ring sections and ring masses from here; the outer-ring resonance model of
seed 000 (:mod:`bearinglab.rings`) needs R, S and I. ``bearinglab.geometry`` re-exports
:class:`RingSection` and :func:`grooved_ring_section`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from .errors import InputError
from .macrogeometry import Race


class RingSection(NamedTuple):
    """Cross-section of a grooved ring: area [m^2], centroid (mean) radius [m],
    second moment about the axis through the centroid parallel to the bearing axis
    [m^4] (the one for in-plane bending), and width [m]."""

    area: float
    mean_radius: float
    second_moment: float
    width: float


def grooved_ring_section(
    inner_radius, outer_radius, width, groove_radius, groove_bottom_radius, race: Race
) -> RingSection:
    """Cross-section of a ring bounded by two cylinders, minus its raceway groove.

    The ring is the rectangle inner_radius <= r <= outer_radius, |z| <= width/2, less the
    part of the groove circle (radius f D_w, touching the groove bottom) inside it.
    Integrated in closed form in r (the groove's chord is 2 sqrt(R^2 - (r - c)^2), whose
    moments have elementary antiderivatives); a test checks it against scipy's quad.

    Parameters
    ----------
    inner_radius, outer_radius : float
        Radial bounds of the ring material (bore or shoulder, shoulder or outside) [m].
    width : float
        Ring width B [m].
    groove_radius : float
        Groove radius f D_w [m].
    groove_bottom_radius : float
        Radius of the groove bottom d_i/2 or d_o/2 [m].
    race : {"inner", "outer"}
        The groove opens outward for the inner ring and inward for the outer ring.
    """
    centre = groove_bottom_radius + (groove_radius if race == "inner" else -groove_radius)

    def chord(r):
        h2 = groove_radius**2 - (r - centre) ** 2
        return 2.0 * math.sqrt(h2) if h2 > 0 else 0.0

    if chord(inner_radius if race == "outer" else outer_radius) >= width:
        raise InputError(
            "width",
            width,
            f"more than the groove opening "
            f"{chord(inner_radius if race == 'outer' else outer_radius):.6g} m",
            "the groove runs over the ring's side faces",
        )
    # moments k = 0, 1, 2 of the section about r_ref (mid-ring, to keep the second moment
    # free of cancellation): rectangle minus the groove, u = r - centre within [-R, R]
    r_ref = 0.5 * (inner_radius + outer_radius)
    big_r, c = groove_radius, centre - r_ref
    a, b = inner_radius - r_ref, outer_radius - r_ref
    rect = [width * (b ** (k + 1) - a ** (k + 1)) / (k + 1) for k in range(3)]
    u0, u1 = max(a - c, -big_r), min(b - c, big_r)
    groove = [0.0, 0.0, 0.0]
    if u1 > u0:

        def antiderivatives(u):  # of s, u s and u^2 s with s = sqrt(R^2 - u^2)
            root = math.sqrt(max(big_r**2 - u * u, 0.0))
            arc = math.asin(max(-1.0, min(1.0, u / big_r)))
            return (
                0.5 * (u * root + big_r**2 * arc),
                -(root**3) / 3.0,
                u * (2.0 * u * u - big_r**2) * root / 8.0 + big_r**4 * arc / 8.0,
            )

        f0, f1, f2 = (
            hi - lo for hi, lo in zip(antiderivatives(u1), antiderivatives(u0), strict=True)
        )
        groove = [2.0 * f0, 2.0 * (f1 + c * f0), 2.0 * (f2 + 2.0 * c * f1 + c * c * f0)]
    m0, m1, m2 = (r - g for r, g in zip(rect, groove, strict=True))
    area = m0
    mean = r_ref + m1 / m0
    second = m2 - m1 * m1 / m0
    return RingSection(area, mean, second, width)
