"""The trend of a series of recordings (issues 23 and 27): readers, indicators, the alarm
rule's arithmetic, trend_records on synthetic series, inputs that lie, and the command
line's one-line errors."""

import json
import math

import numpy as np
import pytest
from conftest import run_error, run_json, write_pronostia

from bearinglab.errors import InputError
from bearinglab.signal import Signal, write_signal
from bearinglab.trend import trend_records
from bearinglab.trend.alarm import (
    crossing_runs,
    robust_location_scale,
    window_count,
    window_levels,
)
from bearinglab.trend.calibration import Calibration, excursion_maxima, fit_calibration
from bearinglab.trend.indicators import (
    acceleration_unit,
    band_limited,
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


#: Small series: 5 records to settle, 30 of baseline, a 30 s persistence window (3 records).
COUNTS = {"settle_records": 5, "baseline_records": 30, "persistence": 30.0}


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
    d = record_indicators(x, FS, max_frequency=FS / 2)
    assert np.median(d["kurtosis"]) == pytest.approx(3.0, abs=0.1)
    assert np.median(d["rms"]) == pytest.approx(1.0, abs=0.02)
    # the default band holds half of white noise's power
    assert np.median(record_indicators(x, FS)["rms"]) == pytest.approx(np.sqrt(0.5), abs=0.02)
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


def test_the_indicators_band_leaves_out_the_top_half_of_the_spectrum():
    # a 10 kHz tone (the top half of 25.6 kHz) on noise: in the full band it sets the rms,
    # in the default band (to 6.4 kHz) it is left out (issue 27: running-in and bursts of a
    # healthy bearing lie there)
    t = np.arange(2560) / FS
    noise_ = 0.1 * np.random.default_rng(0).standard_normal(2560)
    x = noise_ + 3.0 * np.sin(2 * np.pi * 10000.0 * t)
    full = record_indicators(x, FS, max_frequency=FS / 2)["rms"]
    default = record_indicators(x, FS)["rms"]
    assert float(full) > 2.0 and float(default) < 0.1
    y = band_limited(np.sin(2 * np.pi * 1000.0 * t), FS, 6400.0)
    np.testing.assert_allclose(y, np.sin(2 * np.pi * 1000.0 * t), atol=1e-9)
    with pytest.raises(InputError) as info:
        record_indicators(x, FS, max_frequency=20000.0)
    assert info.value.parameter == "max_frequency"


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
def test_a_level_is_above_a_value_exactly_when_most_of_its_window_is():
    rng = np.random.default_rng(3)
    x = rng.standard_normal((200, 2))
    for m in (1, 3, 4, 30):
        levels = window_levels(x, m)
        q = m // 2 + 1
        for i in range(m - 1, 200):
            for v in (-0.5, 0.0, 0.7):
                assert (levels[i, 0] > v) == (np.sum(x[i - m + 1 : i + 1, 0] > v) >= q)
        assert np.all(np.isnan(levels[: m - 1]))
    # a level never reaches back before the start it is given
    late = window_levels(x, 3, start=50)
    assert np.isnan(late[51, 0]) and np.isfinite(late[52, 0])


def test_a_burst_in_the_baseline_barely_moves_its_robust_scale():
    x = np.random.default_rng(4).standard_normal(30)
    m, s = robust_location_scale(x)
    burst = x.copy()
    burst[10:13] += 50.0
    m2, s2 = robust_location_scale(burst)
    assert abs(m2 - m) < 0.3 and s2 < 1.5 * s
    with pytest.raises(InputError):
        robust_location_scale(x[:9])


def test_the_window_is_a_duration_in_records():
    assert window_count(300.0, 10.0) == 30 and window_count(300.0, 100.0) == 3
    assert window_count(30.0, 10.0) == 3 and window_count(1e9, 1.0) == 360
    assert crossing_runs([1, 1, 0, 1]) == [(0, 1), (3, 3)]


def test_the_calibration_gives_the_rate_it_is_asked_for():
    c = Calibration(2.0, 25, 1.6, 0.56, 44.0, ((0.0, 3.1), (1.0, 2.0), (2.0, 0.56)))
    for rate in (1e-6, 3.6e-5, 1e-2, 0.5, 0.56):
        assert c.rate_above(c.limit(rate)) == pytest.approx(rate, rel=1e-9)
    assert c.limit(1e-6) > c.limit(1e-3) > c.limit(0.5) > c.limit(0.56) == 2.0
    with pytest.raises(InputError):  # a limit in the bulk of the healthy scatter
        c.limit(0.6)
    # excursions are counted once each, however many records they last
    assert excursion_maxima([0, 3, 3, 3, 0, 2.5, 0], 2.0).tolist() == [3.0, 2.5]


def test_fitted_on_exponential_excursions_the_calibration_holds_out_of_sample():
    # independent Laplace records: their excursions above 2 have exponential excesses
    rng = np.random.default_rng(5)
    learn = fit_calibration([(row, 1.0) for row in rng.laplace(size=(400, 200))])
    limit = learn.limit(0.5)  # per test-hour
    held = rng.laplace(size=(400, 200))
    counted = sum(excursion_maxima(row, limit).size for row in held)
    assert counted == pytest.approx(0.5 * 400, rel=0.25), counted


# ------------------------------------------------------------------ trend_records
def test_a_healthy_series_raises_no_alarm(healthy):
    r = trend_records(healthy, **COUNTS)
    assert r.alarm is None and r.baseline_records == 30 and r.persistence == 3
    d = r.to_dict()
    assert d["alarm"] is None and d["baseline_records"] == 30 and len(d["records"]) == 90
    assert d["rule"]["tests"] == 10 and d["rule"]["test_level"] == pytest.approx(1e-6)
    assert d["rule"]["false_alarm_per_record"] == pytest.approx(1e-5)  # 3.6e-3 / h, 10 s
    assert d["rule"]["false_alarm_per_hour"] == pytest.approx(3.6e-3)
    assert d["rule"]["band_hz"] == [0.0, 6400.0]
    json.dumps(d, allow_nan=False)


def test_impacts_after_the_baseline_raise_the_alarm_and_it_stays(failing):
    r = trend_records(failing, **COUNTS)
    assert r.alarm is not None
    assert 70 + r.persistence // 2 <= r.alarm.record <= 75
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


def test_a_burst_shorter_than_half_the_window_does_not_alarm_and_is_listed(tmp_path):
    x = noise(90, seed=4, n=1024)
    x[50:54, 0] += impacts(1024, depth=6.0)  # 40 s of strong impacts
    folder = write_pronostia(tmp_path, x)
    counts = {**COUNTS, "persistence": None, "persistence_records": 10}  # 100 s
    r = trend_records(folder, **counts)
    assert r.persistence == 10 and r.alarm is None
    crossings = r.to_dict()["short_crossings"]
    assert crossings and {c["channel"] for c in crossings} == {"horizontal"}
    assert all(500.0 <= c["time_s"] <= c["end_s"] <= 530.0 for c in crossings)
    assert r.to_dict()["records"][51]["above_limit"]  # each record's flags stay
    # the same burst held for 60 s of a 100 s window raises it
    x[54:56, 0] += impacts(1024, depth=6.0)
    r = trend_records(write_pronostia(tmp_path / "longer", x), **counts)
    assert r.alarm is not None and r.alarm.record == 55 and not r.short_crossings


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
        ({"false_alarm_per_hour": 30.0}, "false_alarm_per_hour"),
        ({"persistence_records": 0}, "persistence_records"),
        ({"persistence_records": 361}, "persistence_records"),
        ({"max_frequency": 13000.0}, "max_frequency"),
        ({"learn_from": "no/such/folder"}, "learn_from"),
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


# ------------------------------------------------------------------ inputs that lie (issue 27)
def test_duplicated_time_stamps_are_refused_naming_the_files(tmp_path):
    # issue 27: duplicated times made the spacing 0 s and the alarm impossible without a
    # word; when fewer than half are duplicated the old code ran on, silently
    times = np.arange(60) * 60.0
    times[41:51] = times[40:50]  # ten records share the time of the one before
    with pytest.raises(InputError) as info:
        trend_records(_records(tmp_path / "r", 60, times=times), **COUNTS)
    assert info.value.parameter == "folder" and "share their time" in info.value.hint
    assert "r040.npz" in info.value.hint and "r041.npz" in info.value.hint
    # (PRONOSTIA snapshots are ordered by their numbers: a clock repeated is out of that
    # order and is timed by its number, with a warning naming it)


def test_a_sample_rate_that_contradicts_the_files_is_warned_about(tmp_path):
    folder = _records(tmp_path / "r", 50)  # .npz files that store 25.6 kHz
    r = trend_records(folder, sample_rate=12800.0, **COUNTS)
    assert any("25600 Hz" in w and "12800 Hz" in w for w in r.warnings), r.warnings
    assert r.sample_rate == 12800.0
    p = write_pronostia(tmp_path / "p", short(seed=9))  # PRONOSTIA: 25.6 kHz, not stored
    r = trend_records(p, sample_rate=12800.0, **COUNTS)
    assert any("PRONOSTIA" in w and "12800 Hz" in w for w in r.warnings), r.warnings
    assert not any("sample rate" in w for w in trend_records(p, **COUNTS).warnings)


def test_records_of_absurd_magnitude_are_refused_in_one_line(capsys, tmp_path):
    # the old code gave raw RuntimeWarnings (errors under this suite) and an OverflowError
    folder = write_pronostia(tmp_path / "p", 1e300 * noise(12, seed=13, n=256))
    with pytest.raises(InputError) as info:
        trend_records(folder, **COUNTS)
    assert info.value.parameter == "folder" and "magnitudes below 1e+60" in str(info.value)
    err = run_error(capsys, "trend", str(folder))
    assert err.startswith("error: FOLDER") and "\n" not in err.strip()


def test_a_record_of_absurd_magnitude_among_good_ones_is_skipped_naming_it(tmp_path):
    x = short(seed=10)
    x[45] *= 1e300
    r = trend_records(write_pronostia(tmp_path, x), **COUNTS)
    assert "acc_00046.csv" not in r.files
    assert any("acc_00046.csv" in w and "skipped" in w for w in r.warnings)


def test_a_short_series_gets_a_shortened_baseline_with_a_warning(tmp_path):
    # 40 records (390 s) are shorter than the default settling and baseline (600 + 1200 s)
    r = trend_records(write_pronostia(tmp_path, short(40, seed=11)))
    assert r.baseline_records >= 10 and r.baseline_stop < 40
    assert any("shortened" in w for w in r.warnings)
    # a count asked for that does not fit is still refused
    with pytest.raises(InputError):
        trend_records(write_pronostia(tmp_path / "b", short(40, seed=11)), baseline_records=40)


def test_the_json_states_and_measures_the_rate_and_points_to_installed_docs(healthy):
    import importlib

    d = trend_records(healthy, **COUNTS).to_dict()
    rule = d["rule"]
    assert rule["false_alarm_per_hour"] == pytest.approx(3.6e-3)
    assert rule["false_alarm_per_record"] == pytest.approx(3.6e-3 * 10.0 / 3600.0)
    m = rule["measured_false_alarm"]
    assert {"per_record", "per_hour", "measured_on"} <= set(m)
    assert m["per_hour"] is not None and m["per_record"] is not None
    assert "learning runs" in m["measured_on"]  # 15 min of records: not measurable here
    assert m["per_record"] == pytest.approx(m["per_hour"] * 100.0 / 3600.0)  # their spacing
    # the documentation it names exists after a plain install: modules with docstrings
    assert "docs/capabilities" not in rule["documentation"].split(";")[0]
    for module in ("bearinglab.trend.alarm", "bearinglab.trend.calibration"):
        assert module in rule["documentation"]
        assert "false-alarm" in importlib.import_module(module).__doc__


def test_the_rate_is_measured_on_the_series_itself_when_it_is_long_enough(tmp_path):
    x = noise(420, seed=12, n=256)  # 70 min of healthy records, 10 s apart
    r = trend_records(write_pronostia(tmp_path, x), **COUNTS)
    m = r.to_dict()["rule"]["measured_false_alarm"]
    assert "this series" in m["measured_on"] and m["monitored_hours"] >= 1.0
    assert m["firings"] == 0 and m["per_hour"] == 0.0
    assert m["upper_per_hour"] == pytest.approx(-math.log(0.05) / m["monitored_hours"])


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
        (["HEALTHY", "--settle-s", "10", "--settle-records", "3"], "--running-in-records"),
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


@pytest.mark.parametrize(
    "kwargs, parameter",
    [({"run": 0}, "run"), ({"fraction": 0.0}, "fraction"), ({"sigmas": -1.0}, "sigmas")],
)
def test_plain_rule_refuses_a_rule_that_cannot_run(kwargs, parameter) -> None:
    from bearinglab.trend.alarm import plain_rule

    with pytest.raises(InputError) as err:
        plain_rule([1.0] * 30, **kwargs)
    assert err.value.parameter == parameter
