"""Sound radiation of the inner ring and the balls (bearinglab.noise; seed 003 eqs. 19-27,
seed 002 directivity)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.signal

from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.noise import (
    REFERENCE_PRESSURE,
    Air,
    FieldPoint,
    cylinder_transfer,
    field,
    oscillating_sphere_transfer,
    pulsating_sphere_transfer,
    sound_pressure,
    sound_pressure_level,
    velocity_from_positions,
)
from bearinglab.units import rpm_to_rad_s

FS = 48000.0
N = 4800  # 0.1 s: 10 Hz lines, whole periods of every test tone
T = np.arange(N) / FS
RHO, C = 1.21, 343.0


def _tone(frequency, amplitude=1e-3, phase=0.0):
    return amplitude * np.sin(2 * np.pi * frequency * T + phase)


def _amplitude(p):
    """Amplitude of a pure tone from its RMS."""
    return math.sqrt(2.0) * float(np.sqrt(np.mean(p**2)))


# ---------------------------------------------------------------- SPL, eq. 27


def test_spl_of_reference_pressure_is_zero_db():
    assert sound_pressure_level(REFERENCE_PRESSURE) == 0.0
    assert sound_pressure_level(0.0) == -math.inf
    np.testing.assert_allclose(sound_pressure_level([2e-4, 2e-3]), [20.0, 40.0])


def test_spl_rejects_negative_pressure():
    with pytest.raises(InputError, match="effective_pressure"):
        sound_pressure_level(-1.0)


def test_spl_of_an_rms_pressure_of_2e_5_pa_is_zero():
    """A pressure record whose RMS is p_ref reads 0 dB: a ball tone scaled to it."""
    u = _tone(1000.0)[:, None]
    kw = {"ball_angle": [0.0], "ball_radius": 2e-3, "pitch_radius": 0.02, "point": (0.03, 0.0)}
    p_e = sound_pressure(T, ball_velocity=u, **kw).effective_pressure()
    r = sound_pressure(T, ball_velocity=u * REFERENCE_PRESSURE / p_e, **kw)
    assert r.spl() == pytest.approx(0.0, abs=1e-9)
    assert r.to_dict()["spl_time_mean_db"] == pytest.approx(0.0, abs=1e-6)  # a pure tone


# ---------------------------------------------------------------- pulsating sphere, eq. 23


@pytest.mark.parametrize("frequency", [200.0, 1000.0, 8000.0])
def test_pulsating_sphere_matches_analytic_monopole(frequency):
    """|p| = rho c k a^2 U / (r sqrt(1 + (ka)^2)) (eq. 23), a ball standing still."""
    a, r = 2e-3, 0.01
    res = sound_pressure(
        T,
        ball_velocity=_tone(frequency)[:, None],
        ball_angle=[0.0],
        ball_radius=a,
        pitch_radius=0.02,
        point=FieldPoint(0.02 + r, 0.0),
    )
    k = 2 * np.pi * frequency / C
    expected = RHO * C * k * a**2 * 1e-3 / (r * math.sqrt(1 + (k * a) ** 2))
    assert _amplitude(res.pressure("balls")) == pytest.approx(expected, rel=1e-9)
    h = pulsating_sphere_transfer([frequency], a, r)[0]
    assert abs(h) * 1e-3 == pytest.approx(expected, rel=1e-12)
    # phase at the surface: theta = arctan(1/(ka)) (eq. 23)
    h0 = pulsating_sphere_transfer([frequency], a, a)[0]
    assert np.angle(h0) == pytest.approx(math.atan(1 / (k * a)), abs=1e-12)


def test_pulsating_sphere_pressure_is_delayed_by_r_over_c():
    """The outgoing wave e^{j(omega t - k r)}: moving the point out by dr delays p by dr/c."""
    f, a = 1000.0, 2e-3
    kw = {
        "ball_velocity": _tone(f)[:, None],
        "ball_angle": [0.0],
        "ball_radius": a,
        "pitch_radius": 0.02,
    }
    near = sound_pressure(T, point=(0.03, 0.0), **kw).pressure("balls")
    far = sound_pressure(T, point=(0.03 + C / FS * 10, 0.0), **kw).pressure("balls")  # 10 samples
    scale = (0.01 + C / FS * 10) / 0.01
    np.testing.assert_allclose(np.roll(near, 10) / scale, far, atol=1e-9 * np.abs(far).max())


def test_moving_balls_taylor_series_agrees_across_bin_widths(monkeypatch):
    """Retarded times of balls moving round the pitch circle: one Taylor bin and many
    narrow bins give the same pressure."""
    rng = np.random.default_rng(3)
    psi = 2 * np.pi * np.arange(7) / 7 + 2 * np.pi * 20.0 * T[:, None]
    u = 1e-4 * rng.standard_normal((N, 7, 2))
    kw = {"ball_velocity": u, "ball_angle": psi, "ball_radius": 2e-3, "pitch_radius": 7.5e-3}
    wide = sound_pressure(T, **kw).pressure("balls")
    monkeypatch.setattr(field, "TAYLOR_LIMIT", 0.3)
    narrow = sound_pressure(T, **kw).pressure("balls")
    np.testing.assert_allclose(wide, narrow, atol=1e-10 * np.abs(wide).max())


def test_oscillating_sphere_low_frequency_dipole():
    """A translating sphere at low frequency: p -> j omega rho a^3 U cos(theta) / (2 r^2)."""
    f, a, r = 50.0, 2e-3, 0.01
    h = oscillating_sphere_transfer([f], a, r)[0]
    assert abs(h) == pytest.approx(2 * np.pi * f * RHO * a**3 / (2 * r**2), rel=1e-3)
    # through sound_pressure: a ball moving along x, the point on the y axis hears nothing
    u = np.zeros((N, 1, 2))
    u[:, 0, 0] = _tone(1000.0)
    above = FieldPoint(math.hypot(7.5e-3, r), math.atan2(r, 7.5e-3))  # straight above the ball
    res = sound_pressure(
        T,
        ball_velocity=u,
        ball_angle=[0.0],
        ball_radius=a,
        pitch_radius=7.5e-3,
        point=above,
        ball_source="oscillating",
    )
    assert np.abs(res.pressure("balls")).max() < 1e-15


# ---------------------------------------------------------------- cylinder, eq. 19


def test_cylinder_tends_to_seed_eq19_and_incompressible_limit():
    """Eq. 19 is the small-argument form of the exact 2-D solution; both tend to the
    incompressible near field j omega rho a^2 / r at low frequency."""
    a, r = 5e-3, 1e-2
    f = np.array([5.0, 20.0, 100.0])
    exact = cylinder_transfer(f, a, r)
    seed = cylinder_transfer(f, a, r, form="seed")
    np.testing.assert_allclose(seed, exact, rtol=2e-3)
    np.testing.assert_allclose(np.abs(exact), 2 * np.pi * f * RHO * a**2 / r, rtol=2e-3)
    assert cylinder_transfer([0.0], a, r)[0] == 0
    # at ka ~ 0.9 (10 kHz) the small-argument form is off by more than 10 %
    hi = cylinder_transfer([10000.0], a, r), cylinder_transfer([10000.0], a, r, form="seed")
    assert abs(abs(hi[1][0]) / abs(hi[0][0]) - 1) > 0.1


def test_cylinder_far_field_matches_hankel_asymptote():
    """Far from the ring |H_1^(2)(kr)| -> sqrt(2 / (pi k r)): p r^(1/2) tends to a constant."""
    a, f = 5e-3, 2000.0
    far = np.abs(cylinder_transfer([f], a, 5.0)) * math.sqrt(5.0)
    farther = np.abs(cylinder_transfer([f], a, 20.0)) * math.sqrt(20.0)
    assert farther[0] == pytest.approx(far[0], rel=1e-3)


def test_inner_ring_pressure_follows_cos_phi():
    f, a, d = 500.0, 5e-3, 0.01
    v = np.stack([_tone(f), np.zeros(N)], axis=1)
    h = abs(cylinder_transfer([f], a, d)[0]) * 1e-3
    for phi in (0.0, 0.4, 1.2):
        res = sound_pressure(T, inner_ring_velocity=v, ring_radius=a, point=(d, phi))
        assert _amplitude(res.pressure("inner_ring")) == pytest.approx(
            h * abs(math.cos(phi)), rel=1e-9
        )
        assert np.allclose(res.pressure("inner_ring_y"), 0.0)


# ---------------------------------------------------------------- superposition, eqs. 24-26


def test_pressure_is_linear_in_velocity():
    """Doubling every velocity doubles the pressure: +20 lg 2 = +6.02 dB."""
    rng = np.random.default_rng(5)
    psi = 2 * np.pi * np.arange(7) / 7 + 2 * np.pi * 12.0 * T[:, None]
    v, u = 1e-5 * rng.standard_normal((N, 2)), 1e-5 * rng.standard_normal((N, 7))
    kw = {"ball_angle": psi, "ring_radius": 5.6e-3, "ball_radius": 2e-3, "pitch_radius": 7.5e-3}
    one = sound_pressure(T, v, u, **kw)
    two = sound_pressure(T, 2 * v, 2 * u, **kw)
    assert two.spl() - one.spl() == pytest.approx(20 * math.log10(2), abs=1e-9)
    assert two.spl() - one.spl() == pytest.approx(6.02, abs=0.005)
    np.testing.assert_allclose(two.pressure(), 2 * one.pressure(), rtol=1e-12, atol=1e-20)
    np.testing.assert_allclose(
        one.pressure(), one.pressure("inner_ring") + one.pressure("balls"), atol=1e-18
    )


def test_spectrum_peaks_at_the_velocity_frequencies():
    ring = np.stack([_tone(300.0), _tone(1200.0, 5e-4)], axis=1)
    res = sound_pressure(T, inner_ring_velocity=ring, ring_radius=5e-3, point=(0.01, math.pi / 4))
    s = res.spectrum()
    lines, _ = scipy.signal.find_peaks(s.amplitude)  # local maxima
    top = lines[np.argsort(s.amplitude[lines])[-2:]]
    np.testing.assert_allclose(np.sort(s.frequency[top]), [300.0, 1200.0])


def test_directivity_is_symmetric_for_a_symmetric_source():
    """A ring vibrating along x radiates a dipole: SPL(phi) = SPL(-phi) = SPL(pi - phi);
    a ball pulsating on the x axis is symmetric about that axis."""
    v = np.stack([_tone(800.0), np.zeros(N)], axis=1)
    u = _tone(800.0)[:, None]
    res = sound_pressure(
        T,
        v,
        u,
        ball_angle=[0.0],
        ring_radius=5e-3,
        ball_radius=2e-3,
        pitch_radius=7.5e-3,
        point=(0.02, 0.3),
    )
    angles = np.radians([20.0, -20.0, 160.0, 200.0])
    d = res.directivity(angles)
    ring = d.levels["inner_ring"]
    np.testing.assert_allclose(ring, ring[0], atol=1e-9)
    np.testing.assert_allclose(d.levels["balls"][1], d.levels["balls"][0], atol=1e-9)
    np.testing.assert_allclose(d.levels["balls"][3], d.levels["balls"][2], atol=1e-9)
    assert d.levels["inner_ring"][0] > res.directivity([math.pi / 2]).levels["inner_ring"][0]
    assert len(d.to_dict()["spl_leq_total_db"]) == 4


def test_result_summary_plot_and_table():
    bearing = BallBearing(ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3)
    psi = 2 * np.pi * np.arange(7) / 7 + 2 * np.pi * 5.0 * T[:, None]
    v = np.stack([_tone(100.0, 1e-4), _tone(300.0, 1e-4)], axis=1)
    u = np.repeat(_tone(200.0, 1e-5)[:, None, None], 7, axis=1).repeat(2, axis=2)
    res = sound_pressure(T, v, u, psi, bearing, point=(0.012, 0.7))
    out = res.to_dict()
    for key in (
        "spl_leq_db",
        "spl_time_mean_db",
        "spl_time_max_db",
        "spl_leq_inner_ring_db",
        "spl_leq_balls_db",
        "spl_leq_inner_ring_x_db",
        "spl_leq_balls_y_db",
        "effective_pressure_upa",
    ):
        assert math.isfinite(out[key]), key
    assert out["spl_time_max_db"] >= out["spl_time_mean_db"]
    assert out["ring_radius_mm"] == pytest.approx(0.5 * bearing.inner_raceway_diameter * 1e3)
    # on the y axis a ring vibrating along x is silent: reported as None, not -300 dB
    up = sound_pressure(T, v, u, psi, bearing).to_dict()
    assert up["spl_leq_inner_ring_x_db"] is None and up["angle_deg"] == 90.0
    assert list(res.to_pandas().columns)[:2] == ["time_s", "p_inner_ring_x_pa"]
    windowed = res.spl_time(window=0.01)
    assert windowed.shape == T.shape and np.all(np.isfinite(windowed))
    fig, axes = res.plot()
    assert len(axes) == 2
    fig2, _ = res.directivity(np.radians([0.0, 90.0, 180.0])).plot()
    import matplotlib.pyplot as plt

    plt.close(fig)
    plt.close(fig2)


def test_detrend_removes_a_drift_and_closes_the_record():
    """A drifting velocity (a constant acceleration radiates no sound) and a record that
    stops mid-period: with detrend the tone's pressure comes out as from whole periods."""
    a, d = 5e-3, 0.01
    kw = {"ring_radius": a, "point": (d, 0.0)}
    clean = sound_pressure(T, np.stack([_tone(500.0), np.zeros(N)], 1), **kw)
    drift = np.stack([_tone(500.0) + 0.02 * T, np.zeros(N)], 1)
    raw = sound_pressure(T, drift, **kw)
    fixed = sound_pressure(T, drift, detrend=True, **kw)
    assert abs(raw.spl() - clean.spl()) > 1.0  # the wrap-round jump rings
    assert fixed.spl() == pytest.approx(clean.spl(), abs=0.05)
    cut = N - 37  # not a whole period
    part = sound_pressure(T[:cut], drift[:cut], detrend=True, **kw)
    assert part.spl() == pytest.approx(clean.spl(), abs=0.3)


def test_bearing_noise_runs_the_orbit_and_radiates_it():
    from bearinglab.imperfections import Imperfections, Waviness
    from bearinglab.noise import bearing_noise
    from bearinglab.operating import OperatingCondition

    bearing = BallBearing(
        ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3, diametral_clearance=7.5e-6
    )
    condition = OperatingCondition(radial_load=50.0, shaft_speed=rpm_to_rad_s(720.0))
    imperfections = Imperfections([Waviness("inner", 6, 0.2e-6), Waviness("outer", 8, 0.2e-6)])
    levels = {}
    for model in ("radial", "xy", "oscillating"):
        n = bearing_noise(
            bearing, condition, imperfections, revolutions=1, points=256, ball_model=model
        )
        out = n.to_dict()
        assert out["points"] == 256 and out["speed_rpm"] == pytest.approx(720.0)
        levels[model] = out["spl_leq_balls_db"]
        assert math.isfinite(out["spl_time_mean_db"])
        assert math.isfinite(out["spl_leq_inner_ring_db"])
    assert levels["oscillating"] < levels["radial"]  # a dipole radiates less near the ball
    with pytest.raises(InputError):
        bearing_noise(bearing, condition, imperfections, ball_model="quadrupole")
    with pytest.raises(InputError):
        bearing_noise(bearing, OperatingCondition(radial_load=50.0), imperfections)


def test_velocity_from_positions_differentiates():
    x = np.stack([np.sin(2 * np.pi * 50 * T), np.cos(2 * np.pi * 50 * T)], axis=1) * 1e-6
    v = velocity_from_positions(T, x)
    np.testing.assert_allclose(
        v[5:-5, 0], 2 * np.pi * 50 * 1e-6 * np.cos(2 * np.pi * 50 * T[5:-5]), rtol=1e-3, atol=1e-9
    )


# ---------------------------------------------------------------- input validation


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"time": np.arange(10.0)}, "time"),
        ({"time": np.r_[0.0, np.cumsum(np.ones(20))] ** 1.1}, "time"),
        ({"inner_ring_velocity": np.zeros((N, 3))}, "inner_ring_velocity"),
        ({"inner_ring_velocity": None}, "inner_ring_velocity"),
        ({"ring_radius": -1.0}, "ring_radius"),
        ({"ring_radius": None}, "ring_radius"),
        ({"point": (0.004, 0.0)}, "point"),
        ({"point": (-0.01, 0.0)}, "distance"),
        ({"ring_model": "bem"}, "ring_model"),
        ({"ball_source": "dipole"}, "ball_source"),
        ({"medium": "water"}, "medium"),
    ],
)
def test_inputs_are_validated(kwargs, parameter):
    args = {"time": T, "inner_ring_velocity": np.zeros((N, 2)), "ring_radius": 5e-3}
    args.update(kwargs)
    with pytest.raises(InputError) as err:
        sound_pressure(**args)
    assert err.value.parameter == parameter


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"ball_angle": None}, "ball_angle"),
        ({"ball_angle": np.zeros(3)}, "ball_angle"),
        ({"ball_velocity": np.zeros((N, 2))}, "ball_velocity"),
        ({"point": (0.0085, 0.0)}, "point"),
        ({"ball_radius": math.nan}, "ball_radius"),
    ],
)
def test_ball_inputs_are_validated(kwargs, parameter):
    args = {
        "time": T,
        "ball_velocity": np.zeros((N, 2, 2)),
        "ball_angle": np.zeros(2),
        "ball_radius": 2e-3,
        "pitch_radius": 7.5e-3,
        "ball_source": "oscillating",
    }
    if kwargs.get("ball_velocity") is not None:
        args["ball_angle"] = np.zeros(2)
    args.update(kwargs)
    with pytest.raises(InputError) as err:
        sound_pressure(**args)
    assert err.value.parameter == parameter


def test_medium_and_point_are_validated():
    with pytest.raises(InputError):
        Air(density=0.0)
    with pytest.raises(InputError):
        FieldPoint(0.01, math.inf)
    with pytest.raises(InputError):
        cylinder_transfer([100.0], 5e-3, 1e-3)
    with pytest.raises(InputError):
        pulsating_sphere_transfer([-1.0], 2e-3, 1e-2)


# ---------------------------------------------------------------- the field point, the
# ISO 15242 bands and the whole analysis (issues 12 and 14)


def _608():
    return BallBearing(
        ball_count=7,
        ball_diameter=3.85e-3,
        pitch_diameter=15e-3,
        bore=8e-3,
        outside_diameter=22e-3,
        width=7e-3,
        diametral_clearance=7.5e-6,
    )


def test_default_field_point_lies_outside_the_bearing():
    from bearinglab.noise import FIELD_POINT_GAP, SEED003_POINT_A, default_field_point

    point, rule = default_field_point(_608())
    assert point.distance == pytest.approx(11e-3 + FIELD_POINT_GAP)  # D / 2 + 10 mm
    assert point.angle == pytest.approx(0.5 * math.pi) and "D / 2 = 11 mm" in rule
    # without D: the outer raceway's radius plus half a ball, d_m / 2 + D_w
    bare = BallBearing(ball_count=7, ball_diameter=3.85e-3, pitch_diameter=15e-3)
    point, rule = default_field_point(bare)
    assert point.distance == pytest.approx(7.5e-3 + 3.85e-3 + FIELD_POINT_GAP)
    assert "no D given" in rule
    point, rule = default_field_point(_608(), math.radians(45.0))
    assert point.angle == pytest.approx(math.radians(45.0)) and rule.endswith("at 45 deg from +x")
    assert SEED003_POINT_A.distance == 0.010 < 0.5 * _608().outside_diameter


def test_a_point_inside_the_balls_path_is_refused_and_inside_the_ring_warned():
    from bearinglab.noise import check_field_point, least_field_distance

    b = _608()
    least = least_field_distance(b)
    assert least == pytest.approx(0.5 * (15e-3 + 3.85e-3))
    for d in (5e-3, least):
        with pytest.raises(InputError) as err:
            check_field_point(b, FieldPoint(d, 0.3))
        assert err.value.parameter == "point"
    inside = check_field_point(b, FieldPoint(0.010, 0.3))
    assert len(inside) == 1 and "inside the bearing's outside radius" in inside[0]
    assert check_field_point(b, FieldPoint(0.012, 0.3)) == []


def test_iso_bands_are_the_relative_radial_velocity_with_speed_scaled_edges():
    """The one ISO 15242 computation: RMS of the inner ring's velocity relative to the outer
    ring along y (the rigid model's disp_y, differentiated in time), in the 1800 rpm band
    edges scaled to the speed."""
    from bearinglab.dynamics import simulate
    from bearinglab.imperfections import Imperfections, Waviness
    from bearinglab.noise import bearing_velocity_bands
    from bearinglab.noise.bands import _detrended_velocity
    from bearinglab.operating import OperatingCondition
    from bearinglab.signal import velocity_bands

    b = _608()
    condition = OperatingCondition(radial_load=50.0, shaft_speed=rpm_to_rad_s(3600.0))
    forms = Imperfections([Waviness("outer", 8, 0.3e-6)])
    r = bearing_velocity_bands(b, condition, forms, source="rigid")
    assert r.source == "rigid model" and r.speed_rpm == pytest.approx(3600.0)
    assert r.bands.bands == {
        "low": (100.0, 600.0),
        "medium": (600.0, 3600.0),
        "high": (3600.0, 20000.0),
    }
    assert r.sample_rate == pytest.approx(51200.0) and r.duration == pytest.approx(0.1)
    sim = simulate(b, condition, (), imperfections=forms, duration=0.1, sample_rate=51200.0)
    y = sim.signal.channels["disp_y"]
    t = np.arange(y.size) / 51200.0
    direct = velocity_bands(_detrended_velocity(t, y), 51200.0, "velocity", speed_rpm=3600.0)
    for band in ("low", "medium", "high"):
        assert r[band] == pytest.approx(getattr(direct, band), rel=1e-12)
    # outer waviness of order q = Z + 1 = 8 moves the ring radially at q FTF, about 180 Hz
    # at 3600 rpm: inside the low band (100-600 Hz), which carries most of the velocity
    assert r["low"] > r["medium"]
    d = r.to_dict()
    assert d["velocity_bands_um_s"]["low"] == r["low"] and d["velocity_bands_hz"]["high"][1] == 2e4
    assert list(r.to_pandas().columns) == ["band", "low_hz", "high_hz", "velocity_um_s"]
    with pytest.raises(InputError) as err:
        bearing_velocity_bands(b, condition, source="ear")
    assert err.value.parameter == "bands_from"


def test_noise_analysis_result_table_and_figure():
    import matplotlib.pyplot as plt

    from bearinglab.imperfections import Imperfections, Waviness
    from bearinglab.noise import LEVEL_ROWS, noise_analysis
    from bearinglab.operating import OperatingCondition

    stages = []
    r = noise_analysis(
        _608(),
        OperatingCondition(radial_load=50.0, shaft_speed=rpm_to_rad_s(720.0)),
        Imperfections([Waviness("inner", 7, 0.2e-6)]),
        points=128,
        progress=lambda f, stage: stages.append((f, stage)),
    )
    assert stages[0] == (0.0, "orbit and sound pressure") and stages[-1] == (1.0, "done")
    d = r.to_dict()
    assert d["distance_mm"] == pytest.approx(21.0) and d["field_point_source"].startswith("default")
    assert [k for _, k in LEVEL_ROWS if k not in d] == []
    assert d["spl_time_max_db"] >= d["spl_time_mean_db"]
    assert d["spl_leq_db"] == pytest.approx(r.sound.spl())
    assert d["velocity_bands_um_s"]["low"] == r.bands["low"]
    assert d["peaks"] and d["peaks_resolution_hz"] == pytest.approx(r.spectrum.resolution)
    table = r.to_pandas()
    assert list(table.columns) == ["quantity", "key", "value", "unit"]
    assert set(table["unit"]) == {"dB", "µPa", "µm/s"}
    fig, axes = r.plot()
    assert len(axes) == 4
    plt.close(fig)
    with pytest.raises(InputError) as err:
        noise_analysis(
            _608(), OperatingCondition(radial_load=50.0, shaft_speed=75.0), point=(0.008, 0.0)
        )
    assert err.value.parameter == "point"
