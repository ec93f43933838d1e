"""The rigid dynamic model (seed 003) with a roller bearing: the line-contact law, its
compiled right-hand side against the NumPy twin, the refusals, and the diagnosis of
simulated records (healthy, outer race, inner race)."""

from dataclasses import replace

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.contact.line import iso16281_roller_constant, slice_positions
from bearinglab.contact.roller_race import slice_loads
from bearinglab.diagnosis.families import TOLERANCES, separated
from bearinglab.dynamics import Defect, _kernels, rigid, simulate
from bearinglab.dynamics.defects import pack_defects
from bearinglab.dynamics.record import simulate_record
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.operating import OperatingCondition
from bearinglab.roller_geometry import RollerProfile

NU205 = bearing_from_designation("NU205", rollers=True, overrides={"diametral_clearance": 20e-6})[0]
FLAT = replace(NU205, profile=RollerProfile("flat"))
COND = OperatingCondition.at_rpm(1800, radial_load=1000.0)


def test_unprofiled_roller_follows_the_line_law():
    k, n = rigid.roller_law(FLAT, 1000.0)
    assert n == pytest.approx(10 / 9)
    assert k == pytest.approx(iso16281_roller_constant(FLAT.roller_length))


def test_profiled_roller_is_stiffening():
    # a logarithmic profile under light load touches over part of the roller only:
    # the contact grows with the load, as a point contact's (n between 10/9 and 1.5+)
    k, n = rigid.roller_law(NU205, 1000.0)
    assert 10 / 9 < n < 1.7
    x = slice_positions(NU205.roller_length, 30)
    c_l = iso16281_roller_constant(NU205.roller_length)
    for q in (100.0, 340.0, 600.0):  # within the fit's range, 0.1-2 x 4.08 Fr / Z
        delta = slice_loads(q, c_l, x, NU205.profile_drop(x))[1]
        assert k * delta**n == pytest.approx(q, rel=0.1)


def test_rigid_rhs_twins_agree_for_rollers():
    table = pack_defects([Defect("outer", 1e-3, 20e-6), Defect("inner", 0.8e-3, 5e-6)], NU205)
    for bearing in (NU205, FLAT):
        p = rigid.pack(bearing, COND, rigid.RigidParameters(unbalance=1e-4), table)
        assert p[_kernels.EXPONENT] != 1.5
        rng = np.random.default_rng(3)
        out = np.empty(8)
        for _ in range(50):
            y = rigid.static_state(p) + rng.normal(0, 1e-6, 8) * np.r_[np.ones(4), 1e3 * np.ones(4)]
            t = rng.uniform(0, 1)
            _kernels.rigid_rhs_numba(t, y, p, table, out)
            np.testing.assert_allclose(
                out, _kernels.rigid_rhs_numpy(t, y, p, table), rtol=1e-10, atol=1e-9
            )


def test_static_state_carries_the_load():
    p = rigid.pack(FLAT, COND, rigid.RigidParameters(), pack_defects([], FLAT))
    y = rigid.static_state(p)
    z = FLAT.roller_count
    psi = p[_kernels.CAGE_PHASE] + 2 * np.pi * np.arange(z) / z
    e = np.stack([np.cos(psi), np.sin(psi)])
    delta = (y[0:2] - y[2:4]) @ e - p[_kernels.HALF_CLEARANCE]
    q = p[_kernels.K_HERTZ] * np.clip(delta, 0, None) ** p[_kernels.EXPONENT]
    # the force the rollers carry balances the load along its direction
    load = np.asarray(COND.load_vector()[:2])
    assert (e @ q) @ load / np.linalg.norm(load) == pytest.approx(np.linalg.norm(load), rel=1e-6)


def test_roller_refusals_name_the_parameter():
    with pytest.raises(InputError, match="model"):
        simulate(NU205, COND, (), model="slip", duration=0.2)
    tapered = bearing_from_designation("30205", rollers=True)[0]
    with pytest.raises(InputError, match="bearing"):
        simulate(tapered, COND, (), duration=0.2)
    with pytest.raises(InputError, match="roller diameter"):
        Defect("outer", 8e-3).check(NU205)
    with pytest.raises(InputError, match="roller index"):
        Defect("ball", 1e-3, ball=12).check(NU205)


def test_ball_window_stops_at_the_race_windows():
    kin = defect_frequencies(NU205, COND.shaft_speed)
    freqs = {name: kin.hz(name) for name in ("bpfo", "bpfi", "ball_defect")}
    below, above = separated(freqs, TOLERANCES)["ball"]
    # NU205: 2 x roller spin 152.76 Hz, BPFO 145.92 Hz: the window starts at 1.02 BPFO
    assert freqs["ball_defect"] * (1 - below) == pytest.approx(1.02 * freqs["bpfo"])
    assert above == TOLERANCES["ball"][1]
    ball = bearing_from_designation("6205")[0]
    kin = defect_frequencies(ball, COND.shaft_speed)
    freqs = {name: kin.hz(name) for name in ("bpfo", "bpfi", "ball_defect")}
    assert separated(freqs, TOLERANCES) == TOLERANCES


@pytest.mark.slow
@pytest.mark.parametrize(
    "defects, verdict",
    [
        ((), "no fault detected"),
        ((Defect("outer", 1e-3, 20e-6),), "outer_race"),
        ((Defect("inner", 1e-3, 20e-6),), "inner_race"),
        ((Defect("ball", 1e-3, 20e-6),), "roller"),  # named for the rolling element
    ],
)
def test_simulated_roller_records_are_diagnosed(defects, verdict):
    # with 1 m/s^2 of measurement noise, seeds 0-9; noise-free, the inner-race record is
    # "no fault detected": the leakage of its own lines widens the shaft-harmonic masks
    # over the BPFI series (see the capability page's limitations). Measured 2026-11-28
    # with the diagnosis of issue 27's second round: healthy and outer 10 of 10, inner
    # and roller 9 of 10 (the roller miss: its lines shown are the even harmonics of
    # 2 BSF, read as a series at twice it). At least 8 of 10 right, no wrong fault.
    verdicts = [
        simulate_record(
            NU205, COND, defects, duration=1.0, sample_rate=20e3, noise=1.0, seed=seed
        ).to_dict()["diagnosis"]["verdict"]
        for seed in range(10)
    ]
    assert verdicts.count(verdict) >= 8
    assert set(verdicts) <= {verdict, "no fault detected"}


@pytest.mark.slow
def test_heavily_loaded_roller_outer_race_with_noise():
    # NU310 at 900 rpm and 8 kN: noise-free, the leakage of the defect's lines (z ~ 1e9)
    # widens the shaft-harmonic masks over the BPFO series (see the capability page); with
    # 10 m/s^2 of measurement noise the series stands in 7 of 10 seeds (2026-11-28) and
    # the other 3 are called "roller": a line 2 % above BPFO (65.9 Hz) falls in the
    # roller family's window (2 BSF at -5.3 %). Measured, not fitted: at least 6 of 10,
    # never "no fault detected".
    bearing = bearing_from_designation(
        "NU310", rollers=True, overrides={"diametral_clearance": 20e-6}
    )[0]
    cond = OperatingCondition.at_rpm(900, radial_load=8000.0)
    verdicts = [
        simulate_record(
            bearing,
            cond,
            (Defect("outer", 1e-3, 20e-6),),
            duration=1.0,
            sample_rate=20e3,
            noise=10.0,
            seed=seed,
        ).to_dict()["diagnosis"]["verdict"]
        for seed in range(10)
    ]
    assert verdicts.count("outer_race") >= 6 and "no fault detected" not in verdicts
