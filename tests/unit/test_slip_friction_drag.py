"""Slip model (issue 14): the cage-pocket friction coefficient as a parameter with its
range, and the optional spin drag of the balls (Dennis, Singh & Ingham 1980)."""

import math

import numpy as np
import pytest
from conftest import simulate_seed004_slip

from bearinglab.dynamics import Defect, SlipParameters, _slip_kernels, slip
from bearinglab.dynamics.defects import pack_defects
from bearinglab.errors import InputError
from bearinglab.operating import OperatingCondition
from bearinglab.validation.seed004 import SKF6205, SPEED

COND = OperatingCondition(radial_load=500.0, shaft_speed=SPEED)


def _packed(**kwargs):
    table = pack_defects([Defect("ball", 0.3e-3, ball=2)], SKF6205)
    return slip.pack(SKF6205, COND, SlipParameters(**kwargs), table, None, 0.3e-3), table


def test_default_cage_friction_is_eq11_at_pure_sliding():
    # seed 004 eq. 11, mu = (-0.1 + 22.28 s) exp(-181.46 s) + 0.1, at slide-roll ratio 2
    assert SlipParameters().cage_friction == pytest.approx(
        (-0.1 + 22.28 * 2) * math.exp(-181.46 * 2) + 0.1, rel=1e-12
    )


@pytest.mark.parametrize("value", [-0.01, 0.31, 1.0, float("nan"), float("inf"), True, "0.1"])
def test_cage_friction_outside_its_range_is_refused(value):
    with pytest.raises(InputError, match=r"cage_friction.*\[0, 0\.3\]"):
        SlipParameters(cage_friction=value)


def test_cage_friction_limits_are_accepted_and_packed():
    for value in (0.0, 0.3):
        p, _ = _packed(cage_friction=value)
        assert p[_slip_kernels.CAGE_MU] == value


def test_spin_drag_switch_is_checked():
    with pytest.raises(InputError, match="spin_drag"):
        SlipParameters(spin_drag=1)
    with pytest.raises(InputError, match="oil_fraction"):
        SlipParameters(spin_drag=True, oil_fraction=0.0)
    assert SlipParameters().spin_drag is False  # off by default: not in seed 004


def test_spin_drag_twins_agree_on_both_branches():
    p, _ = _packed(spin_drag=True)
    w = np.concatenate([-np.logspace(-3, 4.5, 40), np.logspace(-3, 4.5, 40), [0.0]])
    twin = _slip_kernels.spin_drag_numpy(w, p)
    compiled = np.array([_slip_kernels.spin_drag(x, p) for x in w])
    np.testing.assert_allclose(compiled, twin, rtol=1e-12, atol=0)
    np.testing.assert_array_equal(np.sign(twin), np.sign(w))  # always opposes the spin


def test_spin_drag_is_stokes_couple_at_low_reynolds_and_continuous():
    p, _ = _packed(spin_drag=True, oil_fraction=0.05)
    rho, mu, r = 0.05 * 850.0, 0.05 * 0.04, 4e-3  # the seed's grease in 5 % mixture
    assert p[_slip_kernels.SPIN_RHO] == pytest.approx(rho)
    assert p[_slip_kernels.SPIN_MU] == pytest.approx(mu)
    w_32 = 32 * mu / (rho * (2 * r) ** 2)  # Re_r = rho w D^2 / mu = 32
    slow = 0.01 * w_32
    assert _slip_kernels.spin_drag(slow, p) == pytest.approx(
        8 * math.pi * mu * r**3 * slow, rel=1e-12
    )
    below, above = (_slip_kernels.spin_drag(w_32 * f, p) for f in (1 - 1e-9, 1 + 1e-9))
    assert above == pytest.approx(below, rel=3e-3)  # the fit meets Stokes at 32


def test_spin_drag_at_the_seed_case():
    # pure-rolling spin of the seed's 6205 at 2400 rpm, 3 % oil: Re_r ~ 800, inside the
    # 32-1000 range of the fit; M = 0.5 rho R^5 C_R w^2, C_R = 12.9 Re^-1/2 + 128.4 / Re
    p, _ = _packed(spin_drag=True)
    _, w = slip.pure_rolling_speeds(p)
    rho, mu, r = 0.03 * 850.0, 0.03 * 0.04, 4e-3
    re = rho * w * (2 * r) ** 2 / mu
    assert 700 < re < 900
    expected = 0.5 * rho * r**5 * (12.9 / math.sqrt(re) + 128.4 / re) * w * w
    assert _slip_kernels.spin_drag(w, p) == pytest.approx(expected, rel=1e-12)
    off, _ = _packed()
    assert _slip_kernels.spin_drag(w, off) == 0.0


@pytest.mark.parametrize("traction", ["seed004", "bair_winer"])
def test_slip_rhs_twins_agree_with_drag_and_pocket_friction(traction):
    p, table = _packed(traction=traction, spin_drag=True, cage_friction=0.25, pocket_clearance=1e-5)
    y0 = slip.initial_state(p)
    rng = np.random.default_rng(11)
    out = np.empty_like(y0)
    parts = np.empty((9, _slip_kernels.NG))
    for _ in range(50):
        y = y0 + rng.normal(0, 1, y0.size) * slip.atol(9) * 1e4
        t = rng.uniform(0, 0.1)
        _slip_kernels.slip_rhs(t, y, p, table, out, parts)
        np.testing.assert_allclose(
            out, _slip_kernels.slip_rhs_numpy(t, y, p, table), rtol=1e-9, atol=1e-6
        )


def test_spin_equation_carries_the_drag_moment():
    on, table = _packed(spin_drag=True)
    off, _ = _packed()
    y = slip.initial_state(on)
    a = _slip_kernels.slip_rhs_numpy(0.01, y, on, table)
    b = _slip_kernels.slip_rhs_numpy(0.01, y, off, table)
    spin = np.arange(_slip_kernels.NG + 5, y.size, _slip_kernels.NB)
    expected = -_slip_kernels.spin_drag_numpy(y[spin], on) / on[_slip_kernels.J_B]
    assert np.all(expected < 0)
    np.testing.assert_allclose(a[spin] - b[spin], expected, rtol=1e-9)
    np.testing.assert_array_equal(np.delete(a, spin), np.delete(b, spin))


def test_pocket_friction_and_spin_drag_slow_the_balls():
    """Both brake the spin of the balls in the unloaded zone: the spin ratio falls."""

    def ratio(**kwargs):
        return simulate_seed004_slip(
            duration=0.1,
            sample_rate=5e3,
            settle=0.15,
            parameters=SlipParameters(**kwargs),
        ).spin_speed_ratio

    base = ratio()
    assert ratio(cage_friction=0.3) < base - 5e-3
    assert ratio(spin_drag=True) < base - 1e-3
