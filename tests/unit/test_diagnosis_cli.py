"""``bearinglab analyze`` and ``bearinglab benchmark`` (issue 11): options, one-line errors
(exit 2, nothing written), and a benchmark over a small labelled folder."""

import json
import math

import numpy as np
import pytest

from bearinglab.cli import main
from bearinglab.engine import most_processes
from bearinglab.signal import Signal, write_signal

FS = 20000.0


def impacts(rate_hz, seconds=1.0, seed=0, shaft_hz=1750 / 60):
    rng = np.random.default_rng(seed)
    t = np.arange(int(FS * seconds)) / FS
    jitter = 1 + 0.01 * rng.standard_normal(int(seconds * rate_hz) + 5)
    starts = np.cumsum(jitter / rate_hz)
    x = np.zeros(t.size)
    for s in starts[starts < seconds]:
        i = int(s * FS)
        m = min(t.size - i, 200)
        tau = np.arange(m) / FS
        x[i : i + m] += np.exp(-tau / 2e-3) * np.sin(2 * np.pi * 4e3 * tau)
    x += sum(0.5 / k * np.sin(2 * np.pi * k * shaft_hz * t) for k in (1, 2, 3))
    return x + 0.2 * rng.standard_normal(t.size)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    """Three records of an ER-16K at 1750 rpm (outer, inner race, noise) and labels.csv."""
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.kinematics import defect_frequencies

    kin = defect_frequencies(bearing_from_designation("ER-16K")[0], 1750 * math.pi / 30)
    d = tmp_path_factory.mktemp("bench")
    t = np.arange(int(FS)) / FS
    inner = impacts(kin.hz("bpfi"), seed=1) * (1 + 0.5 * np.cos(2 * np.pi * kin.shaft_hz * t))
    records = {
        "outer.npz": (impacts(kin.hz("bpfo")), "outer"),
        "inner.npz": (inner, "inner"),
        "noise.npz": (np.random.default_rng(3).standard_normal(t.size), "normal"),
    }
    rows = ["file,channel,sample_rate_hz,speed_rpm,designation,fault"]
    for name, (x, fault) in records.items():
        write_signal(d / name, Signal({"acc": x}, FS))
        rows.append(f"{name},acc,{FS},1750,ER-16K,{fault}")
    (d / "labels.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    return d


def run(capsys, *args):
    code = main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


#: The speed every test record was made at.
AT_1750 = ("--speed-rpm", "1750")


def analyze(capsys, path, *options):
    """``bearinglab analyze`` of an ER-16K record at ``path`` with ``options``."""
    return run(capsys, "analyze", str(path), "--designation", "ER-16K", *options)


def test_analyze_json_and_options(folder, capsys):
    code, out, err = analyze(
        capsys,
        folder / "outer.npz",
        *AT_1750,
        "--method",
        "raw,cpw",
        "--tolerance",
        "ball=0.05",
        "--json",
    )
    assert code == 0, err
    d = json.loads(out)
    assert d["verdict"] == "outer_race" and d["likely_fault"] == "outer_race"
    assert d["methods"] == ["raw", "cpw"] and d["tolerances"]["ball"] == {
        "below": 0.05,
        "above": 0.05,
    }
    assert d["families"]["outer_race"]["passed"] and d["speed"]["source"] == "given"
    code, out, err = analyze(capsys, folder / "noise.npz", *AT_1750, "--json")
    assert json.loads(out)["likely_fault"] is None


def test_analyze_speed_auto(folder, capsys):
    code, out, err = analyze(
        capsys,
        folder / "outer.npz",
        "--speed-rpm",
        "auto",
        "--speed-range-rpm",
        "1600,1900",
        "--method",
        "raw",
        "--json",
    )
    assert code == 0, err
    d = json.loads(out)
    assert d["speed"]["source"] == "signal"
    assert d["speed"]["used_rpm"] == pytest.approx(1750, rel=3e-3)


def test_analyze_human_output(folder, capsys):
    code, out, _ = analyze(capsys, folder / "inner.npz", *AT_1750, "--method", "raw")
    assert code == 0 and "verdict: inner race" in out and "f [Hz]" in out


def test_method_all_and_repeated(folder, capsys):
    """--method all (as the help says) and a repeated --method, in both commands."""
    args = [*AT_1750, "--json"]
    code, out, err = analyze(capsys, folder / "outer.npz", "--method", "all", *args)
    assert code == 0, err
    assert json.loads(out)["methods"] == ["raw", "cpw", "drs-sk"]
    code, out, err = analyze(
        capsys, folder / "outer.npz", "--method", "cpw", "--method", "raw", *args
    )
    assert code == 0, err
    assert json.loads(out)["methods"] == ["cpw", "raw"]
    code, out, err = run(capsys, "benchmark", str(folder), "--method", "all", "--json")
    assert code == 0, err
    assert set(json.loads(out)["right"]) >= {"raw", "cpw", "drs-sk"}


@pytest.mark.parametrize(
    "args, flag",
    [
        (["--speed-rpm", "0"], "--speed-rpm"),
        (["--speed-rpm", "fast"], "--speed-rpm"),
        (["--speed-rpm", "1750", "--channel", "DE"], "--channel"),
        (["--speed-rpm", "1750", "--method", "fourier"], "--method"),
        (["--speed-rpm", "1750", "--tolerance", "ball"], "--tolerance"),
        (["--speed-rpm", "1750", "--sample-rate-hz", "150"], "--sample-rate-hz"),  # BPFO > Nyquist
        (["--speed-rpm", "auto"], "--speed-rpm"),  # no recorded speed to search round
        (["--speed-rpm", "1750", "--record", "X099"], "--record"),  # an .npz holds no records
    ],
)
def test_analyze_errors_are_one_line(folder, capsys, tmp_path, args, flag):
    plot = tmp_path / "never.png"
    code, out, err = analyze(capsys, folder / "outer.npz", *args, "--plot", plot)
    assert code == 2 and err.startswith("error: ") and err.count("\n") == 1, err
    assert flag in err and not plot.exists()


def test_analyze_short_record_and_struct_fields(tmp_path, capsys):
    import scipy.io

    noise = np.random.default_rng(0).standard_normal(2000)
    write_signal(tmp_path / "short.npz", Signal({"acc": noise}, FS))
    code, _, err = analyze(capsys, tmp_path / "short.npz", *AT_1750)
    assert code == 2 and "cage revolutions" in err and err.count("\n") == 1
    scipy.io.savemat(
        tmp_path / "m.mat",
        {"bearing": {"gs": np.ones((40000, 1)), "sr": np.array([[FS]]), "load": "25"}},
    )
    code, _, err = analyze(capsys, tmp_path / "m.mat", *AT_1750, "--channel", "bearing.load")
    assert code == 2 and "--channel" in err and "text" in err


def test_benchmark_json_and_html(folder, capsys, tmp_path):
    page = tmp_path / "bench.html"
    code, out, err = run(
        capsys, "benchmark", str(folder), "--method", "raw", "--json", "--html", str(page)
    )
    assert code == 0, err
    d = json.loads(out)
    assert d["total"] == 3 and d["right"]["raw"] == 3
    # wrong faults and misses apart: a wrong fault costs an engineer more than a miss
    assert d["wrong"]["raw"] == 0 and d["missed"]["raw"] == 0
    assert [r["outcome"] for r in d["records"]] == ["right"] * 3
    assert all("measured_rpm" in r for r in d["records"])
    assert d["confusion"]["raw"]["outer_race"]["outer_race"] == 1
    assert d["recall"]["raw"]["no fault detected"] == 1.0
    assert page.read_text(encoding="utf-8").count("<img") >= 4  # matrix + 3 spectra
    code, out, _ = run(capsys, "benchmark", str(folder), "--method", "raw,cpw", "--jobs", "2")
    assert code == 0 and "confusion" in out
    # the ies note is said of every record: printed once, with their count
    code, out, _ = run(capsys, "benchmark", str(folder), "--method", "ies")
    flat = " ".join(out.split())
    assert code == 0 and flat.count("the ies method") == 1 and "3 records: the ies" in flat
    code, _, err = run(capsys, "benchmark", str(tmp_path))
    assert code == 2 and "labels.csv" in err
    # more processes than 4 per core only take memory (100 000 once filled 24 GB)
    most = most_processes()
    code, _, err = run(capsys, "benchmark", str(folder), "--jobs", str(most + 1))
    assert code == 2 and f"--jobs = {most + 1} is not allowed" in err and f"[1, {most}]" in err


def test_a_sample_rate_that_overrides_the_files_is_named(tmp_path, capsys):
    """--sample-rate-hz 60000 on a file that stores 50 kHz shifts every line by 20 %: the
    analysis says so (an audit found it silent)."""
    path = tmp_path / "rec.npz"
    noise = np.random.default_rng(0).standard_normal(50_000)
    write_signal(path, Signal({"acc_y": noise}, 50_000.0, {}))
    args = ("analyze", str(path), "--designation", "6205", *AT_1750, "--json")

    def said(rate):
        code, out, err = run(capsys, *args, "--sample-rate-hz", rate)
        assert code == 0, err
        return [w for w in json.loads(out)["warnings"] if "stores a sample rate" in w]

    assert "50000 Hz and 60000 Hz was given" in said("60000")[0]
    assert said("50000") == []


def test_labels_in_other_data_sets_spellings(folder, tmp_path, capsys):
    """Fault labels as other data sets spell them ("OR", "Inner race fault", "baseline")
    are read as outer, inner, normal; an unknown one is refused with the spellings."""
    from bearinglab.diagnosis.benchmark import label_fault

    assert [label_fault(t) for t in ("OR", "Inner race fault", "baseline", "B", "crack")] == [
        "outer",
        "inner",
        "normal",
        "ball",
        None,
    ]
    text = (folder / "labels.csv").read_text(encoding="utf-8")
    other = tmp_path / "other"
    other.mkdir()
    for name in ("outer.npz", "inner.npz", "noise.npz"):
        (other / name).symlink_to(folder / name)
    spelled = text.replace(",outer\n", ",OR\n").replace(",inner\n", ",Inner race fault\n")
    (other / "labels.csv").write_text(spelled.replace(",normal\n", ",baseline\n"), "utf-8")
    code, out, err = run(capsys, "benchmark", str(other), "--method", "raw", "--json")
    assert code == 0, err
    assert json.loads(out)["right"]["raw"] == 3
    (other / "labels.csv").write_text(text.replace(",normal\n", ",crack\n"), "utf-8")
    code, _, err = run(capsys, "benchmark", str(other))
    assert code == 2 and "'crack'" in err and "ir" in err


def test_a_blank_speed_in_the_labels_is_the_files_own(folder, tmp_path, capsys):
    """speed_rpm left blank: the speed the file stores; a file with none is that record's
    error, naming speed_rpm, and the other records still run."""
    other = tmp_path / "blank"
    other.mkdir()
    from bearinglab.signal import read_signal

    outer = read_signal(folder / "outer.npz")
    write_signal(other / "stored.npz", Signal(outer.channels, FS, {"speed_rpm": 1750.0}))
    (other / "bare.npz").symlink_to(folder / "outer.npz")
    (other / "labels.csv").write_text(
        "file,channel,sample_rate_hz,speed_rpm,designation,fault\n"
        f"stored.npz,acc,{FS},,ER-16K,outer\nbare.npz,acc,{FS},,ER-16K,outer\n",
        "utf-8",
    )
    code, out, err = run(capsys, "benchmark", str(other), "--method", "raw", "--json")
    assert code == 0, err
    stored, bare = json.loads(out)["records"]
    assert stored["verdict"] == "outer_race" and stored["error"] is None
    assert bare["verdict"] == "error" and "speed_rpm" in bare["error"]


def test_labels_as_spreadsheets_write_them(folder, tmp_path, capsys):
    """labels.csv with a byte-order mark, semicolons, Windows line ends, headers in other
    case with spaces, CWRU's fault codes, blank rows, Windows-1252 text and speed "auto"
    runs; a value with a unit is that record's error naming the column; an unknown fault
    names the line; the table prints each record's warnings."""
    from bearinglab.signal import read_signal

    other = tmp_path / "sheet"
    other.mkdir()
    for name in ("inner.npz", "noise.npz"):
        (other / name).symlink_to(folder / name)
    outer = read_signal(folder / "outer.npz")  # "auto" searches around the stored speed
    write_signal(other / "outer.npz", Signal(outer.channels, FS, {"speed_rpm": 1750.0}))
    lines = [
        "File ; Channel;Sample_Rate_Hz; speed_rpm ;Designation;Fault;note",
        f"outer.npz;acc;{FS};auto;ER-16K;OR007@6;ext\xe9rieur",
        f"inner.npz;acc;{FS};1750;ER-16K;IR014;",
        f"noise.npz;acc;{FS};1750;ER-16K;Normal Baseline;",
        ";;;;;;",
    ]
    text = "\r\n".join(lines) + "\r\n"
    for encoding in ("utf-8-sig", "cp1252"):
        (other / "labels.csv").write_bytes(text.encode(encoding))
        code, out, err = run(capsys, "benchmark", str(other), "--method", "raw", "--json")
        assert code == 0, err
        result = json.loads(out)
        assert result["right"]["raw"] == 3 and result["total"] == 3
        assert result["records"][0]["measured_rpm"] is not None  # auto: read from the signal
    (other / "labels.csv").write_text(
        text.replace("1750;ER-16K;IR014", "1750 rpm;ER-16K;IR014"), encoding="utf-8"
    )
    code, out, _ = run(capsys, "benchmark", str(other), "--method", "raw", "--json")
    inner = json.loads(out)["records"][1]
    assert code == 0 and inner["verdict"] == "error"
    assert "speed_rpm = '1750 rpm'" in inner["error"] and "without a unit" in inner["error"]
    (other / "labels.csv").write_text(text.replace("IR014", "IR014x"), encoding="utf-8")
    code, _, err = run(capsys, "benchmark", str(other))
    assert code == 2 and "'IR014x'" in err and "line 3" in err
    (other / "labels.csv").write_text(text.replace(";1750;", ";1700;"), encoding="utf-8")
    code, out, _ = run(capsys, "benchmark", str(other), "--method", "raw")
    assert code == 0 and "inner.npz: the signal shows the shaft at" in " ".join(out.split())
