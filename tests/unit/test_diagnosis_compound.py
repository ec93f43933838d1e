"""A compound fault reported whole (issue 27 item 10): once a first fault is accepted, its
impacts are removed from the squared envelope and the other families read again on what
is left (bearinglab.diagnosis.residual)."""

import math

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import analyze_signal
from bearinglab.diagnosis.residual import fault_rate, without_impacts
from bearinglab.dynamics import Defect, simulate
from bearinglab.operating import OperatingCondition

FS = 20000.0
SPEED = 1750 * math.pi / 30
OUTER = Defect("outer", 1.2e-3, 0.25e-3)
BALL = Defect("ball", 1.2e-3)


@pytest.fixture(scope="module")
def er16k():
    return bearing_from_designation("ER-16K")[0]


def _simulated(er16k, defects, noise=0.0, seed=None):
    condition = OperatingCondition(radial_load=50.0, shaft_speed=SPEED)
    sim = simulate(
        er16k,
        condition,
        defects,
        model="rigid",
        duration=1.0,
        sample_rate=FS,
        noise=noise,
        seed=seed,
    )
    return sim.signal, sim.kinematic


def test_the_readme_compound_is_reported_whole_by_cpw(er16k):
    """The README's ER-16K, outer race and ball (1 s here): before, "outer race" alone -
    the ball's lines stood under the floor the outer race's impacts raise, 2 x BSF 2.1 Hz
    from BPFO + f_r where the outer race's intermodulation is masked. ~0.6 s."""
    signal, kin = _simulated(er16k, [OUTER, BALL])
    d = analyze_signal(signal, None, kin, methods="cpw")
    assert d.verdict == "compound: outer_race + ball"
    assert d.faults == ("outer_race", "ball")
    # the second fault shows as a series of its own: two harmonics or more at 1 %
    harmonics = {ln["n"] for ln in d.families["ball"]["lines"] if ln["kind"] == "harmonic"}
    assert len(harmonics) >= 2
    assert "impacts recurring at 104.1" in d.reason


def test_a_single_simulated_fault_stays_single(er16k):
    """The outer race alone, whose impacts are removed and the rest read again, in noise:
    nothing else is called (~0.5 s)."""
    signal, kin = _simulated(er16k, [OUTER], noise=1.0, seed=0)
    for methods in ("raw", "cpw"):
        assert analyze_signal(signal, None, kin, methods=methods).verdict == "outer_race"


def _impacts(rate_hz, seconds, jitter, seed=0):
    """Squared-envelope-like impacts at ``rate_hz``, each of its own strength, each
    interval jittered by ``jitter`` (a fraction: a real bearing's random slip)."""
    rng = np.random.default_rng(seed)
    t = np.arange(int(seconds * FS)) / FS
    starts = np.cumsum(1.0 / rate_hz * (1.0 + jitter * rng.standard_normal(int(seconds * rate_hz))))
    e = np.zeros_like(t)
    for start in starts:
        since = t - start
        on = (since >= 0) & (since < 0.01)
        e[on] += (1.0 + 0.5 * rng.random()) * np.exp(-since[on] / 1e-3)
    return e, t


def test_impacts_are_removed_only_where_they_recur_at_one_rate():
    """Strictly periodic impacts of varying strength lose their series; with 2 % random
    slip between impacts (a real bearing's: Randall & Antoni 2011, sec. 2) a fixed
    period's average cannot follow the drift, and the higher harmonics keep most of their
    power (the first fault stays in the remainder: nothing else is read there)."""
    rate = 104.19

    def harmonics(v, f):
        power = np.abs(np.fft.rfft(v - v.mean())) ** 2
        hz = np.fft.rfftfreq(v.size, 1.0 / FS)
        return np.array([power[abs(hz / (k * f) - 1.0) < 0.02].sum() for k in range(4, 9)])

    e, _ = _impacts(rate, 2.0, 0.0)
    found = fault_rate(e - e.mean(), FS, rate * 0.999, 1.2)
    assert found == pytest.approx(rate, rel=2e-5)
    assert np.all(harmonics(without_impacts(e, FS, found), found) < 1e-3 * harmonics(e, found))
    e, _ = _impacts(rate, 2.0, 0.02)
    found = fault_rate(e - e.mean(), FS, rate, 1.2)
    kept = harmonics(without_impacts(e, FS, found), found).sum() / harmonics(e, found).sum()
    assert kept > 0.5
