"""Slip model (issue 14): what a record measures. Speed ratios from the continuous spin
phases and cage angle (not from sampled speeds), the check that a record's two halves
agree, and the settling time that is detected revolution by revolution."""

import math

import numpy as np
import pytest
from conftest import simulate_seed004_slip

from bearinglab.dynamics import Defect, SlipParameters, simulate, slip
from bearinglab.dynamics.defects import pack_defects
from bearinglab.operating import OperatingCondition
from bearinglab.validation.seed004 import SKF6205, SPEED

COND = OperatingCondition(radial_load=500.0, shaft_speed=SPEED)


@pytest.fixture(scope="module")
def packed():
    table = pack_defects([], SKF6205)
    return slip.pack(SKF6205, COND, SlipParameters(), table), table


def test_phase_ratio_needs_no_fine_sampling(packed):
    """The ratio is the phase advance over the span, exact however coarse the samples:
    at 100 Hz a ball at 0.97 of its pure-rolling spin turns 5.7 rad between samples
    (np.unwrap would fold that), and the speed may vary in between."""
    p, _ = packed
    w_c, w_r = slip.pure_rolling_speeds(p)
    t = np.arange(0, 0.3, 1 / 100.0)
    wobble = 0.2 * np.sin(2 * np.pi * 37.0 * t[None, :] + np.arange(9)[:, None])
    phases = 0.97 * w_r * t + wobble  # speed varies by +-0.2 * 2 pi 37 rad/s
    cage_ratio, spin_ratio = slip.phase_ratios(t, 0.99 * w_c * t, phases, p)
    exact = 0.97 + np.mean(wobble[:, -1] - wobble[:, 0]) / (t[-1] - t[0]) / w_r
    assert cage_ratio == pytest.approx(0.99, rel=1e-12)
    assert spin_ratio == pytest.approx(exact, rel=1e-12)
    assert 0.97 * w_r / 100.0 > np.pi  # more than half a turn per sample
    folded = np.unwrap(phases, axis=1)
    assert abs(np.mean(folded[:, -1] - folded[:, 0]) / (t[-1] - t[0]) / w_r - 0.97) > 0.1


def test_halves_check(packed):
    p, _ = packed
    w_c, w_r = slip.pure_rolling_speeds(p)
    t = np.linspace(0, 0.2, 1001)
    steady = np.tile(0.97 * w_r * t, (9, 1))
    check = slip.halves_check(t, w_c * t, steady, p)
    assert check["agree"] and check["difference"] < 1e-12
    assert check["spin_speed_ratio"] == pytest.approx((0.97, 0.97))
    drifting = np.tile(w_r * (0.97 * t + 0.05 * t**2), (9, 1))  # speeds up by 10 %/s
    check = slip.halves_check(t, w_c * t, drifting, p)
    assert not check["agree"]
    first, second = check["spin_speed_ratio"]
    assert second - first == pytest.approx(0.1 * 0.1, rel=1e-9)  # 0.1 s between half centres
    assert check["tolerance"] == slip.HALVES_TOLERANCE


def test_simulation_exposes_phase_and_measures_from_it():
    sim = simulate_seed004_slip(
        [Defect("ball", 0.27e-3)], duration=0.05, sample_rate=5e3, settle=0.1
    )
    n = sim.signal.n_samples
    assert sim.ball_spin_phase.shape == (9, n) and sim.cage_angle.shape == (n,)
    span = (n - 1) / 5e3
    pure_spin = sim.kinematic.orders["bsf"] * sim.kinematic.shaft_speed
    advance = sim.ball_spin_phase[:, -1] - sim.ball_spin_phase[:, 0]
    assert sim.spin_speed_ratio == pytest.approx(np.mean(advance) / span / pure_spin, rel=1e-12)
    # the phase is continuous and its slope is the spin speed the record also carries
    slope = np.gradient(sim.ball_spin_phase, 1 / 5e3, axis=1)[:, 1:-1]
    assert np.median(np.abs(slope / sim.ball_spin_speed[:, 1:-1] - 1)) < 1e-2
    assert np.all(np.diff(sim.ball_spin_phase, axis=1) > 0)
    assert sim.halves["agree"] and sim.warnings == ()


def test_rigid_model_has_no_phase():
    from bearinglab.validation.dynamics import ER16K

    cond = OperatingCondition(radial_load=50.0, shaft_speed=1750 * math.pi / 30)
    sim = simulate(ER16K, cond, duration=0.01, sample_rate=20e3)
    assert sim.ball_spin_phase is None and sim.spin_speed_ratio is None
    assert sim.halves is None and sim.warnings == ()


def test_unsettled_record_is_reported():
    # no settling with pocket friction 0.3: the balls lose spin over the first revolution
    sim = simulate_seed004_slip(
        duration=0.03, sample_rate=5e3, settle=0.0, parameters=SlipParameters(cage_friction=0.3)
    )
    first, second = sim.halves["spin_speed_ratio"]
    assert first - second > slip.HALVES_TOLERANCE
    assert not sim.halves["agree"]
    assert any("halves" in w and "not stationary" in w for w in sim.warnings)


def test_settling_is_detected_by_revolutions(packed):
    p, table = packed
    y0 = slip.initial_state(p)
    t, y, h, info = slip.settle(p, table, y0, 1e-3, slip.atol(9), 2e-4)
    w_c, _ = slip.pure_rolling_speeds(p)
    turns = info["turns"]
    assert slip.MIN_SETTLE_TURNS <= turns < slip.MAX_SETTLE_TURNS and info["settled"]
    assert info["change"] <= slip.SETTLE_TOLERANCE
    assert len(info["spin_speed_ratios"]) == turns
    assert turns * 2 * math.pi / w_c <= t < turns * 2 * math.pi / w_c + 2e-4
    assert y.shape == y0.shape and 0 < h
    # a rule it cannot meet: it stops at max_turns and says so
    *_, info = slip.settle(p, table, y0, 1e-3, slip.atol(9), 2e-4, tolerance=1e-12, max_turns=5)
    assert info["turns"] == 5 and not info["settled"]


def test_simulate_settles_by_the_rule_and_warns_when_it_cannot(monkeypatch):
    sim = simulate_seed004_slip(duration=0.02, sample_rate=5e3)
    turns = sim.stats["settle_turns"]
    assert turns >= slip.MIN_SETTLE_TURNS
    w_c = sim.kinematic.orders["ftf"] * sim.kinematic.shaft_speed
    assert sim.stats["settle_s"] == pytest.approx(turns * 2 * math.pi / w_c, abs=2e-4)
    assert not any("not settled" in w for w in sim.warnings)
    monkeypatch.setattr(slip, "SETTLE_TOLERANCE", 1e-12)
    monkeypatch.setattr(slip, "MAX_SETTLE_TURNS", 4)
    sim = simulate_seed004_slip(duration=0.02, sample_rate=5e3)
    assert sim.stats["settle_turns"] == 4
    assert any("not settled after 4 cage revolutions" in w for w in sim.warnings)
