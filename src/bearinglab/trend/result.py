"""The result of a trend: :class:`TrendResult` (with :class:`Alarm` and
:class:`BlockDiagnosis`), its JSON-ready dict, table, figure and HTML page."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from datetime import UTC, datetime

import numpy as np

from .alarm import Alarm
from .blocks import BlockDiagnosis
from .indicators import INDICATORS
from .rule import MAX_SHORT_CROSSINGS

#: What the test statistic of each indicator is, in words.
STATISTIC_TEXT = (
    "log of the indicator (log(SK + 2) for the spectral kurtosis); a test's level is its "
    "median over the persistence window, compared with the baseline median in robust "
    "scales of the baseline (1.4826 median absolute deviations)"
)
#: The tail model, in words.
TAIL_TEXT = (
    "limits from the rate at which healthy operation carries a level above them: excursions "
    "above the baseline counted once each, their maxima's excess exponential (estimation "
    "accounted for), learned on real runs (calibration.source)"
)
#: Where the rule is documented in an installed package (its module's docstring).
DOCUMENTATION = (
    "python -m pydoc bearinglab.trend.alarm (the rule), bearinglab.trend.calibration (its "
    "limits) and bearinglab.trend.life (the remaining life); measured rates: "
    "docs/capabilities/trend.md of the source"
)
#: Clocks larger than this are read as seconds since 1970 (an ISO 8601 date-time given).
EPOCH_CLOCK = 1e8


def duration_text(seconds: float | None) -> str:
    """A duration for people: seconds, with hours beside from an hour on ("-" for None).

    >>> duration_text(7200.0)
    '7200 s (2 h)'
    """
    if seconds is None:
        return "-"
    return f"{seconds:.6g} s" + (f" ({seconds / 3600:.3g} h)" if seconds >= 3600 else "")


def measured_text(m: dict) -> str:
    """The false-alarm rate measured (``to_dict()["measured_false_alarm"]``) in words."""
    if m["per_hour"] is None:
        return m["measured_on"]
    upper = "" if m["upper_per_hour"] is None else f" (< {m['upper_per_hour']:.3g} at 95 %)"
    return (
        f"{m['firings']} in {m['monitored_hours']:.3g} h: {m['per_hour']:.3g} per hour{upper}, "
        f"{m['per_record']:.3g} per record, on {m['measured_on']}"
    )


def life_text(life: dict) -> str:
    """The remaining-life estimate (``to_dict()["remaining_life"]``) in words, to three
    figures (an estimate whose interval spans a decade has no more).

    Parameters
    ----------
    life : dict
        ``to_dict()["remaining_life"]``.

    Examples
    --------
    >>> life_text({"estimate_s": 1656.97, "low_s": 237.18, "high_s": 9963.4,
    ...            "at_time_s": 28020.0, "basis": "degradation", "method": "similarity"})
    '1660 s (80 %: 237 s to 9960 s (2.77 h)) at 28020 s (7.78 h), from degradation (similarity)'
    """
    est, low, high = (float(f"{life[k]:.3g}") for k in ("estimate_s", "low_s", "high_s"))
    return (
        f"{duration_text(est)} (80 %: {duration_text(low)} to "
        f"{duration_text(high)}) at {duration_text(life['at_time_s'])}, from "
        f"{life['basis']} ({life['method']})"
    )


def _indicator_value(name: str, statistic: float) -> float:
    """An indicator's value from its test statistic (the inverse of STATISTICS)."""
    return math.exp(statistic) - (2.0 if name == "spectral_kurtosis" else 0.0)


@dataclass(frozen=True, eq=False)
class TrendResult:
    """The trend of a machine over a series of records (time order).

    ``files``, ``times`` [s from the first record], ``values`` (indicator -> records x
    channels, over the band 0 to ``max_frequency`` [Hz], in the channels' unit for rms
    and peak), ``velocity`` (records x channels [m/s], or None), ``zones`` (the machine's
    ISO boundaries, or None); the baseline is records ``settle_records`` to
    ``baseline_stop`` - 1; the rule's false-alarm rate per hour (``false_alarm_per_hour``)
    and the level per record it gives at the records' spacing (``false_alarm``); the
    ``persistence`` window (records); ``tests`` (indicator, channel index), their
    ``limits`` (:class:`~.alarm.Reference`, statistic units) and ``first_alarms`` (the
    record where each test's level first crossed its limit, or None); ``alarm``;
    ``short_crossings`` ((first record, last record, test), before the alarm);
    ``learned`` (:class:`~.learning.LearnedRuns`: the calibration and lives used);
    ``measured`` (the rule's firings on held-out healthy stretches of this series, or
    None); ``diagnosis`` (:class:`BlockDiagnosis` or None); ``remaining_life``
    (:class:`~.life.RemainingLife` or None); ``warnings``.
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
    max_frequency: float = math.inf
    short_crossings: tuple = ()
    learned: object | None = None
    measured: dict | None = None
    diagnosis: BlockDiagnosis | None = None
    remaining_life: object | None = None
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
        return min(1.0, self.monitored_records * self.false_alarm)

    @property
    def persistence_seconds(self) -> float:
        """The persistence window's span at the records' spacing [s]."""
        return self.persistence * self.record_spacing

    @property
    def limit_excess(self) -> float:
        """How far above the baseline median a level may go, in robust scales."""
        return self.limits[0].excess if self.limits else math.inf

    def limit(self, j: int) -> float:
        """Test ``j``'s limit in the indicator's unit.

        Parameters
        ----------
        j : int
            The test's index in ``tests``.
        """
        return _indicator_value(self.tests[j][0], self.limits[j].limit)

    def above(self) -> np.ndarray:
        """records x tests: True where a monitored record is above the test's limit."""
        out = np.zeros((len(self.files), len(self.tests)), dtype=bool)
        for j, (name, c) in enumerate(self.tests):
            out[:, j] = self.values[name][:, c] > self.limit(j)
        out[: self.baseline_stop] = False
        return out

    def deviations(self) -> np.ndarray:
        """records x tests: each test's level (the median over the persistence window)
        above the baseline median, in robust scales (NaN where the window reaches into the
        baseline)."""
        from .alarm import deviations
        from .rule import statistics

        base = slice(self.settle_records, self.baseline_stop)
        return deviations(statistics(self.values, self.tests), base, self.persistence)[1]

    def runs(self) -> np.ndarray:
        """records x tests: True where the test's level is above its limit (the first such
        record, over all tests, is the alarm; each run of them is a firing)."""
        return np.nan_to_num(self.deviations(), nan=-np.inf) > self.limit_excess

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
        """The name of test ``j`` (an index of ``tests``): "indicator:channel".

        Parameters
        ----------
        j : int
            The test's index in ``tests``.
        """
        name, c = self.tests[j]
        return f"{name}:{self.channels[c]}"

    def rule_text(self) -> str:
        """The rule in one paragraph, with its false-alarm rates: stated and measured."""
        n = self.baseline_records
        cal = None if self.learned is None else self.learned.calibration
        measured = self.measured_false_alarm()
        return (
            f"Baseline: records {self.settle_records} to {self.baseline_stop - 1} "
            f"({n} records, {self.times[self.settle_records]:.6g} s to "
            f"{self.times[self.baseline_stop - 1]:.6g} s). Each of {len(self.tests)} tests "
            f"({len(INDICATORS)} indicators over 0-{self.max_frequency:.6g} Hz x "
            f"{len(self.channels)} channels) takes the log of its indicator (log(SK + 2) for "
            f"the spectral kurtosis); its level is the median of the last {self.persistence} "
            f"records ({self.persistence_seconds:.3g} s at the cadence of "
            f"{self.record_spacing:.3g} s), and the alarm is raised when "
            f"some test's level exceeds the baseline median by {self.limit_excess:.3g} robust "
            "scales (1.4826 median absolute deviations of the baseline), and stays raised. "
            "That limit is where healthy operation carries a level "
            f"at {self.false_alarm_per_hour / len(self.tests):.3g} per hour and test "
            f"(Bonferroni over the tests: {self.false_alarm_per_hour:.3g} false alarms per "
            f"hour of monitoring, {self.false_alarm:.3g} per record)"
            + ("" if cal is None else f", learned on {cal.source}")
            + f". Measured: {measured['text']}."
        )

    def measured_false_alarm(self) -> dict:
        """The rule's false alarms measured on held-out healthy stretches of this series
        when it holds enough of them, else the figure measured on the learning runs:
        ``per_record``, ``per_hour``, ``upper_per_hour`` (95 %), ``firings``,
        ``monitored_hours``, ``measured_on`` and a sentence (``text``)."""
        from .rule import UPPER_95

        own = self.measured
        if own is not None:
            fired, hours = own["firings"], own["hours"]
            spacing = self.record_spacing
            on = (
                f"this series: {own['baselines']} baseline(s) of {self.baseline_records} "
                f"records slid over its first {own['end']:.6g} s"
                + ("" if self.alarm is None else " (up to an hour before the alarm)")
                + ", each followed by the rest of that stretch"
            )
        else:
            learned = {} if self.learned is None else self.learned.measured
            if not learned:
                return {
                    "per_record": None,
                    "per_hour": None,
                    "upper_per_hour": None,
                    "firings": None,
                    "monitored_hours": None,
                    "measured_on": "nothing: too short a healthy stretch and no learning runs",
                    "text": "not measured",
                }
            fired, hours = learned["firings"], learned["hours"]
            spacing = learned["record_spacing_s"]
            on = (
                "the learning runs, not this series (it holds less than an hour of healthy "
                f"monitoring): {learned['measured_on']}"
            )
        per_hour = fired / hours
        upper = max(fired, UPPER_95) / hours if fired == 0 else None
        text = (
            f"{fired} firing(s) in {hours:.3g} h of monitoring on {on}: {per_hour:.3g} per hour"
            + ("" if upper is None else f" (at most {upper:.3g} per hour at 95 %)")
        )
        return {
            "per_record": per_hour * spacing / 3600.0,
            "per_hour": per_hour,
            "upper_per_hour": upper,
            "firings": fired,
            "monitored_hours": hours,
            "measured_on": on,
            "text": text,
        }

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
                "running_in_records": self.settle_records,
                "start_s": float(self.times[self.settle_records]),
                "end_s": float(self.times[self.baseline_stop - 1]),
            },
            "rule": self._rule_dict(),
            "tests": tests,
            "alarm": alarm,
            "short_crossings": [
                {
                    "time_s": float(self.times[a]),
                    "end_s": float(self.times[b]),
                    "indicator": self.tests[j][0],
                    "channel": self.channels[self.tests[j][1]],
                }
                for a, b, j in self.short_crossings[:MAX_SHORT_CROSSINGS]
            ],
            "remaining_life": None
            if self.remaining_life is None
            else self.remaining_life.to_dict(),
            "diagnosis": diagnosis,
            "severity": severity,
            "warnings": list(self.warnings)
            + list(self.diagnosis.warnings if self.diagnosis else ()),
        }

    def _rule_dict(self) -> dict:
        measured = self.measured_false_alarm()
        cal = None if self.learned is None else self.learned.calibration
        return {
            "statistic": STATISTIC_TEXT,
            "tail_model": TAIL_TEXT,
            "band_hz": [0.0, self.max_frequency],
            "persistence": self.persistence,
            "persistence_s": self.persistence_seconds,
            "tests": len(self.tests),
            "test_level": self.test_level,
            "limit_excess": self.limit_excess,
            "false_alarm_per_hour": self.false_alarm_per_hour,
            "false_alarm_per_record": self.false_alarm,
            "monitored_records": self.monitored_records,
            "false_alarm_per_run": self.false_alarm_per_run,
            "measured_false_alarm": {k: v for k, v in measured.items() if k != "text"},
            "calibration": None
            if cal is None
            else {
                "source": cal.source,
                "excursion_threshold": cal.threshold,
                "excursions": cal.excursions,
                "mean_excess": cal.mean_excess,
                "excursion_rate_per_hour": cal.rate,
                "test_hours": cal.test_hours,
            },
            "documentation": DOCUMENTATION,
            "description": self.rule_text(),
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
        (:func:`.figure.trend_figure`), on ``ax`` (one matplotlib Axes per panel; a new
        figure by default); returns (figure, axes).

        Parameters
        ----------
        ax : sequence of matplotlib Axes or None
            One Axes per panel (one per indicator, and the velocity and the fault families
            when computed); None: a new figure.
        """
        from .figure import trend_figure

        return trend_figure(self, ax)

    def plot_life(self, ax=None):
        """The remaining life estimated over the series with its 80 % interval
        (:func:`.figure.life_figure`), on ``ax`` (a new figure by default); returns (figure,
        axes). InputError without an estimate.

        Parameters
        ----------
        ax : matplotlib Axes or None
            Where to draw; None: a new figure.
        """
        from ..errors import InputError
        from .figure import life_figure

        if self.remaining_life is None:
            raise InputError("remaining_life", None, "a trend with a remaining-life estimate")
        return life_figure(self, ax)
