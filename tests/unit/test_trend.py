"""The trend of a series of recordings (issue 23): readers, indicators, the alarm rule's
arithmetic, trend_records on synthetic series, and the command line's one-line errors."""

import json
import math

import numpy as np
import pytest
from conftest import run_error, run_json, write_pronostia

from bearinglab.errors import InputError
from bearinglab.signal import Signal, write_signal
from bearinglab.trend import trend_records
from bearinglab.trend.alarm import (
    first_run,
    persistence_count,
    tail_constant,
    tail_limit,
    window_probability,
)
from bearinglab.trend.indicators import (
    acceleration_unit,
    record_indicators,
    scalar_indicators,
    velocity_rms,
)
from bearinglab.trend.series import list_records, read_pronostia, snapshot_times
from bearinglab.trend.severity import MACHINES, machine_zones, zones_of

FS = 25600.0


def noise(records: int, seed: int = 0, n: int = 2560, scale: float = 0.3) -> np.ndarray:
    """records x 2 channels x n samples of Gaussian noise [g]."""
    return scale * np.random.default_rng(seed).standard_normal((records, 2, n))


def impacts(n: int = 2560, every: int = 150, depth: float = 2.0) -> np.ndarray:
    """Decaying 4 kHz rings every ``every`` samples (a bearing's impacts) [g]."""
    t = np.arange(n) / FS
    since = (np.arange(n) % every) / FS
    return depth * np.exp(-since / 3e-4) * np.sin(2 * np.pi * 4000.0 * t)


@pytest.fixture(scope="module")
def healthy(tmp_path_factory):
    return write_pronostia(tmp_path_factory.mktemp("healthy"), noise(90, seed=1))


@pytest.fixture(scope="module")
def failing(tmp_path_factory):
    """Healthy for 70 records, then impacts on the horizontal channel."""
    x = noise(90, seed=2)
    x[70:, 0] += impacts()
    return write_pronostia(tmp_path_factory.mktemp("failing"), x)


def short(records: int = 60, seed: int = 0) -> np.ndarray:
    """Short records (1024 samples) for the tests that write their own series."""
    return noise(records, seed=seed, n=1024)


COUNTS = {"settle_records": 5, "baseline_records": 30}


# ------------------------------------------------------------------ readers
def test_pronostia_reader_reads_the_published_columns(tmp_path):
    x = noise(1, seed=3)
    folder = write_pronostia(tmp_path, x, start=9 * 3600 + 39 * 60 + 39.065664)
    clock, samples = read_pronostia(folder / "acc_00001.csv")
    assert clock == pytest.approx(34779.065664, abs=1e-5)
    assert samples.shape == (2, 2560)
    np.testing.assert_allclose(samples, np.round(x[0], 3), atol=1e-12)


@pytest.mark.parametrize(
    "row",
    ["9;39;39;1.6558e+005;0.{k}52;-0.146", "9;39;39;1,6558e+005;0,{k}52;-0,146"],
    ids=["semicolons", "decimal commas"],
)
def test_pronostia_reader_takes_semicolons_decimal_commas_and_long_exponents(tmp_path, row):
    rows = [row.format(k=i % 7) for i in range(300)]
    (tmp_path / "acc_00001.csv").write_text("\n".join(rows) + "\n")
    clock, samples = read_pronostia(tmp_path / "acc_00001.csv")
    assert clock == pytest.approx(34779.16558)
    assert samples[0, 1] == pytest.approx(0.152) and samples[1, 0] == pytest.approx(-0.146)


@pytest.mark.parametrize(
    "text, why",
    [("", "empty"), ("9,39,39,65664,0.5\n" * 300, "5 columns"), ("a,b,c,d,e,f\n" * 300, "text")],
)
def test_a_bad_snapshot_is_an_input_error_naming_it(tmp_path, text, why):
    (tmp_path / "acc_00001.csv").write_text(text)
    with pytest.raises(InputError) as info:
        read_pronostia(tmp_path / "acc_00001.csv")
    assert info.value.value == "acc_00001.csv", why


def test_listing_orders_snapshots_by_number_and_leaves_temperatures_out(tmp_path):
    write_pronostia(tmp_path, noise(3), numbers=[9, 10, 100])
    (tmp_path / "temp_00001.csv").write_text("9,39,39,0,50.1\n")
    listing = list_records(tmp_path)
    assert listing.layout == "pronostia"
    assert listing.files == ("acc_00009.csv", "acc_00010.csv", "acc_00100.csv")


def test_snapshot_times_cross_midnight_and_repair_a_clock_out_of_order():
    t, bad = snapshot_times([1, 2, 3], [86395.0, 5.0, 15.0])
    assert t.tolist() == [86395.0, 86405.0, 86415.0] and bad.size == 0
    t, bad = snapshot_times([1, 11, 21, 31, 41], [100.0, 200.0, 10.0, 400.0, 500.0])
    assert bad.tolist() == [2] and t[2] == pytest.approx(300.0)


def test_a_run_over_midnight_keeps_its_order(tmp_path):
    folder = write_pronostia(tmp_path, short(seed=4), start=86400.0 - 200.0)
    r = trend_records(folder, **COUNTS)
    assert np.all(np.diff(r.times) > 0) and r.times[-1] == pytest.approx(590.0, abs=1e-3)
    assert not any("order" in w for w in r.warnings)


def test_an_unreadable_snapshot_is_skipped_with_a_warning_naming_it(tmp_path):
    folder = write_pronostia(tmp_path, short(seed=5))
    (folder / "acc_00020.csv").write_text("this is not a snapshot\n")
    r = trend_records(folder, **COUNTS)
    assert len(r.files) == 59 and "acc_00020.csv" not in r.files
    assert any("acc_00020.csv" in w and "skipped" in w for w in r.warnings)


def test_a_clock_out_of_the_order_of_the_numbers_is_timed_by_its_number(tmp_path):
    folder = write_pronostia(tmp_path, short(seed=6))
    text = (folder / "acc_00030.csv").read_text().splitlines()
    (folder / "acc_00030.csv").write_text(
        "\n".join("9,0,0," + line.split(",", 3)[3] for line in text) + "\n"
    )
    r = trend_records(folder, **COUNTS)
    assert r.files.index("acc_00030.csv") == 29
    assert r.times[29] == pytest.approx(290.0, abs=1e-3)
    assert any("acc_00030.csv" in w and "clock" in w for w in r.warnings)


def _records(folder, count, rate=FS, times=None, index=True, seed=7):
    folder.mkdir()
    x = noise(count, seed=seed, n=1024)
    times = np.arange(count) * 60.0 if times is None else np.asarray(times)
    rows = ["file,time_s"]
    for k in range(count):
        meta = {} if index else {"time_s": float(times[k])}
        name = f"r{k:03d}.npz"
        write_signal(folder / name, Signal({"DE": x[k, 0], "FE": x[k, 1]}, rate, meta))
        rows.append(f"{name},{times[k]}")
    if index:
        (folder / "index.csv").write_text("\n".join(rows) + "\n")
    return folder


def test_records_with_an_index_are_put_in_time_order(tmp_path):
    times = np.arange(60) * 60.0
    shuffled = np.random.default_rng(0).permutation(times)
    r = trend_records(_records(tmp_path / "r", 60, times=shuffled), **COUNTS)
    assert np.all(np.diff(r.times) > 0) and r.channels == ("DE", "FE")
    k = int(np.argmin(shuffled))
    assert r.files[0] == f"r{k:03d}.npz"
    assert any("time order" in w for w in r.warnings)


def test_records_take_their_time_from_their_metadata(tmp_path):
    r = trend_records(_records(tmp_path / "r", 50, index=False), **COUNTS)
    assert r.times[-1] == pytest.approx(49 * 60.0) and r.layout == "records"


def test_records_of_another_sample_rate_are_refused_naming_the_file(tmp_path):
    folder = _records(tmp_path / "r", 50)
    x = noise(1, seed=9, n=1024)[0]
    write_signal(folder / "r010.npz", Signal({"DE": x[0], "FE": x[1]}, 20000.0))
    with pytest.raises(InputError) as info:
        trend_records(folder, **COUNTS)
    assert info.value.value == "r010.npz" and "sample rate" in info.value.allowed


@pytest.mark.parametrize(
    "make, why",
    [(lambda p: p, "an empty folder"), (lambda p: (p / "notes.txt").write_text("x"), "no records")],
)
def test_a_folder_without_recordings_is_an_input_error(tmp_path, make, why):
    make(tmp_path)
    with pytest.raises(InputError) as info:
        trend_records(tmp_path)
    assert info.value.parameter == "folder", why


# ------------------------------------------------------------------ indicators
def test_indicators_of_gaussian_noise_and_of_a_sine():
    x = np.random.default_rng(0).standard_normal((50, 8192))
    d = record_indicators(x, FS)
    assert np.median(d["kurtosis"]) == pytest.approx(3.0, abs=0.1)
    assert np.median(d["rms"]) == pytest.approx(1.0, abs=0.02)
    assert np.all(d["crest_factor"] == d["peak"] / d["rms"])
    assert np.all(np.abs(d["spectral_kurtosis"]) < 1.0)
    t = np.arange(4096) / FS
    s = scalar_indicators(3.0 + np.sin(2 * np.pi * 100 * t))  # the mean is removed
    assert float(s["crest_factor"]) == pytest.approx(math.sqrt(2), rel=1e-3)
    assert float(s["kurtosis"]) == pytest.approx(1.5, rel=1e-3)


def test_impacts_raise_the_kurtosis_and_the_spectral_kurtosis():
    x = noise(2, seed=1)[:, 0]
    x[1] += impacts()
    d = record_indicators(x, FS)
    assert d["kurtosis"][1] > 2 * d["kurtosis"][0]
    assert d["spectral_kurtosis"][1] > d["spectral_kurtosis"][0] + 2


def test_velocity_in_g_is_9_81_times_that_in_m_s2():
    x = noise(3, seed=2)
    np.testing.assert_allclose(velocity_rms(x, FS, "g"), 9.80665 * velocity_rms(x, FS, "m/s2"))


@pytest.mark.parametrize("unit", ["V", "mm/s", "um"])
def test_units_the_zones_cannot_use_are_refused(unit):
    with pytest.raises(InputError) as info:
        acceleration_unit(unit)
    assert info.value.parameter == "unit"


def test_zones_and_machines():
    z = machine_zones("Group2 Rigid")
    assert z is MACHINES["group2-rigid"] and z.a_b < z.b_c < z.c_d
    assert zones_of([z.a_b * 0.99, z.a_b, z.c_d * 2], z).tolist() == ["A", "B", "D"]
    with pytest.raises(InputError):
        machine_zones("group3")


# ------------------------------------------------------------------ the rule's arithmetic
@pytest.mark.parametrize(
    "n, r, level", [(10, 1, 1e-2), (30, 3, 1e-7), (200, 2, 1e-5), (60, 5, 1e-3)]
)
def test_the_tail_constant_gives_the_level(n, r, level):
    k = n // 2
    c = tail_constant(n, k, r, level)
    assert c > 0 and window_probability(n, k, r, c) == pytest.approx(level, rel=1e-9)
    assert window_probability(n, k, r, 2 * c) < level


def test_a_lower_level_and_a_shorter_run_raise_the_limit():
    x = np.random.default_rng(1).laplace(size=40)
    assert tail_limit(x, 1e-6, 3).limit > tail_limit(x, 1e-3, 3).limit
    assert tail_limit(x, 1e-6, 2).limit > tail_limit(x, 1e-6, 3).limit
    with pytest.raises(InputError):
        tail_limit(x[:9], 1e-3, 3)


def test_runs_and_persistence():
    assert first_run([1, 1, 0, 1, 1, 1], 3) == 5
    assert first_run([1, 1, 0, 1, 1], 3) is None
    assert persistence_count(30.0, 10.0) == 3
    assert persistence_count(30.0, 50.0) == 2 and persistence_count(1e6, 1.0) == 50


# ------------------------------------------------------------------ trend_records
def test_a_healthy_series_raises_no_alarm(healthy):
    r = trend_records(healthy, **COUNTS)
    assert r.alarm is None and r.baseline_records == 30 and r.persistence == 3
    d = r.to_dict()
    assert d["alarm"] is None and d["baseline_records"] == 30 and len(d["records"]) == 90
    assert d["rule"]["tests"] == 10 and d["rule"]["test_level"] == pytest.approx(1e-7)
    json.dumps(d, allow_nan=False)


def test_impacts_after_the_baseline_raise_the_alarm_and_it_stays(failing):
    r = trend_records(failing, **COUNTS)
    assert r.alarm is not None
    assert 70 + r.persistence - 1 <= r.alarm.record <= 75
    assert r.alarm.channel == "horizontal"
    assert r.alarm.indicator in ("kurtosis", "spectral_kurtosis", "crest_factor", "peak", "rms")
    d = r.to_dict()
    assert d["alarm"]["record"] == r.alarm.record
    assert d["alarm"]["time_s"] == pytest.approx(r.alarm.record * 10.0, abs=1e-3)
    assert d["records"][r.alarm.record]["above_limit"]


def test_the_alarm_is_never_inside_the_baseline(tmp_path):
    x = short(seed=3)
    x[20:, 0] += impacts(1024)  # the bearing is already damaged while the baseline is learnt
    r = trend_records(write_pronostia(tmp_path, x), **COUNTS)
    assert r.alarm is None or r.alarm.record >= r.baseline_stop


def test_a_burst_shorter_than_the_persistence_does_not_alarm(tmp_path):
    x = short(seed=4)
    x[50:52, 0] += impacts(1024)
    folder = write_pronostia(tmp_path, x)
    r = trend_records(folder, **COUNTS)
    assert r.persistence == 3 and r.alarm is None
    r = trend_records(folder, persistence_records=2, **COUNTS)
    assert r.alarm is not None and r.alarm.record == 51


def test_the_baseline_as_a_duration_holds_at_least_30_records(healthy):
    r = trend_records(healthy, settle=60.0, baseline=60.0)
    assert r.settle_records == 6 and r.baseline_records == 30


def test_a_rising_baseline_is_reported(tmp_path):
    x = short(seed=5)
    x[:, 1] *= np.exp(np.linspace(0.0, 1.0, 60))[:, None]
    r = trend_records(write_pronostia(tmp_path, x), **COUNTS)
    assert any("rms (vertical) still rises" in w for w in r.warnings)


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        ({"baseline_records": 100}, "baseline_records"),
        ({"baseline": 5000.0, "baseline_records": None}, "baseline"),
        ({"baseline_records": 5}, "baseline_records"),
        ({"channels": "radial"}, "channels"),
        ({"unit": "V"}, "unit"),
        ({"machine": "class1"}, "unit"),
        ({"false_alarm_per_hour": 0.0}, "false_alarm_per_hour"),
        ({"false_alarm_per_hour": 3600.0}, "false_alarm_per_hour"),
        ({"persistence_records": 0}, "persistence_records"),
        ({"shaft_speed": 100.0}, "bearing"),
        ({"jobs": 0}, "jobs"),
    ],
)
def test_bad_inputs_name_their_parameter(healthy, kwargs, parameter):
    with pytest.raises(InputError) as info:
        trend_records(healthy, **{**COUNTS, **kwargs})
    assert info.value.parameter == parameter


def test_outputs_table_figure_page_and_velocity(failing, tmp_path):
    r = trend_records(failing, unit="g", machine="group2-rigid", **COUNTS)
    df = r.to_pandas()
    assert len(df) == 90 and {"rms_horizontal", "zone_vertical", "baseline"} <= set(df.columns)
    assert df["baseline"].sum() == 30
    d = r.to_dict()
    v = d["records"][0]["indicators"]["horizontal"]["velocity_rms_mm_s"]
    assert v == pytest.approx(r.velocity[0, 0] * 1e3) and v > 0
    assert d["severity"]["boundaries_mm_s"]["a_b"] == pytest.approx(1.4)
    fig, axes = r.plot()
    assert len(axes) == 6  # five indicators and the velocity
    from bearinglab.report.trend import write_trend_page

    page = write_trend_page(r, tmp_path / "trend.html").read_text()
    assert "bearinglab trend" in page and "data:image/png;base64" in page


# ------------------------------------------------------------------ the command line
def test_cli_json(capsys, failing):
    counts = ["--settle-records", "5", "--baseline-records", "30"]
    out = run_json(capsys, "trend", str(failing), *counts)
    assert out["alarm"]["indicator"] and out["baseline_records"] == 30
    assert out["records"][0]["time_s"] == 0.0 and out["records"][0]["file"] == "acc_00001.csv"


def test_cli_tables(capsys, failing):
    from bearinglab.cli import main

    assert main(["trend", str(failing), "--settle-records", "5", "--baseline-records", "30"]) == 0
    out = capsys.readouterr().out
    assert "alarm" in out and "kurtosis" in out


@pytest.mark.parametrize(
    "args, flag",
    [
        (["EMPTY"], "FOLDER"),
        (["NOTES"], "FOLDER"),
        (["HEALTHY", "--baseline-records", "200"], "--baseline-records"),
        (["HEALTHY", "--baseline-s", "100000"], "--baseline-s"),
        (["HEALTHY", "--channel", "radial"], "--channel"),
        (["HEALTHY", "--unit", "V"], "--unit"),
        (["HEALTHY", "--machine", "class1"], "--unit"),
        (["HEALTHY", "--speed-rpm", "1800"], "--designation"),
        (["HEALTHY", "--settle-s", "10", "--settle-records", "3"], "--settle-records"),
    ],
)
def test_cli_bad_input_is_one_line_and_writes_nothing(capsys, tmp_path, healthy, args, flag):
    (tmp_path / "empty").mkdir()
    (tmp_path / "notes").mkdir()
    (tmp_path / "notes" / "notes.txt").write_text("x")
    where = {"EMPTY": tmp_path / "empty", "NOTES": tmp_path / "notes", "HEALTHY": healthy}
    argv = [str(where.get(a, a)) for a in args]
    page, plot = tmp_path / "out.html", tmp_path / "out.png"
    err = run_error(capsys, "trend", *argv, "--html", str(page), "--plot", str(plot))
    assert err.startswith(f"error: {flag}"), err
    assert not page.exists() and not plot.exists()


@pytest.mark.slow
def test_dask_workers_give_the_same_trend(failing):
    one = trend_records(failing, **COUNTS)
    two = trend_records(failing, jobs=2, **COUNTS)
    assert two.files == one.files and two.alarm == one.alarm
    for name in one.values:
        np.testing.assert_array_equal(two.values[name], one.values[name])
