"""Inputs that lie (issue 21): a dead, constant, overflowing, monotonic or clipped channel,
and a CSV without a header row - each refused in one line naming what it holds, or analysed
with a named warning, never a verdict from nothing."""

import math

import numpy as np
import pytest

from bearinglab.catalog import bearing_from_designation
from bearinglab.cli import main
from bearinglab.diagnosis import NO_FAULT, analyze_signal
from bearinglab.errors import InputError
from bearinglab.kinematics import defect_frequencies
from bearinglab.signal import Signal, read_signal, write_signal
from bearinglab.signal.quality import check_channel

FS = 12000.0


@pytest.fixture(scope="module")
def kin():
    return defect_frequencies(bearing_from_designation("6205-2RS")[0], 1797 * math.pi / 30)


def noise(n=24000, seed=0):
    return np.random.default_rng(seed).standard_normal(n)


@pytest.mark.parametrize(
    "x, says",
    [
        (np.zeros(24000), "every sample 0"),
        (np.full(24000, 2.5), "every sample 2.5"),
        (1e300 * noise(), "samples up to"),
        (np.arange(24000) / FS, "rises at every sample"),
        (-np.arange(24000.0), "falls at every sample"),
    ],
    ids=["zeros", "constant", "1e300", "time column", "falling index"],
)
def test_a_channel_that_cannot_be_vibration_is_refused(kin, x, says):
    with pytest.raises(InputError) as err:
        analyze_signal(x, FS, kin)
    assert err.value.parameter == "signal_or_array" and says in str(err.value)


def test_a_clipped_channel_is_analysed_with_a_warning(kin):
    x = np.clip(noise(), -1.5, 1.5)
    d = analyze_signal(x, FS, kin)
    assert any("looks clipped" in w for w in d.warnings)
    # a sound one is not
    assert check_channel(noise()) == []
    assert not any("clipped" in w for w in analyze_signal(noise(), FS, kin).warnings)


def test_a_coarse_channel_is_named():
    x = np.round(noise())  # 9 or so levels: below its converter's resolution
    (warning,) = check_channel(x, "acc")
    assert "distinct values" in warning and warning.startswith("acc:")


def test_a_headerless_csv_is_read_with_its_time_column_as_time(tmp_path, kin):
    t = np.arange(24000) / FS
    x = noise()
    path = tmp_path / "record.csv"
    np.savetxt(path, np.column_stack([t, x]), delimiter=",")
    signal = read_signal(path)
    assert signal.names == ("column_2",) and signal.sample_rate == pytest.approx(FS)
    assert np.allclose(signal.channel("column_2"), x)
    d = analyze_signal(signal, None, kin)
    assert d.channel == "column_2" and d.verdict == NO_FAULT
    assert any("no header row" in w for w in d.warnings)
    assert any("column_1 rises at every row" in w for w in d.warnings)


@pytest.mark.parametrize(
    "samples, says",
    [(np.zeros(24000), "every sample 0"), (1e300 * noise(), "samples up to")],
    ids=["zeros", "1e300"],
)
def test_analyze_refuses_a_dead_or_overflowing_file_in_one_line(tmp_path, capsys, samples, says):
    path = tmp_path / "dead.npz"
    write_signal(path, Signal({"DE": samples}, FS))
    code = main(["analyze", str(path), "--designation", "6205-2RS", "--speed-rpm", "1797"])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1
    assert "SIGNAL_FILE" in err and says in err and "Traceback" not in err


def test_a_series_the_bearing_does_not_explain_is_named(kin):
    """An outer-race fault of one bearing analysed as another (the designation wrong):
    no family of the bearing given passes, but the series is named, with what the bearing
    given predicts, and the advice to check the bearing and the speed."""
    fs, seconds, bpfo = 12000.0, 5.0, 107.3  # a 6205's BPFO at 1797 rpm
    rng = np.random.default_rng(4)
    t = np.arange(int(fs * seconds)) / fs
    x = 0.3 * rng.standard_normal(t.size)
    for start in np.cumsum(
        np.full(int(seconds * bpfo) - 1, 1 / bpfo)
        * (1 + 0.005 * rng.standard_normal(int(seconds * bpfo) - 1))
    ):
        i = int(start * fs)
        tau = np.arange(min(120, t.size - i)) / fs
        x[i : i + tau.size] += np.exp(-tau / 1.5e-3) * np.sin(2 * np.pi * 3500 * tau)
    x += 0.4 * np.sin(2 * np.pi * 29.95 * t)
    other = defect_frequencies(bearing_from_designation("6310")[0], 1797 * math.pi / 30)
    d = analyze_signal(x, fs, other, methods="raw")
    assert d.verdict == NO_FAULT
    (warning,) = [w for w in d.warnings if "harmonic series at" in w]
    assert "check the bearing and the speed" in warning and "BPFO 91.2" in warning
    found = float(warning.split("harmonic series at ")[1].split(" Hz")[0])
    assert found == pytest.approx(bpfo, rel=0.01)
    # the right bearing finds the fault, and then no stray series is named
    d = analyze_signal(x, fs, kin, methods="raw")
    assert d.verdict == "outer_race"
    assert not any("harmonic series at" in w for w in d.warnings)
