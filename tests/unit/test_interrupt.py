"""Ctrl-C in any command (issue 30, item 8): exit status 130, one line on stderr, no
traceback, no half-written file, and a study or data set that resumes to the full result.

Each command runs as a user runs it (``python -m bearinglab.cli`` in a process group of its
own) and gets SIGINT the way a terminal sends it, to the whole group (a LocalCluster's
workers too). A long command gets it once it is at work: after a delay that its inputs
make far shorter than its run, or when its first partitions are on disk. A command that
takes a fraction of a second gets it while it starts (where such a command spends its
time). Before: a serial data set exited 0 and lost a record for good (numba turned the
KeyboardInterrupt into a SystemError that the per-record ``except Exception`` recorded as
a failed record), ``simulate`` reported an internal error, ``validate`` counted "1 errors"
and went on, ``report`` wrote its page with a failed section, and a LocalCluster's workers
printed walls of tracebacks.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import bearinglab
from bearinglab.cli import main
from bearinglab.engine import Interrupted, interrupted, open_runner, reraise_interrupt
from bearinglab.engine import run_partitions as run
from bearinglab.signal import Signal, write_signal

#: Seconds a command may take to stop and exit after SIGINT (a LocalCluster included).
STOP_WITHIN = 60.0


def interrupt(args, cwd: Path, *, after: float | None = None, when=None, env=None):
    """Run ``bearinglab args`` in ``cwd`` (with ``env`` added to the environment); SIGINT
    its process group ``after`` seconds, or as soon as ``when()`` holds; (exit code,
    stdout, stderr)."""
    # the bearinglab this test imported, whatever the working folder
    path = [str(Path(bearinglab.__file__).parents[1]), os.environ.get("PYTHONPATH", "")]
    process = subprocess.Popen(
        [sys.executable, "-m", "bearinglab.cli", *map(str, args)],
        cwd=cwd,
        env={
            **os.environ,
            "PYTHONPATH": os.pathsep.join(p for p in path if p),
            **(env or {}),
        },
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    start = time.monotonic()
    try:
        while process.poll() is None and time.monotonic() - start < STOP_WITHIN:
            if (when is not None and when()) or (
                after is not None and time.monotonic() - start >= after
            ):
                break
            time.sleep(0.01)
        assert process.poll() is None, "the command ended before it could be interrupted"
        os.killpg(process.pid, signal.SIGINT)
        out, err = process.communicate(timeout=STOP_WITHIN)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.communicate()
    return process.returncode, out, err


def assert_stopped(code: int, err: str, resume: str | None = None) -> str:
    """Ended by SIGINT after its line, as Python ends a program on Ctrl-C (a shell reports
    exit status 130 = 128 + SIGINT, and a shell loop that runs the command stops), and one
    line, ``interrupted`` (with ``resume`` in it when given); the notice of a first
    compile, said before the Ctrl-C, may precede it."""
    notice = "compiling the numerical kernels"
    lines = [line for line in err.splitlines() if line.strip() and not line.startswith(notice)]
    assert code == -signal.SIGINT, (code, err)
    assert len(lines) == 1 and lines[0].startswith("interrupted"), err
    if resume is not None:
        assert resume in lines[0], lines[0]
    return lines[0]


def no_partial_files(folder: Path, *outputs: Path) -> None:
    """No output asked for was written, and no temporary file is left in ``folder``."""
    assert not [p for p in outputs if p.exists()]
    hidden = [p for p in folder.rglob(".*") if p.is_file()]
    assert not hidden, hidden


# ------------------------------------------------------------------ the library's rule
def test_an_interrupt_is_told_from_a_failure():
    """numba's dispatcher hands a KeyboardInterrupt back as a SystemError caused by it."""
    try:
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as exc:
            raise SystemError("CPUDispatcher(...) returned a result with an exception set") from exc
    except SystemError as wrapped:
        assert interrupted(wrapped)
        with pytest.raises(KeyboardInterrupt):
            reraise_interrupt(wrapped)
    assert not interrupted(ValueError("a failed case"))
    reraise_interrupt(ValueError("a failed case"))  # a failure is left to the caller


def test_a_file_interrupted_as_it_is_written_is_not_there(tmp_path):
    from bearinglab.files import write_atomically

    def write(tmp):
        Path(tmp).write_text("half")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_atomically(tmp_path / "page.html", write)
    assert list(tmp_path.iterdir()) == []


def _stop_at_two(task):
    if task == 2:
        raise SystemError("returned a result with an exception set") from KeyboardInterrupt()
    return task


def test_run_partitions_stops_with_what_it_finished():
    kept, told = [], []
    with open_runner("serial") as runner, pytest.raises(Interrupted) as stop:
        run(
            runner,
            _stop_at_two,
            [0, 1, 2, 3],
            [5, 5, 5, 5],
            lambda task, r: kept.append(r),
            progress=lambda done, total: told.append((done, total)),
            done=10,
            total=30,
        )
    assert kept == [0, 1]
    assert told == [(10, 30), (15, 30), (20, 30)]
    assert (stop.value.done, stop.value.total) == (20, 30)
    assert isinstance(stop.value, KeyboardInterrupt)


LOADER = """
def _numba_unpickle(seconds):
    import time

    start = time.monotonic()
    while time.monotonic() - start < seconds:
        pass
    return "loaded"
"""


def test_a_ctrl_c_waits_for_numbas_loader_to_return():
    """numba calls ``_numba_unpickle`` from C as a cached kernel loads: a KeyboardInterrupt
    raised in it came back as a SystemError or crashed the process (SIGSEGV)."""
    import threading

    from bearinglab.engine import catch_interrupts

    namespace: dict = {}
    exec(compile(LOADER, "/site-packages/numba/core/serialize.py", "exec"), namespace)
    loaded = []
    with catch_interrupts(), pytest.raises(KeyboardInterrupt):
        threading.Timer(0.05, os.kill, (os.getpid(), signal.SIGINT)).start()
        loaded.append(namespace["_numba_unpickle"](0.3))
        time.sleep(2.0)  # raised here, once the loader has returned
    assert loaded == ["loaded"]
    assert not interrupted()  # the block is over


# ------------------------------------------------------------------ the entry point
def _main_with(monkeypatch, capsys, run) -> tuple[int, str]:
    """main() with the typer app replaced by ``run`` (in this process)."""
    from bearinglab.cli import _app

    monkeypatch.setattr(_app, "app", lambda **kw: run())
    code = main(["info", "6205"])
    return code, capsys.readouterr().err


def test_main_reads_numbas_system_error_as_an_interrupt(monkeypatch, capsys):
    """It printed "internal error (SystemError: CPUDispatcher(...) returned a result with
    an exception set)" and exit code 1."""

    def run():
        raise SystemError("returned a result with an exception set") from KeyboardInterrupt()

    assert _main_with(monkeypatch, capsys, run) == (130, "interrupted\n")


def test_main_stops_a_run_that_swallowed_the_interrupt(monkeypatch, capsys):
    """A library that catches the KeyboardInterrupt and goes on does not make the run a
    success: the SIGINT was seen."""

    def run():
        try:
            signal.raise_signal(signal.SIGINT)
            time.sleep(1.0)
        except BaseException:  # noqa: BLE001 - what a careless library does
            pass
        return 0

    assert _main_with(monkeypatch, capsys, run) == (130, "interrupted\n")
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # put back


def test_main_says_how_to_resume(monkeypatch, capsys):
    def run():
        raise Interrupted(3, 30, "3 of 30 records are kept in out; run the same command again")

    code, err = _main_with(monkeypatch, capsys, run)
    assert code == 130
    assert err == "interrupted: 3 of 30 records are kept in out; run the same command again\n"


# ------------------------------------------------------------------ commands that take ms
@pytest.mark.parametrize(
    "args",
    [
        ["info", "6205"],
        ["frequencies", "6205", "--speed-rpm", "1797"],
        ["contact", "6205", "--ball-load-n", "1000"],
        ["static", "6205", "--radial-load-n", "1000", "--speed-rpm", "3000"],
        ["ring-modes", "6205", "--axial-load-n", "1000"],
        ["friction", "6205", "--speed-rpm", "3000", "--radial-load-n", "1000"],
        ["life", "6205", "--radial-load-n", "1000", "--speed-rpm", "3000"],
    ],
    ids=lambda a: a[0],
)
def test_a_quick_command_stops_while_it_starts(tmp_path, args):
    code, out, err = interrupt(args, tmp_path, after=0.15)
    assert_stopped(code, err)
    assert out == ""


# ------------------------------------------------------------------ long commands
def test_simulate_stops_inside_its_compiled_model(tmp_path):
    """It said "internal error (SystemError: CPUDispatcher(...) returned a result with an
    exception set)"."""
    args = ["simulate", "6205", "--speed-rpm", "1800", "--radial-load-n", "500"]
    args += ["--defect", "outer:width_mm=1", "--duration-s", "30", "--json"]
    code, out, err = interrupt(args, tmp_path, after=2.0)
    assert_stopped(code, err)
    assert out == ""


@pytest.mark.slow
def test_simulate_stops_while_numba_compiles_its_model(tmp_path):
    """The first run after an install compiles the model (20 s or more): a Ctrl-C then was
    printed as "Exception ignored on calling ctypes callback function" (llvmlite) and lost;
    the model was compiled and simulated to the end. An empty numba cache makes the run a
    first one."""
    cache = {"NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    args = ["simulate", "6205", "--speed-rpm", "1800", "--radial-load-n", "500"]
    args += ["--defect", "outer:width_mm=1", "--duration-s", "0.3", "--json"]
    code, out, err = interrupt(args, tmp_path, after=4.0, env=cache)
    assert_stopped(code, err)
    assert out == ""


def test_validate_stops_and_writes_no_page(tmp_path):
    """It counted the interrupted case as "1 errors" and went on to the end."""
    page = tmp_path / "validation.html"
    code, out, err = interrupt(["validate", "--html", page], tmp_path, after=2.0)
    assert_stopped(code, err)
    assert out == ""
    no_partial_files(tmp_path, page)


def test_report_stops_and_writes_no_page(tmp_path):
    """It wrote its page with the interrupted section as failed (3 runs in 10)."""
    page = tmp_path / "report.html"
    args = ["report", "6205", "--speed-rpm", "1800", "--radial-load-n", "500", "-o", page]
    code, _, err = interrupt([*args, "--duration-s", "5"], tmp_path, after=2.0)
    assert_stopped(code, err)
    no_partial_files(tmp_path, page)


@pytest.mark.slow
def test_noise_stops_and_draws_no_figure(tmp_path):
    figure = tmp_path / "noise.png"
    args = ["noise", "6205", "--speed-rpm", "1800", "--radial-load-n", "500"]
    code, _, err = interrupt([*args, "--duration-s", "2", "--plot", figure], tmp_path, after=2.0)
    assert_stopped(code, err)
    no_partial_files(tmp_path, figure)


@pytest.mark.slow
def test_analyze_stops(tmp_path):
    record = tmp_path / "long.npz"
    noise = np.random.default_rng(0).standard_normal(4_000_000).astype(np.float32)
    write_signal(record, Signal({"acc": noise}, 50_000.0))
    args = ["analyze", record, "--designation", "6205", "--speed-rpm", "1800", "--method", "all"]
    code, out, err = interrupt(args, tmp_path, after=2.0)
    assert_stopped(code, err)
    assert out == ""


@pytest.mark.slow
def test_stiffness_map_stops_its_worker_processes(tmp_path):
    figure = tmp_path / "map.png"
    args = ["stiffness-map", "6205", "--radial-load-n", "100:5000:60"]
    args += ["--speed-rpm", "0:20000:400", "--workers", "2", "--plot", figure]
    code, _, err = interrupt(args, tmp_path, after=2.0)
    assert_stopped(code, err)
    no_partial_files(tmp_path, figure)


def _labelled(folder: Path, records: int) -> Path:
    folder.mkdir()
    rows = ["file,channel,sample_rate_hz,speed_rpm,designation,fault"]
    for i in range(records):
        x = np.random.default_rng(i).standard_normal(20_000)
        write_signal(folder / f"r{i:03d}.npz", Signal({"acc": x}, 20_000.0))
        rows.append(f"r{i:03d}.npz,acc,20000,1750,6205,normal")
    (folder / "labels.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    return folder


@pytest.mark.slow
def test_benchmark_stops_its_process_pool(tmp_path):
    folder = _labelled(tmp_path / "records", 300)
    page = tmp_path / "benchmark.html"
    args = ["benchmark", folder, "--jobs", "2", "--html", page]
    code, _, err = interrupt(args, tmp_path, after=2.0)
    assert_stopped(code, err)
    no_partial_files(tmp_path, page)


def _series(folder: Path, records: int) -> Path:
    folder.mkdir()
    x = 0.3 * np.random.default_rng(0).standard_normal((records, 2, 2560))
    rows = ["file,time_s"]
    for k in range(records):
        write_signal(folder / f"r{k:04d}.npz", Signal({"h": x[k, 0], "v": x[k, 1]}, 25_600.0))
        rows.append(f"r{k:04d}.npz,{k * 10.0}")
    (folder / "index.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    return folder


@pytest.mark.slow
def test_trend_stops_on_the_engine(tmp_path):
    folder = _series(tmp_path / "series", 600)
    page = tmp_path / "trend.html"
    args = ["trend", folder, "--settle-records", "5", "--baseline-records", "30"]
    args += ["--designation", "6205", "--speed-rpm", "1800", "--html", page]
    code, _, err = interrupt(args, tmp_path, after=2.5)
    assert_stopped(code, err)
    no_partial_files(tmp_path, page)


# ------------------------------------------------------------------ runs that resume
def _files(pattern: str, folder: Path, at_least: int):
    return lambda: len(list(folder.glob(pattern))) >= at_least


DATASET = ["--records", "30", "--duration-s", "0.3", "--partition-size", "1"]


def test_a_serial_data_set_resumes_to_every_record(tmp_path, capsys):
    """The user's run: Ctrl-C a few seconds in exited 0 and the rerun ended with 29 of 30
    records (the interrupted record was kept as failed)."""
    out = tmp_path / "out"
    code, _, err = interrupt(
        ["dataset", out, *DATASET, "--scheduler", "serial"],
        tmp_path,
        when=_files("meta-*.parquet", out / "_bearinglab", 3),
    )
    line = assert_stopped(code, err, "run the same command again to make the other")
    kept = len(list((out / "_bearinglab").glob("meta-*.parquet")))
    assert f"{kept} of 30 records are kept in {out}" in line
    failed = out / "_bearinglab" / "failed.csv"
    assert not failed.exists(), failed.read_text()
    no_partial_files(out)
    capsys.readouterr()
    assert main(["dataset", str(out), *DATASET, "--scheduler", "serial", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert (d["records_written"], d["records_failed"]) == (30, 0)
    assert d["partitions_reused"] == kept


@pytest.mark.slow
def test_a_serial_study_resumes_to_every_case(tmp_path, capsys):
    out = tmp_path / "study"
    study = ["study", "simulate", "-o", out, "--set", "designation=6205"]
    study += ["--set", "speed_rpm=1800", "--set", "radial_load_n=100:1000:30"]
    study += ["--set", "duration_s=0.3", "--partition-size", "1", "--scheduler", "serial"]
    code, _, err = interrupt(study, tmp_path, when=_files("part-*.parquet", out, 2))
    line = assert_stopped(code, err, "run the same command again to compute the other")
    kept = len(list(out.glob("part-*.parquet")))
    assert f"{kept} of 30 cases are kept" in line
    no_partial_files(out)
    capsys.readouterr()
    assert main([*map(str, study), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert (d["cases"], d["partitions_reused"], d["failed_cases"]) == (30, kept, 0)
    from bearinglab.study import read_study

    table = read_study(out)
    assert table["case"].tolist() == list(range(30)) and table["error"].isna().all()


@pytest.mark.slow
def test_a_data_set_on_a_local_cluster_stops_without_a_traceback(tmp_path, capsys):
    """6 runs in 8 printed walls of tracebacks: the workers, in the terminal's process
    group, got the SIGINT too, and the cluster logged the workers it lost."""
    out = tmp_path / "out"
    code, _, err = interrupt(
        ["dataset", out, *DATASET, "--scheduler", "local", "--workers", "2", "--json"],
        tmp_path,
        when=_files("meta-*.parquet", out / "_bearinglab", 2),
    )
    assert_stopped(code, err, "run the same command again to make the other")
    no_partial_files(out)
    capsys.readouterr()
    assert main(["dataset", str(out), *DATASET, "--scheduler", "serial", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert (d["records_written"], d["records_failed"]) == (30, 0)
