"""The command line: JSON keys, readable output, explicit geometry and bad input."""

import json
import math
import os
import subprocess
import sys

import pytest
from conftest import run_json

from bearinglab.cli import main

INFO_KEYS = {
    "designation",
    "system",
    "bearing_type",
    "bore_mm",
    "outside_diameter_mm",
    "width_mm",
    "ball_count",
    "ball_diameter_mm",
    "pitch_diameter_mm",
    "contact_angle_deg",
    "geometry_source",
}
FREQ_KEYS = {
    f"{n}_{u}" for n in ("ftf", "bpfo", "bpfi", "bsf", "ball_defect") for u in ("hz", "order")
}
CONTACT_KEYS = {
    "semi_major_mm",
    "semi_minor_mm",
    "max_pressure_gpa",
    "approach_um",
    "ellipticity",
    "stiffness_n_per_um",
}


def test_info_6205_json(capsys):
    d = run_json(capsys, "info", "6205")
    assert INFO_KEYS <= d.keys()
    assert d["system"] == "iso" and d["bearing_type"] == "radial_ball"
    assert (d["bore_mm"], d["outside_diameter_mm"], d["width_mm"]) == (25, 52, 15)
    assert d["ball_count"] == 9 and d["ball_diameter_mm"] == pytest.approx(7.94, abs=0.01)
    assert d["geometry_source"] in ("catalog", "mixed")
    # the GOST reading of 6205 (angular contact) is reported, not silently dropped
    assert d["decoded"]["alternatives"]


def test_info_180205_is_6205_2rs(capsys):
    d = run_json(capsys, "info", "180205")
    assert d["system"] == "gost" and d["bearing_type"] == "radial_ball"
    assert d["decoded"]["iso_equivalent"].replace(" ", "") == "6205-2RS"
    assert d["bore_mm"] == 25 and d["ball_count"] == 9


def test_info_310_forced_gost(capsys):
    d = run_json(capsys, "info", "310", "--system", "gost")
    assert d["system"] == "gost" and d["bore_mm"] == 50 and d["outside_diameter_mm"] == 110
    assert d["decoded"]["iso_equivalent"] == "6310"


def test_info_of_a_roller_bearing_gives_its_roller_geometry(capsys):
    d = run_json(capsys, "info", "7206", "--system", "gost")
    assert d["bearing_type"] == "tapered_roller" and d["bore_mm"] == 30
    assert d["rolling_element"] == "roller" and "ball_count" not in d
    assert d["roller_count"] > 10 and 0 < d["roller_diameter_mm"] < (62 - 30) / 2
    assert 5 < d["contact_angle_deg"] < 30 and d["geometry_source"] in (
        "catalog",
        "estimated",
        "mixed",
    )


def test_frequencies_6205_at_1797(capsys):
    d = run_json(capsys, "frequencies", "6205", "--speed-rpm", "1797")
    assert FREQ_KEYS <= d.keys()
    assert d["bpfo_order"] == pytest.approx(3.5848, rel=3e-4)  # CWRU table
    assert d["bpfi_hz"] == pytest.approx(5.4152 * 1797 / 60, rel=3e-4)
    assert d["ball_defect_hz"] == pytest.approx(2 * d["bsf_hz"])


def test_frequencies_outer_rotating(capsys):
    inner = run_json(capsys, "frequencies", "6205", "--speed-rpm", "600")
    outer = run_json(capsys, "frequencies", "6205", "--speed-rpm", "600", "--outer-rotating")
    assert outer["ftf_order"] == pytest.approx(1 - inner["ftf_order"])


def test_frequencies_at_a_speed_past_the_makers_limits_says_so(capsys):
    # an audit: 900 000 rpm was silent (the frequencies themselves stay kinematic)
    fast = run_json(capsys, "frequencies", "6205", "--speed-rpm", "900000")
    assert any("speed factor n d_m" in w for w in fast["warnings"])
    slow = run_json(capsys, "frequencies", "6205", "--speed-rpm", "1797")
    assert not any("speed factor" in w for w in slow["warnings"])


def test_contact_json(capsys):
    d = run_json(capsys, "contact", "6205", "--ball-load-n", "1000")
    for side in ("inner", "outer"):
        assert CONTACT_KEYS <= d[side].keys()
        assert 1.0 < d[side]["max_pressure_gpa"] < 4.0
    assert d["inner"]["max_pressure_gpa"] > d["outer"]["max_pressure_gpa"]


def test_contact_methods_agree(capsys):
    exact = run_json(capsys, "contact", "6205", "--ball-load-n", "500")
    approx = run_json(
        capsys, "contact", "6205", "--ball-load-n", "500", "--method", "hamrock-brewe"
    )
    assert approx["inner"]["approach_um"] == pytest.approx(exact["inner"]["approach_um"], rel=0.03)


def test_explicit_geometry_without_designation(capsys):
    d = run_json(
        capsys,
        "frequencies",
        "--balls",
        "9",
        "--ball-diameter-mm",
        "7.94",
        "--pitch-diameter-mm",
        "38.51",
        "--speed-rpm",
        "1750",
    )
    assert d["bpfo_hz"] == pytest.approx(104.19, abs=0.01)  # seed 003, ER-16K


def test_override_wins_and_is_marked_user(capsys):
    d = run_json(capsys, "info", "6205", "--balls", "8")
    assert d["ball_count"] == 8
    assert d["geometry_sources"]["ball_count"]["kind"] == "user"


def test_geometry_file(tmp_path, capsys):
    f = tmp_path / "g.toml"
    f.write_text("balls = 9\nball_diameter_mm = 7.94\npitch_diameter_mm = 38.51\n")
    d = run_json(capsys, "contact", "--geometry", str(f), "--ball-load-n", "100")
    assert d["inner"]["semi_major_mm"] > 0


def test_material_options(capsys):
    soft = run_json(
        capsys, "contact", "6205", "--ball-load-n", "500", "--elastic-modulus-gpa", "100"
    )
    steel = run_json(capsys, "contact", "6205", "--ball-load-n", "500")
    assert soft["inner"]["approach_um"] > steel["inner"]["approach_um"]


def test_readable_output(capsys):
    assert main(["info", "6205-2RS"]) == 0
    out = capsys.readouterr().out
    assert "deep-groove" in out.lower() or "radial" in out.lower()
    assert "BPFO" in out and "catalog" in out
    assert main(["frequencies", "6205", "--speed-rpm", "1797"]) == 0
    assert "BPFI" in capsys.readouterr().out


@pytest.mark.parametrize(
    "args, words",
    [
        (["frequencies", "6205", "--speed-rpm", "-5"], "--speed-rpm"),
        (["frequencies", "6205", "--speed-rpm", "abc"], "speed-rpm"),
        (["frequencies", "6205"], "speed-rpm"),
        (["contact", "6205", "--ball-load-n", "0"], "--ball-load-n"),
        (["info", "6205-XYZ"], "XYZ"),
        (["info", "6205", "--system", "din"], "system"),
        (["info", "6205", "--balls", "40"], "--balls = 40"),
        (["info", "6205", "--inner-groove-factor", "0.5"], "--inner-groove-factor = 0.5"),
        (["frequencies", "--balls", "9", "--speed-rpm", "100"], "--ball-diameter-mm"),
        (["contact", "--geometry", "/nonexistent.toml", "--ball-load-n", "1"], "--geometry"),
    ],
)
def test_bad_input_is_one_line_with_exit_code_2(capsys, args, words):
    assert main(args) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1, captured.err
    assert words in lines[0] and "Traceback" not in captured.err
    assert captured.out == ""


def test_console_script_end_to_end():
    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "bearinglab.cli",
            "frequencies",
            "6205",
            "--speed-rpm",
            "1797",
            "--json",
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert math.isclose(json.loads(done.stdout)["bpfo_order"], 3.5848, rel_tol=3e-4)
    bad = subprocess.run(
        [sys.executable, "-m", "bearinglab.cli", "info", "??"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert bad.returncode == 2 and "Traceback" not in bad.stderr


def test_plots_are_written(tmp_path, capsys):
    for cmd in (
        ["contact", "6205", "--ball-load-n", "800"],
        ["frequencies", "6205", "--speed-rpm", "1797"],
    ):
        out = tmp_path / f"{cmd[0]}.png"
        assert main([*cmd, "--plot", str(out)]) == 0
        assert out.stat().st_size > 10_000 and out.read_bytes()[:4] == b"\x89PNG"
    capsys.readouterr()
    assert main(["contact", "6205", "--ball-load-n", "800", "--plot", str(tmp_path / "x.txt")]) == 2
    assert "--plot" in capsys.readouterr().err
    assert not list(tmp_path.glob(".*"))  # no temporary files left behind


def test_info_catalogue_name_and_dimension_only_bearings(capsys):
    d = run_json(capsys, "info", "ER-16K")
    assert d["ball_count"] == 9 and d["pitch_diameter_mm"] == pytest.approx(38.51)
    d = run_json(capsys, "info", "1205")
    assert d["bearing_type"] == "self_aligning_ball" and d["outside_diameter_mm"] == 52
    assert d["ball_count"] is None and "single-row" in d["no_geometry_reason"]


# ------------------------------------------------------------------ review fixes


def one_error_line(capsys, args, code=2):
    """The one error line; with --json, stdout holds the error's fields, nothing else."""
    assert main(args) == code
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1, captured.err
    assert "Traceback" not in captured.err
    if "--json" in args and code == 2:
        error = json.loads(captured.out)["error"]
        assert lines[0] == "error: " + error["message"] and error["input"]
    else:
        assert captured.out == ""
    return lines[0]


def _no_nan(text):
    def refuse(name):
        raise AssertionError(f"{name} in JSON")

    return json.loads(text, parse_constant=refuse)


GEOMETRY_FILE_ERRORS = [
    ("balls = true", "--geometry balls = True", "integer"),
    ("balls = 9.0", "--geometry balls = 9", "integer"),
    ('balls = "9"', "--geometry balls = '9'", "integer"),
    ("ball_count = 9.5", "--geometry ball_count = 9.5", "integer"),
    ('ball_diameter_mm = "7.94"', "--geometry ball_diameter_mm = '7.94'", "number"),
    ("ball_diameter_mm = [7.94]", "--geometry ball_diameter_mm = [7.94]", "number"),
    ("ball_diameter_mm = true", "--geometry ball_diameter_mm = True", "number"),
    ("ball_diameter_mm = inf", "--geometry ball_diameter_mm = inf", "finite"),
    ("pitch_diameter_mm = nan", "--geometry pitch_diameter_mm = nan", "finite"),
    ("[pitch_diameter_mm]\nvalue = 38.5", "--geometry pitch_diameter_mm", "number"),
    ('system = "din"', "--geometry system = 'din'", "'gost' or 'iso'"),
    ("name = 3", "--geometry name = 3", "text"),
    ('designation = "6205"', "--geometry key 'designation'", "one of"),
    ('geometry = "other.toml"', "--geometry key 'geometry'", "one of"),
    ("[bearing]\nballs = 9", "--geometry key 'bearing'", "one of"),
    ("balls = 9\nball_count = 9", "--geometry key 'ball_count'", "once"),
    ("clearance_um = -1000", "--geometry clearance_um = -1000", "[-397.002 µm, 635.203 µm]"),
]


@pytest.mark.parametrize(
    "content, start, words",
    GEOMETRY_FILE_ERRORS,
    ids=[c[0].split("\n")[0] for c in GEOMETRY_FILE_ERRORS],
)
def test_geometry_file_values_are_checked(tmp_path, capsys, content, start, words):
    f = tmp_path / "g.toml"
    f.write_text(content + "\n", encoding="utf-8")
    line = one_error_line(capsys, ["info", "6205", "--geometry", str(f)])
    assert line.startswith("error: " + start) and words in line


def test_geometry_file_that_cannot_be_read(tmp_path, capsys):
    assert "a TOML file, not a directory" in one_error_line(
        capsys, ["info", "--geometry", str(tmp_path)]
    )
    latin1 = tmp_path / "latin1.toml"
    latin1.write_bytes("name = 'Kugellager größe 6205'\n".encode("latin-1"))
    assert "UTF-8" in one_error_line(capsys, ["info", "--geometry", str(latin1)])
    if hasattr(os, "geteuid") and os.geteuid() != 0:  # root reads anything
        locked = tmp_path / "locked.toml"
        locked.write_text("balls = 9\n")
        locked.chmod(0)
        assert "readable" in one_error_line(capsys, ["info", "--geometry", str(locked)])


def test_geometry_file_system_and_name_are_honoured(tmp_path, capsys):
    f = tmp_path / "g.toml"
    f.write_text('system = "gost"\nname = "test rig bearing"\n', encoding="utf-8")
    d = run_json(capsys, "info", "310", "--geometry", str(f))
    assert d["system"] == "gost" and d["name"] == "test rig bearing"
    # the command line wins over the file
    d = run_json(capsys, "info", "6205", "--geometry", str(f), "--system", "iso")
    assert d["system"] == "iso"


def test_full_width_digits_work_and_other_digits_are_one_line(capsys):
    d = run_json(capsys, "info", "６２０５")
    assert d["bore_mm"] == 25 and d["ball_count"] == 9
    line = one_error_line(capsys, ["info", "٦٢٠٥"])
    assert "'٦٢٠٥'" in line and "0-9" in line


def test_extreme_groove_factor_is_solved(capsys):
    d = run_json(
        capsys, "contact", "6205", "--ball-load-n", "1000", "--inner-groove-factor", "0.500005"
    )
    assert d["inner"]["ellipticity"] > 900 and math.isfinite(d["inner"]["approach_um"])
    assert any("groove shoulder" in w for w in d["warnings"])


@pytest.mark.parametrize(
    "args, start, words",
    [
        (["contact", "6205", "--ball-load-n", "1e300"], "--ball-load-n = 1e+300", "(0, 1e+07] N"),
        (["contact", "6205", "--ball-load-n", "inf"], "--ball-load-n = inf", "N"),
        (["contact", "6205", "--ball-load-n", "nan"], "--ball-load-n = nan", "N"),
        (["frequencies", "6205", "--speed-rpm", "1e308"], "--speed-rpm = 1e+308", "[0, 1e+06] rpm"),
        (["frequencies", "6205", "--speed-rpm", "1e300", "--json"], "--speed-rpm", "rpm"),
        (
            ["info", "--balls", "9", "--ball-diameter-mm", "1e300", "--pitch-diameter-mm", "40"],
            "--ball-diameter-mm = 1e+300",
            "(0, 100000] mm",
        ),
        (
            ["info", "6205", "--elastic-modulus-gpa", "1e300"],
            "--elastic-modulus-gpa = 1e+300",
            "GPa",
        ),
        (["info", "6205", "--density-kg-m3", "-1"], "--density-kg-m3 = -1", "kg/m³"),
        (["info", "6205", "--poisson-ratio", "0.5"], "--poisson-ratio = 0.5", "[0, 0.5)"),
        (["info", "6205", "--clearance-um", "nan"], "--clearance-um = nan", "finite"),
    ],
)
def test_huge_and_non_finite_inputs_are_refused_with_a_range(capsys, args, start, words):
    line = one_error_line(capsys, args)
    assert line.startswith("error: " + start) and words in line


def test_json_is_finite_at_the_limits(capsys):
    for args in (
        ["contact", "6205", "--ball-load-n", "1e7"],
        [
            "contact",
            "--balls",
            "3",
            "--ball-diameter-mm",
            "0.001",
            "--pitch-diameter-mm",
            "100000",
            "--ball-load-n",
            "1e7",
        ],
        ["frequencies", "6205", "--speed-rpm", "1e6"],
        ["info", "6205", "--elastic-modulus-gpa", "10000", "--density-kg-m3", "1e5"],
    ):
        assert main([*args, "--json"]) == 0, args
        _no_nan(capsys.readouterr().out)


@pytest.mark.parametrize("args", [[], ["--help"]])
def test_no_arguments_print_the_help(capsys, args):
    assert main(args) == 0
    captured = capsys.readouterr()
    assert "Usage" in captured.out and "frequencies" in captured.out
    assert captured.out.count("\n") > 5 and captured.err == ""


def test_no_arguments_as_a_program():
    done = subprocess.run(
        [sys.executable, "-m", "bearinglab.cli"], capture_output=True, text=True, check=False
    )
    assert done.returncode == 0 and "Usage" in done.stdout and done.stderr == ""


NOT_IN_CATALOGUE = ["4-3003124P", "67206", "6-18030PR20P", "3205", "23024", "6330"]


@pytest.mark.parametrize("text", NOT_IN_CATALOGUE)
def test_info_decodes_designations_without_catalogue_dimensions(capsys, text):
    d = run_json(capsys, "info", text)
    assert d["bore_mm"] == d["decoded"]["bore_mm"] > 0
    assert d["ball_count"] is None and d["geometry_source"] is None
    assert d["outside_diameter_mm"] is None and d["dimensions"] is None
    assert d["no_dimensions_reason"] and d["no_geometry_reason"]
    assert main(["info", text]) == 0
    out = capsys.readouterr().out
    assert d["decoded"]["description"].split(",")[0] in " ".join(out.split())
    assert "no boundary dimensions" in out and "no internal geometry" in out


# seed 003's worked examples, read as GOST 3189-89 (the system the seed describes)
SEED_003 = [
    ("7206", "tapered_roller", 30.0),
    ("67206", "tapered_roller", 30.0),
    ("311", "radial_ball", 55.0),
    ("6-36209", "angular_contact_ball", 45.0),
    ("4-12210", "cylindrical_roller", 50.0),
    ("4-3003124P", "spherical_roller", 120.0),
    ("60205", "radial_ball", 25.0),
    ("80205", "radial_ball", 25.0),
    ("160205", "radial_ball", 25.0),
    ("180205", "radial_ball", 25.0),
    ("6-18030PR20P", "thrust_ball", 150.0),
]


@pytest.mark.parametrize("text, bearing_type, bore_mm", SEED_003, ids=[c[0] for c in SEED_003])
def test_info_json_of_every_seed_003_example(capsys, text, bearing_type, bore_mm):
    d = run_json(capsys, "info", text, "--system", "gost")
    assert d["system"] == "gost" and d["bearing_type"] == bearing_type
    assert d["decoded"]["bore_mm"] == bore_mm
    if d.get("rolling_element") == "roller":
        assert {"roller_count", "roller_diameter_mm", "roller_length_mm"} <= d.keys()
        return
    assert INFO_KEYS <= d.keys()
    if d["ball_count"] is None:
        assert d["no_geometry_reason"]
    else:
        assert d["geometry_source"] in ("catalog", "estimated", "mixed")


@pytest.mark.parametrize(
    "args, message",
    [
        (
            ["info", "6205", "--contact-angle-deg", "95"],
            "--contact-angle-deg = 95 is not allowed: expected an angle in [0, 90] degrees",
        ),
        (
            ["info", "6205", "--clearance-um", "-1000"],
            "--clearance-um = -1000 is not allowed: expected a value in [-397.002 µm, 635.203 µm]",
        ),
        (["info", ""], "DESIGNATION = '' is not allowed"),
        (
            ["info", "6205", "--ball-diameter-mm", "50"],
            "--ball-diameter-mm = 50 is not allowed: expected less than the pitch diameter "
            "39.0398 mm",
        ),
        (
            ["info", "6205", "--outside-diameter-mm", "20"],
            "--outside-diameter-mm = 20 is not allowed: expected more than the bore 25 mm",
        ),
        (["info", "6205", "--ball-diameter-mm", "-2"], "--ball-diameter-mm = -2"),
        (
            [
                "frequencies",
                "--balls",
                "9",
                "--ball-diameter-mm",
                "7.94",
                "--pitch-diameter-mm",
                "39",
                "--contact-angle-deg",
                "-1",
                "--speed-rpm",
                "10",
            ],
            "--contact-angle-deg = -1",
        ),
    ],
)
def test_errors_name_the_option_with_its_value_in_its_units(capsys, args, message):
    line = one_error_line(capsys, args)
    assert line.startswith("error: " + message), line
    assert "diametral_clearance" not in line and "contact_angle =" not in line


@pytest.mark.parametrize(
    "command, extra",
    [("frequencies", ["--speed-rpm", "1797"]), ("contact", ["--ball-load-n", "1000"])],
)
def test_results_carry_the_geometry_and_its_source(capsys, command, extra):
    d = run_json(capsys, command, "6205", *extra)
    assert (d["ball_count"], d["ball_diameter_mm"]) == (9, pytest.approx(7.94, abs=0.01))
    assert d["pitch_diameter_mm"] == pytest.approx(39.04, abs=0.01)
    assert d["contact_angle_deg"] == 0 and d["geometry_source"] == "mixed"
    # 6205 also reads as a GOST bearing: the ISO reading is said, nothing else
    assert [w for w in d["warnings"] if not w.startswith("also reads as GOST")] == []
    assert main([command, "6205", *extra]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "geometry (mixed): Z = 9, D_w = 7.94 mm, d_m = 39.04 mm" in out


def test_estimated_ball_count_of_an_angular_contact_bearing_is_warned(capsys):
    d = run_json(capsys, "frequencies", "7206", "--speed-rpm", "1000")
    assert d["geometry_source"] == "mixed" and d["contact_angle_deg"] == 40
    assert any("lower bound" in w for w in d["warnings"])
    assert main(["frequencies", "7206", "--speed-rpm", "1000"]) == 0
    assert "warning: ball count Z = " in capsys.readouterr().out
    d = run_json(capsys, "frequencies", "7206", "--speed-rpm", "1000", "--balls", "14")
    assert not any("lower bound" in w for w in d["warnings"])


def test_contact_warns_when_the_ellipse_leaves_the_groove(capsys):
    d = run_json(capsys, "contact", "6205", "--ball-load-n", "20000")
    assert any(
        w.startswith("inner contact: the contact ellipse runs over the groove shoulder")
        for w in d["warnings"]
    )
    assert main(["contact", "6205", "--ball-load-n", "20000"]) == 0
    assert "warning: inner contact" in capsys.readouterr().out


def test_thrust_ball_bearing_with_explicit_geometry(capsys):
    args = [
        "frequencies",
        "51105",
        "--speed-rpm",
        "1000",
        "--balls",
        "15",
        "--ball-diameter-mm",
        "6",
        "--pitch-diameter-mm",
        "38",
    ]
    d = run_json(capsys, *args)
    assert d["contact_angle_deg"] == 90 and d["ball_count"] == 15
    assert d["bpfo_order"] == pytest.approx(7.5) and d["bpfi_order"] == pytest.approx(7.5)
    assert d["ftf_order"] == pytest.approx(0.5)
    # this example's balls (32-44 mm) reach past the washers' 42 mm: said, not refused
    assert any("outside diameter 42 mm" in w for w in d["warnings"])
    i = run_json(
        capsys,
        "info",
        "51105",
        "--balls",
        "15",
        "--ball-diameter-mm",
        "6",
        "--pitch-diameter-mm",
        "33.5",
    )
    assert i["bearing_type"] == "thrust_ball" and i["outside_diameter_mm"] == 42
    assert i["width_mm"] == 11
    assert [w for w in i["warnings"] if not w.startswith("also reads as GOST")] == []
    line = one_error_line(capsys, ["frequencies", "51105", "--speed-rpm", "1000"])
    assert "give --balls, --ball-diameter-mm and --pitch-diameter-mm" in line
    assert "boundary_dimensions()" not in line


def test_gost_angular_contact_bearing_asks_for_the_angle(capsys):
    line = one_error_line(
        capsys, ["frequencies", "6205", "--system", "gost", "--speed-rpm", "1000"]
    )
    assert line.endswith("give --contact-angle-deg")
    d = run_json(
        capsys,
        "frequencies",
        "6205",
        "--system",
        "gost",
        "--speed-rpm",
        "1000",
        "--contact-angle-deg",
        "26",
    )
    assert d["contact_angle_deg"] == 26
    i = run_json(capsys, "info", "6205", "--system", "gost")  # dimensions only
    assert i["ball_count"] is None and "--contact-angle-deg" in i["no_geometry_reason"]


def test_unwritable_plot_is_one_line(tmp_path, capsys):
    a_file = tmp_path / "not_a_directory"
    a_file.write_text("x")
    line = one_error_line(
        capsys, ["frequencies", "6205", "--speed-rpm", "100", "--plot", str(a_file / "f.png")]
    )
    assert line.startswith("error: --plot = ") and "writable" in line
    assert list(tmp_path.iterdir()) == [a_file]


def test_tables_wrap_long_cells_instead_of_cutting_them():
    """In a narrow terminal a long cell (a file path, a verdict) wraps; no "…" is printed."""
    from rich.console import Console

    from bearinglab.cli._output import _table

    path = "cwru/12k_DE/3001.mat/" * 4
    console = Console(width=50, record=True, color_system=None)
    console.print(_table("verdicts", ["file", "verdict"], [[path, "no fault detected"]]))
    text = console.export_text()
    assert "…" not in text
    cells = "".join(line.split("│")[1].strip() for line in text.splitlines() if "│" in line)
    assert path in cells


def test_a_table_of_words_fits_80_columns_with_whole_headers():
    """benchmark's verdicts as a table of words (no vertical rules, left-aligned): at 80
    columns every header word and every verdict stays whole; only the paths wrap."""
    from rich.console import Console

    from bearinglab.cli._output import _table

    heads = ["file", "label", "S&R 2015", "raw", "cpw", "drs-sk", "combined", "right"]
    row = ["mfpt/OuterRaceFault_vload_1.mat", "outer", "M1:Y2 M2:Y2", *["no fault"] * 4, "yes"]
    console = Console(width=80, record=True, color_system=None)
    console.print(_table("verdicts", heads, [row], words=True))
    lines = console.export_text().splitlines()
    assert all(len(ln.rstrip()) <= 80 for ln in lines)
    assert all(h in lines[1].split() for h in ("file", "label", "combined", "drs-sk", "right"))
    assert lines[3].count("no fault") == 4 and lines[3].rstrip().endswith("yes")


@pytest.mark.parametrize("width", [60, 80, 120])
def test_wide_tables_keep_their_last_column(width):
    """A table that needs more than the terminal has (benchmark's verdicts: eight columns,
    long paths) wraps its cells; its last column and right border are never cropped, and
    where it fits, the header words stay whole."""
    from rich.console import Console

    from bearinglab.cli._output import _table

    heads = ["file", "label", "S&R 2015", "raw", "cpw", "drs-sk", "combined", "right"]
    row = ["mfpt/OuterRaceFault_vload_1.mat", "outer", "M1:Y2 M2:Y2", *["no fault"] * 4, "yes"]
    console = Console(width=width, record=True, color_system=None)
    console.print(_table("verdicts", heads, [row, row]))
    lines = [ln.rstrip() for ln in console.export_text().splitlines()[1:] if ln.strip()]
    assert all(ln[-1] in "┓┃┩│┘" for ln in lines), lines
    if width >= 120:
        header = "".join(lines[1:3])
        assert all(h in header for h in ("combined", "drs-sk", "label", "right"))
