"""The command line: JSON keys, readable output, explicit geometry and bad input."""

import json
import math
import subprocess
import sys

import pytest

from bearinglab.cli import main

INFO_KEYS = {"designation", "system", "bearing_type", "bore_mm", "outside_diameter_mm",
             "width_mm", "ball_count", "ball_diameter_mm", "pitch_diameter_mm",
             "contact_angle_deg", "geometry_source"}
FREQ_KEYS = {f"{n}_{u}" for n in ("ftf", "bpfo", "bpfi", "bsf", "ball_defect")
             for u in ("hz", "order")}
CONTACT_KEYS = {"semi_major_mm", "semi_minor_mm", "max_pressure_gpa", "approach_um",
                "ellipticity", "stiffness_n_per_um"}


def run_json(capsys, *args):
    code = main([*args, "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)


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


def test_info_of_a_roller_bearing_gives_dimensions_only(capsys):
    d = run_json(capsys, "info", "7206", "--system", "gost")
    assert d["bearing_type"] == "tapered_roller" and d["bore_mm"] == 30
    assert d["ball_count"] is None


def test_frequencies_6205_at_1797(capsys):
    d = run_json(capsys, "frequencies", "6205", "--speed-rpm", "1797")
    assert FREQ_KEYS <= d.keys()
    assert d["bpfo_order"] == pytest.approx(3.5848, rel=3e-4)       # CWRU table
    assert d["bpfi_hz"] == pytest.approx(5.4152 * 1797 / 60, rel=3e-4)
    assert d["ball_defect_hz"] == pytest.approx(2 * d["bsf_hz"])


def test_frequencies_outer_rotating(capsys):
    inner = run_json(capsys, "frequencies", "6205", "--speed-rpm", "600")
    outer = run_json(capsys, "frequencies", "6205", "--speed-rpm", "600", "--outer-rotating")
    assert outer["ftf_order"] == pytest.approx(1 - inner["ftf_order"])


def test_contact_json(capsys):
    d = run_json(capsys, "contact", "6205", "--ball-load-n", "1000")
    for side in ("inner", "outer"):
        assert CONTACT_KEYS <= d[side].keys()
        assert 1.0 < d[side]["max_pressure_gpa"] < 4.0
    assert d["inner"]["max_pressure_gpa"] > d["outer"]["max_pressure_gpa"]


def test_contact_methods_agree(capsys):
    exact = run_json(capsys, "contact", "6205", "--ball-load-n", "500")
    approx = run_json(capsys, "contact", "6205", "--ball-load-n", "500", "--method",
                      "hamrock-brewe")
    assert approx["inner"]["approach_um"] == pytest.approx(exact["inner"]["approach_um"],
                                                           rel=0.03)


def test_explicit_geometry_without_designation(capsys):
    d = run_json(capsys, "frequencies", "--balls", "9", "--ball-diameter-mm", "7.94",
                 "--pitch-diameter-mm", "38.51", "--speed-rpm", "1750")
    assert d["bpfo_hz"] == pytest.approx(104.19, abs=0.01)        # seed 003, ER-16K


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
    soft = run_json(capsys, "contact", "6205", "--ball-load-n", "500",
                    "--elastic-modulus-gpa", "100")
    steel = run_json(capsys, "contact", "6205", "--ball-load-n", "500")
    assert soft["inner"]["approach_um"] > steel["inner"]["approach_um"]


def test_readable_output(capsys):
    assert main(["info", "6205-2RS"]) == 0
    out = capsys.readouterr().out
    assert "deep-groove" in out.lower() or "radial" in out.lower()
    assert "BPFO" in out and "catalog" in out
    assert main(["frequencies", "6205", "--speed-rpm", "1797"]) == 0
    assert "BPFI" in capsys.readouterr().out


@pytest.mark.parametrize("args, words", [
    (["frequencies", "6205", "--speed-rpm", "-5"], "--speed-rpm"),
    (["frequencies", "6205", "--speed-rpm", "abc"], "speed-rpm"),
    (["frequencies", "6205"], "speed-rpm"),
    (["contact", "6205", "--ball-load-n", "0"], "--ball-load-n"),
    (["info", "6205-XYZ"], "XYZ"),
    (["info", "6205", "--system", "din"], "system"),
    (["info", "6205", "--balls", "40"], "ball_count"),
    (["info", "6205", "--inner-groove-factor", "0.5"], "inner_groove_factor"),
    (["frequencies", "--balls", "9", "--speed-rpm", "100"], "--ball-diameter-mm"),
    (["contact", "--geometry", "/nonexistent.toml", "--ball-load-n", "1"], "--geometry"),
])
def test_bad_input_is_one_line_with_exit_code_2(capsys, args, words):
    assert main(args) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1, captured.err
    assert words in lines[0] and "Traceback" not in captured.err
    assert captured.out == ""


def test_console_script_end_to_end():
    done = subprocess.run([sys.executable, "-m", "bearinglab.cli", "frequencies", "6205",
                           "--speed-rpm", "1797", "--json"], capture_output=True, text=True,
                          check=False)
    assert done.returncode == 0, done.stderr
    assert math.isclose(json.loads(done.stdout)["bpfo_order"], 3.5848, rel_tol=3e-4)
    bad = subprocess.run([sys.executable, "-m", "bearinglab.cli", "info", "??"],
                         capture_output=True, text=True, check=False)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr


def test_plots_are_written(tmp_path, capsys):
    for cmd in (["contact", "6205", "--ball-load-n", "800"],
                ["frequencies", "6205", "--speed-rpm", "1797"]):
        out = tmp_path / f"{cmd[0]}.png"
        assert main([*cmd, "--plot", str(out)]) == 0
        assert out.stat().st_size > 10_000 and out.read_bytes()[:4] == b"\x89PNG"
    capsys.readouterr()
    assert main(["contact", "6205", "--ball-load-n", "800", "--plot", str(tmp_path / "x.txt")]) == 2
    assert "--plot" in capsys.readouterr().err
    assert not list(tmp_path.glob(".*"))          # no temporary files left behind


def test_info_catalogue_name_and_dimension_only_bearings(capsys):
    d = run_json(capsys, "info", "ER-16K")
    assert d["ball_count"] == 9 and d["pitch_diameter_mm"] == pytest.approx(38.51)
    d = run_json(capsys, "info", "1205")
    assert d["bearing_type"] == "self_aligning_ball" and d["outside_diameter_mm"] == 52
    assert d["ball_count"] is None and "single-row" in d["no_geometry_reason"]
