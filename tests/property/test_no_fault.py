"""Records without a bearing fault give "no fault detected" at the default false-alarm
probability (1 %): white noise and healthy simulated bearings, in at least 95 % of seeds
(issue 11), with and without measurement noise (issue 21). Measured 2026-11-24 with the
nested sideband templates: white noise 0/200 seeds called faulty with cpw and raw, 1/200
with drs-sk and with all three; healthy rigid-model 6205 records 0/40 (noise 1 m/s^2;
1/40 before the nested templates). The optional ``ies`` method (2026-11-26): 0/200
white-noise records of 1-5 s (benchmarks/null_diagnosis.py). The default run is short;
the ``slow`` ones use more seeds."""

import math

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.diagnosis import NO_FAULT, analyze_signal
from bearinglab.dynamics import simulate
from bearinglab.kinematics import defect_frequencies
from bearinglab.operating import OperatingCondition

FS = 12000.0
SPEED = 1797 * math.pi / 30


@pytest.fixture(scope="module")
def bearing():
    return bearing_from_designation("6205")[0]


def _false_alarms_white(bearing, seeds, methods):
    kin = defect_frequencies(bearing, SPEED)
    return sum(
        analyze_signal(
            np.random.default_rng(s).standard_normal(int(FS)), FS, kin, methods=methods
        ).verdict
        != NO_FAULT
        for s in seeds
    )


def _false_alarms_healthy(bearing, seeds):
    condition = OperatingCondition(radial_load=500.0, shaft_speed=SPEED)
    bad = 0
    for s in seeds:
        sim = simulate(
            bearing, condition, [], model="rigid", duration=0.5, sample_rate=FS, noise=1.0, seed=s
        )
        bad += analyze_signal(sim.signal, None, sim.kinematic).verdict != NO_FAULT
    return bad


def _false_alarms_noise_free(cases, methods=("raw", "cpw", "drs-sk"), duration=0.5, sample_rate=FS):
    """Healthy rigid-model records without measurement noise, at (designation, radial load
    [N], speed [rpm]): the only lines are the varying compliance's (issue 21: before it was
    named and masked, `simulate` without a defect reported "outer race" every time)."""
    bad = 0
    for designation, load, rpm in cases:
        sim = simulate(
            bearing_from_designation(designation)[0],
            OperatingCondition(radial_load=load, shaft_speed=rpm * math.pi / 30),
            [],
            model="rigid",
            duration=duration,
            sample_rate=sample_rate,
        )
        bad += sum(
            analyze_signal(sim.signal, None, sim.kinematic, methods=m).verdict != NO_FAULT
            for m in methods
        )
    return bad


@pytest.mark.parametrize("methods", ["cpw", "all", "ies"])
def test_white_noise_is_no_fault(bearing, methods):
    assert _false_alarms_white(bearing, range(20), methods) <= 1  # >= 95 %


def test_healthy_simulation_is_no_fault(bearing):
    assert _false_alarms_healthy(bearing, range(4)) == 0


def test_noise_free_healthy_simulation_is_no_fault_with_every_method():
    assert _false_alarms_noise_free([("6205", 500.0, 1797.0), ("ER-16K", 50.0, 1750.0)]) == 0


@pytest.mark.slow
def test_noise_free_healthy_simulations_are_no_fault_over_loads_and_speeds():
    # measured 2026-11-26 (1 s at 20 kHz, these 27 cases x 3 methods): 2 of 81 called
    # faulty noise-free (6205 at 2000 N and 1797 rpm "ball" by cpw, 6310 at 2000 N and
    # 3600 rpm "outer race" by drs-sk: lines of the noise-free record's numerical floor),
    # 1 of 81 with 1 m/s^2 of noise
    cases = [
        (d, load, rpm)
        for d in ("6205", "ER-16K", "6310")
        for load in (100.0, 500.0, 2000.0)
        for rpm in (900.0, 1797.0, 3600.0)
    ]
    bad = _false_alarms_noise_free(cases, duration=1.0, sample_rate=20000.0)
    assert bad <= 0.05 * 3 * len(cases)


@pytest.mark.slow
@pytest.mark.parametrize("methods", ["raw", "cpw", "drs-sk", "all", "ies"])
def test_white_noise_is_no_fault_many_seeds(bearing, methods):
    assert _false_alarms_white(bearing, range(100, 300), methods) <= 10


@pytest.mark.slow
def test_healthy_simulation_is_no_fault_many_seeds(bearing):
    assert _false_alarms_healthy(bearing, range(100, 140)) <= 2
