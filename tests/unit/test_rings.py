"""Ring resonances (seed 000): limits, special cases, cross-checks and bad input."""

import dataclasses
import json
import math

import numpy as np
import pytest

from bearinglab.contact.ball_race import ball_contacts, load_deflection_constants
from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.rings import (
    free_ring_frequency,
    linear_stiffness_ratio,
    loaded_ring_frequencies,
    loaded_ring_frequency,
    radial_stiffness_under_axial_load,
    refined_equal_stiffness,
    refined_frequency,
    refined_ring_frequencies,
    rigid_body_frequency,
    ring_modes,
    split_mode,
)

B = BallBearing(
    ball_count=8,
    ball_diameter=19.05e-3,
    pitch_diameter=80e-3,
    bore=50e-3,
    outside_diameter=110e-3,
    width=27e-3,
    diametral_clearance=20e-6,
    name="6310",
)


def paper(**kw):
    args = {
        "ball_count": 8,
        "rigid_body_frequency": 2500.0,
        "ball_mass_ratio": 0.33,
        "free_frequencies": {2: 1920.0, 3: 5340.0, 4: 10000.0, 5: 16200.0},
        "modes": [2, 3, 4, 5],
    }
    return ring_modes(**{**args, **kw})


# ---------------------------------------------------------------- layer 1


def test_free_ring_is_timoshenkos_rectangular_ring():
    # rectangular section of thickness h: f = m (m^2-1) / sqrt(m^2+1) sqrt(E h^2/(12 rho R^4)) / 2pi
    e, rho, h, w, r = 208e9, 7830.0, 4e-3, 10e-3, 0.04
    m = np.arange(2, 8)
    expected = (
        m * (m**2 - 1) / np.sqrt(m**2 + 1) * np.sqrt(e * h**2 / (12 * rho * r**4)) / (2 * np.pi)
    )
    got = free_ring_frequency(m, e, rho, w * h**3 / 12, r, w * h)
    assert got == pytest.approx(expected, rel=1e-12)
    assert free_ring_frequency(1, e, rho, 1e-10, r, 1e-5) == 0.0


def test_rigid_body_mode_is_f1():
    assert loaded_ring_frequency(0.0, 2500.0, 1) == pytest.approx(2500.0)


def test_split_mode():
    assert split_mode([2, 3, 4, 5, 8], 8).tolist() == [False, False, True, False, True]
    assert split_mode([7, 14], 14).tolist() == [True, True]
    assert split_mode(3, 3)  # 2m = 6 = 2 n


def test_lambda_cases_and_ordering():
    f1, fs = 2500.0, 10000.0
    low, high = loaded_ring_frequencies(fs, f1, 4, 8)  # 2m = n: split
    assert low == pytest.approx(fs)  # nodes, lambda = 0
    assert high**2 == pytest.approx(fs**2 + 4 * f1**2 / (1 + 1 / 16))  # antinodes, lambda = 2
    assert low < high
    one, same = loaded_ring_frequencies(fs, f1, 3, 8)  # not split: lambda = 1
    assert one == same == pytest.approx(math.sqrt(fs**2 + 2 * f1**2 / (1 + 1 / 9)))
    # (1.8) with an intermediate phi_0 lies between the extremes
    mid = loaded_ring_frequency(fs, f1, 4, 1 - math.cos(2 * 4 * 0.1))
    assert low < mid < high


def test_zero_stiffness_and_no_balls_give_the_free_ring():
    r = paper(rigid_body_frequency=0.0, ball_mass_ratio=0.0)
    for mode in r.modes:
        assert all(f == pytest.approx(mode.free) for f in mode.approximate + mode.refined)
    r = ring_modes(B, radial_stiffness=0.0, ball_mass_ratio=0.0)
    assert [m.approximate[0] for m in r.modes] == pytest.approx([m.free for m in r.modes])
    # zero stiffness but heavy balls: the ring mode keeps f* (epsilon = 0)
    m3 = paper(rigid_body_frequency=0.0).mode(3)
    assert m3.refined == pytest.approx((5340.0,)) and m3.epsilon == pytest.approx((0.0,))


@pytest.mark.parametrize("lam", [1.0, 2.0])
@pytest.mark.parametrize("ratio", [1.0, 0.7, 1.6])
def test_refined_tends_to_approximate_as_ball_mass_vanishes(lam, ratio):
    f, e = refined_ring_frequencies(10e3, 2.5e3, 4, 1e-9, ratio, lam)
    assert f[0] == pytest.approx(loaded_ring_frequency(10e3, 2.5e3, 4, lam), rel=1e-8)
    assert e[0] == pytest.approx(ratio / (1 + ratio), rel=1e-6)  # static K1/(K1+K2)
    assert f[1] > 1e6  # ball mode goes to infinity
    f0, e0 = refined_ring_frequencies(10e3, 2.5e3, 4, 0.0, ratio, lam)
    assert f0[0] == pytest.approx(loaded_ring_frequency(10e3, 2.5e3, 4, lam))
    assert np.isinf(e0[1]) and np.isinf(f0[1])


def test_ball_mass_lowers_the_in_phase_mode():
    kappas = np.linspace(0, 1, 11)
    f, _ = refined_ring_frequencies(5.34e3, 2.5e3, 3, kappas)
    assert np.all(np.diff(f[0]) < 0) and np.all(f[0] <= f[1])


@pytest.mark.parametrize("antinodes", [False, True])
def test_equal_stiffness_forms_equal_the_general_solution(antinodes):
    fs = np.array([1.92, 5.34, 10.0, 16.2, 3.5])
    f1 = np.array([2.5, 2.5, 2.5, 2.5, 5.07])
    m = np.array([2, 3, 4, 5, 3])
    kappa = np.array([0.33, 0.2, 0.33, 0.5, 0.1])
    (f_pos, f_neg), (e_pos, e_neg) = refined_equal_stiffness(fs, f1, m, kappa, antinodes)
    (f_low, f_high), (e_low, e_high) = refined_ring_frequencies(
        fs, f1, m, kappa, 1.0, 2.0 if antinodes else 1.0
    )
    assert e_low == pytest.approx(e_pos) and e_high == pytest.approx(e_neg)
    assert f_low == pytest.approx(f_pos) and f_high == pytest.approx(f_neg)


@pytest.mark.parametrize("seed", range(5))
def test_stationary_values_are_the_two_dof_eigenvalues(seed):
    # (3.3)/(3.6) is a Rayleigh quotient in (a, s = epsilon a): its stationary values are the
    # eigenvalues of M^-1 K with K = [[a + lam b1, -lam b1], [-lam b1, lam (b1+b2)]],
    # M = diag(1, lam c)
    rng = np.random.default_rng(seed)
    fs, f1, kappa, r = (
        rng.uniform(1, 20),
        rng.uniform(0.5, 8),
        rng.uniform(0.05, 1),
        rng.uniform(0.3, 3),
    )
    m, lam = int(rng.integers(2, 8)), float(rng.choice([1.0, 2.0]))
    g = 1 / (1 + m**-2)
    b1, b2, c = 2 * g * f1**2 * (1 + r), 2 * g * f1**2 * (1 + 1 / r), kappa * g
    k = np.array([[fs**2 + lam * b1, -lam * b1], [-lam * b1, lam * (b1 + b2)]])
    eig = np.sort(np.linalg.eigvals(np.linalg.solve(np.diag([1, lam * c]), k)).real)
    f, e = refined_ring_frequencies(fs, f1, m, kappa, r, lam)
    assert np.array(f) ** 2 == pytest.approx(eig, rel=1e-10)
    assert e[0] > 0 > e[1]
    for ei, fi in zip(e, f, strict=False):  # stationary: derivative in epsilon vanishes
        h = 1e-6 * max(1.0, abs(ei))
        d = refined_frequency(ei + h, fs, f1, m, kappa, r, lam) - refined_frequency(
            ei - h, fs, f1, m, kappa, r, lam
        )
        assert abs(d) / fi < 1e-8


def test_p_equal_four_gives_epsilon_one_and_the_free_frequency():
    # sec. 3: with p = kappa (f*/f_1)^2 = 4 at the antinodes, epsilon_2 = 1 and f = f*
    kappa, f1 = 0.25, 2.5
    fs = f1 * math.sqrt(4 / kappa)
    (f_low, _), (e_low, _) = refined_ring_frequencies(fs, f1, 4, kappa, 1.0, 2.0)
    assert e_low == pytest.approx(1.0) and f_low == pytest.approx(fs)


def test_nodes_have_no_ball_motion():
    f, e = refined_ring_frequencies(10.0, 2.5, 4, 0.33, 1.0, 0.0)
    assert f[0] == f[1] == pytest.approx(10.0) and np.isnan(e).all()


def test_radial_stiffness_is_the_projected_hertz_stiffness():
    # K_x = (n/2) cos^2 tau dQ/d(delta) at Q = A / (n sin tau), Q = K_n delta^1.5
    tau, load = 0.25, 200.0
    k_n = load_deflection_constants(B, tau)[2]
    q = load / (B.ball_count * math.sin(tau))
    delta = (q / k_n) ** (2 / 3)
    h = 1e-6 * delta
    dq = k_n * ((delta + h) ** 1.5 - (delta - h) ** 1.5) / (2 * h)
    expected = B.ball_count / 2 * math.cos(tau) ** 2 * dq
    assert radial_stiffness_under_axial_load(B.ball_count, k_n, load, tau) == pytest.approx(
        expected, rel=1e-8
    )
    # and the axial load scaling A^(1/3)
    ratio = radial_stiffness_under_axial_load(
        8, k_n, 8 * load, tau
    ) / radial_stiffness_under_axial_load(8, k_n, load, tau)
    assert ratio == pytest.approx(2.0)


def test_linear_stiffness_ratio_matches_the_contact_stiffnesses():
    c = ball_contacts(B, 300.0, 0.2)
    k_i, k_o, _ = load_deflection_constants(B, 0.2)
    assert linear_stiffness_ratio(k_o, k_i) == pytest.approx(
        float(c.outer.stiffness / c.inner.stiffness), rel=1e-10
    )


def test_rigid_body_frequency():
    assert rigid_body_frequency(150e6, 0.6) == pytest.approx(2516.46, rel=1e-5)


# ---------------------------------------------------------------- layer 3


def test_ring_modes_from_a_bearing():
    r = ring_modes(B, axial_load=200.0)
    assert r.contact_angle == pytest.approx(B.free_contact_angle)  # nominal angle is 0
    assert r.ring_mass == pytest.approx(B.outer_ring_mass)
    assert r.ball_mass_ratio == pytest.approx(8 * B.ball_mass / B.outer_ring_mass)
    k_n = load_deflection_constants(B, B.free_contact_angle)[2]
    assert r.radial_stiffness == pytest.approx(
        radial_stiffness_under_axial_load(8, k_n, 200.0, B.free_contact_angle)
    )
    assert r.rigid_body_frequency == pytest.approx(
        rigid_body_frequency(r.radial_stiffness, r.ring_mass)
    )
    s = B.outer_ring_section
    assert r.mode(3).free == pytest.approx(
        free_ring_frequency(
            3,
            B.ring_material.elastic_modulus,
            B.ring_material.density,
            s.second_moment,
            s.mean_radius,
            s.area,
        )
    )
    assert [m.mode for m in r.modes] == [2, 3, 4, 5, 6]
    assert r.mode(4).split and len(r.mode(4).approximate) == 2 and len(r.mode(4).refined) == 3
    assert r.mode(4).positions == ("antinodes", "nodes", "antinodes")
    assert r.sources["radial_stiffness"].startswith("derived")
    angled = ring_modes(B, axial_load=200.0, contact_angle=0.3)
    assert angled.contact_angle == 0.3 and angled.sources["contact_angle"] == "user"


def test_overrides_win_and_are_recorded():
    r = ring_modes(
        B,
        axial_load=200.0,
        ring_mass=0.6,
        radial_stiffness=150e6,
        free_frequencies={2: 1920.0},
        ball_mass_ratio=0.33,
        contact_stiffness_ratio=1.0,
        modes=[2, 3],
    )
    assert r.rigid_body_frequency == pytest.approx(2516.46, rel=1e-5)
    assert r.mode(2).free == 1920.0 and r.mode(3).free != 5340.0
    assert r.sources["free_frequencies"] == "user+bearing"
    assert r.sources["ring_mass"] == r.sources["radial_stiffness"] == "user"
    assert r.axial_load is None  # K_x was given: the load was not used


def test_to_dict_to_pandas_plot():
    r = paper(measured={2: 3800.0, 4: [9200.0, 10000.0]})
    d = json.loads(json.dumps(r.to_dict()))
    assert d["ball_count"] == 8 and d["rigid_body_frequency_hz"] == 2500.0
    m4 = next(m for m in d["modes"] if m["m"] == 4)
    assert m4["approx_hz"] == pytest.approx([10000.0, 11114.4], abs=0.1)
    assert m4["epsilon"][1] is None and m4["measured_hz"] == [9200.0, 10000.0]
    assert set(d) >= {
        "ring_mass_kg",
        "radial_stiffness_n_per_um",
        "ball_mass_ratio",
        "modes",
        "contact_stiffness_ratio",
        "axial_load_n",
        "contact_angle_deg",
    }
    df = r.to_pandas()
    assert list(df.columns) == ["m", "model", "ball_position", "frequency_hz", "epsilon"]
    assert set(df["model"]) == {"rigid body", "free", "approximate", "refined", "measured"}
    fig, ax = r.plot()
    assert ax.get_ylabel() == "natural frequency [kHz]"
    import matplotlib.pyplot as plt

    fig2, ax2 = plt.subplots()
    assert r.plot(ax=ax2) == (fig2, ax2)
    plt.close(fig)
    plt.close(fig2)


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"modes": [0, 2]}, "modes"),
        ({"modes": [2.5]}, "modes"),
        ({"modes": []}, "modes"),
        ({"modes": [True]}, "modes"),
        ({"ball_count": 2}, "ball_count"),
        ({"ring_mass": -1.0, "rigid_body_frequency": None, "radial_stiffness": 1e8}, "ring_mass"),
        ({"ball_mass_ratio": -0.1}, "ball_mass_ratio"),
        ({"ball_mass_ratio": math.nan}, "ball_mass_ratio"),
        ({"contact_stiffness_ratio": 0.0}, "contact_stiffness_ratio"),
        ({"rigid_body_frequency": -1.0}, "rigid_body_frequency"),
        ({"rigid_body_frequency": None}, "rigid_body_frequency"),
        ({"free_frequencies": {2: 1920.0}}, "free_frequencies"),
        ({"free_frequencies": [1.0, 2.0]}, "free_frequencies"),
        ({"free_frequencies": {2: 1.0, 3: -2.0, 4: 1.0, 5: 1.0}}, "free_frequencies"),
        ({"ball_mass_ratio": None}, "ball_mass_ratio"),
        ({"measured": {2: -5.0}}, "measured"),
    ],
)
def test_bad_input(kwargs, parameter):
    with pytest.raises(InputError) as err:
        paper(**kwargs)
    assert err.value.parameter == parameter


def test_bad_input_with_a_bearing():
    with pytest.raises(InputError) as err:
        ring_modes(B)  # no K_x, no axial load
    assert err.value.parameter == "rigid_body_frequency"
    zero = dataclasses.replace(B, diametral_clearance=0.0)
    with pytest.raises(InputError) as err:
        ring_modes(zero, axial_load=200.0)  # no contact angle for a pure axial load
    assert err.value.parameter == "contact_angle"
    with pytest.raises(InputError) as err:
        ring_modes(B, axial_load=-5.0)
    assert err.value.parameter == "axial_load"
    with pytest.raises(InputError):
        paper().mode(7)
    with pytest.raises(TypeError):
        ring_modes(B, axial_load=200.0, sensor_mass=0.1)  # unknown keywords are refused


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda: free_ring_frequency(0, 1, 1, 1, 1, 1), "mode"),
        (lambda: free_ring_frequency(2.5, 1, 1, 1, 1, 1), "mode"),
        (lambda: free_ring_frequency(2, 1, -1, 1, 1, 1), "density"),
        (lambda: loaded_ring_frequency(1.0, 1.0, 2, 2.5), "lam"),
        (lambda: loaded_ring_frequency(-1.0, 1.0, 2), "free_frequency"),
        (lambda: refined_ring_frequencies(1.0, 1.0, 2, -0.1), "ball_mass_ratio"),
        (lambda: refined_ring_frequencies(1.0, 1.0, 2, 0.1, 0.0), "stiffness_ratio"),
        (lambda: radial_stiffness_under_axial_load(8, 1e10, 0.0, 0.2), "axial_load"),
        (lambda: radial_stiffness_under_axial_load(8, 1e10, 100.0, 0.0), "contact_angle"),
        (lambda: rigid_body_frequency(1e8, 0.0), "ring_mass"),
        (lambda: split_mode(2, 0), "ball_count"),
    ],
)
def test_bad_input_layer_1(call, parameter):
    with pytest.raises(InputError) as err:
        call()
    assert err.value.parameter == parameter


def test_rigid_body_mode_on_request_and_stiffness_from_the_load_distribution():
    """m = 1 (the ring as a rigid body, f_1) is listed first when asked for; K_x may come from
    the load distribution's tangent stiffness instead of seed 000's closed form."""
    r = ring_modes(B, axial_load=200.0, modes=[1, 2])
    d = r.to_dict()
    assert [m["m"] for m in d["modes"]] == [1, 2]
    assert d["modes"][0]["approx_hz"] == [pytest.approx(r.rigid_body_frequency)]
    assert [m.mode for m in r.modes] == [2]
    solved = ring_modes(B, axial_load=200.0, radial_stiffness_from="load_distribution")
    assert solved.sources["radial_stiffness"].startswith("load distribution")
    assert solved.radial_stiffness > 0 and solved.radial_stiffness != r.radial_stiffness
    with pytest.raises(InputError):
        ring_modes(B, axial_load=200.0, radial_stiffness_from="guess")
