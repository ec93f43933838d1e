"""bearinglab noise on the command line (seed 003's C&U 608 example, short records), the
form-error options shared with simulate and static, and the example script."""

import importlib.util
import json
import math
from pathlib import Path

import pytest
from conftest import run_error, run_json

from bearinglab.cli import main

NOISE = ["noise", "608", "--speed-rpm", "720", "--radial-load-n", "50"]
FORMS = [
    "--waviness",
    "inner:order=7,amplitude_um=0.2",
    "--waviness",
    "outer:order=7,amplitude_um=0.2",
    "--ball-size-error-um",
    "2",
    "--seed",
    "1",
]
POINT_A = ["--distance-mm", "10"]  # seed 003's point A, inside the 608 (radius 11 mm)
FAST = ["--points", "256"]  # one cage revolution (0.224 s) at ~1.1 kHz
EXAMPLE = Path(__file__).parents[2] / "examples" / "seed003_608_noise.py"


def _numbers(value, path=""):
    """Every number in a JSON tree, with its path."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _numbers(v, f"{path}.{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _numbers(v, f"{path}[{i}]")
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        yield path, value


@pytest.fixture(scope="module")
def base():
    """The 608 base case of seed 003 (our choices: 0.2 um waviness, 2 um band, seed 1)."""
    import contextlib
    import io

    buffer = io.StringIO()
    with contextlib.redirect_stdout(buffer):
        assert main([*NOISE, *FORMS, *FAST, *POINT_A, "--json"]) == 0
    return json.loads(buffer.getvalue())


def test_noise_json_keys_and_values(base):
    for key in (
        "spl_time_mean_db",
        "spl_time_max_db",
        "spl_leq_db",
        "spl_leq_inner_ring_db",
        "spl_leq_balls_db",
        "field_point_source",
        "velocity_bands_um_s",
        "velocity_bands_hz",
        "velocity_bands_source",
        "velocity_bands_note",
        "peaks",
        "kinematic",
        "imperfections",
        "seed",
        "speed_rpm",
        "radial_load_n",
        "distance_mm",
        "points",
        "duration_s",
        "orbit_peak_to_peak_um",
        "warnings",
    ):
        assert key in base, key
    for path, value in _numbers(base):
        assert math.isfinite(value), path
    assert base["speed_rpm"] == 720 and base["radial_load_n"] == 50 and base["distance_mm"] == 10
    assert base["points"] == 256 and base["seed"] == 1
    assert 0 < base["spl_time_mean_db"] < base["spl_time_max_db"]
    assert base["spl_leq_inner_ring_db"] > base["spl_leq_balls_db"]
    bands = base["velocity_bands_um_s"]
    assert set(bands) == {"low", "medium", "high"} and all(v > 0 for v in bands.values())
    # ISO 15242's 1800 rpm edges scaled to 720 rpm (x 0.4)
    assert base["velocity_bands_hz"] == {
        "low": [20.0, 120.0],
        "medium": [120.0, 720.0],
        "high": [720.0, 4000.0],
    }
    # 256 points over 0.224 s cannot resolve 4 kHz: the rigid dynamic model gives the bands
    assert base["velocity_bands_source"] == "rigid model"
    assert base["velocity_bands_sample_rate_hz"] == pytest.approx(10240.0)
    assert base["velocity_bands_duration_s"] >= 0.5  # ten periods of 20 Hz
    imp = base["imperfections"]
    assert [w["order"] for w in imp["waviness"]] == [7, 7]
    assert len(imp["ball_size_errors"]["ball_size_errors_um"]) == 7
    assert imp["ball_size_errors"]["band_um"] <= 2.0


def test_pressure_lines_sit_at_the_ball_pass_frequencies(base):
    """Inner-race waviness of order Z = 7 under a radial load moves the ring at BPFI (seed
    002: the pressure peaks at the ball-pass frequencies)."""
    peaks = base["peaks"]
    assert peaks and {"frequency_hz", "amplitude", "matched", "harmonic"} <= peaks[0].keys()
    top = max(peaks, key=lambda p: p["amplitude"])
    assert (top["matched"], top["harmonic"]) == ("bpfi", 1)
    assert top["frequency_hz"] == pytest.approx(
        base["kinematic"]["bpfi_hz"], abs=base["peaks_resolution_hz"]
    )


def test_spl_grows_with_the_waviness_amplitude(capsys, base):
    levels = []
    for amplitude in ("0.1", "0.4"):
        d = run_json(
            capsys,
            *NOISE,
            "--waviness",
            f"inner:order=7,amplitude_um={amplitude}",
            "--waviness",
            f"outer:order=7,amplitude_um={amplitude}",
            *FAST,
            *POINT_A,
        )
        levels.append(d["spl_time_mean_db"])
    # without ball-size errors the pressure is about proportional to the amplitude (+12 dB
    # for 4x); the base case (0.2 um, with ball errors) lies between
    assert levels[1] - levels[0] == pytest.approx(12.0, abs=2.0)
    assert levels[0] < base["spl_time_mean_db"] < levels[1]


def test_seed_makes_the_ball_errors_reproducible(capsys, base):
    again = run_json(capsys, *NOISE, *FORMS, *FAST, *POINT_A)
    other = run_json(capsys, *NOISE, *FORMS[:-1], "2", *FAST, *POINT_A)
    errors = base["imperfections"]["ball_size_errors"]["ball_size_errors_um"]
    assert again["imperfections"]["ball_size_errors"]["ball_size_errors_um"] == errors
    assert again["spl_time_mean_db"] == base["spl_time_mean_db"]
    assert other["imperfections"]["ball_size_errors"]["ball_size_errors_um"] != errors


def test_random_surface_and_ball_waviness(capsys):
    d = run_json(
        capsys,
        *NOISE,
        "--surface3d",
        "outer:amplitude_um=0.05,length_circ_mm=0.5,length_axial_mm=0.5",
        "--waviness",
        "ball:order=2,amplitude_um=0.05,ball=3",
        "--seed",
        "4",
        "--points",
        "128",
    )
    surface = d["imperfections"]["surfaces"][0]
    assert surface["race"] == "outer" and surface["seed"] == 5  # SEED + 1 + index
    assert d["imperfections"]["waviness"][0]["ball"] == 3
    assert all(math.isfinite(v) for _, v in _numbers(d))


def test_human_output_and_plot(tmp_path, capsys):
    png = tmp_path / "noise.png"
    assert main([*NOISE, *FORMS, *FAST, "--plot", str(png)]) == 0
    out = capsys.readouterr().out
    assert "mean SPL" in out and "ISO 15242 velocity bands" in out and "1x bpfi" in out
    assert png.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.slow
def test_bands_come_from_the_orbit_when_it_is_sampled_finely_enough(capsys):
    """At 720 rpm the ISO bands reach 4 kHz and start at 20 Hz: 4100 instants over 0.5 s
    (8.2 kHz) let the orbit itself resolve them; its low band agrees with the rigid
    model's (quasi-static below the resonances)."""
    orbit = run_json(
        capsys,
        *NOISE,
        "--waviness",
        "outer:order=8,amplitude_um=0.5",
        "--duration-s",
        "0.5",
        "--points",
        "4100",
    )
    rigid = run_json(
        capsys,
        *NOISE,
        "--waviness",
        "outer:order=8,amplitude_um=0.5",
        *FAST,
        "--bands-from",
        "rigid",
    )
    assert orbit["velocity_bands_source"] == "orbit"
    assert orbit["velocity_bands_sample_rate_hz"] == pytest.approx(4100 / 0.5, rel=1e-3)
    assert rigid["velocity_bands_source"] == "rigid model"
    low = orbit["velocity_bands_um_s"]["low"]
    assert low == pytest.approx(rigid["velocity_bands_um_s"]["low"], rel=0.25)


def test_default_field_point_lies_outside_the_bearing(capsys, base):
    """Issue 14: the default point is 10 mm outside the outside diameter (the 608's radius
    is 11 mm), not seed 003's point A 10 mm from the centre, which lies inside it."""
    d = run_json(capsys, *NOISE, "--waviness", "inner:order=7,amplitude_um=0.2", "--points", "128")
    assert d["distance_mm"] == pytest.approx(21.0) and d["angle_deg"] == 90
    assert d["field_point_source"].startswith("default: 10 mm outside")
    assert not any("outside radius" in w for w in d["warnings"])
    assert base["field_point_source"] == "given"
    side = run_json(capsys, *NOISE, "--angle-deg", "0", "--points", "64")
    assert side["distance_mm"] == pytest.approx(21.0) and side["angle_deg"] == 0
    assert side["field_point_source"].endswith("at 0 deg from +x")
    assert any("inside the bearing's outside radius" in w for w in base["warnings"])


def test_the_command_and_the_report_give_the_same_numbers(capsys):
    """Issue 12: one ISO 15242 computation (and one sound) for the command and the report:
    `noise --json` equals the report's sections for the same bearing, speed and load."""
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.operating import OperatingCondition
    from bearinglab.report import vibration
    from bearinglab.report.context import Context
    from bearinglab.report.document import number
    from bearinglab.units import rpm_to_rad_s

    cli = run_json(capsys, "noise", "6205", "--speed-rpm", "1797", "--radial-load-n", "1000")
    bearing, _ = bearing_from_designation("6205")
    ctx = Context(
        bearing=bearing,
        condition=OperatingCondition(radial_load=1000.0, shaft_speed=rpm_to_rad_s(1797.0)),
    )
    html, _ = vibration.bands(ctx)
    vibration.noise(ctx)
    report = ctx.results["noise"].to_dict()
    assert cli["velocity_bands_source"] == report["velocity_bands_source"] == "rigid model"
    for band in ("low", "medium", "high"):
        assert cli["velocity_bands_um_s"][band] == pytest.approx(
            report["velocity_bands_um_s"][band], rel=1e-9
        )
        assert cli["velocity_bands_hz"][band] == pytest.approx(report["velocity_bands_hz"][band])
    for key in ("spl_leq_db", "spl_time_mean_db", "distance_mm"):
        assert cli[key] == pytest.approx(report[key], rel=1e-9), key
    assert cli["velocity_bands_hz"]["high"][1] == pytest.approx(10e3 * 1797 / 1800)
    # the page's table shows the same value
    medium = number(cli["velocity_bands_um_s"]["medium"])
    assert f'<td class="num">{medium}</td>' in html, medium


@pytest.mark.parametrize(
    "args, words",
    [
        (["--waviness", "inner"], ["--waviness = 'inner'", "no KEY=VALUE given"]),
        (["--waviness", "middle:order=7,amplitude_um=1"], ["unknown race 'middle'"]),
        (["--waviness", "inner:order=0,amplitude_um=1"], ["order must be >= 1"]),
        (["--waviness", "inner:order=7.5,amplitude_um=1"], ["order = '7.5' is not a whole number"]),
        (["--waviness", "inner:order=7"], ["amplitude_um is required"]),
        (["--waviness", "inner:order=7,amplitude_um=-1"], ["amplitude_um must be >= 0"]),
        (["--waviness", "inner:order=7,amplitude_um=1,ball=2"], ["unknown key 'ball'"]),
        (["--waviness", "ball:order=2,amplitude_um=0.1,ball=7"], ["a ball index in [0, 6]"]),
        (["--waviness", "inner:order=7,amplitude_um=500"], ["amplitude_um must be at most"]),
        (["--ball-size-error-um", "-1"], ["--ball-size-error-um = '-1'", "must be >= 0"]),
        (["--ball-size-error-um", "3,1"], ["LOW > HIGH"]),
        (["--ball-size-error-um", "wide"], ["--ball-size-error-um = 'wide'"]),
        (["--ball-size-error-um", "1000"], ["within +-"]),
        (["--surface3d", "inner:amplitude_um=0.1"], ["--surface3d", "length_circ_mm is required"]),
        (
            ["--surface3d", "ball:amplitude_um=0.1,length_circ_mm=1,length_axial_mm=1"],
            ["unknown race 'ball'"],
        ),
        (
            ["--surface3d", "inner:amplitude_um=0.1,length_circ_mm=0.001,length_axial_mm=0.001"],
            ["a grid of"],
        ),
        (
            ["--surface3d", "inner:amplitude_um=0.1,length_circ_mm=100,length_axial_mm=1"],
            ["length_circ_mm must be at most"],
        ),
        (["--distance-mm", "8"], ["--distance-mm = 8", "outside the inner ring"]),
        (["--radial-load-n", "0"], ["--radial-load-n"]),
        (["--points", "5"], ["--points"]),
        (["--seed", "-1"], ["--seed"]),
        (["--plot", "noise.txt"], ["--plot"]),
        (["--bands-from", "ear"], ["--bands-from"]),
    ],
)
def test_bad_input_is_one_line(tmp_path, monkeypatch, capsys, args, words):
    monkeypatch.chdir(tmp_path)
    err = run_error(capsys, *NOISE, *args)
    for word in words:
        assert word in err, err
    assert not list(tmp_path.iterdir())


def test_example_script_draws_every_figure(tmp_path, capsys):
    spec = importlib.util.spec_from_file_location("seed003_608_noise", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert module.main([str(tmp_path), "--points", "64", "--quick"]) == 0
    names = {p.name for p in tmp_path.iterdir()}
    assert names == {
        "fig09_inner_ring.png",
        "fig10_ball_centres.png",
        "fig11_ball_velocity.png",
        "fig12_14_spl_time.png",
        "pressure_spectrum.png",
        "directivity.png",
        "fig15_16_waviness_number.png",
        "fig17_amplitude.png",
        "fig18_speed.png",
        "fig19_load.png",
        "fig20_ball_band.png",
    }
    assert "mean SPL" in capsys.readouterr().out


def test_the_record_sampling_is_checked_against_the_bearing(capsys, base):
    """Too few points for the ball-pass lines, or less than a cage revolution, ran without
    a word (an audit: 16 points in 1 s gave -17.7 dB and one aliased line)."""
    assert not any("Nyquist" in w or "cage revolution" in w for w in base["warnings"])
    sparse = run_json(capsys, *NOISE, *FORMS, "--points", "16", *POINT_A)
    assert any("BPFI" in w and "Nyquist" in w for w in sparse["warnings"])
    short = run_json(capsys, *NOISE, *FORMS, "--duration-s", "0.01", *FAST, *POINT_A)
    assert any("shorter than one cage revolution" in w for w in short["warnings"])
