"""`bearinglab study` and `bearinglab dataset`: the README's small examples and bad input
(one line on stderr, exit code 2, nothing written or changed)."""

import pandas as pd
import pytest
from conftest import require, run_json

from bearinglab.cli import main


def test_study_on_the_default_localcluster(tmp_path, capsys):
    out = tmp_path / "stiffness-6205"
    study = (
        "study",
        "stiffness",
        "--set",
        "designation=6205",
        "--set",
        "radial_load_n=0:2000:5",
        "--set",
        "speed_rpm=0,6000",
        "-o",
        str(out),
    )
    d = run_json(
        capsys,
        *study,
        "--workers",
        "2",
        "--plot",
        str(tmp_path / "map.png"),
    )
    assert d["cases"] == 10 and d["workers"] == 2 and d["scheduler"].startswith("LocalCluster")
    assert d["failed_cases"] == 2 and d["partitions_computed"] == d["partitions"]
    table = pd.read_parquet(out)
    assert len(table) == 10 and "radial_stiffness_n_per_um" in table.columns
    assert (tmp_path / "map.png").stat().st_size > 0
    # rerun: everything is there already
    again = run_json(capsys, *study)
    assert again["partitions_computed"] == 0 and again["partitions_reused"] == d["partitions"]


def test_study_table_and_cases_file(tmp_path, capsys):
    path = tmp_path / "cases.csv"
    pd.DataFrame(
        {
            "designation": ["6205", "6206"],
            "speed_rpm": [1500.0, 3000.0],
            "radial_load_n": [1400.0, 2000.0],
        }
    ).to_csv(path, index=False)
    assert (
        main(
            [
                "study",
                "life",
                "--cases",
                str(path),
                "-o",
                str(tmp_path / "life"),
                "--scheduler",
                "serial",
            ]
        )
        == 0
    )
    out = capsys.readouterr().out
    # the table's headers carry the units
    assert "cases per second" in out and "[rpm]" in out and "[N]" in out


def test_dataset_command_reads_back(tmp_path, capsys):
    bd = require("bearing_datasets")
    d = run_json(
        capsys,
        "dataset",
        str(tmp_path / "synth"),
        "--records",
        "4",
        "--duration-s",
        "0.1",
        "--faults",
        "outer,inner",
        "--defect-position-deg",
        "-100:-80",
        "--resonance",
        "3000:3500@0.05",
        "--scheduler",
        "serial",
    )
    assert d["records_written"] == 4
    meta = bd.open("synth", root=tmp_path).metadata()
    assert set(meta["fault_type"]) <= {"outer", "inner"} and (meta["n_samples"] == 2000).all()


@pytest.mark.parametrize(
    "args, words",
    [
        (
            ["study", "stiffness", "--set", "designation=6205", "--set", "radial_lod_n=1"],
            "did you mean radial_load_n",
        ),
        (
            ["study", "stiffness", "--set", "designation=6205", "--set", "radial_load_n=5:10:0"],
            "empty",
        ),
        (
            [
                "study",
                "stiffness",
                "--set",
                "designation=6205",
                "--set",
                "radial_load_n=0:1:400",
                "--set",
                "speed_rpm=0:1:300",
            ],
            "without --yes",
        ),
        (
            ["study", "stiffness", "--set", "designation=6205", "--scheduler", "tcp://127.0.0.1:9"],
            "connection refused: nothing listens there",
        ),
        (["study", "stifness", "--set", "designation=6205"], "one of stiffness"),
        (["study", "stiffness"], "--set"),
        (["dataset", "--records", "2000"], "without --yes"),
        (["dataset", "--faults", "outer,cage"], "no cage defect model"),
        (["dataset", "--resonance", "3000"], "FREQ_HZ@DAMPING"),
        (["dataset", "--speed-rpm", "1800:1700"], "empty"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(tmp_path, capsys, args, words):
    out = tmp_path / "out"
    argv = (
        args[:1]
        + ([str(out)] if args[0] == "dataset" else [])
        + args[1:]
        + (["-o", str(out)] if args[0] == "study" else [])
    )
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: ") and err.count("\n") == 1 and words in err
    assert not out.exists()


def test_a_folder_holding_another_study_is_kept(tmp_path, capsys):
    out = tmp_path / "held"

    def study(designation):
        return main(
            [
                "study",
                "frequencies",
                "--set",
                f"designation={designation}",
                "--set",
                "speed_rpm=1000",
                "-o",
                str(out),
                "--scheduler",
                "serial",
            ]
        )

    assert study("6205") == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    capsys.readouterr()
    assert study("6206") == 2
    err = capsys.readouterr().err
    assert "different study" in err and err.count("\n") == 1
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
