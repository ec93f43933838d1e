"""bearinglab.study: grids, case files, failed cases, determinism, resuming, bad input,
and the same table on a real dask LocalCluster (2 worker processes) as computed serially."""

import json
import math
import os
import signal
import subprocess
import sys
import textwrap
import time

import pandas as pd
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.life import rating_life
from bearinglab.operating import OperatingCondition
from bearinglab.quasistatic import solve_load_distribution
from bearinglab.study import parse_values, read_study, run_study
from bearinglab.study.analyses import ANALYSES

GRID = {
    "designation": "6205",
    "radial_load_n": "0:1500:7",
    "axial_load_n": [0.0, 200.0],
    "speed_rpm": [0.0, 8000.0],
}


@pytest.fixture(scope="module")
def cluster():
    """One real LocalCluster of 2 single-threaded worker processes for this module."""
    from distributed import LocalCluster

    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as c:
        yield c


def test_values_forms():
    number = ANALYSES["stiffness"].options["radial_load_n"]
    assert parse_values("radial_load_n", "0:100:3", number) == [0.0, 50.0, 100.0]
    assert parse_values("radial_load_n", "log:10:1000:3", number) == pytest.approx(
        [10.0, 100.0, 1000.0]
    )
    assert parse_values("radial_load_n", "5,7", number) == [5.0, 7.0]
    assert parse_values("radial_load_n", [1, 2], number) == [1.0, 2.0]
    balls = ANALYSES["stiffness"].options["balls"]
    assert parse_values("balls", "8,9", balls) == [8, 9]


def test_stiffness_table_against_direct_calls(tmp_path):
    r = run_study("stiffness", GRID, output=tmp_path / "s", scheduler="serial", partition_size=5)
    table = r.to_pandas()
    assert len(table) == r.cases == 28 and list(table["case"]) == list(range(28))
    assert r.computed == r.partitions == 6
    # the unloaded cases fail with their reason; the study goes on
    unloaded = (table["radial_load_n"] == 0) & (table["axial_load_n"] == 0)
    assert r.failed_cases == int(unloaded.sum()) == 2
    assert table.loc[unloaded, "error"].str.contains("radial_load_n").all()
    assert table.loc[unloaded, "radial_stiffness_n_per_um"].isna().all()
    bearing, _ = bearing_from_designation("6205")
    for _, row in table[~unloaded].sample(6, random_state=1).iterrows():
        direct = solve_load_distribution(
            bearing,
            OperatingCondition(
                radial_load=row["radial_load_n"],
                axial_load=row["axial_load_n"],
                shaft_speed=row["speed_rpm"] * math.pi / 30,
            ),
        )
        # warm-started stiffness_map lines converge to the same equilibrium
        assert row["radial_stiffness_n_per_um"] == pytest.approx(
            direct.radial_stiffness * 1e-6, rel=1e-6
        )
        assert row["axial_displacement_um"] == pytest.approx(
            direct.axial_displacement * 1e6, rel=1e-6, abs=1e-9
        )


def test_life_and_frequencies_from_a_case_file(tmp_path):
    cases = pd.DataFrame(
        {
            "designation": ["6205", "6206", "6205"],
            "radial_load_n": [1400.0, 2000.0, -5.0],
            "speed_rpm": [1500.0, 3000.0, 1500.0],
        }
    )
    path = tmp_path / "cases.csv"
    cases.to_csv(path, index=False)
    table = run_study("life", cases=path, output=tmp_path / "life", scheduler="serial").to_pandas()
    b, _ = bearing_from_designation("6206")
    direct = rating_life(b, OperatingCondition(radial_load=2000.0, shaft_speed=3000 * math.pi / 30))
    assert table.loc[1, "l10_hours"] == pytest.approx(direct.l10_hours, rel=1e-12)
    assert table.loc[2, "error"].startswith("radial_load") and pd.isna(table.loc[2, "l10_hours"])

    def random_speeds(folder, **kw):
        return run_study(
            "frequencies",
            {"designation": "6205", "speed_rpm": "uniform:1000:2000"},
            output=tmp_path / folder,
            repeats=4,
            seed=3,
            scheduler="serial",
            **kw,
        ).to_pandas()

    f = random_speeds("f")
    assert f["speed_rpm"].nunique() == 4 and f["speed_rpm"].between(1000, 2000).all()
    kin = defect_frequencies(
        bearing_from_designation("6205")[0], f.loc[2, "speed_rpm"] * math.pi / 30
    )
    assert f.loc[2, "bpfo_hz"] == pytest.approx(kin.hz("bpfo"), rel=1e-12)
    again = random_speeds("f2", partition_size=3)
    # a case's random inputs depend on (seed, case) only, not on the partitioning
    pd.testing.assert_frame_equal(f, again)


def test_ring_modes_columns_follow_the_analysis(tmp_path):
    from bearinglab.rings import ring_modes

    table = run_study(
        "ring-modes",
        {"designation": "6205", "axial_load_n": [100.0, 1000.0]},
        output=tmp_path / "rm",
        scheduler="serial",
    ).to_pandas()
    assert table["error"].isna().all()
    direct = ring_modes(bearing_from_designation("6205")[0], axial_load=1000.0, modes=[3])
    assert table.loc[1, "m3_free_hz"] == pytest.approx(direct.mode(3).free, rel=1e-12)
    assert table.loc[1, "m3_approx_low_hz"] == pytest.approx(
        min(direct.mode(3).approximate), rel=1e-12
    )


def test_simulate_with_diagnosis_and_a_cage_fault(tmp_path):
    table = run_study(
        "simulate",
        {
            "designation": "6205-2RS",
            "radial_load_n": 500.0,
            "speed_rpm": 1797.0,
            "fault": ["outer", "cage"],
            "duration_s": 1.0,
        },
        output=tmp_path / "sim",
        scheduler="serial",
    ).to_pandas()
    assert table.loc[0, "likely_fault"] == "outer_race" and pd.isna(table.loc[0, "error"])
    assert table.loc[0, "bpfo_hz"] == pytest.approx(107.36, abs=0.01)
    assert "no cage defect model" in table.loc[1, "error"]


def test_localcluster_matches_serial_row_for_row(tmp_path, cluster):
    serial = run_study(
        "stiffness", GRID, output=tmp_path / "serial", scheduler="serial", partition_size=4
    )
    dist = run_study(
        "stiffness",
        GRID,
        output=tmp_path / "dask",
        scheduler=cluster.scheduler_address,
        partition_size=4,
    )
    assert dist.workers == 2 and dist.computed == dist.partitions == 7
    pd.testing.assert_frame_equal(dist.to_pandas(), serial.to_pandas())
    assert len(dist.peak_memory) == 2 and min(dist.peak_memory.values()) > 10e6
    static = {"designation": "6205", "radial_load_n": [500.0, 1000.0], "misalignment_mrad": [0, 1]}
    a = run_study("static", static, output=tmp_path / "st1", scheduler="serial")
    b = run_study("static", static, output=tmp_path / "st2", scheduler=cluster.scheduler_address)
    pd.testing.assert_frame_equal(a.to_pandas(), b.to_pandas())


_KILLABLE = textwrap.dedent("""
    import sys, time
    import bearinglab.study.runner as runner
    from bearinglab.study import run_study
    compute = runner._partition
    def slowed(task):
        # 0.2 s a partition: the parent kills the run part-way even on a loaded machine,
        # where the 60 partitions could otherwise all finish between two of its polls
        time.sleep(0.2)
        return compute(task)
    runner._partition = slowed
    run_study("static", {"designation": "6205", "radial_load_n": "100:3000:40",
                         "misalignment_mrad": [0.0, 0.5, 1.0]},
              output=sys.argv[1], scheduler="serial", partition_size=2)
""")


def test_interrupted_study_resumes_with_only_the_missing_partitions(tmp_path, cluster):
    out = tmp_path / "killed"
    proc = subprocess.Popen([sys.executable, "-c", _KILLABLE, str(out)])
    try:
        # generous: a cold numba cache makes the first partition wait for the compiler
        deadline = time.monotonic() + 300
        while len(list(out.glob("part-*.parquet"))) < 5 and time.monotonic() < deadline:
            time.sleep(0.05)
        os.kill(proc.pid, signal.SIGKILL)
    finally:
        proc.wait()
    done = {p.name: p.stat().st_mtime_ns for p in out.glob("part-*.parquet")}
    assert 5 <= len(done) < 60, "the study was not interrupted part-way"
    resumed = run_study(
        "static",
        {
            "designation": "6205",
            "radial_load_n": "100:3000:40",
            "misalignment_mrad": [0.0, 0.5, 1.0],
        },
        output=out,
        scheduler=cluster.scheduler_address,
        partition_size=2,
    )
    assert resumed.computed == 60 - len(done) and resumed.computed_cases == 2 * resumed.computed
    assert all((out / n).stat().st_mtime_ns == t for n, t in done.items())
    fresh = run_study(
        "static",
        {
            "designation": "6205",
            "radial_load_n": "100:3000:40",
            "misalignment_mrad": [0.0, 0.5, 1.0],
        },
        output=tmp_path / "fresh",
        scheduler="serial",
        partition_size=2,
    )
    pd.testing.assert_frame_equal(read_study(out), fresh.to_pandas())
    assert not list(out.glob(".*"))  # no half-written partition left behind


@pytest.mark.parametrize(
    "grid, match",
    [
        ({"designation": "6205", "radial_lod_n": [1.0]}, "radial_load_n"),
        ({"designation": "6205", "radial_load_n": "100:200:0"}, "empty"),
        ({"designation": "6205", "radial_load_n": []}, "empty"),
        ({"designation": "6205", "radial_load_n": "uniform:5:5"}, "LOW < HIGH"),
        ({"designation": "6205", "radial_load_n": "abc"}, "a number"),
        ({"radial_load_n": [1.0]}, "designation"),
    ],
)
def test_bad_grids_are_one_clear_error(tmp_path, grid, match):
    with pytest.raises(InputError, match=match):
        run_study("stiffness", grid, output=tmp_path / "x", scheduler="serial")
    assert not (tmp_path / "x").exists()


def test_limits_unreachable_scheduler_and_a_different_study(tmp_path):
    from bearinglab.engine import most_processes

    with pytest.raises(InputError, match=rf"\[1, {most_processes()}\] \(4 per core\)"):
        run_study("stiffness", GRID, output=tmp_path / "w", workers=most_processes() + 1)
    assert not (tmp_path / "w").exists()
    with pytest.raises(InputError, match="`yes`"):
        run_study("stiffness", GRID, output=tmp_path / "x", max_cases=10, scheduler="serial")
    with pytest.raises(InputError, match="analysis"):
        run_study("stifness", GRID, output=tmp_path / "x")
    start = time.monotonic()
    with pytest.raises(InputError, match="connection refused: nothing listens there"):
        run_study(
            "stiffness",
            GRID,
            output=tmp_path / "y",
            scheduler="tcp://127.0.0.1:9",
            connect_timeout=1.0,
        )
    assert time.monotonic() - start < 10 and not (tmp_path / "y").exists()
    with pytest.raises(InputError, match="tcp://HOST:PORT"):
        run_study("stiffness", GRID, output=tmp_path / "z", scheduler="my-cluster")

    def frequencies(speed_rpm, folder):
        run_study(
            "frequencies",
            {"designation": "6205", "speed_rpm": speed_rpm},
            output=tmp_path / folder,
            scheduler="serial",
        )

    frequencies(1000.0, "held")
    before = sorted(p.name for p in (tmp_path / "held").iterdir())
    marker = json.loads((tmp_path / "held" / "_study.json").read_text())
    with pytest.raises(InputError, match="different study"):
        frequencies(2000.0, "held")
    assert sorted(p.name for p in (tmp_path / "held").iterdir()) == before
    assert json.loads((tmp_path / "held" / "_study.json").read_text()) == marker
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "notes.txt").write_text("mine")
    with pytest.raises(InputError, match="other files"):
        frequencies(1000.0, "other")


def test_plot_one_output_over_two_inputs(tmp_path):
    r = run_study("stiffness", GRID, output=tmp_path / "s", scheduler="serial")
    _fig, ax = r.plot(
        "radial_stiffness_n_per_um", "radial_load_n", "speed_rpm", path=tmp_path / "map.png"
    )
    assert (tmp_path / "map.png").stat().st_size > 0
    assert ax.get_xlabel() == "radial load [N]" and "mean over other inputs" in ax.get_title()
    with pytest.raises(InputError, match="column"):
        r.plot("nope", "radial_load_n", "speed_rpm")
