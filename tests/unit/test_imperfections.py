"""Form errors: waviness, ball-size errors, random 3-D surfaces, the seed-002 axial shift,
and the time sweep of the quasi-static orbit that uses them."""

import math

import numpy as np
import pytest

from bearinglab.errors import ConvergenceError, InputError
from bearinglab.geometry import BallBearing
from bearinglab.imperfections import (
    BallSizeErrors,
    Imperfections,
    RandomSurface,
    Waviness,
    ball_axial_shift,
    exponential_autocorrelation,
    sample_autocorrelation,
)
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.quasistatic.orbit import inner_ring_orbit

B608 = BallBearing(
    ball_count=7, ball_diameter=3.969e-3, pitch_diameter=15e-3, diametral_clearance=10e-6
)
SPEED = 720 * math.pi / 30  # seed 003's 608 example: 720 rpm, 0.05 kN


# ------------------------------------------------------------------ waviness
@pytest.mark.parametrize(
    "kwargs",
    [
        {"race": "cage", "order": 3, "amplitude": 1e-7},
        {"race": "outer", "order": 0, "amplitude": 1e-7},
        {"race": "outer", "order": True, "amplitude": 1e-7},
        {"race": "outer", "order": 2.0, "amplitude": 1e-7},
        {"race": "outer", "order": 3, "amplitude": -1e-7},
        {"race": "outer", "order": 3, "amplitude": float("nan")},
        {"race": "outer", "order": 3, "amplitude": 1e-7, "phase": float("inf")},
        {"race": "inner", "order": 3, "amplitude": 1e-7, "ball": 0},
        {"race": "ball", "order": 3, "amplitude": 1e-7, "ball": -1},
    ],
)
def test_waviness_refuses_bad_input(kwargs):
    with pytest.raises(InputError):
        Waviness(**kwargs)


def test_waviness_is_seed003_sine_with_shifted_phase():
    # seed 003 eq. 9-10: P = A sin(2 pi s / lambda + theta_0), lambda = 2 pi R / N_w, so at
    # ring angle theta = s/R: P = A sin(N_w theta + theta_0) = A cos(N_w theta + theta_0 - pi/2)
    theta = np.linspace(0, 2 * math.pi, 50)
    theta0 = 0.7
    w = Waviness("inner", 6, 0.2e-6, phase=theta0 - math.pi / 2)
    np.testing.assert_allclose(
        w.radius_deviation(theta), 0.2e-6 * np.sin(6 * theta + theta0), atol=1e-18
    )


def test_approach_change_follows_seed003_eqs_14_to_16():
    # seed 003 eq. 14 (inner, angle 2 pi (j-1)/N_b + (w_c - w_i) t) and eq. 15 (outer,
    # 2 pi (j-1)/N_b + w_c t); eq. 16: P_k = P_i - P_o
    z, a_i, a_o, n_w = 7, 0.3e-6, 0.5e-6, 5
    th_i, th_o = 0.4, -1.1
    imp = Imperfections(
        [
            Waviness("inner", n_w, a_i, phase=th_i - math.pi / 2),
            Waviness("outer", n_w, a_o, phase=th_o - math.pi / 2),
        ]
    )
    w_i = SPEED
    w_c = 0.5 * w_i * (1 - B608.gamma)
    t = np.linspace(0, 0.1, 11)[:, None]
    slots = 2 * math.pi * np.arange(z) / z
    psi = slots + w_c * t
    d = imp.approach_change(B608, psi, w_i * t)
    p_i = a_i * np.sin(n_w * (slots + (w_c - w_i) * t) + th_i)
    p_o = a_o * np.sin(n_w * (slots + w_c * t) + th_o)
    assert d.total.shape == (11, z)
    np.testing.assert_allclose(d.inner, p_i, atol=1e-18)
    np.testing.assert_allclose(d.outer, -p_o, atol=1e-18)
    np.testing.assert_allclose(d.total, p_i - p_o, atol=1e-18)


def test_ball_waviness_changes_the_diameter_only_for_even_orders():
    psi = 2 * math.pi * np.arange(7) / 7
    phi = np.linspace(0, 2 * math.pi, 40)[:, None] * np.ones(7)
    for q in (1, 3, 5):
        d = Imperfections([Waviness("ball", q, 1e-6)]).approach_change(B608, psi, 0.0, phi)
        np.testing.assert_allclose(d.total, 0.0, atol=1e-20)
        assert np.max(np.abs(d.outer)) == pytest.approx(1e-6)  # the ball is still wavy
    d = Imperfections([Waviness("ball", 4, 1e-6, ball=2)]).approach_change(B608, psi, 0.0, phi)
    np.testing.assert_allclose(d.total[:, 2], 2e-6 * np.cos(4 * phi[:, 2]), atol=1e-18)
    assert not np.any(np.delete(d.total, 2, axis=1))


def test_approach_change_signs_and_inner_ring_frame():
    psi = np.zeros(7)
    psi[0] = 0.3
    bump = Imperfections([Waviness("inner", 1, 1e-6, phase=0.0)])
    # the inner ring turned by theta_s: its crest (ring angle 0) is now at psi = theta_s
    d = bump.approach_change(B608, psi, shaft_angle=0.3)
    assert d.inner[0] == pytest.approx(1e-6) and d.outer[0] == 0
    d = Imperfections([Waviness("outer", 1, 1e-6)]).approach_change(B608, psi)
    assert d.outer[1] == pytest.approx(-1e-6)  # outer radius larger: less approach


def test_imperfections_refuse_what_does_not_fit():
    with pytest.raises(InputError):
        Imperfections([Waviness("ball", 2, 1e-7, ball=7)]).approach_change(B608, np.zeros(7))
    with pytest.raises(InputError):
        Imperfections(ball_size_errors=[1e-6] * 6).approach_change(B608, np.zeros(7))
    with pytest.raises(InputError):
        Imperfections(["not waviness"])
    with pytest.raises(InputError):
        Imperfections().approach_change(B608, np.zeros(6))
    assert Imperfections().is_empty and not Imperfections(Waviness("outer", 3, 0.0)).is_empty


# --------------------------------------------------------------- ball sizes
def test_ball_size_errors_are_reproducible_and_fill_the_band():
    a = BallSizeErrors.random(500, 3e-6, seed=11)
    assert a == BallSizeErrors.random(500, 3e-6, seed=11)
    assert a != BallSizeErrors.random(500, 3e-6, seed=12)
    # the band is the width of the interval (lot diameter variation), centred on D_w
    assert np.all(np.abs(a.errors) <= 1.5e-6) and a.band > 0.95 * 3e-6
    assert abs(float(np.mean(a.errors))) < 0.2e-6
    b = BallSizeErrors.random(500, (1e-6, 3e-6), seed=np.random.default_rng(3))
    assert np.all((b.errors >= 1e-6) & (b.errors <= 3e-6))
    assert BallSizeErrors.random(7, 0.0, seed=1).band == 0


@pytest.mark.parametrize(
    "band, seed",
    [(-1e-6, 1), ((3e-6, 1e-6), 1), ((1e-6,), 1), ("wide", 1), (1e-6, None), (1e-6, -2)],
)
def test_ball_size_errors_refuse_bad_input(band, seed):
    with pytest.raises(InputError):
        BallSizeErrors.random(7, band, seed=seed)


# ----------------------------------------------------------- random surface
SURFACE = {
    "amplitude": 1e-6,
    "length_circumferential": 0.5e-3,
    "length_axial": 0.4e-3,
    "radius": 5.5e-3,
    "width": 3e-3,
    "points_circumferential": 512,
    "points_axial": 41,
}


def test_same_seed_same_surface():
    a = RandomSurface("inner", seed=5, **SURFACE)
    b = RandomSurface("inner", seed=5, **SURFACE)
    c = RandomSurface("inner", seed=6, **SURFACE)
    np.testing.assert_array_equal(a.heights, b.heights)
    assert not np.allclose(a.heights, c.heights)


def test_surface_autocorrelation_matches_seed002_eq6():
    """Sample autocorrelation, averaged over 16 seeds, against R of seed 002 eq. 6.

    Statistical tolerance: the seed-to-seed standard error of the mean (about 0.007 dh^2
    here: a 34.6 mm x 3 mm band holds ~500 correlation areas) times 4, plus 0.003 dh^2 for
    the periodisation images (< 1e-4) and the scatter of the error estimate itself.
    Measured when written: worst |mean - R| = 0.0085 dh^2 (1.4 standard errors; standard
    errors 0.006-0.009 dh^2), variance 0.995 dh^2 +- 0.009.
    """
    lags = [0, 1, 2, 4, 8]
    samples = []
    for seed in range(16):
        s = RandomSurface("outer", seed=seed, **SURFACE)
        samples.append(sample_autocorrelation(s.heights, lags, lags))
    samples = np.array(samples) / s.amplitude**2
    mean = samples.mean(axis=0)
    error = samples.std(axis=0, ddof=1) / math.sqrt(len(samples))
    lag = np.array(lags)
    target = exponential_autocorrelation(
        lag[:, None] * s.circumferential_step,
        lag[None, :] * s.axial_step,
        1.0,
        s.length_circumferential,
        s.length_axial,
    )
    assert np.all(np.abs(mean - target) <= 4 * error + 0.003), (mean - target) / error
    # the lags cover both directions and the diagonal: 8 steps are 1.08 beta_r (R = 0.08
    # dh^2) and 1.5 beta_z (R = 0.03 dh^2)
    assert target[-1, 0] < 0.1 and target[0, -1] < 0.05


def test_surface_variance_is_exact_in_expectation_and_optionally_per_realisation():
    s = RandomSurface("outer", seed=1, **SURFACE)
    density = s.spectral_density()
    assert density.mean() == pytest.approx(s.amplitude**2, rel=1e-12)
    assert np.all(density >= 0)
    exact = RandomSurface("outer", seed=1, exact_rms=True, **SURFACE)
    assert exact.rms == pytest.approx(1e-6, rel=1e-12)
    assert abs(exact.heights.mean()) < 1e-18


def test_surface_height_interpolates_and_is_periodic():
    s = RandomSurface("inner", seed=2, **SURFACE)
    np.testing.assert_allclose(s.height(s.theta[:, None], s.z[None, :]), s.heights, atol=1e-20)
    theta = np.linspace(-1, 7, 33)
    np.testing.assert_allclose(
        s.height(theta + 2 * math.pi, 0.3e-3), s.height(theta, 0.3e-3), atol=1e-20
    )
    mid = s.height(0.5 * (s.theta[3] + s.theta[4]), s.z[7])
    assert mid == pytest.approx(0.5 * (s.heights[3, 7] + s.heights[4, 7]), abs=1e-20)
    assert s.height(0.1, 1.0) == s.height(0.1, 0.5 * s.width)  # held at the edge
    assert RandomSurface("inner", **{**SURFACE, "amplitude": 0.0}, seed=1).rms == 0


@pytest.mark.parametrize(
    "change",
    [
        {"points_circumferential": 64},
        {"points_axial": 5},
        {"length_axial": 0.0},
        {"radius": -1.0},
        {"race": "ball"},
        {"seed": -1},
        {"exact_rms": 1},
    ],
)
def test_surface_refuses_bad_input(change):
    kwargs = {"race": "outer", "seed": 1, **SURFACE, **change}
    with pytest.raises(InputError):
        RandomSurface(**kwargs)


def test_surface_for_bearing_takes_the_raceway_radius():
    s = RandomSurface.for_bearing(B608, "outer", 0.1e-6, 1e-3, 1e-3, seed=0)
    assert s.radius == pytest.approx(B608.outer_raceway_diameter / 2)
    assert s.width == B608.ball_diameter and s.circumferential_step <= 0.25e-3


# ------------------------------------------------------- seed 002 eqs. 7-9
def test_flat_raceways_leave_the_ball_centred_at_the_nominal_angle():
    r = ball_axial_shift(B608)
    assert abs(r.ball_shift) < 1e-9 and abs(r.contact_angle) < 1e-6
    assert r.inner_deviation == 0 and r.outer_deviation == 0


def test_inner_ring_offset_gives_the_free_contact_angle():
    # flat raceways, inner ring moved axially by s: sin(beta) = s / A, z_b = s (r_o - D/2)/A;
    # at s = A sin(alpha_0) (half the end play) beta is the free contact angle
    a = B608.groove_centre_distance
    s = a * math.sin(B608.free_contact_angle)
    r = ball_axial_shift(B608, inner_offset=s)
    assert r.contact_angle == pytest.approx(B608.free_contact_angle, rel=1e-3)
    free_o = (B608.outer_groove_factor - 0.5) * B608.ball_diameter
    assert r.ball_shift == pytest.approx(s * free_o / a, rel=1e-3)


def test_tilted_outer_raceway_shifts_the_ball_towards_its_wider_side():
    """Outer raceway radius growing along +z (h_o = t z): more room at +z, so the ball moves
    to +z (seed 002 fig. 3) and the contact line leans back (beta < 0). Small-slope solution
    of eqs. 8-9: z_b = t R (1 + a_o)/(a_i + a_o), a = R/(r - R)."""
    radius = B608.ball_diameter / 2
    a_i = radius / (B608.inner_groove_factor * B608.ball_diameter - radius)
    a_o = radius / (B608.outer_groove_factor * B608.ball_diameter - radius)
    slopes = np.array([-2e-3, 1e-3, 2e-3])
    r = ball_axial_shift(B608, outer_height=lambda z: slopes[:, None] * z)
    expected = slopes * radius * (1 + a_o) / (a_i + a_o)
    np.testing.assert_allclose(r.ball_shift, expected, rtol=0.02)
    assert np.all(np.sign(r.contact_angle) == -np.sign(slopes))
    np.testing.assert_allclose(r.residual, 0.0, atol=1e-8)
    np.testing.assert_allclose(r.outer_deviation, slopes * r.outer_contact_z, rtol=1e-3)
    # a tilted inner raceway (radius growing along +z: less room there) pushes it to -z
    assert ball_axial_shift(B608, inner_height=lambda z: 1e-3 * z).ball_shift < 0


def test_axial_shift_on_random_surfaces_for_every_ball():
    imp = Imperfections(
        surfaces=[RandomSurface.for_bearing(B608, "outer", 0.2e-6, 0.3e-3, 0.3e-3, seed=4)]
    )
    psi = 2 * math.pi * np.arange(7) / 7
    r = ball_axial_shift(B608, outer_height=lambda z: imp.surface_profile("outer", psi, z))
    assert r.ball_shift.shape == (7,) and np.all(np.abs(r.ball_shift) < 20e-6)
    # a root of eq. 9 for most balls; where the contact jumps between two crests eq. 9
    # changes sign across the jump (the residual is the jump, bounded by the crest spacing)
    assert np.count_nonzero(np.abs(r.residual) < 1e-8) >= 5
    assert np.all(np.abs(r.residual) < 0.5e-3)
    flat = ball_axial_shift(B608, outer_height=lambda z: 0 * psi[:, None] + 0 * z)
    np.testing.assert_allclose(flat.ball_shift, 0.0, atol=1e-9)


def test_axial_shift_refuses_bad_input():
    with pytest.raises(InputError):
        ball_axial_shift(B608, points=10)
    with pytest.raises(InputError):
        ball_axial_shift(B608, outer_height=lambda z: np.zeros(3))
    with pytest.raises(InputError):
        ball_axial_shift(B608, inner_offset=1e-3)
    with pytest.raises(ConvergenceError):
        ball_axial_shift(B608, outer_height=lambda z: 2.0 * z)  # a cone, not a groove


# --------------------------------------------------------------- time sweep
def test_time_sweep_with_ball_size_errors_is_the_ball_set_sweep_in_time():
    errors = BallSizeErrors.random(7, 2e-6, seed=1)
    c = OperatingCondition(radial_load=50.0, shaft_speed=SPEED)
    o = inner_ring_orbit(
        B608, c, imperfections=Imperfections(ball_size_errors=errors), revolutions=2, points=8
    )
    assert o.time.shape == (8,) and o.ball_centre.shape == (8, 7, 2)
    assert o.ball_phase[0] == 0.0  # ball 0 at psi = 0 at time 0 (conventions)
    for k in (0, 5):
        r = solve_load_distribution(
            B608, c, ball_phase=float(o.ball_phase[k]), ball_diameter_errors=errors.errors
        )
        assert o.x[k] == pytest.approx(r.displacement[0], abs=1e-12)
        assert o.y[k] == pytest.approx(r.displacement[1], abs=1e-12)
    cage = o.frequencies["cage_hz"] / o.frequencies["shaft_hz"]
    assert cage == pytest.approx(0.5 * (1 - B608.gamma))
    np.testing.assert_allclose(np.diff(o.ball_phase), 2 * math.pi * cage * 2 / 8)


def test_ball_centres_take_the_unequal_split_of_the_approach():
    # the solver's per-contact film is an exact per-contact approach change: with it, the
    # loaded balls' centres must be where the orbit puts them after its correction
    imp = Imperfections(
        [
            Waviness("outer", 5, 0.5e-6, phase=0.3),
            Waviness("inner", 6, 0.3e-6),
            Waviness("ball", 3, 0.2e-6, ball=5),
        ],
        ball_size_errors=BallSizeErrors.random(7, 2e-6, seed=4),
    )
    c = OperatingCondition(radial_load=50.0, shaft_speed=SPEED)
    o = inner_ring_orbit(B608, c, imperfections=imp, revolutions=1, points=8)
    k = 5
    spin = 2 * math.pi * o.frequencies["ball_spin_hz"] * o.time[k]
    d = imp.approach_change(B608, o.ball_angle[k], SPEED * o.time[k], spin)
    r = solve_load_distribution(
        B608, c, ball_phase=float(o.ball_phase[k]), film=np.stack([d.inner, d.outer], axis=1)
    )
    np.testing.assert_allclose(r.displacement[:2], [o.x[k], o.y[k]], atol=1e-12)
    loaded = r.load.min(axis=1) > 1.0
    assert loaded.sum() >= 2
    np.testing.assert_allclose(r.ball_centre[loaded], o.ball_centre[k][loaded], atol=1e-11)


def test_time_sweep_outputs_and_refusals():
    c = OperatingCondition(radial_load=50.0, shaft_speed=SPEED)
    imp = Imperfections(
        [Waviness("outer", 6, 0.2e-6)],
        surfaces=[RandomSurface.for_bearing(B608, "inner", 0.1e-6, 0.5e-3, 0.5e-3, seed=3)],
    )
    o = inner_ring_orbit(B608, c, imperfections=imp, duration=0.02, points=6)
    d = o.to_dict()
    assert len(d["time_s"]) == 6 and len(d["ball_radial_displacement_um"][0]) == 7
    assert d["cage_hz"] == pytest.approx(12 * 0.5 * (1 - B608.gamma))
    assert o.ring_velocity.shape == (6, 2) and o.ball_radial_velocity.shape == (6, 7)
    shifted = inner_ring_orbit(
        B608, c, imperfections=imp, duration=0.02, points=3, surface_contact="axial_shift"
    )
    assert shifted.peak_to_peak > 0
    with pytest.raises(InputError):
        inner_ring_orbit(B608, OperatingCondition(radial_load=50.0), revolutions=1)
    with pytest.raises(InputError):
        inner_ring_orbit(B608, c, revolutions=1, duration=0.1)
    with pytest.raises(InputError):
        inner_ring_orbit(B608, c, revolutions=1, span="revolution")
    with pytest.raises(InputError):
        inner_ring_orbit(B608, c, revolutions=-1)
    with pytest.raises(InputError):
        inner_ring_orbit(B608, c, imperfections=imp, surface_contact="middle")
    with pytest.raises(InputError):
        inner_ring_orbit(B608, c, imperfections="wavy")
    with pytest.raises(InputError):
        inner_ring_orbit(B608, c, revolutions=1, ball_phase=0.1)  # the sweep sets it
    ball_set = inner_ring_orbit(B608, c)
    with pytest.raises(InputError):
        _ = ball_set.ring_velocity  # a ball-set sweep has no time


def test_orbit_plots():
    pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    c = OperatingCondition(radial_load=50.0, shaft_speed=SPEED)
    o = inner_ring_orbit(
        B608,
        c,
        imperfections=Imperfections([Waviness("inner", 6, 2e-7)]),
        revolutions=0.5,
        points=6,
    )
    fig, _ = o.plot()
    fig2, axes = o.plot_history()
    assert len(axes) == 2
    plt.close(fig)
    plt.close(fig2)
