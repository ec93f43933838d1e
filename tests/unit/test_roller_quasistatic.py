"""The roller-bearing load distribution (issue 28): the compiled kernels against their
NumPy twins, the series shortcut against the rollers' equilibrium, the stiffness against
finite differences, equilibrium, the kinds' rules, pairs and speed."""

import dataclasses
import math

import numpy as np
import pytest

from bearinglab.errors import InputError
from bearinglab.geometry import BallBearing
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import _roller_compiled as compiled
from bearinglab.quasistatic import _roller_kernels as twin
from bearinglab.quasistatic import roller as R
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.roller_geometry import RollerBearing, RollerProfile

CYL = RollerBearing(
    roller_count=14,
    roller_diameter=10e-3,
    roller_length=9.6e-3,
    pitch_diameter=65e-3,
    diametral_clearance=20e-6,
)
TAP = RollerBearing(
    roller_count=16,
    roller_diameter=6.5e-3,
    roller_length=11e-3,
    pitch_diameter=39e-3,
    contact_angle=math.radians(13.86),
    bearing_type="tapered_roller",
    width=16.25e-3,
)
PAIR = dataclasses.replace(TAP, rows=2, arrangement="back_to_back", axial_clearance=-10e-6)

CASES = [
    (CYL, OperatingCondition(radial_load=4000.0)),
    (CYL, OperatingCondition(radial_load=4000.0, moment=(3.0, 0.0))),
    (CYL, OperatingCondition(radial_load=4000.0, shaft_speed=12000 * math.pi / 30)),
    (TAP, OperatingCondition(radial_load=3000.0, axial_load=2000.0, moment=(0.0, 2.0))),
    (PAIR, OperatingCondition(radial_load=3000.0, axial_load=-1500.0, moment=(4.0, 0.0))),
]
IDS = ["cylindrical", "cylindrical-moment", "cylindrical-speed", "tapered", "pair"]


@pytest.mark.parametrize("bearing, condition", CASES, ids=IDS)
def test_compiled_and_numpy_solutions_agree(bearing, condition, monkeypatch):
    fast = R.solve_roller_distribution(bearing, condition)
    monkeypatch.setattr(R, "COMPILED", False)
    slow = R.solve_roller_distribution(bearing, condition)
    assert fast.displacement == pytest.approx(slow.displacement, rel=1e-7, abs=1e-13)
    assert fast.inner_load == pytest.approx(slow.inner_load, rel=1e-6, abs=1e-6)
    assert fast.flange_load == pytest.approx(slow.flange_load, rel=1e-6, abs=1e-6)
    scale = np.max(np.abs(fast.stiffness_matrix))
    assert np.max(np.abs(fast.stiffness_matrix - slow.stiffness_matrix)) < 1e-6 * scale


def test_the_state_kernels_agree_off_equilibrium():
    problem = R.RollerProblem(TAP, CASES[3][1], 20, 0.3, 1e-9)
    u = np.array([2e-6, -5e-6, 12e-6, 1e-4, -2e-4])
    v0 = problem.initial_rollers(u)
    a = compiled.roller_set_state(u, v0, problem.rs)
    b = twin.roller_set_state_numpy(u, v0, problem.rs)
    assert a[5] and b[5]
    v, q, delta, force, stiff = a[:5]
    # a roller the rings do not load is free: its position is not unique, so only the
    # loaded rollers' positions and approaches are compared
    loaded = q.sum(axis=1) > 1.0
    assert loaded.sum() > 4
    assert v[loaded] == pytest.approx(b[0][loaded], rel=1e-6, abs=1e-12)
    assert q == pytest.approx(b[1], rel=1e-6, abs=1e-6)  # contacts at the floor: 1e-8 N
    assert delta[loaded] == pytest.approx(b[2][loaded], rel=1e-6, abs=1e-12)
    assert force == pytest.approx(b[3], rel=1e-7, abs=1e-6)
    assert np.max(np.abs(stiff - b[4])) < 1e-6 * np.max(np.abs(stiff))


@pytest.mark.parametrize("profile", ["flat", "logarithmic"])
def test_the_series_shortcut_is_the_rollers_equilibrium(profile, monkeypatch):
    """Cylindrical rollers at rest: each slice pair as two springs in series (ISO/TS 16281's
    model) gives what the rollers' own equilibrium gives."""
    b = dataclasses.replace(CYL, profile=RollerProfile(profile))
    condition = OperatingCondition(
        radial_load=4000.0, moment=(2.0, 1.0), outer_misalignment=(5e-4, 0.0)
    )
    short = R.solve_roller_distribution(b, condition)
    monkeypatch.setattr(R, "SERIES_SHORTCUT", False)
    full = R.solve_roller_distribution(b, condition)
    assert short.displacement == pytest.approx(full.displacement, rel=1e-8, abs=1e-14)
    assert short.outer_load == pytest.approx(full.outer_load, rel=1e-7, abs=1e-7)
    assert short.stiffness_matrix == pytest.approx(full.stiffness_matrix, rel=1e-6, abs=1e-3)


@pytest.mark.parametrize("bearing, condition", CASES, ids=IDS)
def test_stiffness_is_the_derivative_of_the_ring_force(bearing, condition):
    r = R.solve_roller_distribution(bearing, condition)
    problem = R.RollerProblem(bearing, condition, 30, condition.radial_load_angle, 1e-9)
    free = problem.free
    steps = np.array([1e-9, 1e-9, 1e-9, 1e-7, 1e-7])
    for d in np.flatnonzero(free):
        du = np.zeros(5)
        du[d] = steps[d]
        plus = compiled.roller_set_state(r.displacement + du, r.roller_state, problem.rs)[3]
        minus = compiled.roller_set_state(r.displacement - du, r.roller_state, problem.rs)[3]
        column = -(plus - minus) / (2 * steps[d])
        exact = r.stiffness_matrix[:, d]
        assert column[free] == pytest.approx(exact[free], rel=2e-4, abs=1e-4 * np.abs(exact).max())


@pytest.mark.parametrize("bearing, condition", CASES, ids=IDS)
def test_equilibrium(bearing, condition):
    r = R.solve_roller_distribution(bearing, condition)
    d = r.to_dict()
    assert d["equilibrium_residual_n"] < 1e-6 * max(condition.radial_load, 1.0)
    # each roller in balance: the outer load carries the inner load and the centrifugal
    # force (cylindrical rollers have no rib)
    if not bearing.is_tapered:
        loaded = r.outer_roller_load > 1e-6
        expected = r.inner_roller_load[loaded] + r.centrifugal_force
        assert r.outer_roller_load[loaded] == pytest.approx(expected, rel=1e-6, abs=1e-6)


def test_to_dict_keys_follow_the_ball_bearing_with_roller_for_ball():
    d = R.solve_roller_distribution(TAP, CASES[3][1]).to_dict()
    for key in (
        "max_roller_load_n",
        "stiffness_matrix_si",
        "stiffness_matrix_order",
        "radial_stiffness_n_per_um",
        "axial_stiffness_n_per_um",
        "roller_count",
        "roller_diameter_mm",
        "rollers",
        "max_flange_load_n",
        "max_pressure_gpa",
    ):
        assert key in d
    assert "max_ball_load_n" not in d
    assert {"inner_load_n", "outer_load_n", "flange_load_n", "angle_deg"} <= set(d["rollers"][0])


def test_solve_load_distribution_dispatches_on_the_kind():
    r = solve_load_distribution(CYL, OperatingCondition(radial_load=1000.0), slices=12)
    assert r.slices == 12 and r.max_roller_load > 1000.0 / 14
    with pytest.raises(InputError) as err:
        solve_load_distribution(CYL, OperatingCondition(radial_load=1000.0), gyroscopic=True)
    assert err.value.parameter == "gyroscopic"
    ball = BallBearing(ball_count=9, ball_diameter=8e-3, pitch_diameter=39e-3)
    with pytest.raises(InputError) as err:
        solve_load_distribution(ball, OperatingCondition(radial_load=1000.0), slices=10)
    assert err.value.parameter == "slices"


def test_the_kinds_rules():
    with pytest.raises(InputError) as err:
        R.solve_roller_distribution(CYL, OperatingCondition(radial_load=100.0, axial_load=10.0))
    assert err.value.parameter == "axial_load"
    with pytest.raises(InputError, match="induced axial force") as err:
        R.solve_roller_distribution(TAP, OperatingCondition(radial_load=1000.0, axial_load=100.0))
    assert err.value.parameter == "axial_load"
    sph = RollerBearing(
        roller_count=16,
        roller_diameter=8e-3,
        roller_length=8e-3,
        pitch_diameter=70e-3,
        contact_angle=0.2,
        bearing_type="spherical_roller",
    )
    with pytest.raises(InputError, match="not modelled") as err:
        R.solve_roller_distribution(sph, OperatingCondition(radial_load=100.0))
    assert err.value.parameter == "bearing_type"


def test_induced_axial_force_with_the_axial_displacement_imposed():
    r = R.solve_roller_distribution(
        TAP, OperatingCondition(radial_load=3000.0), axial_displacement=0.0
    )
    assert r.displacement[2] == 0.0 and not r.free[2]
    tan_a = math.tan(TAP.contact_angle)
    assert 1.0 < r.induced_axial_force / (3000.0 * tan_a) < 1.3
    assert r.to_dict()["induced_axial_force_n"] == pytest.approx(r.induced_axial_force)
    # the axial load it carries at that displacement brings back the same state
    again = R.solve_roller_distribution(
        TAP, OperatingCondition(radial_load=3000.0, axial_load=r.induced_axial_force)
    )
    assert again.displacement[2] == pytest.approx(0.0, abs=1e-11)


def test_pure_axial_load_shares_evenly_and_loads_the_rib():
    fa = 3000.0
    r = R.solve_roller_distribution(TAP, OperatingCondition(axial_load=fa))
    q = fa / (TAP.roller_count * math.sin(TAP.contact_angle))
    assert r.outer_roller_load == pytest.approx(np.full(16, q), rel=1e-6)
    # the rib closes the roller's force triangle; with the rib normal along the roller
    # axis, across the axis Q_i cos(phi) = Q_o cos(phi) and along it
    # Q_f = (Q_i + Q_o) sin(phi), phi the roller's half-angle
    assert r.inner_roller_load == pytest.approx(r.outer_roller_load, rel=1e-6)
    expected = 2 * q * math.sin(TAP.roller_half_angle)
    assert r.flange_load == pytest.approx(np.full(16, expected), rel=1e-4)


def test_pairs_back_to_back_are_stiffer_in_tilt_and_preload_both_rows():
    condition = OperatingCondition(radial_load=1e-3)
    o = R.solve_roller_distribution(PAIR, condition)
    x = R.solve_roller_distribution(
        dataclasses.replace(PAIR, arrangement="face_to_face"), condition
    )
    assert o.stiffness_matrix[1, 1] == pytest.approx(x.stiffness_matrix[1, 1], rel=1e-6)
    assert o.stiffness_matrix[3, 3] > 5 * x.stiffness_matrix[3, 3]
    rows = [o.outer_roller_load[o.roller_row == k].sum() for k in (0, 1)]
    assert rows[0] == pytest.approx(rows[1], rel=1e-6) and rows[0] > 0
    loose = R.solve_roller_distribution(
        dataclasses.replace(PAIR, axial_clearance=20e-6), OperatingCondition(radial_load=1000.0)
    )
    assert o.stiffness_matrix[1, 1] > loose.stiffness_matrix[1, 1]
    assert "preloaded pair" in " ".join(o.warnings)


def test_centrifugal_force_presses_every_roller_on_the_outer_race():
    fast = R.solve_roller_distribution(CYL, CASES[2][1])
    assert fast.centrifugal_force == pytest.approx(
        R.roller_centrifugal_force(CYL, CASES[2][1].shaft_speed)
    )
    assert np.all(fast.outer_roller_load >= fast.centrifugal_force * (1 - 1e-9))
    assert fast.to_dict()["centrifugal_force_n"] > 0


def test_a_logarithmic_profile_keeps_the_load_off_the_edges_under_tilt():
    condition = OperatingCondition(radial_load=5000.0, misalignment=(2e-3, 0.0))
    flat = R.solve_roller_distribution(
        dataclasses.replace(CYL, profile=RollerProfile("flat")), condition
    )
    log = R.solve_roller_distribution(CYL, condition)
    assert np.any(flat.edge_loaded) and "edge loading" in " ".join(flat.warnings)
    assert not np.any(log.edge_loaded)
