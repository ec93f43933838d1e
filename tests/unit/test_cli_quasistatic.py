"""static, stiffness-map and ring-modes on the command line."""

import numpy as np
import pytest
from conftest import README_STATIC, STATIC_BALL_KEYS, STATIC_KEYS, run_json

from bearinglab.cli import main

BALL_KEYS = set(STATIC_BALL_KEYS)
#: seed 000's ring-level inputs for bearing 310: n = 8, m_h = 0.6 kg, K_x = 150e6 N/m,
#: kappa = 0.33, measured free-ring frequencies 1.92 / 5.34 / 10.00 kHz (m = 2, 3, 4)
SEED000_RING = (
    "--modes",
    "1:4",
    "--ring-mass-kg",
    "0.6",
    "--radial-stiffness-n-per-m",
    "150e6",
    "--free-frequencies-hz",
    "1920,5340,10000",
    "--ball-mass-ratio",
    "0.33",
    "--contact-stiffness-ratio",
    "1",
)


def test_static_json_keys_and_equilibrium(capsys):
    d = run_json(capsys, *README_STATIC)
    for key in STATIC_KEYS:
        assert key in d
    assert d["stiffness_matrix_order"] == ["x", "y", "z", "tilt_x", "tilt_y"]
    assert np.array(d["stiffness_matrix_si"]).shape == (5, 5)
    assert len(d["balls"]) == 9 and BALL_KEYS <= d["balls"][0].keys()
    assert d["equilibrium_residual_n"] < 1e-6 * 1000
    # the most loaded ball sits under the load (radial load acts downwards by default)
    top = max(d["balls"], key=lambda b: b["inner_load_n"])
    assert top["angle_deg"] == pytest.approx(270.0)


def test_static_film_and_orbit(capsys):
    args = ("static", "6205", "--radial-load-n", "1000", "--speed-rpm", "6000")
    dry = run_json(capsys, *args)
    wet = run_json(capsys, *args, "--film", "--orbit")
    # the film is a layer between the surfaces: it takes up play, the ring moves less
    assert wet["radial_displacement_um"] < dry["radial_displacement_um"]
    assert wet["orbit_peak_to_peak_um"] > 0 and len(wet["orbit"]["x_um"]) > 10


def test_static_lubricant_options_without_film_are_checked_and_named_as_unused(capsys):
    args = ("static", "6205", "--radial-load-n", "1000")
    quiet = run_json(capsys, *args, "--film", "--speed-rpm", "3000")
    assert not any("no effect" in w for w in quiet["warnings"])
    unused = run_json(capsys, *args, "--temperature-c", "50", "--lubricant", "seed004-grease")
    assert any(
        "--lubricant and --temperature-c: no effect without --film" in w for w in unused["warnings"]
    )
    # the same answer as without them
    assert unused["radial_displacement_um"] == run_json(capsys, *args)["radial_displacement_um"]
    # at 0 rpm the speed's effects have nothing to act on
    idle = run_json(capsys, *args, "--gyroscopic", "--film")
    assert (
        "--gyroscopic and --film: no effect at --speed-rpm 0 (no rolling speed)"
        in (idle["warnings"])
    )
    # out of range even without --film (it was accepted silently)
    assert main([*args, "--temperature-c", "500"]) == 2
    assert "--temperature-c = 500" in capsys.readouterr().err


def test_static_plot(tmp_path, capsys):
    out = tmp_path / "s.png"
    assert main(["static", "6205", "--radial-load-n", "800", "--plot", str(out)]) == 0
    assert out.read_bytes()[:4] == b"\x89PNG"
    capsys.readouterr()


@pytest.mark.parametrize(
    "args, words",
    [
        (["static", "6205", "--radial-load-n", "-5"], "--radial-load-n"),
        (
            ["static", "6205", "--radial-load-n", "10", "--misalignment-mrad", "50"],
            "--misalignment-mrad",
        ),
        (
            ["static", "6205", "--radial-load-n", "10", "--film", "--lubricant", "honey"],
            "--lubricant",
        ),
        (["stiffness-map", "6205", "--radial-load-n", "0:100"], "--radial-load-n"),
        (["stiffness-map", "6205", "--speed-rpm", "abc"], "--speed-rpm"),
        (["ring-modes", "6310", "--modes", "0:3"], "--modes"),
        (["ring-modes", "6310", "--free-frequencies-hz", "1900,x"], "--free-frequencies-hz"),
        (
            ["ring-modes", "6310", "--modes", "2:4", "--free-frequencies-hz", "1900"],
            "--free-frequencies-hz",
        ),
        (["ring-modes", "--balls", "8", "--modes", "2:3"], "--free-frequencies-hz"),
        (["ring-modes", "--modes", "2:3"], "DESIGNATION"),
        (["ring-modes", "6310", "--axial-load-n", "0"], "--axial-load-n"),
        (["ring-modes", "6310", "--ring-mass-kg", "0"], "--ring-mass-kg"),
        # an audit: 1e6 N gave a "tangent stiffness"; f_1 silently replaced the K_x given
        (["ring-modes", "6205", "--axial-load-n", "1e6"], "--axial-load-n = 1000000"),
        (
            ["ring-modes", "6205", "--radial-stiffness-n-per-m", "2e8"]
            + ["--rigid-body-frequency-hz", "100"],
            "give one of them",
        ),
        (
            [
                "stiffness-map",
                "6205",
                "--radial-load-n",
                "0:1:10000",
                "--axial-load-n",
                "0:1:10000",
            ],
            "at most",
        ),
        (["stiffness-map", "6205", "--plot", "/nonexistent/x.png"], "existing directory"),
        (
            ["static", "6205", "--radial-load-n", "100", "--stiffness-csv", "/nonexistent/k.csv"],
            "existing directory",
        ),
    ],
)
def test_bad_input(capsys, args, words):
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]


def test_stiffness_map_plot_with_nothing_solved_is_an_error(tmp_path, capsys):
    # it exited 0 and wrote nothing (an audit); now: no file at all, and the reason
    out = tmp_path / "map.csv"
    plot = tmp_path / "map.png"
    args = ["stiffness-map", "6205", "--radial-load-n", "0", "-o", str(out), "--plot", str(plot)]
    assert main(args) == 2
    assert "no case of the map solved" in capsys.readouterr().err
    assert not out.exists() and not plot.exists()


def test_stiffness_map_csv_and_json(tmp_path, capsys):
    csv = tmp_path / "m.csv"
    d = run_json(
        capsys,
        "stiffness-map",
        "6205",
        "--radial-load-n",
        "0:1000:3",
        "--axial-load-n",
        "0,200",
        "-o",
        str(csv),
    )
    assert d["cases"] == 6 and d["solved"] == 5  # (0, 0) has no load
    rows = [r for r in d["rows"] if r["status"] == "ok"]
    assert all(r["radial_stiffness_n_per_um"] > 0 for r in rows)
    assert csv.read_text().startswith("radial_load_n,")


def test_ring_modes_json_with_the_paper_overrides(capsys):
    # seed 000's bearing 310 with its ring-level inputs (SEED000_RING)
    d = run_json(
        capsys,
        "ring-modes",
        "310",
        "--system",
        "gost",
        *SEED000_RING,
    )
    modes = {m["m"]: m for m in d["modes"]}
    assert set(modes) == {1, 2, 3, 4}
    assert modes[1]["approx_hz"][0] == pytest.approx(2516, abs=10)  # f_1
    assert modes[3]["approx_hz"][0] == pytest.approx(6300, abs=50)  # seed 000: 6.3 kHz
    assert len(modes[4]["approx_hz"]) == 2  # 2m = n: split
    for m in modes.values():
        assert {"m", "free_hz", "approx_hz", "refined_hz", "epsilon"} <= m.keys()


def test_ring_modes_from_ring_level_inputs_alone(capsys):
    """Seed 000's own inputs, with no ball geometry: the same frequencies as with the 310."""
    alone = run_json(capsys, "ring-modes", "--balls", "8", *SEED000_RING)
    with_bearing = run_json(capsys, "ring-modes", "310", "--system", "gost", *SEED000_RING)
    assert alone["modes"] == with_bearing["modes"] and alone["bearing"] is None


def test_ring_modes_with_the_load_distribution_stiffness(capsys):
    args = ("ring-modes", "6310", "--axial-load-n", "200", "--modes", "2:3")
    closed = run_json(capsys, *args)
    solved = run_json(capsys, *args, "--stiffness-from", "load-distribution")
    assert solved["sources"]["radial_stiffness"].startswith("load distribution")
    # both are the radial stiffness of the same axially loaded bearing: close, not equal
    ratio = solved["radial_stiffness_n_per_um"] / closed["radial_stiffness_n_per_um"]
    assert 0.7 < ratio < 1.3 and ratio != 1.0


def test_four_point_bearings_get_gothic_arches(capsys):
    radial = run_json(capsys, "static", "QJ205", "--radial-load-n", "2000")
    loaded = [b for b in radial["balls"] if b["inner_load_n"] > 0]
    assert loaded and all(b["contact_points"] == 4 for b in loaded)  # seed 001 fig. 5a
    axial = run_json(capsys, "static", "QJ205", "--axial-load-n", "2000")
    assert all(b["contact_points"] == 2 for b in axial["balls"])  # seed 001 fig. 1
    assert axial["balls"][0]["inner_contact_angle_deg"] > 35.0
    arches = run_json(
        capsys,
        "static",
        "6205",
        "--radial-load-n",
        "2000",
        "--clearance-um",
        "0",
        "--inner-arch-angle-deg",
        "20",
        "--outer-arch-angle-deg",
        "20",
    )
    assert max(b["contact_points"] for b in arches["balls"]) == 4


def test_stiffness_map_function_refuses_negative_loads():
    from bearinglab.errors import InputError
    from bearinglab.geometry import BallBearing
    from bearinglab.quasistatic.study import stiffness_map

    b = BallBearing(ball_count=9, ball_diameter=7.94e-3, pitch_diameter=39.04e-3)
    with pytest.raises(InputError, match="radial_loads"):
        stiffness_map(b, [-1.0, 100.0], [0.0], [0.0], workers=1)


# ------------------------------------------------------------------ orbits (issue 5)
B608 = ["static", "608", "--radial-load-n", "50"]


def test_static_orbit_over_one_ball_spacing(capsys):
    d = run_json(capsys, *B608, "--orbit")
    assert d["orbit_kind"] == "ball_set"
    assert len(d["orbit"]["x_um"]) == 25  # 24 steps, both ends
    assert d["orbit"]["ball_phase_deg"][-1] - d["orbit"]["ball_phase_deg"][0] == pytest.approx(
        360 / 7
    )
    assert 0 < d["orbit_peak_to_peak_um"] == pytest.approx(d["orbit"]["orbit_peak_to_peak_um"])


def test_static_orbit_with_waviness_runs_in_time(tmp_path, capsys):
    plain = run_json(capsys, *B608, "--speed-rpm", "720", "--orbit")
    png = tmp_path / "orbit.png"
    d = run_json(
        capsys,
        *B608,
        "--speed-rpm",
        "720",
        "--waviness",
        "outer:order=8,amplitude_um=0.5",
        "--orbit-points",
        "64",
        "--orbit-plot",
        str(png),
    )
    assert d["orbit_kind"] == "time" and len(d["orbit"]["time_s"]) == 64
    assert d["orbit"]["cage_hz"] == pytest.approx(4.46, abs=0.01)
    # q = Z + 1 on the outer race moves the ring at Z f_c, more than a perfect bearing's
    # ball passage does (0.77 um: the ball-set orbit)
    assert d["orbit_peak_to_peak_um"] > 1.3 * plain["orbit_peak_to_peak_um"]
    assert d["imperfections"]["waviness"][0]["order"] == 8
    assert len(d["effective_diameter_error_um"]) == 7 and d["seed"] == 0
    assert png.read_bytes()[:4] == b"\x89PNG"


def test_static_with_form_errors_changes_the_load_distribution(capsys):
    plain = run_json(capsys, *B608)
    wavy = run_json(capsys, *B608, "--waviness", "inner:order=7,amplitude_um=2,phase_deg=90")
    # order Z on the inner race: at t = 0 (ball 0 at -90 deg, under the load) every ball
    # sits in a trough, cos(7 (-90 deg) + 90 deg) = -1: the ring drops by about 2 um
    assert wavy["effective_diameter_error_um"] == pytest.approx([-2.0] * 7)
    shift = wavy["radial_displacement_um"] - plain["radial_displacement_um"]
    assert shift == pytest.approx(2.0, abs=0.5)
    assert "orbit" not in wavy


@pytest.mark.parametrize(
    "args, flag",
    [
        (["--waviness", "inner:order=7,amplitude_um=0.5", "--orbit"], "--speed-rpm"),
        (["--orbit-points", "1", "--orbit"], "--orbit-points"),
        (["--orbit-plot", "orbit.txt"], "--orbit-plot"),
        (["--waviness", "outer:order=7"], "--waviness"),
        (["--ball-size-error-um", "-2"], "--ball-size-error-um"),
    ],
)
def test_bad_orbit_and_form_error_options(tmp_path, monkeypatch, capsys, args, flag):
    monkeypatch.chdir(tmp_path)
    code = main([*B608, *args])
    err = capsys.readouterr().err
    assert code == 2 and err.startswith("error: ") and flag in err and err.count("\n") == 1


def test_stiffness_map_table_with_units_says_which_rows_it_shows(capsys):
    assert main(["stiffness-map", "6205", "--radial-load-n", "0:2000:50"]) == 0
    out = capsys.readouterr().out
    assert "C_r [N/µm]" in out and "S_r [µm]" in out and "(40 of 49 shown)" in out
