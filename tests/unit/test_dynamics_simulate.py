"""simulate(): inputs refused with a clear error, reproducible output, the fault lines
where the kinematics put them (rigid model, two bearings), and the slip model's outputs."""

import math

import numpy as np
import pytest
from conftest import simulate_seed004_slip

from bearinglab.catalog import bearing_from_designation
from bearinglab.dynamics import Defect, RigidParameters, SlipParameters, simulate
from bearinglab.errors import InputError
from bearinglab.operating import OperatingCondition
from bearinglab.signal import envelope_spectrum, find_peaks, match_peaks
from bearinglab.validation.dynamics import ER16K

COND = OperatingCondition(radial_load=50.0, shaft_speed=1750 * math.pi / 30)


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"model": "flexible"}, "model"),
        ({"duration": -1.0}, "duration"),
        ({"duration": 1e-3, "sample_rate": 20e3}, "duration"),
        ({"sample_rate": 0.0}, "sample_rate"),
        ({"rtol": 0.5}, "rtol"),
        ({"noise": -1.0}, "noise"),
        ({"settle": -0.1}, "settle"),
        ({"parameters": SlipParameters()}, "parameters"),
    ],
)
def test_bad_inputs_name_the_parameter(kwargs, parameter):
    with pytest.raises(InputError, match=parameter):
        simulate(ER16K, COND, **{"duration": 0.01, **kwargs})


def test_parameters_are_checked():
    with pytest.raises(InputError, match="shaft_mass"):
        RigidParameters(shaft_mass=0.0)
    with pytest.raises(InputError, match="traction"):
        SlipParameters(traction="coulomb")
    for onset in (0.0, -1e-8, float("nan")):  # the ramp divides by it
        with pytest.raises(InputError, match="damping_onset"):
            SlipParameters(damping_onset=onset)
    with pytest.raises(InputError, match="shaft_speed"):
        simulate(ER16K, OperatingCondition(radial_load=50.0), duration=0.01)
    with pytest.raises(InputError, match="contact_angle"):
        simulate(bearing_from_designation("7205")[0], COND, model="slip", duration=0.01)


def test_same_inputs_same_signal():
    a = simulate(
        ER16K, COND, [Defect("outer", 1e-3)], duration=0.05, sample_rate=20e3, noise=0.5, seed=7
    )
    b = simulate(
        ER16K, COND, [Defect("outer", 1e-3)], duration=0.05, sample_rate=20e3, noise=0.5, seed=7
    )
    np.testing.assert_array_equal(a.signal.channels["acc_y"], b.signal.channels["acc_y"])
    assert a.signal.n_samples == 1000 and a.signal.sample_rate == 20e3


def _lines(bearing, load, defects, seconds=1.0):
    sim = simulate(
        bearing,
        OperatingCondition(radial_load=load, shaft_speed=1750 * math.pi / 30),
        defects,
        duration=seconds,
        sample_rate=20e3,
    )
    spec = envelope_spectrum(sim.signal.channels["acc_y"], 20e3, band="auto")
    names = ("shaft", "ftf", "bpfo", "bpfi", "bsf", "ball_defect")
    peaks = match_peaks(
        find_peaks(spec, count=8, min_frequency=5, max_frequency=500),
        {k: sim.kinematic.hz(k) for k in names},
        slip_tolerance=0.0,
    )
    return [(p["matched"], p["harmonic"]) for p in peaks]


@pytest.mark.parametrize("designation, load", [("ER-16K", 50.0), ("6205-2RS", 500.0)])
def test_race_faults_show_their_lines(designation, load):
    bearing = bearing_from_designation(designation)[0]
    outer = _lines(bearing, load, [Defect("outer", 1.2e-3, 0.25e-3)])
    assert outer[0] in (("bpfo", 1), ("bpfo", 2)) and ("bpfo", 1) in outer
    inner = _lines(bearing, load, [Defect("inner", 1.2e-3, 0.25e-3)])
    assert ("bpfi", 1) in inner


@pytest.mark.parametrize("bearing, load", [(ER16K, 50.0), ("6205-2RS", 500.0)])
def test_ball_fault_shows_its_line(bearing, load):
    if isinstance(bearing, str):
        bearing = bearing_from_designation(bearing)[0]
    assert ("ball_defect", 1) in _lines(bearing, load, [Defect("ball", 1.2e-3)], seconds=2.0)


def test_slip_model_outputs():
    sim = simulate_seed004_slip(
        [Defect("ball", 0.3e-3)], duration=0.01, sample_rate=20e3, settle=0.01
    )
    assert set(sim.signal.names) >= {"acc_x", "acc_y", "disp_x", "disp_y", "cage_speed"}
    assert sim.ball_spin_speed.shape == (9, 200) and sim.slip_outer.shape == (9, 200)
    assert 0.95 < sim.spin_speed_ratio < 1.0  # balls lag pure rolling, a little
    assert abs(sim.cage_speed_ratio - 1) < 0.01
    assert np.all(np.isfinite(sim.signal.channels["acc_y"]))
    # the inner ring sits on the lower balls: its mean displacement points down
    assert np.mean(sim.signal.channels["disp_y"]) < 0


def test_slip_tolerances_do_not_move_the_ball_speeds():
    runs = [
        simulate_seed004_slip(
            duration=0.005,
            sample_rate=20e3,
            settle=0.01,
            rtol=rtol,
            parameters=SlipParameters(regularisation_speed=v, damping_onset=onset),
        )
        for rtol, v, onset in (
            (1e-3, 1e-3, 1e-8),
            (1e-4, 1e-3, 1e-8),
            (1e-3, 5e-4, 1e-8),
            (1e-3, 1e-3, 1e-9),
        )
    ]
    ratios = [r.spin_speed_ratio for r in runs]
    assert max(ratios) - min(ratios) < 1e-3, ratios
