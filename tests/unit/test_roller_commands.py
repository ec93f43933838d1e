"""Roller bearings through the commands: each takes a roller designation, or refuses in
the user's terms what is modelled for ball bearings only (issue 28)."""

from __future__ import annotations

import math

import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from tests.conftest import run_error, run_json

NU205 = bearing_from_designation("NU205", rollers=True)[0]


def test_stiffness_map_of_a_cylindrical_bearing_matches_the_static_solution(capsys):
    d = run_json(capsys, "stiffness-map", "NU205", "--radial-load-n", "500,2000", "--workers", "1")
    assert d["solved"] == 2
    for row in d["rows"]:
        assert "max_ball_load_n" not in row
        r = solve_load_distribution(
            NU205,
            OperatingCondition(radial_load=row["radial_load_n"], radial_load_angle=-math.pi / 2),
        )
        assert row["radial_stiffness_n_per_um"] == pytest.approx(
            r.radial_stiffness * 1e-6, rel=1e-3
        )
        assert row["max_roller_load_n"] == pytest.approx(r.max_roller_load, rel=1e-3)
    # a roller line contact stiffens more slowly than a ball's (Q ~ delta^1.1 vs ^1.5)
    first, second = d["rows"]
    ratio = second["radial_stiffness_n_per_um"] / first["radial_stiffness_n_per_um"]
    assert 1.0 < ratio < 4 ** (1 / 3)


def test_a_lone_tapered_row_without_axial_load_is_a_case_not_solved(capsys):
    d = run_json(
        capsys, "stiffness-map", "32206", "--radial-load-n", "1000", "--axial-load-n", "0,2000"
    )
    status = {row["axial_load_n"]: row["status"] for row in d["rows"]}
    assert status[2000.0] == "ok" and "induced axial force" in status[0.0]


def test_ball_only_options_are_refused_for_a_roller_map(capsys):
    assert "--gyroscopic" in run_error(capsys, "stiffness-map", "NU205", "--gyroscopic")


@pytest.mark.parametrize(
    "option, value",
    [
        ("--waviness-amplitude-um", "0.5"),
        ("--ball-size-error-um", "0:1"),
        ("--dynamic-model", "slip"),
    ],
)
def test_a_data_set_refuses_ball_only_models_with_a_roller_bearing(capsys, tmp_path, option, value):
    err = run_error(
        capsys, "dataset", str(tmp_path / "set"), "--bearings", "6205,NU205", option, value
    )
    assert err.startswith(f"error: {option} = ") and "NU205 is a roller bearing" in err
    assert not (tmp_path / "set").exists()


def test_a_roller_report_leaves_out_the_ball_models_and_says_why(tmp_path):
    from bearinglab.report.request import report_from

    r = report_from(
        {"designation": "NU205", "speed_rpm": 1500, "radial_load_n": 2000, "slip_duration_s": 0}
    )
    assert not r.failed
    assert {s.key for s in r.left_out} == {"ring-resonances", "noise"}
    html = r.to_html()
    assert "Largest roller load" in html and "number of rollers" in html
    assert "Not computed: seed 000" in html


def test_a_tapered_report_leaves_out_the_planar_dynamic_model():
    from bearinglab.report.request import report_from

    r = report_from(
        {
            "designation": "32206",
            "speed_rpm": 1500,
            "radial_load_n": 2000,
            "axial_load_n": 1500,
            "slip_duration_s": 0,
        }
    )
    assert not r.failed
    assert {s.key for s in r.left_out} == {
        "ring-resonances",
        "noise",
        "envelope-spectrum",
        "vibration-bands",
    }
    friction = next(s for s in r.sections if s.key == "friction")
    assert dict(friction.highlights)["Friction torque"].endswith("N·mm")


def test_friction_of_a_tapered_row_under_axial_load_takes_iso_281s_equivalent_load(capsys):
    d = run_json(
        capsys,
        "friction",
        "32206",
        "--speed-rpm",
        "1500",
        "--radial-load-n",
        "2000",
        "--axial-load-n",
        "1500",
    )
    life = run_json(
        capsys,
        "life",
        "32206",
        "--speed-rpm",
        "1500",
        "--radial-load-n",
        "2000",
        "--axial-load-n",
        "1500",
    )
    assert d["equivalent_load_n"] == pytest.approx(life["equivalent_load_n"], rel=1e-9)
    assert d["equivalent_load_n"] > 2000


def test_friction_of_a_cylindrical_bearing_under_axial_load_asks_for_p(capsys):
    err = run_error(
        capsys,
        "friction",
        "NU205",
        "--speed-rpm",
        "1500",
        "--radial-load-n",
        "2000",
        "--axial-load-n",
        "150",
    )
    assert "--axial-load-n = 150" in err and "--equivalent-load-n" in err
