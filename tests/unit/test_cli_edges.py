"""Edges of the long commands (issue 22): ``study``, ``dataset``, ``benchmark`` and
``trend`` check the whole request before any work starts and fail in one line on stderr
(exit code 2), leave no partial folder, and print no progress bar off a terminal.

Network tests use loopback servers started here (127.0.0.1 only)."""

import contextlib
import json
import os
import socket
import threading
import time
from pathlib import Path

import pytest

from bearinglab.cli import main

STUDY = ("study", "frequencies", "--set", "designation=6205", "--set", "speed_rpm=1000")
#: the same over two speeds
SPEEDS = ("study", "frequencies", "--set", "designation=6205", "--set", "speed_rpm=1000,2000")
SERIAL = ("--scheduler", "serial")


def one_line_error(capsys, argv, *words, code=2):
    """Run ``argv``: exit ``code``, stderr one line "error: ..." holding ``words``."""
    assert main([str(a) for a in argv]) == code
    err = capsys.readouterr().err
    assert err.startswith("error: ") and err.count("\n") == 1, err
    for w in words:
        assert w in err, err
    return err


@pytest.fixture
def read_only(tmp_path):
    """A folder where no file can be written: a folder without write permission, or for
    root (who ignores permissions) a path under /sys (read-only for every user)."""
    if os.geteuid() != 0:
        folder = tmp_path / "ro"
        folder.mkdir()
        folder.chmod(0o555)
        yield folder
        folder.chmod(0o755)
        return
    folder = Path("/sys")
    try:
        probe = folder / "bearinglab-probe"
        probe.mkdir()
        probe.rmdir()
        pytest.skip("no read-only folder to write into")
    except OSError:
        yield folder


# ------------------------------------------------------------------ 1, 2: outputs first
@pytest.mark.parametrize("kind", ["study", "dataset", "plot", "benchmark", "trend"])
def test_a_read_only_output_is_one_line_before_any_work(tmp_path, capsys, read_only, kind):
    target = read_only / "out"
    if kind == "study":
        argv, words = [*STUDY, "-o", target, *SERIAL], ["--output", str(target)]
    elif kind == "dataset":
        argv, words = ["dataset", target, "--records", "2", *SERIAL], ["OUTPUT", str(target)]
    elif kind == "plot":
        out = tmp_path / "s"
        argv = [*SPEEDS, "-o", out, "--plot", read_only / "map.png"]
        argv = [*argv, "--plot-of", "bpfo_hz,speed_rpm,case"]
        words = ["--plot", "map.png"]
    elif kind == "benchmark":  # before the folder is even read
        argv, words = ["benchmark", tmp_path, "--html", read_only / "b.html"], ["--html"]
    else:
        argv, words = ["trend", tmp_path, "--html", read_only / "t.html"], ["--html"]
    one_line_error(capsys, argv, *words, "a folder where files can be written")
    assert not (tmp_path / "s").exists()


def test_study_plot_columns_are_checked_before_the_study_runs(tmp_path, capsys):
    out = tmp_path / "s"
    plot = ("--plot", tmp_path / "map.png")
    one_line_error(
        capsys,
        [*SPEEDS, "-o", out, *plot, "--plot-of", "bpfo,speed_rpm,x"],
        "--plot-of",
        "'bpfo' is not one of them",
        "bpfo_hz",
    )
    # the default plot needs two inputs that vary: only speed_rpm does
    one_line_error(capsys, [*SPEEDS, "-o", out, *plot], "two inputs that vary")
    one_line_error(capsys, [*STUDY, "-o", out, "--plot", tmp_path / "map.jpg"], ".png")
    assert not out.exists() and not (tmp_path / "map.png").exists()


# ------------------------------------------------------------------ 3: failed cases
def test_a_study_whose_every_case_fails_exits_2_and_keeps_nothing(tmp_path, capsys):
    out = tmp_path / "unloaded"
    stiffness = ["study", "stiffness", "--set", "designation=6205", "-o", out, *SERIAL]
    one_line_error(
        capsys,
        [*stiffness, "--set", "radial_load_n=0", "--set", "speed_rpm=0,1000"],
        "all 2 cases of the study failed",
        "the first, case 0: radial_load_n = 0.0",
    )
    assert not out.exists()
    # some cases fail: exit 0, the table written, a warning counting them
    assert main([*map(str, stiffness), "--set", "radial_load_n=0,500", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["failed_cases"] == 1
    assert any(w.startswith("1 of 2 cases failed") for w in d["warnings"])


# ------------------------------------------------------------------ 4: data sets
@pytest.mark.parametrize(
    "options, words",
    [
        (["--duration-s", "0.01"], ["--duration-s = '0.01'", "all 2 records failed"]),
        (
            ["--faults", "outer", "--defect-width-mm", "50"],
            ["--defect-width-mm = '50'", "defect_width_mm = 50.0", "7.94004 mm"],
        ),
        (["--ball-size-error-um", "3000"], ["--ball-size-error-um", "ball_size_error_um = 3000"]),
        (["--bearings", "6205,XYZ123"], ["--bearings = 'XYZ123'"]),
    ],
)
def test_a_data_set_no_record_of_which_can_be_made(tmp_path, capsys, options, words):
    """The error names the option at fault, in its unit (mm, not m), and no folder is
    left behind (it blamed --records and left a partial folder)."""
    out = tmp_path / "synth"
    argv = ["dataset", out, "--records", "2", "--duration-s", "0.1", *SERIAL, *options]
    err = one_line_error(capsys, argv, *words)
    assert "--records" not in err and "0.05 " not in err
    assert not out.exists()
    # an empty folder given is kept, empty
    out.mkdir()
    one_line_error(capsys, argv, *words)
    assert out.is_dir() and not any(out.iterdir())


# ------------------------------------------------------------------ 5: schedulers
@contextlib.contextmanager
def loopback_server(answer: bytes | None, *, wait_for_request: bool = False):
    """A TCP server on 127.0.0.1 that sends ``answer`` to each connection (after the
    client's first bytes with ``wait_for_request``), or with None accepts and never
    answers. Yields its port."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    server.settimeout(0.2)
    stop, held = threading.Event(), []

    def serve():
        while not stop.is_set():
            try:
                conn, _ = server.accept()
            except OSError:
                continue
            held.append(conn)
            if answer is not None:
                with contextlib.suppress(OSError):
                    if wait_for_request:
                        conn.recv(4096)
                    conn.sendall(answer)

    thread = threading.Thread(target=serve, daemon=True)
    thread.start()
    try:
        yield server.getsockname()[1]
    finally:
        stop.set()
        thread.join(2)
        for conn in held:
            conn.close()
        server.close()


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


HTTP = b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"


@pytest.mark.parametrize(
    "server, words",
    [
        ("nothing", "connection refused: nothing listens there"),
        ("http", "it answers in another protocol (its first bytes: 'HTTP/1.1')"),
        ("http-eager", "it answers in another protocol (its first bytes: 'HTTP/1.1')"),
        ("silent", "it accepted the connection but sent no dask handshake within 1 s"),
    ],
)
@pytest.mark.parametrize("command", ["study", "dataset", "trend"])
def test_a_scheduler_address_that_is_no_dask_scheduler(
    tmp_path, capsys, monkeypatch, server, words, command
):
    """A port where nothing listens, an HTTP server (it gave "MemoryError: 3.07 EiB") and
    a server that never answers (it hung): one line within seconds, nothing written."""
    from bearinglab.engine import scheduler

    monkeypatch.setattr(scheduler, "CONNECT_TIMEOUT", 1.0)
    out = tmp_path / "out"
    answers = {"nothing": None, "http": HTTP, "http-eager": HTTP, "silent": None}
    with contextlib.ExitStack() as stack:
        if server == "nothing":
            port = free_port()
        else:
            port = stack.enter_context(
                loopback_server(answers[server], wait_for_request=server == "http")
            )
        address = f"tcp://127.0.0.1:{port}"
        argv = {
            "study": [*STUDY, "-o", out],
            "dataset": ["dataset", out, "--records", "2"],
            "trend": ["trend", tmp_path],
        }[command]
        start = time.monotonic()
        one_line_error(
            capsys,
            [*argv, "--scheduler", address],
            f"--scheduler = '{address}' is not allowed: expected the address of a running "
            f"dask scheduler ({words}",
        )
        assert time.monotonic() - start < 4
    assert not out.exists()


def test_the_environment_scheduler_is_named(tmp_path, capsys, monkeypatch):
    address = f"tcp://127.0.0.1:{free_port()}"
    monkeypatch.setenv("DASK_SCHEDULER_ADDRESS", address)
    one_line_error(capsys, [*STUDY, "-o", tmp_path / "o"], f"$DASK_SCHEDULER_ADDRESS = '{address}'")


# ------------------------------------------------------------------ 6: benchmark files
def test_benchmark_refuses_a_labels_file_naming_a_missing_recording(tmp_path, capsys):
    """It diagnosed the others and exited 0: a benchmark of fewer records than labelled
    misleads. Now one line naming labels.csv, the line and the file, before any work."""
    (tmp_path / "labels.csv").write_text(
        "file,fault,sample_rate_hz,speed_rpm,designation\n"
        "bad.csv,normal,12000,1797,6205-2RS\n"
        "gone.mat,outer,12000,1797,6205-2RS\n"
    )
    (tmp_path / "bad.csv").write_text("a\nhello\n")
    one_line_error(
        capsys,
        ["benchmark", tmp_path],
        f"{tmp_path / 'labels.csv'} line 3: file = 'gone.mat'",
        f"there is no {tmp_path / 'gone.mat'}",
    )
    # no record read at all: exit 2 with the reason (a table of errors scored nothing)
    (tmp_path / "labels.csv").write_text(
        "file,fault,sample_rate_hz,speed_rpm,designation\nbad.csv,normal,12000,1797,6205-2RS\n"
    )
    one_line_error(capsys, ["benchmark", tmp_path], "could not be diagnosed: bad.csv")


# ------------------------------------------------------------------ 7: progress bars
BAR = ("━", "%", "1/1", "2/2", "0:00")


@pytest.mark.parametrize("json_output", [False, True])
def test_no_progress_bar_off_a_terminal(tmp_path, capsys, json_output):
    """stderr is not a terminal under capsys: nothing of a bar may print there (the
    study's and data set's bars printed "frequencies ━━━ 1/1 0:00:00")."""
    tail = ["--json"] if json_output else []
    runs = [
        [*STUDY, "-o", tmp_path / "s", *SERIAL],
        ["dataset", tmp_path / "d", "--records", "2", "--duration-s", "0.1", *SERIAL],
    ]
    for argv in runs:
        assert main([*map(str, argv), *tail]) == 0
        err = capsys.readouterr().err
        assert not any(mark in err for mark in BAR), err


# ------------------------------------------------------------------ 9: the page's snippets
# docs/capabilities/studies.md's ```python blocks (they crashed without
# ``if __name__ == "__main__":``) run in tests/unit/test_readme.py with every page's.
