"""Friction: seed 003's Table III and the published behaviour of the SKF model.

Seed 003 (friction section, lines 1079-1113): Table III of coefficients, F = P mu and
M = mu P d_m / 2 with d_m the pitch diameter. The coefficients are also cases in
bearinglab.validation.friction (run by test_published_cases.py); here they are checked
once more against the printed rows, with the torque formula that uses them.

SKF model: no published worked example (an SKF catalogue example or a calculator value
with all its inputs) was found in the stored sources, so no SKF number is asserted as a
published value. Instead these tests check what the SKF catalogue (10000 EN, "The SKF model
for calculating the frictional moment", Diagram 1 and the text around it) says the model
does: the four zones of friction against speed -- high boundary friction at start-up, a
fall through mixed lubrication, a rise in full-film lubrication, and a levelling-off by
inlet shear heating and starvation -- the sliding coefficient moving from mu_bl = 0.15 to
mu_EHL = 0.05 as the film builds (catalogue page 105 as stored), and the moment growing with
load. What was and was not checked against the catalogue is listed in
docs/capabilities/friction.md.
"""

import math
from itertools import pairwise

import numpy as np
import pytest

from bearinglab.friction import (
    constant_coefficient_torque,
    deep_groove_constants,
    deep_groove_load_variables,
    friction_coefficient,
    skf_frictional_moment,
)
from bearinglab.validation.friction import TABLE_III

RPM = math.pi / 30.0
C62 = deep_groove_constants("62")


@pytest.mark.parametrize("row, kind, printed", TABLE_III, ids=[k for _, k, _ in TABLE_III])
def test_seed003_table_iii(row, kind, printed):
    # printed to four decimals; stored exactly
    assert friction_coefficient(kind) == printed


def test_seed003_torque_uses_the_pitch_diameter():
    # lines 1105-1111: M from P, mu and "дм = диаметр шага подшипника" (pitch diameter)
    mu = friction_coefficient("radial_ball")
    assert constant_coefficient_torque(mu, 1000.0, 0.039) == pytest.approx(mu * 1000 * 0.039 / 2)


def _moment(n_rpm, nu_mm2_s=20.0, fr=1000.0, fa=0.0, **kw):
    return skf_frictional_moment(
        "radial_ball", 0.025, 0.052, fr, fa, n_rpm * RPM, nu_mm2_s * 1e-6, C62, **kw
    )


def test_skf_zones_of_friction_against_speed():
    speeds = np.geomspace(1.0, 30000.0, 200)
    total = np.array([_moment(n).total for n in speeds])
    i = int(np.argmin(total))
    # zone 1 -> 2: friction falls from its boundary value; zone 3: then rises again
    assert 0 < i < len(speeds) - 1
    assert total[0] > total[i] and total[-1] > total[i]
    # at start-up only boundary sliding acts: mu_sl = mu_bl = 0.15
    start = _moment(0.0)
    assert start.sliding_friction_coefficient == 0.15 and start.rolling == 0.0
    # zone 4: the thermal and starvation factors make the rise slower than M_rr ~ (nu n)^0.6
    hi = [_moment(n, 68.0) for n in (10000.0, 20000.0)]
    slope = math.log(hi[1].rolling / hi[0].rolling) / math.log(2.0)
    assert slope < 0.6


def test_skf_sliding_coefficient_goes_from_boundary_to_full_film():
    mu = [_moment(n).sliding_friction_coefficient for n in (0.0, 10.0, 1000.0, 20000.0)]
    assert mu[0] == 0.15 and all(a > b for a, b in pairwise(mu))
    assert mu[-1] == pytest.approx(0.05, abs=1e-6)


@pytest.mark.parametrize("n", [100.0, 3000.0])
def test_skf_moment_grows_with_load(n):
    loads = [100.0, 500.0, 2000.0, 5000.0]
    m = [_moment(n, fr=f).total for f in loads]
    assert all(a < b for a, b in pairwise(m))
    # and with an added axial load (deep-groove form with alpha_F, C_0 = 7.8 kN)
    assert _moment(n, fa=500.0, static_load_rating=7800.0).total > _moment(n).total


def test_skf_rolling_moment_grows_with_viscosity_times_speed_in_full_film():
    # at high kappa the rolling moment follows (nu n)^0.6 damped by phi_ish, phi_rs < 1
    nus = [20.0, 40.0, 80.0]
    m = [_moment(3000.0, nu) for nu in nus]
    assert all(a.rolling < b.rolling for a, b in pairwise(m))
    raw = [x.rolling / (x.inlet_shear_factor * x.replenishment_factor) for x in m]
    assert raw[1] / raw[0] == pytest.approx(2**0.6, rel=1e-12)


def test_table_2a_deep_groove_forms_as_printed():
    # catalogue Table 2a (as stored): F_a = 0 -> d_m^-0.26 F_r^(5/3); F_a > 0 -> d_m^-0.145
    # (F_r^5 + S2 d_m^1.5 / sin(alpha_F) F_a^4)^(1/3), alpha_F = 24.6 (F_a/C_0)^0.24 deg
    dm, fr, fa, c0 = 38.5, 1000.0, 300.0, 7800.0
    g0 = deep_groove_load_variables(dm * 1e-3, fr, 0.0, C62)
    assert g0[1] == pytest.approx(C62.s1 * dm**-0.26 * fr ** (5 / 3), rel=1e-12)
    g = deep_groove_load_variables(dm * 1e-3, fr, fa, C62, static_load_rating=c0)
    sin_a = math.sin(math.radians(24.6 * (fa / c0) ** 0.24))
    assert g[0] == pytest.approx(C62.r1 * dm**1.96 * (fr + C62.r2 / sin_a * fa) ** 0.54)
    assert g[1] == pytest.approx(
        C62.s1 * dm**-0.145 * (fr**5 + C62.s2 * dm**1.5 / sin_a * fa**4) ** (1 / 3)
    )
