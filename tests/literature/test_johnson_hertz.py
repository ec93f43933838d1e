"""Hertz contact against the closed-form textbook solution for two spheres.

Johnson K. L., *Contact Mechanics*, Cambridge University Press, 1985, section 4.2,
eqs. (4.22)-(4.24): for a circular contact a^3 = 3 P R / (4 E*), delta = a^2 / R,
p_0 = 3 P / (2 pi a^2), with 1/R = 1/R_1 + 1/R_2 and 1/E* = (1-nu_1^2)/E_1 + (1-nu_2^2)/E_2.
Our general elliptical solution must collapse to it when R_x = R_y (k = 1, K = E = pi/2).
The tolerance (1e-9 relative) is numerical: both are exact formulas.
"""

import math

import pytest

from bearinglab.contact import hertz
from bearinglab.materials import BEARING_STEEL, effective_modulus


@pytest.mark.parametrize("load", [1.0, 250.0, 5000.0])
@pytest.mark.parametrize("r1, r2", [(6.35e-3, math.inf), (6.35e-3, 20e-3), (3.0e-3, 3.0e-3)])
def test_two_spheres_match_johnson(load, r1, r2):
    r_star = 1.0 / (1.0 / r1 + 1.0 / r2)
    e_star = 1.0 / (2 * BEARING_STEEL.compliance)
    a = (3 * load * r_star / (4 * e_star)) ** (1 / 3)
    delta = a**2 / r_star
    p0 = 3 * load / (2 * math.pi * a**2)
    # Hamrock's R_x, R_y are per direction: each direction sees both spheres' curvatures.
    c = hertz.point_contact(load, r_star, r_star, effective_modulus(BEARING_STEEL, BEARING_STEEL))
    assert float(c.ellipticity) == pytest.approx(1.0, abs=1e-12)
    assert float(c.semi_major) == pytest.approx(a, rel=1e-9)
    assert float(c.semi_minor) == pytest.approx(a, rel=1e-9)
    assert float(c.approach) == pytest.approx(delta, rel=1e-9)
    assert float(c.max_pressure) == pytest.approx(p0, rel=1e-9)
