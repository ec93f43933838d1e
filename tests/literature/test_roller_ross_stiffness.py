"""ROSS (petrobras/ross ``RollerBearingElement``, after Friswell M. I. et al., *Dynamics of
Rotating Machines*, Cambridge 2010, pp. 182-185): kyy = 1.0e9 n^0.9 l^0.8 F_s^0.1
cos(a)^1.9 [N/m with l in m, F_s in N], kxx = 0.49 kyy for 8 rollers; its docstring
example, 8 rollers of 0.03 m under 500 N (with alpha = 0: kyy = 7.32e8 N/m).

The model's radial stiffness (ISO/TS 16281's c_l, the discrete rollers, zero clearance,
a roller on the load line) has ROSS's exponents exactly (k = (10/9) F / delta with
F ~ Z c_l delta^(10/9), c_l ~ l^(8/9)), so the check holds beyond the example: within 3 %
(issue 28) for other counts, lengths and loads. ROSS's kxx/kyy ratios for 12 and 16
rollers (0.66, 0.74) are not reproduced (0.640, 0.711): the discrete set's ratio at 8
rollers (0.490) is; docs/capabilities/roller_bearings.md.
"""

import pytest

from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.roller_geometry import RollerBearing, RollerProfile


def stiffness(n, length, load):
    b = RollerBearing(
        roller_count=n,
        roller_diameter=10e-3,
        roller_length=length,
        pitch_diameter=0.1,
        profile=RollerProfile("flat"),
    )
    return solve_load_distribution(b, OperatingCondition(radial_load=load)).stiffness_matrix


def ross(n, length, load):
    return 1.0e9 * n**0.9 * length**0.8 * load**0.1


def test_the_docstring_example():
    k = stiffness(8, 0.03, 500.0)
    assert ross(8, 0.03, 500.0) == pytest.approx(7.32e8, rel=1e-3)
    assert k[1, 1] == pytest.approx(7.32e8, rel=0.03)
    assert k[0, 0] / k[1, 1] == pytest.approx(0.49, abs=0.005)


@pytest.mark.parametrize(
    "n, length, load", [(12, 0.02, 2000.0), (16, 0.01, 10e3), (20, 0.05, 300.0)]
)
def test_the_same_law_elsewhere(n, length, load):
    assert stiffness(n, length, load)[1, 1] == pytest.approx(ross(n, length, load), rel=0.03)
