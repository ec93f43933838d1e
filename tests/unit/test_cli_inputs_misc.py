"""Options without effect and option errors of `frequencies`, `study`, `dataset` and
`ring-modes`: a warning naming the options (table and JSON `warnings`), an error naming the
option the user typed, one line, nothing written."""

import pandas as pd
import pytest
from conftest import run_error, run_json

from bearinglab.analyses.vibration import SIMULATE
from bearinglab.cli import main
from bearinglab.dataset.sampling import DatasetSpec
from bearinglab.errors import InputError
from bearinglab.study.cases import Grid

NO_FREQUENCY_EFFECT = "no effect on the defect frequencies"


def _no_effect(warnings: list[str]) -> list[str]:
    return [w for w in warnings if "no effect" in w or "identical" in w]


# ------------------------------------------------------------------ frequencies
def test_frequencies_names_the_geometry_options_kinematics_does_not_use(capsys):
    args = ("frequencies", "6205", "--speed-rpm", "1800")
    plain = run_json(capsys, *args)
    assert _no_effect(plain["warnings"]) == []
    moot = ("--clearance-um", "20", "--width-mm", "16", "--elastic-modulus-gpa", "200")
    d = run_json(capsys, *args, *moot, "--contact-angle-deg", "5")
    (warning,) = _no_effect(d["warnings"])
    assert warning.startswith("--clearance-um and --width-mm and --elastic-modulus-gpa: ")
    assert NO_FREQUENCY_EFFECT in warning and "--contact-angle-deg" not in warning
    # indeed no effect: the same frequencies as without them
    assert run_json(capsys, *args, *moot)["bpfo_hz"] == plain["bpfo_hz"]
    # the people's table shows the same warning
    assert main([*args, *moot]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "--clearance-um and --width-mm and --elastic-modulus-gpa: no effect" in out


def test_frequencies_bore_counts_when_the_geometry_is_estimated_from_it(capsys):
    # 6305 has no published internal geometry: Z, D_w and d_m are estimated from d and D
    args = ("frequencies", "6305", "--speed-rpm", "1800")
    d = run_json(capsys, *args, "--bore-mm", "24")
    assert d["bpfo_hz"] != run_json(capsys, *args)["bpfo_hz"]
    assert _no_effect(d["warnings"]) == []
    # 6205's geometry is published: its bore does not enter the kinematics
    published = run_json(capsys, "frequencies", "6205", "--speed-rpm", "1800", "--bore-mm", "24")
    assert any(w.startswith("--bore-mm: ") for w in _no_effect(published["warnings"]))


# ------------------------------------------------------------------ study
def _study(tmp_path, name, *args):
    return (
        "study",
        "frequencies",
        "--set",
        "designation=6205",
        *args,
        "-o",
        str(tmp_path / name),
        "--scheduler",
        "serial",
    )


def test_study_seed_repeats_and_workers_without_effect_are_named(tmp_path, capsys):
    d = run_json(
        capsys,
        *_study(tmp_path, "fixed", "--set", "speed_rpm=1000,2000", "--seed", "3"),
        "--repeats",
        "2",
        "--workers",
        "2",
    )
    seed, repeats, workers = _no_effect(d["warnings"])
    assert seed.startswith("--study-seed: no effect without random inputs")
    assert repeats.startswith("--repeats 2: the 2 repeats of each grid point are identical")
    assert workers.startswith("--workers: no effect with the scheduler 'serial'")
    assert d["cases"] == 4
    # a random input: the seed and the repeats matter
    drawn = run_json(
        capsys,
        *_study(tmp_path, "drawn", "--set", "speed_rpm=uniform:1000:2000", "--seed", "3"),
        "--repeats",
        "2",
    )
    assert _no_effect(drawn["warnings"]) == []
    speeds = pd.read_parquet(tmp_path / "drawn")["speed_rpm"]
    assert speeds.nunique() == 2
    # the table shows the warnings too
    assert main([*_study(tmp_path, "table", "--set", "speed_rpm=1000", "--seed", "1")]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "warning: --study-seed: no effect without random inputs" in out


def test_study_repeats_with_a_cases_file_are_named(tmp_path, capsys):
    path = tmp_path / "cases.csv"
    pd.DataFrame({"designation": ["6205"], "speed_rpm": [1500.0]}).to_csv(path, index=False)
    argv = ("study", "frequencies", "--cases", str(path), "--scheduler", "serial")
    d = run_json(capsys, *argv, "-o", str(tmp_path / "a"), "--repeats", "3")
    assert _no_effect(d["warnings"]) == ["--repeats: no effect with --cases (one row, one case)"]
    assert d["cases"] == 1


def test_a_study_knows_its_random_inputs():
    options = SIMULATE.options
    fixed = {"designation": ["6205"], "speed_rpm": [1000.0, 2000.0]}
    assert Grid(fixed, 1, 0).random_inputs(options) == ()
    noisy = Grid({**fixed, "noise_ms2": [0.0, 0.5]}, 1, 0).random_inputs(options)
    assert noisy == ("noise_ms2",)
    quiet = Grid({**fixed, "noise_ms2": [0.0], "ball_size_error_um": [0.0]}, 1, 0)
    assert quiet.random_inputs(options) == ()


# ------------------------------------------------------------------ dataset
def _dataset(tmp_path, name, *args):
    return (
        "dataset",
        str(tmp_path / name),
        "--records",
        "1",
        "--duration-s",
        "0.1",
        "--scheduler",
        "serial",
        *args,
    )


def test_dataset_sample_rate_below_the_path_names_the_sample_rate(tmp_path, capsys):
    err = run_error(capsys, *_dataset(tmp_path, "slow", "--sample-rate-hz", "500"))
    assert err.startswith("error: --sample-rate-hz = '500' is not allowed")
    assert "at least 10000 Hz" in err and "4500 Hz" in err and "--resonance" not in err
    assert not (tmp_path / "slow").exists()
    # a resonance the user chose above the default sample rate still names --resonance
    err = run_error(capsys, *_dataset(tmp_path, "high", "--resonance", "9500@0.05"))
    assert err.startswith("error: --resonance = '9500@0.05'") and "9000 Hz" in err
    assert not (tmp_path / "high").exists()
    with pytest.raises(InputError) as exc:
        DatasetSpec(records=1, sample_rate_hz=500.0)
    assert exc.value.parameter == "sample_rate_hz"


def test_dataset_options_without_effect_are_named(tmp_path, capsys):
    healthy = run_json(
        capsys,
        *_dataset(tmp_path, "healthy", "--faults", "none", "--defect-depth-mm", "0.2"),
        "--waviness-orders",
        "5",
        "--workers",
        "2",
    )
    assert _no_effect(healthy["warnings"]) == [
        "--defect-depth-mm: no effect with --faults none (no record has a defect)",
        "--waviness-orders: no effect at --waviness-amplitude-um 0 (no waviness)",
        "--workers: no effect with the scheduler 'serial' (it sizes a LocalCluster only)",
    ]
    inner = run_json(
        capsys, *_dataset(tmp_path, "inner", "--faults", "inner", "--defect-position-deg", "-90")
    )
    (position,) = _no_effect(inner["warnings"])
    assert position.startswith("--defect-angle-deg: no effect without outer or compound")
    # used: a compound fault can be on the outer race, waviness above 0 has orders
    used = run_json(
        capsys,
        *_dataset(tmp_path, "used", "--faults", "compound", "--defect-position-deg", "-90"),
        "--waviness-um",
        "0.1",
        "--waviness-orders",
        "5",
    )
    assert _no_effect(used["warnings"]) == []
    # the table shows them too
    assert main([*_dataset(tmp_path, "table", "--faults", "none", "--defect-width-mm", "1")]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "warning: --defect-width-mm: no effect with --faults none" in out


# ------------------------------------------------------------------ ring-modes
def test_ring_modes_json_carries_the_warnings_the_table_shows(capsys):
    # 7205B's ball count is estimated (a lower bound for an angular-contact bearing)
    d = run_json(capsys, "ring-modes", "7205B")
    assert any("ball count Z = " in w for w in d["warnings"])
    assert main(["ring-modes", "7205B"]) == 0
    out = " ".join(capsys.readouterr().out.split())
    for warning in d["warnings"]:
        assert warning in out
    # the static safety of the axial load (s0 < 1) is no longer dropped
    heavy = run_json(capsys, "ring-modes", "6205", "--axial-load-n", "20000")
    assert any(w.startswith("static safety factor s0 = ") for w in heavy["warnings"])
    warnings = run_json(capsys, "ring-modes", "6205")["warnings"]
    assert [w for w in warnings if not w.startswith("also reads as GOST")] == []


def test_ring_modes_axial_load_without_effect_is_named(capsys):
    given = ("ring-modes", "6205", "--radial-stiffness-n-per-m", "1e8")
    assert _no_effect(run_json(capsys, *given)["warnings"]) == []
    d = run_json(capsys, *given, "--axial-load-n", "300", "--stiffness-from", "load-distribution")
    assert _no_effect(d["warnings"]) == [
        "--axial-load-n and --stiffness-from: no effect with --radial-stiffness-n-per-m "
        "(K_x is given)"
    ]
    # the ring-level inputs alone (no bearing): f_1 given, no contacts to take K_x from
    ring = ("ring-modes", "--balls", "9", "--ring-mass-kg", "0.1", "--ball-mass-ratio", "0.1")
    ring += (
        "--rigid-body-frequency-hz",
        "500",
        "--free-frequencies-hz",
        "1000,2000,3000,4000,5000",
    )
    assert _no_effect(run_json(capsys, *ring)["warnings"]) == []
    (warning,) = _no_effect(
        run_json(capsys, *ring, "--stiffness-from", "load-distribution")["warnings"]
    )
    assert warning.startswith("--stiffness-from: no effect without a bearing")


def test_ring_modes_axial_load_with_a_given_f1_only_sets_the_reported_stiffness(capsys):
    # f_1 fixes the contact stiffness: the axial load changes the K_x reported, not the
    # frequencies, and the warning says so (no warning when the load is left at default)
    f1 = ("ring-modes", "6205", "--rigid-body-frequency-hz", "800")
    low, high = (run_json(capsys, *f1, "--axial-load-n", a) for a in ("300", "5000"))
    assert low["modes"] == high["modes"]
    assert low["radial_stiffness_n_per_um"] != high["radial_stiffness_n_per_um"]
    assert _no_effect(high["warnings"]) == [
        "--axial-load-n: no effect on the frequencies with --rigid-body-frequency-hz "
        "(only on the K_x reported)"
    ]
    assert _no_effect(run_json(capsys, *f1)["warnings"]) == []
