"""Diagnosis of real recordings against Smith & Randall's benchmark (issue 11).

Source: Smith W. A., Randall R. B., "Rolling element bearing diagnostics using the Case
Western Reserve University data: a benchmark study", MSSP 64-65 (2015) 100-131: the
diagnosability category of each CWRU drive-end record by their Methods 1-3 (Y clearly
diagnosable, P partially, N not), as transcribed in shared/data/real/labels.csv; the MFPT
files (Bechhoefer, MFPT fault data sets) are labelled by their data set. The recordings
are read as published from ../shared/data/real relative to the repository root; the tests
skip when it is absent.

What is asserted, with the default method (cpw) and false-alarm probability (1 %):
every record Smith & Randall call Y with some method gets its fault; the healthy record
and the MFPT files are right; a P or N record gets its fault or "no fault detected",
never a wrong fault. Where we do not reproduce a Y, the case is a strict xfail with the
reason (docs/capabilities/diagnosis.md has the table).
"""

import math
from pathlib import Path

import pytest

from bearinglab.diagnosis import NO_FAULT, analyze_file
from bearinglab.diagnosis.benchmark import EXPECTED, _bearing, read_labels

REAL = Path(__file__).resolve().parents[3] / "shared" / "data" / "real"
pytestmark = pytest.mark.skipif(
    not (REAL / "labels.csv").is_file(), reason="shared/data/real is absent"
)

#: Y records (with some method) the default method does not diagnose: file -> reason.
NOT_REPRODUCED = {
    "cwru/12k_DE/197.mat": "outer 0.014 in at 6 o'clock, Y2 with M3 only: the cpw SES is "
    "flat (largest line z 3.9), outer race 10^-0.0 with cpw and "
    "drs-sk, 10^-0.3 with raw; our fast-kurtogram band does not "
    "find what Smith & Randall's Method 3 did",
}


def _rows():
    if not (REAL / "labels.csv").is_file():
        return []
    return read_labels(REAL)


def _case(row):
    category = row.get("smith_randall_2015") or ""
    marks = []
    if row["file"] in NOT_REPRODUCED:
        marks.append(pytest.mark.xfail(strict=True, reason=NOT_REPRODUCED[row["file"]]))
    return pytest.param(row, id=f"{row['file']} [{row['fault']} {category or '-'}]", marks=marks)


def _verdict(row, methods=None) -> str:
    fs = float(row["sample_rate_hz"])
    d = analyze_file(
        REAL / row["file"],
        _bearing(row),
        channel=row["channel"],
        sample_rate=fs,
        shaft_speed=float(row["speed_rpm"]) * math.pi / 30,
        methods=methods,
    )
    return d.verdict


def _clear(row) -> bool:
    return "Y" in (row.get("smith_randall_2015") or "")


@pytest.mark.parametrize(
    "row",
    [_case(r) for r in _rows() if _clear(r) or r["dataset"] == "MFPT" or r["fault"] == "normal"],
)
def test_clear_records_healthy_and_mfpt_are_diagnosed(row):
    assert _verdict(row) == EXPECTED[row["fault"]]


@pytest.mark.parametrize(
    "row", [_case(r) for r in _rows() if r.get("smith_randall_2015") and not _clear(r)]
)
def test_partial_or_undiagnosable_records_get_no_wrong_fault(row):
    assert _verdict(row) in (EXPECTED[row["fault"]], NO_FAULT)


def test_a_ball_series_lists_its_cage_rate_line_as_ftf():
    """CWRU 185 (ball 0.014 in, Smith & Randall P2 with Methods 1 and 2): the cage-rate
    line of its ball series is listed as "1x ftf" (the modulation's own line), never as a
    0th harmonic, and the reason counts it apart from the sidebands beside the strength
    of the harmonics."""
    from bearinglab.diagnosis import peak_label

    row = next((r for r in _rows() if r["file"] == "cwru/12k_DE/185.mat"), None)
    if row is None:
        pytest.skip("cwru/12k_DE/185.mat is not in shared/data/real")
    d = analyze_file(
        REAL / row["file"],
        _bearing(row),
        channel=row["channel"],
        sample_rate=float(row["sample_rate_hz"]),
        shaft_speed=float(row["speed_rpm"]) * math.pi / 30,
        methods="all",
    )
    labels = [peak_label(p) for p in d.peaks]
    assert d.verdict == "ball"
    assert "1x ftf" in labels and not any(label.startswith("0x") for label in labels)
    assert "k x FTF 1" in d.reason
    assert "its harmonics alone or with their first sidebands" in d.reason


def _has_channel(row, channel: str) -> bool:
    """Whether the labelled file holds ``channel``, as its variables say (some CWRU files
    have the drive end only - the 0.028 in. faults of the 3000 series - and the healthy
    97 has no base accelerometer): read from the file, so that a new file is tested
    with the channels it has."""
    import scipy.io

    names = (name for name, _, _ in scipy.io.whosmat(REAL / row["file"]))
    return any(name.endswith(f"_{channel}_time") for name in names)


@pytest.mark.parametrize(
    "row",
    [
        pytest.param(dict(r, channel=ch), id=f"{r['file']} {ch} [{r['fault']}]")
        for ch in ("FE", "BA")
        for r in _rows()
        if r["dataset"] == "CWRU" and _has_channel(r, ch)
    ],
)
def test_other_accelerometers_get_no_wrong_fault(row):
    """A check held out from the development of the method: the same drive-end faults
    seen by the fan-end and base accelerometers (other transfer paths, weaker and with
    other machine lines; nobody tuned the method on them). The default method may miss a
    fault there, but never names another one, and calls the healthy 97 healthy
    (measured 2026-11-24: right on 8 of 14 FE and 7 of 13 BA records, no wrong fault; the
    raw envelope calls the ball record 118 "inner race" on BA)."""
    assert _verdict(row) in (EXPECTED[row["fault"]], NO_FAULT)


def _samples(row, channel=None):
    """(samples, sample rate [Hz]) of a labelled record's channel, as published."""
    from bearinglab.signal import read_signal

    signal = read_signal(
        REAL / row["file"],
        sample_rate=float(row["sample_rate_hz"]),
        channel=channel or row["channel"],
    )
    return signal.channel(signal.names[0]), signal.sample_rate


def _kinematics(row, factor=1.0):
    from bearinglab.kinematics import defect_frequencies

    return defect_frequencies(_bearing(row), factor * float(row["speed_rpm"]) * math.pi / 30)


@pytest.mark.parametrize("channel", ["DE", "FE"])
def test_healthy_record_segments_and_speeds_get_no_fault(channel):
    """The healthy 97 cut into four 2.5 s segments, each analysed at the logged speed and
    at 1 and 2 % either side of it (a tachometer's error): 20 records per channel, every
    one "no fault detected" with the default method (measured 2026-11-24: 0 of 40 with
    cpw and with drs-sk; the raw envelope 0 of 40, and 2 of 40 "outer race" when the
    outer race's harmonic gate also counted its first sidebands, the change tried and
    not kept in docs/capabilities/diagnosis.md)."""
    from bearinglab.diagnosis import analyze_signal

    row = next((r for r in _rows() if r["fault"] == "normal"), None)
    if row is None:
        pytest.skip("no healthy record in shared/data/real")
    x, fs = _samples(row, channel)
    quarter = x.size // 4
    verdicts = [
        analyze_signal(x[q * quarter : (q + 1) * quarter], fs, _kinematics(row, f)).verdict
        for q in range(4)
        for f in (0.98, 0.99, 1.0, 1.01, 1.02)
    ]
    assert verdicts == [NO_FAULT] * 20


#: Halves of records where the default method names a wrong fault: (file, half) -> reason.
WRONG_ON_A_HALF: dict = {}


@pytest.mark.parametrize(
    "row, half",
    [
        pytest.param(
            r,
            h,
            id=f"{r['file']} half {h + 1} [{r['fault']}]",
            marks=[pytest.mark.xfail(strict=True, reason=WRONG_ON_A_HALF[r["file"], h])]
            if (r["file"], h) in WRONG_ON_A_HALF
            else [],
        )
        for r in _rows()
        for h in (0, 1)
    ],
)
def test_record_halves_get_no_wrong_fault(row, half):
    """Each labelled record cut in two halves (5 s of CWRU, 1.5 s of MFPT), each
    analysed alone with the default method: the fault, or "no fault detected", never a
    wrong fault - a check of how much a verdict rests on one stretch of noise (measured
    2026-11-24 over the halves and +-1 % speed of the records and of their FE and BA
    channels: 1 wrong fault in 270 verdicts with cpw, 9 with the raw envelope, 4 with
    drs-sk)."""
    from bearinglab.diagnosis import analyze_signal

    x, fs = _samples(row)
    part = x[: x.size // 2] if half == 0 else x[x.size // 2 :]
    verdict = analyze_signal(part, fs, _kinematics(row)).verdict
    assert verdict in (EXPECTED[row["fault"]], NO_FAULT)


#: Fan-end records where the default method names a fault of the healthy 6203: file ->
#: reason.
FAN_END_CALLED = {
    "cwru/12k_DE/131.mat": "outer 0.007 in at 6 o'clock, 1 hp: 'cage' at 10^-3.3 (level "
    "10^-2.6), seven FTF harmonics of z 1.9-2.8 at +2.06 % of the 6203's FTF (11.51 Hz): "
    "that is the drive-end 6205's cage rate (11.76 Hz, FTF 0.398 x shaft against the "
    "6203's 0.389 x, 2.2 % apart), whose lines an outer-race fault carries (a series of "
    "unequal balls repeats once per cage revolution). Two cages on one shaft turn within "
    "a few per cent of each other; the tail's reading (issue 27) sees the line the rank "
    "floored",
}


@pytest.mark.parametrize(
    "row",
    [
        pytest.param(
            r,
            id=f"{r['file']} FE [{r['fault']} at the drive end]",
            marks=[pytest.mark.xfail(strict=True, reason=FAN_END_CALLED[r["file"]])]
            if r["file"] in FAN_END_CALLED
            else [],
        )
        for r in _rows()
        if r["dataset"] == "CWRU" and _has_channel(r, "FE")
    ],
)
def test_the_healthy_fan_end_bearing_gets_no_fault(row):
    """A null test on real records: the fan-end accelerometer read for the fan-end bearing,
    a 6203-2RS that is healthy in every drive-end fault record (the faults were seeded in
    the drive-end bearing only). Its BPFO is 3.053 x shaft, which puts sidebands of
    neighbouring harmonics in one bin: before each line was read once, the outer race
    passed its threshold on 130, 234, 144 and 246 and only the harmonic gate stopped it.
    Measured 2026-11-24: "no fault detected" on all 14 with cpw and raw; drs-sk (and all
    three) call 118 "inner race" (10^-4.2)."""
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis import analyze_signal
    from bearinglab.kinematics import defect_frequencies

    x, fs = _samples(row, "FE")
    fan_end = bearing_from_designation("6203-2RS")[0]
    kin = defect_frequencies(fan_end, float(row["speed_rpm"]) * math.pi / 30)
    assert analyze_signal(x, fs, kin).verdict == NO_FAULT


@pytest.mark.parametrize(
    "file, declared, way",
    [
        ("cwru/normal_48k/97.mat", 12000.0, "4 times too low"),
        ("cwru/12k_DE/130.mat", 48000.0, "4 times too high"),
        ("cwru/12k_DE/130.mat", 3000.0, "4 times too low"),
    ],
)
def test_a_sample_rate_given_4_times_wrong_names_no_fault_and_says_which_way(file, declared, way):
    """A record read at 4 times or a quarter of its sample rate: every line of the record
    reads 4 times too high or too low, so the shaft series near the speed is missing (a
    series stands at 4 x it) or is the 4th harmonic of the real shaft (a series stands at
    1/4 of it). No fault is named at a speed the signal contradicts, and the warning says
    which way the rate is off (before issue 21 the 12 kHz 130 read at 48 kHz got "no
    fault detected" with only "no shaft line found", and the warning for 97 read at 12
    kHz said a rate too low reads frequencies too high)."""
    row = next((r for r in _rows() if r["file"] == file), None)
    if row is None:
        pytest.skip(f"{file} is not in shared/data/real")
    d = analyze_file(REAL / file, _bearing(row), channel=row["channel"], sample_rate=declared)
    assert d.verdict == NO_FAULT and d.speed["confirmed"] is False
    assert any(f"sample rate given may be {way}" in w for w in d.warnings)


# ------------------------------------------------------------------ the optional ies method
#: With ``ies`` (improved envelope spectrum, docs/capabilities/diagnosis.md "A fourth
#: method"): the Y records it does not diagnose, and the records it names a wrong fault
#: on, file -> reason (measured 2026-11-26).
IES_EXPECTED_FAILURES = {
    "cwru/12k_DE/223.mat": "ball 0.021 in, M1/M2 Y2: ball 10^-3.9 over the level 10^-2.6 "
    "and its harmonics 10^-4.2, but without its strongest line (2 BSF) 10^-1.9 (the "
    "support gate is 10^-2); cpw diagnoses it",
    "cwru/12k_DE/197.mat": "outer 0.014 in at 6 o'clock, Y2 with M3 only: no outer-race "
    "series in the improved envelope spectrum either (10^-0.0; best family cage 10^-1.3)",
    "cwru/12k_DE/118.mat": "ball 0.007 in, N with every method: 'outer race' at 10^-9.4, "
    "BPFO harmonics each among the spectrum's largest readings; the raw envelope and "
    "drs-sk call it 'outer race' too: the record carries a BPFO series",
    "cwru/12k_DE/119.mat": "ball 0.007 in at 1 hp, N: 'outer race' at 10^-6.6, as 118; the "
    "raw envelope calls it 'outer race' too",
}


def _ies_case(row):
    marks = []
    if row["file"] in IES_EXPECTED_FAILURES:
        marks.append(pytest.mark.xfail(strict=True, reason=IES_EXPECTED_FAILURES[row["file"]]))
    category = row.get("smith_randall_2015") or "-"
    return pytest.param(row, id=f"{row['file']} [{row['fault']} {category}]", marks=marks)


@pytest.mark.parametrize(
    "row",
    [
        _ies_case(r)
        for r in _rows()
        if _clear(r) or r["dataset"] == "MFPT" or r["fault"] == "normal"
    ],
)
def test_ies_clear_records_healthy_and_mfpt_are_diagnosed(row):
    """ies diagnoses 20 of the 23 Y records (cpw 19: ies adds 247, outer race at
    3 o'clock, whose harmonics alone reach 10^-8.6 by ies and 10^-1.8 by cpw), the
    healthy record and both MFPT files."""
    assert _verdict(row, "ies") == EXPECTED[row["fault"]]


@pytest.mark.parametrize(
    "row", [_ies_case(r) for r in _rows() if r.get("smith_randall_2015") and not _clear(r)]
)
def test_ies_partial_or_undiagnosable_records_get_no_wrong_fault(row):
    assert _verdict(row, "ies") in (EXPECTED[row["fault"]], NO_FAULT)


@pytest.mark.slow
@pytest.mark.parametrize(
    "row",
    [
        pytest.param(dict(r, channel=ch), id=f"{r['file']} {ch} [{r['fault']}]")
        for ch in ("FE", "BA")
        for r in _rows()
        if r["dataset"] == "CWRU" and _has_channel(r, ch)
    ],
)
def test_ies_other_accelerometers_get_no_wrong_fault(row):
    """The held-out fan-end and base channels read with ies (measured 2026-11-26: right
    on 21 of 27 FE and 20 of 26 BA records, cpw 13 and 13; no wrong fault)."""
    assert _verdict(row, "ies") in (EXPECTED[row["fault"]], NO_FAULT)


@pytest.mark.slow
@pytest.mark.parametrize("channel", ["DE", "FE"])
def test_ies_healthy_record_segments_and_speeds_get_no_fault(channel):
    """The healthy 97 in four 2.5 s segments at the logged speed and 1 and 2 % either
    side, read with ies: "no fault detected" in all 20 per channel (2026-11-26); with the
    tail's reading (2026-11-29) the fan end's third segment at the logged speed reads
    "outer race" at 10^-2.63 (level 10^-2.60): at most one of 20, ies being no verdict at
    a stated false-alarm probability (docs/capabilities/diagnosis.md)."""
    from bearinglab.diagnosis import analyze_signal

    row = next((r for r in _rows() if r["fault"] == "normal"), None)
    if row is None:
        pytest.skip("no healthy record in shared/data/real")
    x, fs = _samples(row, channel)
    quarter = x.size // 4
    verdicts = [
        analyze_signal(
            x[q * quarter : (q + 1) * quarter], fs, _kinematics(row, f), methods="ies"
        ).verdict
        for q in range(4)
        for f in (0.98, 0.99, 1.0, 1.01, 1.02)
    ]
    assert sum(v != NO_FAULT for v in verdicts) <= 1


@pytest.mark.slow
@pytest.mark.parametrize(
    "row",
    [
        pytest.param(r, id=f"{r['file']} FE [{r['fault']} at the drive end]")
        for r in _rows()
        if r["dataset"] == "CWRU" and _has_channel(r, "FE")
    ],
)
def test_ies_the_healthy_fan_end_bearing_gets_no_fault(row):
    """The fan-end channel read for the healthy fan-end 6203-2RS with ies: "no fault
    detected" on all 27 (2026-11-26)."""
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.diagnosis import analyze_signal
    from bearinglab.kinematics import defect_frequencies

    x, fs = _samples(row, "FE")
    fan_end = bearing_from_designation("6203-2RS")[0]
    kin = defect_frequencies(fan_end, float(row["speed_rpm"]) * math.pi / 30)
    assert analyze_signal(x, fs, kin, methods="ies").verdict == NO_FAULT
