"""Johnson K. L., *Contact Mechanics*, Cambridge 1985, sec. 4.2, eqs. 4.43-4.45 (two
parallel cylinders): a = (4 P R / (pi E*))^(1/2), p_0 = (P E* / (pi R))^(1/2) with P the
load per unit length, 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2. Issue 28's case: a
roller of 20 mm diameter and 20 mm length on a flat, 40 kN, E = 210 GPa, nu = 0.3 for
both: p_0 = 2710 MPa (0.1 %), half-width 0.470 mm. And Palmgren's empirical approach as
the check of ISO/TS 16281's roller constant: two contacts in series within 4 %.
"""

import math

import pytest

from bearinglab.contact.line import (
    iso16281_approach,
    iso16281_roller_constant,
    line_contact,
    palmgren_approach,
)

E_STAR = 1.0 / (2 * (1 - 0.3**2) / 210e9)
E_PRIME = 2 * E_STAR  # bearinglab's E' (Hamrock)
P = 40e3 / 0.02


def test_p0_of_the_issue():
    c = line_contact(P, 0.01, E_PRIME)
    assert float(c.max_pressure) / 1e6 == pytest.approx(2710.0, rel=1e-3)
    assert float(c.max_pressure) == pytest.approx(math.sqrt(P * E_STAR / (math.pi * 0.01)))
    assert float(c.half_width) == pytest.approx(math.sqrt(4 * P * 0.01 / (math.pi * E_STAR)))
    assert float(c.half_width) * 1e3 == pytest.approx(0.470, abs=5e-4)


def test_palmgren_checks_the_iso_constant():
    """Palmgren: 3.84e-5 Q^0.9 / l^0.8 mm per contact; ISO/TS 16281: c_l = 35948 l^(8/9)
    N/mm^(10/9) for both contacts, i.e. 35948^-0.9 = 7.94e-5 Q^0.9 / l^0.8 mm."""
    assert 35948.0**-0.9 == pytest.approx(7.94e-5, rel=1e-3)
    assert iso16281_roller_constant(0.01) == pytest.approx(35948e6 * 0.01 ** (8 / 9))
    ratio = iso16281_approach(4000.0, 0.02) / (2 * palmgren_approach(4000.0, 0.02))
    assert ratio == pytest.approx(1.0, abs=0.04)
