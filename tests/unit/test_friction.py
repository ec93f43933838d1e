"""bearinglab.friction (both models) and the ``friction`` command."""

import math

import conftest
import numpy as np
import pytest

from bearinglab.analyses.operation import FRICTION
from bearinglab.catalog import bearing_from_designation
from bearinglab.cli import main
from bearinglab.errors import InputError
from bearinglab.friction import (
    DEEP_GROOVE_CONSTANTS,
    K_RS,
    MU_EHL,
    SEED003_COEFFICIENTS,
    FrictionResult,
    SkfGeometryConstants,
    angular_contact_load_variables,
    bearing_friction,
    constant_coefficient_torque,
    constant_friction,
    deep_groove_constants,
    deep_groove_load_variables,
    friction_coefficient,
    friction_type_of,
    inlet_shear_heating_factor,
    power_loss,
    replenishment_factor,
    seal_moment,
    skf_friction,
    skf_frictional_moment,
    sliding_friction_coefficient,
    sliding_weighting_factor,
    viscosity_ratio,
)
from bearinglab.life import equivalent_dynamic_load, load_ratings

RPM = math.pi / 30.0
C62 = deep_groove_constants("62")
#: SKF-model command lines the CLI tests extend: a sealed 6205-2RS, a 7206 with its own
#: geometry constants, and a 6205 at 10 rpm for the input checks.
SKF_6205_2RS = ("6205-2RS", "--speed-rpm", "3000", "--radial-load-n", "1000", "--model", "skf")
SKF_7206 = (
    "7206",
    "--speed-rpm",
    "3000",
    "--radial-load-n",
    "1000",
    "--model",
    "skf",
    "--skf-constants",
    "5e-7,2,1e-2,0.7,2e-12,2e-12",
)
SKF_SLOW = ("6205", "--speed-rpm", "10", "--model", "skf")
#: A bearing given by its bore and outside diameter alone (25 x 52 mm), at 10 rpm.
BORE_AND_OD = ("--bore-mm", "25", "--outside-diameter-mm", "52", "--speed-rpm", "10")


def skf_by_hand(
    n,
    nu,
    d,
    big_d,
    fr,
    r1,
    r2,
    s1,
    s2,
    k_rs=6e-8,
    k_z=3.1,
    fa=0.0,
    c0=None,
    mu_bl=0.15,
    mu_ehl=0.05,
):
    """The SKF model written out again in SKF units (rpm, mm^2/s, mm, N -> N mm)."""
    dm = 0.5 * (d + big_d)
    if fa == 0:
        g_rr = r1 * dm**1.96 * fr**0.54
        g_sl = s1 * dm**-0.26 * fr ** (5 / 3)
    else:
        sin_a = math.sin(math.radians(24.6 * (fa / c0) ** 0.24))
        g_rr = r1 * dm**1.96 * (fr + r2 / sin_a * fa) ** 0.54
        g_sl = s1 * dm**-0.145 * (fr**5 + s2 * dm**1.5 / sin_a * fa**4) ** (1 / 3)
    ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    rs = 1 / math.exp(k_rs * nu * n * (d + big_d) * math.sqrt(k_z / (2 * (big_d - d))))
    bl = 1 / math.exp(2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = bl * mu_bl + (1 - bl) * mu_ehl
    return ish * rs * g_rr * (nu * n) ** 0.6 + g_sl * mu_sl


# ------------------------------------------------------------------ constant model
def test_constant_torque_and_power():
    m = constant_coefficient_torque(0.0015, 2000.0, 0.05)
    assert m == pytest.approx(0.0015 * 2000 * 0.05 / 2)
    assert power_loss(m, 100.0) == pytest.approx(m * 100.0)
    arr = constant_coefficient_torque(0.002, np.array([0.0, 1.0, 2.0]), 0.04)
    assert arr.shape == (3,) and arr[0] == 0.0


@pytest.mark.parametrize(
    "bearing_type, variant, expected",
    [
        ("radial_ball", None, "radial_ball"),
        ("angular_contact_ball", None, "angular_contact_ball"),
        ("cylindrical_roller", "NU", "cylindrical_roller"),
        ("cylindrical_roller", "NCF", "cylindrical_roller_full_complement"),
        ("cylindrical_roller", "njg", "cylindrical_roller_full_complement"),
        ("tapered_roller", None, "tapered_roller"),
        ("spherical_roller", None, "spherical_roller"),
        ("thrust_ball", None, "thrust_ball"),
    ],
)
def test_friction_type_mapping(bearing_type, variant, expected):
    assert friction_type_of(bearing_type, variant) == expected


@pytest.mark.parametrize(
    "bearing_type",
    [
        "self_aligning_ball",
        "four_point_contact_ball",
        "needle_roller",
        "thrust_roller",
        "spiral_roller",
    ],
)
def test_types_without_a_row_are_refused(bearing_type):
    with pytest.raises(InputError, match="bearing_type"):
        friction_type_of(bearing_type)


def test_unknown_friction_type():
    with pytest.raises(InputError, match="friction_type"):
        friction_coefficient("plain")


@pytest.mark.parametrize(
    "call",
    [
        lambda: constant_coefficient_torque(0.0015, -1.0, 0.04),
        lambda: constant_coefficient_torque(0.0015, 1.0, 0.0),
        lambda: constant_coefficient_torque(float("nan"), 1.0, 0.04),
        lambda: power_loss(1.0, float("inf")),
        lambda: constant_friction(100.0, 0.04, -1.0, "radial_ball"),
        lambda: constant_friction(True, 0.04, 1.0, "radial_ball"),
    ],
)
def test_constant_model_refuses_bad_input(call):
    with pytest.raises(InputError):
        call()


# ------------------------------------------------------------------ SKF model, layer 1
def test_skf_matches_the_equations_written_out():
    for n, nu, fr in [(3000.0, 20.0, 1000.0), (200.0, 100.0, 50.0), (12000.0, 8.0, 3000.0)]:
        m = skf_frictional_moment("radial_ball", 0.025, 0.052, fr, 0.0, n * RPM, nu * 1e-6, C62)
        ref = skf_by_hand(n, nu, 25.0, 52.0, fr, C62.r1, C62.r2, C62.s1, C62.s2)
        assert m.total * 1e3 == pytest.approx(ref, rel=1e-12)


def test_skf_axial_load_matches_the_equations_written_out():
    m = skf_frictional_moment(
        "radial_ball",
        0.025,
        0.052,
        1000.0,
        400.0,
        3000 * RPM,
        20e-6,
        C62,
        static_load_rating=7800.0,
        k_rs=K_RS["oil-jet"],
    )
    ref = skf_by_hand(
        3000, 20, 25, 52, 1000, C62.r1, C62.r2, C62.s1, C62.s2, k_rs=3e-8, fa=400.0, c0=7800.0
    )
    assert m.total * 1e3 == pytest.approx(ref, rel=1e-12)
    radial = skf_frictional_moment(
        "radial_ball", 0.025, 0.052, 1000.0, 0.0, 3000 * RPM, 20e-6, C62, k_rs=K_RS["oil-jet"]
    )
    assert m.total > radial.total


def test_skf_at_rest_is_boundary_sliding_only():
    m = skf_frictional_moment("radial_ball", 0.025, 0.052, 1000.0, 0.0, 0.0, 20e-6, C62)
    assert m.rolling == 0.0
    assert m.inlet_shear_factor == 1.0 and m.replenishment_factor == 1.0
    assert m.sliding_weighting_factor == 1.0 and m.sliding_friction_coefficient == 0.15
    g_sl = deep_groove_load_variables(0.0385, 1000.0, 0.0, C62)[1]
    assert m.total == pytest.approx(g_sl * 0.15 * 1e-3)


def test_skf_factors():
    w = np.array([100.0, 1000.0, 10000.0]) * RPM
    ish = inlet_shear_heating_factor(w, 0.0385, 30e-6)
    rs = replenishment_factor(w, 30e-6, 0.025, 0.052, K_RS["grease"], 3.1)
    bl = sliding_weighting_factor(w, 30e-6, 0.0385)
    for f in (ish, rs, bl):
        assert np.all((f > 0) & (f <= 1)) and np.all(np.diff(f) < 0)
    # grease starves more than oil jet (K_rs 6e-8 against 3e-8)
    assert replenishment_factor(w[-1], 30e-6, 0.025, 0.052, 6e-8, 3.1) < replenishment_factor(
        w[-1], 30e-6, 0.025, 0.052, 3e-8, 3.1
    )
    assert sliding_friction_coefficient(0.0, 0.15, 0.04) == 0.04
    assert sliding_friction_coefficient(0.5) == pytest.approx(0.1)


def test_viscosity_ratio():
    # ISO 281: nu_1 = 45000 n^-0.83 d_m^-0.5 below 1000 r/min, 4500 n^-0.5 d_m^-0.5 from 1000 on
    assert viscosity_ratio(30e-6, 500 * RPM, 0.1) == pytest.approx(30 / (45000 * 500**-0.83 / 10))
    assert viscosity_ratio(30e-6, 4000 * RPM, 0.1) == pytest.approx(30 / (4500 / 63.245553 / 10))
    with pytest.raises(InputError, match="shaft_speed"):
        viscosity_ratio(30e-6, 0.0, 0.1)


def test_angular_contact_with_user_constants():
    c = SkfGeometryConstants(5e-7, 2.0, 1e-2, 0.7, 2e-12, 2e-12)
    slow = skf_frictional_moment(
        "angular_contact_ball", 0.030, 0.062, 500.0, 1000.0, 1000 * RPM, 20e-6, c
    )
    g_slow = angular_contact_load_variables(0.046, 500.0, 1000.0, 1000 * RPM, c)
    g_fast = angular_contact_load_variables(0.046, 500.0, 1000.0, 20000 * RPM, c)
    assert g_fast[0] > g_slow[0] and g_fast[1] > g_slow[1]  # F_g grows with n^2
    assert math.isfinite(slow.total) and slow.total > 0
    with pytest.raises(InputError, match="k_z"):
        skf_frictional_moment("four_point_contact_ball", 0.030, 0.062, 500.0, 0.0, 10.0, 20e-6, c)
    with pytest.raises(InputError, match="R3"):
        skf_frictional_moment("angular_contact_ball", 0.030, 0.062, 500.0, 0.0, 10.0, 20e-6, C62)


def test_seal_moment():
    assert seal_moment(0.02, 2.0, 2.25, 0.0313) == pytest.approx((0.02 * 31.3**2.25 + 2) * 1e-3)
    m = skf_frictional_moment(
        "radial_ball", 0.025, 0.052, 1000.0, 0.0, 100.0, 20e-6, C62, seal=0.01
    )
    assert m.seal == 0.01 and m.total == pytest.approx(m.rolling + m.sliding + 0.01)


def test_shipped_constants():
    assert set(DEEP_GROOVE_CONSTANTS) >= {"60", "62", "63", "64", "160", "618", "619"}
    assert all(not c.verified and c.r3 is None for c in DEEP_GROOVE_CONSTANTS.values())
    with pytest.raises(InputError, match="series"):
        deep_groove_constants("72")


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"radial_load": -1.0}, "radial_load"),
        ({"axial_load": float("nan")}, "axial_load"),
        ({"shaft_speed": -5.0}, "shaft_speed"),
        ({"viscosity": 0.0}, "viscosity"),
        ({"outside_diameter": 0.02}, "outside_diameter"),
        ({"bore": float("inf")}, "bore"),
        ({"axial_load": 100.0}, "static_load_rating"),
        ({"axial_load": 9000.0, "static_load_rating": 7800.0}, "axial_load"),
        ({"bearing_type": "spherical_roller"}, "bearing_type"),
        ({"constants": (1, 2, 3, 4)}, "constants"),
        ({"k_rs": -1.0}, "k_rs"),
        ({"seal": -0.1}, "seal"),
    ],
)
def test_skf_refuses_bad_input(kwargs, parameter):
    args = {
        "bearing_type": "radial_ball",
        "bore": 0.025,
        "outside_diameter": 0.052,
        "radial_load": 500.0,
        "axial_load": 0.0,
        "shaft_speed": 100.0,
        "viscosity": 20e-6,
        "constants": C62,
    }
    args.update(kwargs)
    with pytest.raises(InputError) as info:
        skf_frictional_moment(**args)
    assert info.value.parameter == parameter


def test_constants_are_validated():
    with pytest.raises(InputError, match="r1"):
        SkfGeometryConstants(float("nan"), 1.0, 1.0, 1.0)
    with pytest.raises(InputError, match="s3"):
        SkfGeometryConstants(1.0, 1.0, 1.0, 1.0, 1.0, -1.0)


def test_no_nan_over_a_grid_including_zeros():
    for n in (0.0, 1.0, 500.0, 5000.0, 50000.0):
        for nu in (1e-7, 20e-6, 1e-3):
            for fr, fa in ((0.0, 0.0), (1000.0, 0.0), (0.0, 500.0), (1e5, 1e3)):
                m = skf_frictional_moment(
                    "radial_ball", 0.025, 0.052, fr, fa, n * RPM, nu, C62, static_load_rating=1e5
                )
                assert all(math.isfinite(v) for v in m) and m.total >= 0


# ------------------------------------------------------------------ analyses
def test_result_objects():
    r = skf_friction(
        "radial_ball",
        0.025,
        0.052,
        1000.0,
        0.0,
        3000 * RPM,
        20e-6,
        C62,
        name="6205",
        lubrication="oil-air",
        lubricant_kind="synthetic",
    )
    d = r.to_dict()
    assert d["friction_torque_n_mm"] == pytest.approx(r.torque * 1e3)
    assert d["power_loss_w"] == pytest.approx(r.torque * 3000 * RPM)
    assert sum(
        d[f"{k}_torque_n_mm"] for k in ("rolling", "sliding", "seal", "drag")
    ) == pytest.approx(d["friction_torque_n_mm"])
    assert d["k_rs"] == 6e-8 and d["geometry_constants"]["verified"] is False
    assert any("not checked" in w for w in d["warnings"])
    table = r.to_pandas()
    assert list(table["component"]) == ["rolling", "sliding", "seal", "drag"]
    assert table["share"].sum() == pytest.approx(1.0)
    c = constant_friction(1000.0, 0.039, 1500 * RPM, "radial_ball")
    assert isinstance(c, FrictionResult) and c.to_dict()["friction_coefficient"] == 0.0015
    assert len(c.to_pandas()) == 1
    with pytest.raises(InputError, match="lubrication"):
        skf_friction("radial_ball", 0.025, 0.052, 1.0, 0.0, 1.0, 20e-6, C62, lubrication="mist")
    with pytest.raises(InputError, match="lubricant_kind"):
        skf_friction("radial_ball", 0.025, 0.052, 1.0, 0.0, 1.0, 20e-6, C62, lubricant_kind="water")


def test_result_plot():
    pytest.importorskip("matplotlib")
    r = skf_friction("radial_ball", 0.025, 0.052, 1000.0, 0.0, 3000 * RPM, 20e-6, C62)
    fig, ax = r.plot()
    assert len(ax.patches) == 4
    import matplotlib.pyplot as plt

    plt.close(fig)


def test_bearing_friction_from_the_catalogue():
    b, _ = bearing_from_designation("6205")
    c = bearing_friction(b, 1500 * RPM, 1000.0)
    assert c.torque == pytest.approx(0.0015 * 1000.0 * b.pitch_diameter / 2)
    p = bearing_friction(b, 1500 * RPM, 1000.0, 500.0)
    assert p.parameters["equivalent_load"] == pytest.approx(
        equivalent_dynamic_load(b, 1000.0, 500.0)[0]
    )
    assert p.parameters["equivalent_load"] > 1000.0
    s = bearing_friction(b, 1500 * RPM, 1000.0, model="skf", viscosity=20e-6)
    assert s.parameters["constants"] == C62 and s.model == "skf"
    sa = bearing_friction(b, 1500 * RPM, 1000.0, 300.0, model="skf", viscosity=20e-6)
    ref = skf_by_hand(
        1500, 20, 25, 52, 1000, C62.r1, C62.r2, C62.s1, C62.s2, fa=300.0, c0=load_ratings(b).static
    )
    assert sa.torque * 1e3 == pytest.approx(ref, rel=1e-9)
    assert any("ISO 76" in w for w in sa.warnings)
    a, _ = bearing_from_designation("7206")
    with pytest.raises(InputError, match="constants"):
        bearing_friction(a, 100.0, 1000.0, model="skf", viscosity=20e-6)
    with pytest.raises(InputError, match="viscosity"):
        bearing_friction(b, 100.0, 1000.0, model="skf")
    with pytest.raises(InputError, match="model"):
        bearing_friction(b, 100.0, 1000.0, model="palmgren")
    # a temperature the constant model does not use is still checked (50 degC given as K)
    with pytest.raises(InputError, match=r"temperature.*-60 to 300 degC"):
        bearing_friction(b, 100.0, 1000.0, temperature=50.0)


# ------------------------------------------------------------------ command line
def run_json(capsys, *args):
    return conftest.run_json(capsys, "friction", *args)


def run_error(capsys, *args):
    return conftest.run_error(capsys, "friction", *args)


def test_cli_constant_json(capsys):
    d = run_json(capsys, "6205", "--speed-rpm", "1500", "--radial-load-n", "1000")
    for key in (
        "friction_torque_n_mm",
        "power_loss_w",
        "friction_coefficient",
        "equivalent_load_n",
        "pitch_diameter_mm",
        "speed_rpm",
        "warnings",
        "sources",
    ):
        assert key in d
    assert d["friction_torque_n_mm"] == pytest.approx(0.0015 * 1000 * d["pitch_diameter_mm"] / 2)
    assert d["power_loss_w"] == pytest.approx(d["friction_torque_n_mm"] * 1e-3 * 1500 * RPM)


def test_cli_skf_json(capsys):
    args = (*SKF_6205_2RS, "--viscosity-mm2-s", "20", "--lubrication", "grease")
    d = run_json(capsys, *args)
    ref = skf_by_hand(3000, 20, 25, 52, 1000, C62.r1, C62.r2, C62.s1, C62.s2)
    assert d["friction_torque_n_mm"] == pytest.approx(ref, rel=1e-9)
    for key in (
        "rolling_torque_n_mm",
        "sliding_torque_n_mm",
        "seal_torque_n_mm",
        "drag_torque_n_mm",
        "kappa",
        "rated_viscosity_mm2_s",
        "mean_diameter_mm",
    ):
        assert key in d
    assert d["seals"] == "contact" and any("M_seal is not included" in w for w in d["warnings"])
    sealed = run_json(
        capsys, *args, "--seal-constants", "0.02,2,2.25", "--seal-diameter-mm", "31.3"
    )
    assert sealed["seal_torque_n_mm"] == pytest.approx(0.02 * 31.3**2.25 + 2)
    assert sealed["friction_torque_n_mm"] == pytest.approx(ref + sealed["seal_torque_n_mm"])


def test_cli_skf_viscosity_from_temperature(capsys):
    args = ("6205", "--speed-rpm", "3000", "--radial-load-n", "1000", "--model", "skf")
    cool = run_json(capsys, *args, "--temperature-c", "40")
    hot = run_json(capsys, *args, "--temperature-c", "80")
    assert cool["viscosity_mm2_s"] == pytest.approx(68.0)
    assert hot["viscosity_mm2_s"] < cool["viscosity_mm2_s"]
    assert hot["rolling_torque_n_mm"] < cool["rolling_torque_n_mm"]
    assert cool["lubrication"] == "oil-jet"
    grease = run_json(capsys, *args, "--lubricant", "seed004-grease")
    assert grease["lubrication"] == "grease"


def test_cli_axial_and_other_types(capsys):
    combined = ("--speed-rpm", "1500", "--radial-load-n", "1000", "--axial-load-n", "500")
    d = run_json(capsys, "6205", *combined)
    b, _ = bearing_from_designation("6205")
    assert d["equivalent_load_n"] == pytest.approx(equivalent_dynamic_load(b, 1000.0, 500.0)[0])
    assert "ISO 281" in d["equivalent_load_source"]
    own_c0 = run_json(capsys, "6205", *combined, "--model", "skf", "--viscosity-mm2-s", "30")
    assert any("ISO 76" in w for w in own_c0["warnings"])
    s = run_json(
        capsys,
        "6205",
        *combined,
        "--static-load-rating-kn",
        "7.8",
        "--model",
        "skf",
        "--viscosity-mm2-s",
        "30",
    )
    assert s["friction_torque_n_mm"] > 0
    nu = run_json(capsys, "NU205", "--speed-rpm", "1500", "--radial-load-n", "2000")
    assert nu["friction_coefficient"] == 0.0010 and nu["pitch_diameter_mm"] == pytest.approx(38.5)
    thrust = run_json(
        capsys,
        "51105",
        "--speed-rpm",
        "1000",
        "--axial-load-n",
        "1000",
        "--equivalent-load-n",
        "1000",
    )
    assert thrust["friction_type"] == "thrust_ball"
    plain = run_json(
        capsys,
        "--bore-mm",
        "25",
        "--outside-diameter-mm",
        "52",
        "--speed-rpm",
        "100",
        "--radial-load-n",
        "10",
        "--type",
        "tapered_roller",
    )
    assert plain["friction_coefficient"] == 0.0020
    ac = run_json(capsys, *SKF_7206, "--axial-load-n", "500", "--viscosity-mm2-s", "20")
    assert ac["k_z"] == 4.4 and ac["geometry_constants"]["r3"] == 2e-12


def test_cli_table(capsys):
    assert (
        main(
            ["friction", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000", "--model", "skf"]
        )
        == 0
    )
    out = capsys.readouterr().out
    assert "friction torque M" in out and "phi_ish" in out and "[N·mm]" in out


@pytest.mark.parametrize(
    "args, words",
    [
        (["6205", "--speed-rpm", "-1"], "--speed-rpm"),
        (["6205", "--speed-rpm", "10", "--radial-load-n", "nan"], "--radial-load-n"),
        ([*BORE_AND_OD, "--axial-load-n", "10"], "--axial-load-n"),
        # the library names its parameter (equivalent_load), the request its input, the
        # command line its flag
        (["NU205", "--speed-rpm", "10", "--axial-load-n", "10"], "give P (--equivalent-load-n)"),
        (["1205", "--speed-rpm", "10"], "--friction-type"),
        (["6205", "--speed-rpm", "10", "--type", "plain"], "--friction-type"),
        # issue 28: the SKF model takes roller bearings, with their constants given
        (["NU205", "--speed-rpm", "10", "--model", "skf"], "table is not shipped"),
        (["7206", "--speed-rpm", "10", "--model", "skf"], "--skf-constants"),
        ([*SKF_SLOW, "--skf-constants", "1,2"], "--skf-constants"),
        (
            [
                *BORE_AND_OD,
                "--model",
                "skf",
                "--skf-constants",
                "1e-7,1,1e-3,1",
                "--axial-load-n",
                "5",
            ],
            "--static-load-rating-kn",
        ),
        ([*SKF_SLOW, "--axial-load-n", "9000", "--static-load-rating-kn", "7.8"], "--axial-load-n"),
        ([*SKF_SLOW, "--viscosity-mm2-s", "5", "--temperature-c", "50"], "--temperature-c"),
        ([*SKF_SLOW, "--lubricant", "honey"], "--lubricant"),
        ([*SKF_SLOW, "--viscosity-mm2-s", "0"], "--viscosity-mm2-s"),
        (
            ["6205-2RS", "--speed-rpm", "10", "--model", "skf", "--seal-constants", "1,2,2"],
            "--seal-diameter-mm",
        ),
        (["--speed-rpm", "10"], "DESIGNATION"),
        (
            ["--bore-mm", "52", "--outside-diameter-mm", "25", "--speed-rpm", "10"],
            "--outside-diameter-mm",
        ),
        (["6205", "--radial-load-n", "10"], "--speed-rpm"),
        (["XYZ", "--speed-rpm", "10"], "XYZ"),
    ],
)
def test_cli_errors(capsys, args, words):
    assert words in run_error(capsys, *args)


def test_cli_enums_mirror_the_model_tables():
    assert set(FRICTION.options["lubrication"].choices) == set(K_RS)
    assert set(FRICTION.options["oil"].choices) == set(MU_EHL)
    assert set(SEED003_COEFFICIENTS) >= {"radial_ball", "thrust_ball"}


def test_unloaded_bearing_is_flagged():
    r = skf_friction("radial_ball", 0.025, 0.052, 0.0, 0.0, 1000 * RPM, 20e-6, C62)
    assert r.torque == 0.0 and any("no load" in w for w in r.warnings)
    c = constant_friction(0.0, 0.039, 100.0, "radial_ball")
    assert c.torque == 0.0 and any("no load" in w for w in c.warnings)


# ------------------------------------------------------------------ one rule for CLI and report
def _report_section(designation, speed_rpm, radial, axial, *, lubricant=None, viscosity=None):
    """The report's friction section for these inputs, with its context made as
    build_report makes it (bearinglab.report.builder)."""
    from bearinglab.operating import OperatingCondition
    from bearinglab.report import operation
    from bearinglab.report.builder import _viscosity
    from bearinglab.report.context import Context

    b, des = bearing_from_designation(designation)
    nu, how = _viscosity(lubricant, viscosity)
    ctx = Context(
        bearing=b,
        designation=des,
        viscosity=nu,
        viscosity_source=how,
        lubricant=lubricant if viscosity is None else None,
        condition=OperatingCondition(
            radial_load=radial, axial_load=axial, shaft_speed=speed_rpm * RPM
        ),
    )
    html, highlights = operation.friction(ctx)
    models = {
        m: bearing_friction(
            b,
            speed_rpm * RPM,
            radial,
            axial,
            model=m,
            **(operation.friction_inputs(ctx) if m == "skf" else {"designation": des}),
        )
        for m in ("constant", "skf")
    }
    return html, dict(highlights), models


@pytest.mark.parametrize(
    "designation, cli, report",
    [
        ("6205", [], {"lubricant": "iso-vg68"}),  # both defaults
        ("6205-2RS", ["--viscosity-mm2-s", "20"], {"viscosity": 20e-6}),
        ("6205", ["--lubricant", "seed004-grease"], {"lubricant": "seed004-grease"}),
    ],
)
def test_cli_and_report_give_the_same_torques(capsys, designation, cli, report):
    # the command and the report call bearing_friction with the same inputs; a rule that
    # one of them applied alone (lubrication method, C_0, seals) would split the numbers
    args = (designation, "--speed-rpm", "3000", "--radial-load-n", "1000", "--axial-load-n", "300")
    html, highlights, models = _report_section(designation, 3000.0, 1000.0, 300.0, **report)
    for model in ("constant", "skf"):
        d = run_json(capsys, *args, "--model", model, *cli)
        r = models[model].to_dict()
        for key in ("friction_torque_n_mm", "power_loss_w"):
            assert d[key] == pytest.approx(r[key], rel=1e-9), (model, key)
        if model == "skf":
            for key in (
                "rolling_torque_n_mm",
                "sliding_torque_n_mm",
                "viscosity_mm2_s",
                "k_rs",
                "static_rating_n",
            ):
                assert d[key] == pytest.approx(r[key], rel=1e-9), key
            assert d["seals"] == r["seals"]
    # and the page shows that SKF torque (its highlight, 3 digits)
    from bearinglab.report.document import number

    skf = run_json(capsys, *args, "--model", "skf", *cli)
    assert highlights["Friction torque"] == f"{number(skf['friction_torque_n_mm'], 3)} N·mm"
    assert "SKF four-component model" in html


# ------------------------------------------------------------------ bad input, named in units
@pytest.mark.parametrize(
    "args, words",
    [
        # issue 14: was silently ignored by the constant model
        (
            ["6205", "--speed-rpm", "10", "--viscosity-mm2-s", "-5"],
            "--viscosity-mm2-s = -5 is not allowed: expected a viscosity in (0, 1e+06] mm²/s",
        ),
        (
            [*SKF_SLOW, "--viscosity-mm2-s", "-5"],
            "--viscosity-mm2-s = -5 is not allowed: expected a viscosity in (0, 1e+06] mm²/s",
        ),
        (["6205", "--speed-rpm", "10", "--viscosity-mm2-s", "nan"], "--viscosity-mm2-s = nan"),
        (
            [*SKF_SLOW, "--temperature-c", "400"],
            "--temperature-c = 400 is not allowed: expected a temperature in [-60, 300] °C",
        ),
        (["6205", "--speed-rpm", "10", "--temperature-c", "-100"], "[-60, 300] °C"),
        (
            ["6205", "--speed-rpm", "10", "--static-load-rating-kn", "-1"],
            "--static-load-rating-kn = -1 is not allowed: expected a rating in (0, 100000] kN",
        ),
        (
            ["6205", "--speed-rpm", "10", "--equivalent-load-n", "-3"],
            "--equivalent-load-n = -3 is not allowed: expected a load in [0, 1e+07] N",
        ),
        (
            [
                "6205-2RS",
                "--speed-rpm",
                "10",
                "--model",
                "skf",
                "--seal-constants",
                "1,2,2",
                "--seal-diameter-mm",
                "0",
            ],
            "--seal-diameter-mm = 0 is not allowed: expected a diameter in (0, 100000] mm",
        ),
        (
            [*SKF_SLOW, "--seal-constants", "1,2,2"],
            "--seal-constants = '1,2,2' is not allowed: expected seal constants only with contact",
        ),
        (
            [*SKF_SLOW, "--seal-constants", "1,-2,2"],
            "--seal-constants = '1,-2,2' is not allowed: expected K_S1,K_S2,BETA",
        ),
        (
            ["6205", "--speed-rpm", "10", "--lubricant", "honey"],
            "--lubricant = 'honey' is not allowed: expected one of iso-vg68, seed004-grease",
        ),
        (
            ["NU205", "--speed-rpm", "10", "--pitch-diameter-mm", "60"],
            "--pitch-diameter-mm = 60 is not allowed: expected between the bore 25 mm and the "
            "outside diameter 52 mm",
        ),
        (
            ["NU205", "--speed-rpm", "10", "--bore-mm", "60"],
            "--bore-mm = 60 is not allowed: expected less than the outside diameter 52 mm",
        ),
        ([*BORE_AND_OD, "--type", "plain"], "--friction-type = 'plain' is not allowed"),
        (
            ["--bore-mm", "-25", "--outside-diameter-mm", "52", "--speed-rpm", "10"],
            "--bore-mm = -25 is not allowed: expected a length in (0, 100000] mm",
        ),
    ],
)
def test_cli_errors_name_option_value_and_range(capsys, args, words):
    assert words in run_error(capsys, *args)


def test_inputs_the_model_does_not_use_are_checked_and_named(capsys):
    d = run_json(
        capsys,
        "6205",
        "--speed-rpm",
        "1500",
        "--radial-load-n",
        "1000",
        "--viscosity-mm2-s",
        "30",
        "--lubrication",
        "grease",
    )
    # the command names the options as typed; the library's own note is not repeated
    unused = "--viscosity-mm2-s and --lubrication: no effect with --friction-model constant"
    assert unused in d["warnings"] and not any("does not use" in w for w in d["warnings"])
    t = run_json(capsys, "6205", "--speed-rpm", "10", "--temperature-c", "50")
    assert "--temperature-c: no effect with --friction-model constant" in t["warnings"]
    b, _ = bearing_from_designation("6205")
    with pytest.raises(InputError, match="viscosity"):
        bearing_friction(b, 100.0, 1000.0, viscosity=-5e-6)
    with pytest.raises(InputError, match="temperature"):
        bearing_friction(b, 100.0, 1000.0, model="skf", lubricant="iso-vg68", temperature=20.0)
    s = bearing_friction(b, 100.0, 1000.0, model="skf", viscosity=20e-6, equivalent_load=9.0)
    assert s.unused == ("equivalent_load",)
    assert "the SKF model does not use: equivalent_load" in s.to_dict()["warnings"]


def test_bearings_without_a_ball_model():
    from bearinglab.friction import FrictionBearing

    nu = FrictionBearing.from_designation("NU205")
    assert nu.bearing_type == "cylindrical_roller" and nu.pitch_diameter == pytest.approx(0.0385)
    ncf = bearing_friction(
        FrictionBearing(
            "NCF205", "cylindrical_roller", 0.025, 0.052, 0.0385, "given", design_variant="NCF"
        ),
        100.0,
        1000.0,
    )
    assert ncf.parameters["friction_type"] == "cylindrical_roller_full_complement"
    own = FrictionBearing.from_dimensions(
        0.025, 0.052, pitch_diameter=0.04, bearing_type="tapered_roller_thrust"
    )
    assert own.bearing_type == "thrust_roller" and own.pitch_diameter_source == "given"
    with pytest.raises(InputError, match="pitch_diameter"):
        FrictionBearing.from_dimensions(0.025, 0.052, pitch_diameter=0.06)


@pytest.mark.parametrize(
    "args",
    [
        ["6205", "--speed-rpm", "3000", "--radial-load-n", "1000"],
        [
            *SKF_6205_2RS,
            "--axial-load-n",
            "500",
            "--seal-constants",
            "0.02,2,2.25",
            "--seal-diameter-mm",
            "31.3",
            "--temperature-c",
            "70",
        ],
        [*SKF_7206, "--viscosity-mm2-s", "12.5"],
    ],
)
def test_cli_tables_fit_80_columns_uncut(capsys, monkeypatch, args):
    from rich.console import Console

    from bearinglab.cli import _app

    monkeypatch.setattr(_app._LazyConsole, "_console", Console(width=80))
    assert main(["friction", *args]) == 0
    out = capsys.readouterr().out
    assert "…" not in out and max(len(line) for line in out.splitlines()) <= 80
    d = run_json(capsys, *args)
    # every number of the table is printed whole (4 significant digits)
    for key in ("friction_torque_n_mm", "power_loss_w"):
        assert f"{d[key]:.4g}" in out


def test_the_load_and_speed_are_checked_as_for_static():
    """friction at 7.6 C0 or 2.7e6 mm/min ran without the warnings static gives (an audit);
    a bearing known by its dimensions alone has no C0 to check against."""
    b, _ = bearing_from_designation("6205")
    heavy = bearing_friction(b, 100.0, 60_000.0)
    assert any("s0 = C0/P0" in w for w in heavy.warnings)
    fast = bearing_friction(b, 70_000 * math.pi / 30, 1000.0, lubricant="iso-vg68", model="skf")
    assert any("speed factor" in w for w in fast.warnings)
    assert not any("s0 = C0/P0" in w for w in bearing_friction(b, 100.0, 1000.0).warnings)
    from bearinglab.friction import FrictionBearing

    dims = FrictionBearing.from_dimensions(0.025, 0.052, pitch_diameter=0.0385)
    assert not any("s0" in w for w in bearing_friction(dims, 100.0, 60_000.0).warnings)
