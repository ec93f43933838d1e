"""The result of a trend: :class:`TrendResult` (with :class:`Alarm` and
:class:`BlockDiagnosis`), its JSON-ready dict, table, figure and HTML page."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from datetime import UTC, datetime

import numpy as np

from .blocks import BlockDiagnosis
from .indicators import INDICATORS

#: What the test statistic of each indicator is, in words.
STATISTIC_TEXT = "log of the indicator (log(SK + 2) for the spectral kurtosis)"
#: The tail model, in words.
TAIL_TEXT = (
    "exponential upper tail above the baseline median, its scale the mean excess of the "
    "upper half (estimation accounted for)"
)
#: Clocks larger than this are read as seconds since 1970 (an ISO 8601 date-time given).
EPOCH_CLOCK = 1e8


@dataclass(frozen=True)
class Alarm:
    """The alarm: the ``record`` (index in time order) that completed the first run of
    exceedances, the ``indicator`` and ``channel`` whose test raised it, and its ``value``
    there (in the indicator's unit)."""

    record: int
    indicator: str
    channel: str
    value: float


def _indicator_value(name: str, statistic: float) -> float:
    """An indicator's value from its test statistic (the inverse of STATISTICS)."""
    return math.exp(statistic) - (2.0 if name == "spectral_kurtosis" else 0.0)


@dataclass(frozen=True, eq=False)
class TrendResult:
    """The trend of a machine over a series of records (time order).

    ``files``, ``times`` [s from the first record], ``values`` (indicator -> records x
    channels, in the channels' unit for rms and peak), ``velocity`` (records x channels
    [m/s], or None), ``zones`` (the machine's ISO boundaries, or None); the baseline is
    records ``settle_records`` to ``baseline_stop`` - 1; the rule's false-alarm rate per
    hour (``false_alarm_per_hour``) and the level per record it gives at the records'
    spacing (``false_alarm``); ``tests`` (indicator, channel index), their ``limits``
    (:class:`~.alarm.TailLimit`, statistic units) and ``first_alarms`` (record or None);
    ``alarm``; ``diagnosis`` (:class:`BlockDiagnosis` or None); ``warnings``.
    """

    folder: str
    layout: str
    channels: tuple
    sample_rate: float
    record_samples: int
    unit: str | None
    start: float
    files: tuple
    times: np.ndarray
    values: dict
    velocity: np.ndarray | None
    zones: object | None
    settle_records: int
    baseline_stop: int
    false_alarm_per_hour: float
    false_alarm: float
    persistence: int
    record_spacing: float
    tests: tuple
    limits: tuple
    first_alarms: tuple
    alarm: Alarm | None
    diagnosis: BlockDiagnosis | None = None
    warnings: tuple = field(default=())

    # ------------------------------------------------------------------ derived
    @property
    def baseline_records(self) -> int:
        """Records in the baseline."""
        return self.baseline_stop - self.settle_records

    @property
    def monitored_records(self) -> int:
        """Records after the baseline, tested against it."""
        return len(self.files) - self.baseline_stop

    @property
    def test_level(self) -> float:
        """Level of each test: the false-alarm probability over the tests (Bonferroni)."""
        return self.false_alarm / len(self.tests)

    @property
    def false_alarm_per_run(self) -> float:
        """Bound on the chance of a false alarm over the monitored records [-]."""
        windows = max(self.monitored_records - self.persistence + 1, 0)
        return min(1.0, windows * self.false_alarm)

    def limit(self, j: int) -> float:
        """Test ``j``'s limit in the indicator's unit."""
        return _indicator_value(self.tests[j][0], self.limits[j].limit)

    def above(self) -> np.ndarray:
        """records x tests: True where a monitored record is above the test's limit."""
        out = np.zeros((len(self.files), len(self.tests)), dtype=bool)
        for j, (name, c) in enumerate(self.tests):
            out[:, j] = self.values[name][:, c] > self.limit(j)
        out[: self.baseline_stop] = False
        return out

    def runs(self) -> np.ndarray:
        """records x tests: True where a run of ``persistence`` monitored records above the
        test's limit ends (each such record is a window where the rule fires; the first
        one, over all tests, is the alarm)."""
        above = self.above().astype(int)
        r = self.persistence
        out = np.zeros_like(above, dtype=bool)
        if above.shape[0] >= r:
            kernel = np.ones(r, dtype=int)
            for j in range(above.shape[1]):
                out[r - 1 :, j] = np.convolve(above[:, j], kernel, mode="valid") >= r
        return out

    @property
    def velocity_zones(self) -> np.ndarray | None:
        """records x channels: the ISO zone of each velocity (None without a machine)."""
        if self.zones is None or self.velocity is None:
            return None
        from .severity import zones_of

        return zones_of(self.velocity, self.zones)

    def start_time(self) -> str | None:
        """The first record's time as the files give it: the time of day (PRONOSTIA), a
        UTC date and time (an ISO 8601 index or metadata), or None (seconds only)."""
        if self.layout == "pronostia":
            from .series import time_of_day

            return time_of_day(self.start)
        if self.start > EPOCH_CLOCK:
            return datetime.fromtimestamp(self.start, UTC).isoformat()
        return None

    def test_name(self, j: int) -> str:
        """The name of test ``j`` (an index of ``tests``): "indicator:channel"."""
        name, c = self.tests[j]
        return f"{name}:{self.channels[c]}"

    def rule_text(self) -> str:
        """The rule in one paragraph, with its nominal false-alarm probabilities."""
        n = self.baseline_records
        return (
            f"Baseline: records {self.settle_records} to {self.baseline_stop - 1} "
            f"({n} records, {self.times[self.settle_records]:.6g} s to "
            f"{self.times[self.baseline_stop - 1]:.6g} s). Each of {len(self.tests)} tests "
            f"({len(INDICATORS)} indicators x {len(self.channels)} channels) compares the "
            f"{STATISTIC_TEXT} with a limit from the baseline ({TAIL_TEXT}); it alarms when "
            f"{self.persistence} consecutive records exceed it ({self.persistence} x "
            f"{self.record_spacing:.3g} s, the cadence), at a level of "
            f"{self.test_level:.3g} per record (Bonferroni). The alarm is raised by the first "
            f"test to alarm and stays raised. False-alarm probability: at most "
            f"{self.false_alarm_per_hour:.3g} per hour of monitoring, so "
            f"{self.false_alarm:.3g} per record at a record every {self.record_spacing:.3g} s, "
            f"and at most {self.false_alarm_per_run:.3g} over the {self.monitored_records} "
            f"records monitored (independent records, exponential tail; measured rates: "
            f"docs/capabilities/trend.md)."
        )

    # ------------------------------------------------------------------ outputs
    def _record(self, i: int, above: np.ndarray, zones) -> dict:
        per = {}
        for c, ch in enumerate(self.channels):
            d = {name: float(self.values[name][i, c]) for name in INDICATORS}
            if self.velocity is not None:
                d["velocity_rms_mm_s"] = float(self.velocity[i, c]) * 1e3
                d["zone"] = None if zones is None else str(zones[i, c])
            per[ch] = d
        diag = self.diagnosis
        return {
            "time_s": float(self.times[i]),
            "file": self.files[i],
            "indicators": per,
            "above_limit": [self.test_name(j) for j in np.flatnonzero(above[i])],
            "verdict": None if diag is None else diag.verdicts[i],
            "significance": None if diag is None else diag.significance[i],
        }

    def to_dict(self) -> dict:
        """JSON-ready: the records with their indicators, the baseline, the rule, each
        test's limit, the alarm, the diagnosis and the severity (docs/json.md)."""
        above = self.above()
        zones = self.velocity_zones
        tests = []
        for j, (name, c) in enumerate(self.tests):
            a = self.first_alarms[j]
            tests.append(
                {
                    "indicator": name,
                    "channel": self.channels[c],
                    "baseline_median": _indicator_value(name, self.limits[j].median),
                    "limit": self.limit(j),
                    "first_alarm_record": a,
                    "first_alarm_s": None if a is None else float(self.times[a]),
                }
            )
        alarm = None
        if self.alarm is not None:
            a = self.alarm
            j = self.tests.index((a.indicator, self.channels.index(a.channel)))
            alarm = {
                "time_s": float(self.times[a.record]),
                "record": a.record,
                "file": self.files[a.record],
                "indicator": a.indicator,
                "channel": a.channel,
                "value": a.value,
                "limit": self.limit(j),
                "time_to_last_record_s": float(self.times[-1] - self.times[a.record]),
                "verdict": None,
                "significance": None,
            }
            if self.diagnosis is not None and self.diagnosis.alarm is not None:
                alarm["verdict"] = self.diagnosis.alarm["verdict"]
                alarm["significance"] = self.diagnosis.alarm["significance"]
        diagnosis = None
        if self.diagnosis is not None:
            d = self.diagnosis
            diagnosis = {
                "channel": d.channel,
                "block_records": d.block_records,
                "blocks": len(d.blocks),
                "threshold": d.threshold,
                "kinematic": {
                    f"{k}_hz": d.frequencies.hz(k)
                    for k in ("shaft", "ftf", "bpfo", "bpfi", "ball_defect")
                },
                "after_alarm": None if self.alarm is None else d.after(self.alarm.record),
            }
        severity = None
        if self.zones is not None and zones is not None:
            first = {}
            for z in ("B", "C", "D"):
                hit = np.flatnonzero(np.any(zones >= z, axis=1))
                first[z] = None if hit.size == 0 else float(self.times[hit[0]])
            severity = {**self.zones.to_dict(), "first_zone_s": first}
        n = len(self.files)
        return {
            "folder": self.folder,
            "layout": self.layout,
            "channels": list(self.channels),
            "channel_unit": self.unit,
            "sample_rate_hz": self.sample_rate,
            "points": self.record_samples,
            "start_time": self.start_time(),
            "duration_s": float(self.times[-1]),
            "record_spacing_s": self.record_spacing,
            "records": [self._record(i, above, zones) for i in range(n)],
            "baseline_records": self.baseline_records,
            "baseline": {
                "settle_records": self.settle_records,
                "start_s": float(self.times[self.settle_records]),
                "end_s": float(self.times[self.baseline_stop - 1]),
            },
            "rule": {
                "statistic": STATISTIC_TEXT,
                "tail_model": TAIL_TEXT,
                "persistence": self.persistence,
                "tests": len(self.tests),
                "test_level": self.test_level,
                "false_alarm_per_hour": self.false_alarm_per_hour,
                "false_alarm_per_record": self.false_alarm,
                "monitored_records": self.monitored_records,
                "false_alarm_per_run": self.false_alarm_per_run,
                "description": self.rule_text(),
            },
            "tests": tests,
            "alarm": alarm,
            "diagnosis": diagnosis,
            "severity": severity,
            "warnings": list(self.warnings)
            + list(self.diagnosis.warnings if self.diagnosis else ()),
        }

    def to_pandas(self):
        """One row per record: time_s, file, each indicator per channel
        (``rms_horizontal`` ...), the velocity and zone, the verdict, and flags for the
        baseline and for being above a limit."""
        import pandas as pd

        data = {"time_s": self.times, "file": list(self.files)}
        for name in INDICATORS:
            for c, ch in enumerate(self.channels):
                data[f"{name}_{ch}"] = self.values[name][:, c]
        zones = self.velocity_zones
        if self.velocity is not None:
            for c, ch in enumerate(self.channels):
                data[f"velocity_rms_mm_s_{ch}"] = self.velocity[:, c] * 1e3
                if zones is not None:
                    data[f"zone_{ch}"] = zones[:, c]
        if self.diagnosis is not None:
            data["verdict"] = list(self.diagnosis.verdicts)
        idx = np.arange(len(self.files))
        data["baseline"] = (idx >= self.settle_records) & (idx < self.baseline_stop)
        data["above_limit"] = self.above().any(axis=1)
        return pd.DataFrame(data)

    # ------------------------------------------------------------------ figure
    def plot(self, ax=None):
        """The indicators over time, the baseline, the limits and the alarm
        (:func:`.figure.trend_figure`), on ``ax`` (six matplotlib Axes; a new figure by
        default); returns (figure, axes)."""
        from .figure import trend_figure

        return trend_figure(self, ax)
