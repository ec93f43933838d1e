"""What a trend learns from runs to failure: the excursion rates of healthy operation that
set the alarm's limits (:mod:`.calibration`), the rule's false alarms measured on those
runs, and the lives and degradation that the remaining-life estimate uses (:mod:`.life`).

The defaults are learned from the six learning runs of the PHM 2012 challenge
([data-PRONOSTIA]; every k-th snapshot, as kept in ../shared/data/run-to-failure) by
``benchmarks/trend_learn.py`` and shipped as package data (``data/learned_runs.json``):
learning on them is the challenge's protocol, and the method is judged leave-one-run-out
and on runs that are not here. :func:`learn_runs` learns the same from a user's own folder
of runs to failure (one sub-folder per run, each recorded from new until it failed: its
last record is taken as the failure).

A run's *healthy stretch* is its first half (:data:`HEALTHY_FRACTION`) after the baseline:
the issue that set the rule's goals counts an alarm there as a false one.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from ..errors import InputError
from .calibration import Calibration, fit_calibration

#: Share of a run's life counted as healthy operation when learning.
HEALTHY_FRACTION = 0.5
#: The packaged file of what was learned from the six PRONOSTIA learning runs.
PACKAGED = "learned_runs.json"


@dataclass(frozen=True)
class LearnedRuns:
    """What was learned from runs to failure: the ``calibration`` of the alarm's limits,
    the ``runs`` (one dict each: ``run``, ``life_s``, ``alarm_s``, ... and the degradation
    the remaining life uses), the rule's false alarms ``measured`` on them (firings,
    hours, how), the ``settings`` they were learned with and their ``source`` in words."""

    calibration: Calibration
    runs: tuple = field(default=())
    measured: dict = field(default_factory=dict)
    settings: dict = field(default_factory=dict)
    source: str = ""
    life: dict = field(default_factory=dict)

    def to_dict(self) -> dict:
        return {
            "source": self.source,
            "settings": self.settings,
            "calibration": self.calibration.to_dict(),
            "measured_false_alarm": self.measured,
            "runs": list(self.runs),
            "life": self.life,
        }

    @classmethod
    def from_dict(cls, d: dict) -> LearnedRuns:
        """The inverse of :meth:`to_dict`.

        Parameters
        ----------
        d : dict
            What :meth:`to_dict` gave (as read from JSON).
        """
        return cls(
            Calibration.from_dict(d["calibration"]),
            tuple(d.get("runs", ())),
            dict(d.get("measured_false_alarm", {})),
            dict(d.get("settings", {})),
            str(d.get("source", "")),
            dict(d.get("life", {})),
        )

    def write(self, path) -> Path:
        """Write as JSON to ``path`` (atomically).

        Parameters
        ----------
        path : str or Path
            The JSON file to write; its directory must exist.

        Returns
        -------
        Path
            The file written.
        """
        from ..files import write_text_atomically

        text = json.dumps(self.to_dict(), indent=1, allow_nan=False) + "\n"
        return write_text_atomically(path, text)


def read_learned(path) -> LearnedRuns:
    """A :class:`LearnedRuns` written by :meth:`LearnedRuns.write` (InputError naming the
    file when it is not one)."""
    p = Path(path)
    try:
        return LearnedRuns.from_dict(json.loads(p.read_text(encoding="utf-8")))
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise InputError(
            "learn_from",
            str(path),
            "a folder of runs to failure, or a file written by learn_runs(...).write()",
            hint=f"{type(exc).__name__}: {exc}",
        ) from None


_DEFAULT: list[LearnedRuns] = []


def packaged_learned() -> LearnedRuns:
    """What the package learned from the six PRONOSTIA learning runs (read once)."""
    if not _DEFAULT:
        from importlib.resources import files

        text = (files("bearinglab.trend") / "data" / PACKAGED).read_text(encoding="utf-8")
        _DEFAULT.append(LearnedRuns.from_dict(json.loads(text)))
    return _DEFAULT[0]


def learned_from(source) -> LearnedRuns:
    """``source`` as :class:`LearnedRuns`: None (the packaged defaults), a LearnedRuns, a
    file written by :meth:`LearnedRuns.write`, or a folder of runs (:func:`learn_runs`)."""
    if source is None:
        return packaged_learned()
    if isinstance(source, LearnedRuns):
        return source
    path = Path(source)
    if path.is_dir():
        return learn_runs(path)
    if path.is_file():
        return read_learned(path)
    raise InputError(
        "learn_from", str(source), "a folder of runs to failure or a learned file (.json)"
    )


def run_folders(folder) -> list[Path]:
    """The sub-folders of ``folder`` that hold recordings, in name order."""
    from .series import list_records

    path = Path(folder)
    if not path.is_dir():
        raise InputError("learn_from", str(folder), "a folder of runs to failure")
    out = []
    for sub in sorted(p for p in path.iterdir() if p.is_dir()):
        try:
            list_records(sub)
        except InputError:
            continue
        out.append(sub)
    if len(out) < 2:
        raise InputError(
            "learn_from",
            str(folder),
            "a folder with at least two runs to failure, one sub-folder of recordings each",
            hint=f"{len(out)} found",
        )
    return out


def healthy_stretches(result, fraction: float = HEALTHY_FRACTION) -> list[tuple[np.ndarray, float]]:
    """(deviations of one test over the healthy stretch of a trend ``result``, its duration
    [h]) for each test: the levels after the baseline up to ``fraction`` of the run's
    life (:mod:`.calibration`)."""
    from .alarm import deviations
    from .rule import statistics

    stats = statistics(result.values, result.tests)
    base = slice(result.settle_records, result.baseline_stop)
    _, z = deviations(stats, base, result.persistence)
    end = int(np.searchsorted(result.times, fraction * result.times[-1], side="right"))
    start = result.baseline_stop + result.persistence - 1
    if end - start < 2:
        return []
    hours = float(result.times[end - 1] - result.times[start]) / 3600.0
    return [(z[start:end, j], hours) for j in range(z.shape[1])]


@dataclass(frozen=True, eq=False)
class RunSeries:
    """One run to failure read for learning: its ``name``, ``times`` [s], indicator
    ``values``, ``channels``, ``tests``, baseline records ``settle_records`` to
    ``baseline_stop`` - 1, the ``persistence`` window, ``record_spacing`` [s] and the
    rule's ``false_alarm_per_hour`` (the attributes of a TrendResult that learning uses)."""

    name: str
    times: np.ndarray
    values: dict
    channels: tuple
    tests: tuple
    settle_records: int
    baseline_stop: int
    persistence: int
    record_spacing: float
    false_alarm_per_hour: float
    rule: dict


def read_run(path, *, max_frequency=None, **rule_settings) -> RunSeries:
    """A run to failure read as the trend reads a series (all channels, the files'
    sample rate), with the rule's settings (keyword arguments of
    :func:`~.rule.settings`; defaults otherwise)."""
    from ..engine import open_runner
    from .alarm import FALSE_ALARM_PER_HOUR, PERSISTENCE, window_count
    from .indicators import INDICATORS, band_top
    from .reading import probe, read_series
    from .rule import BASELINE, SETTLE, baseline_span, settings, spacing_of
    from .series import list_records

    given = {
        "rate": FALSE_ALARM_PER_HOUR,
        "persistence": PERSISTENCE,
        "persistence_n": None,
        "settle": SETTLE,
        "settle_n": None,
        "baseline": BASELINE,
        "baseline_n": None,
        **rule_settings,
    }
    rule = settings(**given)
    listing = list_records(path)
    channels, first_record = probe(listing, None, None)
    top = band_top(first_record.sample_rate, max_frequency)
    with open_runner("serial") as runner:
        series = read_series(listing, channels, None, None, top, runner, (None, None))
    times = series.times
    spacing = spacing_of(times)
    window = rule["persistence_n"] or window_count(rule["persistence"], spacing)
    first, stop = baseline_span(times, rule, window, [])
    tests = tuple((name, c) for name in INDICATORS for c in range(len(channels)))
    return RunSeries(
        Path(path).name,
        times,
        series.values,
        tuple(channels),
        tests,
        first,
        stop,
        window,
        spacing,
        rule["false_alarm_per_hour"],
        rule,
    )


def learn_runs(folder, *, source: str | None = None, conditions=None, **rule_settings):
    """Learn the alarm's calibration and the lives from a folder of runs to failure.

    Parameters
    ----------
    folder : str or Path
        One sub-folder per run, each a series the trend reads (:mod:`.series`),
        recorded from new until the bearing failed (the last record).
    source : str, optional
        The runs in words (default: the folder's name and the number of runs).
    conditions : dict, optional
        Run name -> dict of its operating conditions (e.g. ``speed_rpm``,
        ``radial_load_n``), kept with its life.
    **rule_settings
        The rule's settings (keyword arguments of :func:`read_run`: ``settle``,
        ``baseline``, ``persistence``, ``max_frequency``...; the defaults otherwise;
        they are kept in ``settings``).

    Returns
    -------
    LearnedRuns
    """
    folders = run_folders(folder)
    runs = {p.name: read_run(p, **rule_settings) for p in folders}
    what = source or f"{len(runs)} runs to failure in {Path(folder).name}"
    return learn_from_runs(runs, what, conditions, _settings(rule_settings))


def learn_from_runs(runs: dict, source: str, conditions=None, settings=None) -> LearnedRuns:
    """:func:`learn_runs` from runs already read: ``runs`` (name -> :class:`RunSeries`),
    described by ``source``, with their ``conditions`` and the rule's ``settings``."""
    from .life import learn_life

    what = source
    stretches = [s for r in runs.values() for s in healthy_stretches(r)]
    try:
        calibration = fit_calibration(stretches, source=f"the healthy first halves of {what}")
        measured = leave_one_out_false_alarms(runs, calibration.source)
    except InputError as exc:
        # too quiet (or too short) to learn limits from: the packaged ones are kept
        default = packaged_learned()
        calibration = replace(
            default.calibration,
            source=f"{default.calibration.source} (the runs given hold {exc.value}: too few "
            "to learn limits from)",
        )
        measured = default.measured
    rows = []
    for name, r in runs.items():
        d = {"run": name, "life_s": float(r.times[-1]), "record_spacing_s": r.record_spacing}
        d.update((conditions or {}).get(name, {}))
        rows.append(d)
    learned = LearnedRuns(calibration, tuple(rows), measured, settings or _settings({}), what)
    return learn_life(learned, runs)


def _settings(trend: dict) -> dict:
    """The rule's settings a learning used, JSON-ready (defaults where not given)."""
    from .alarm import FALSE_ALARM_PER_HOUR, PERSISTENCE
    from .indicators import BAND_FRACTION
    from .rule import BASELINE, SETTLE

    out = {
        "settle_s": SETTLE,
        "baseline_s": BASELINE,
        "persistence_s": PERSISTENCE,
        "false_alarm_per_hour": FALSE_ALARM_PER_HOUR,
        "band_fraction": BAND_FRACTION,
        "healthy_fraction": HEALTHY_FRACTION,
    }
    for key, value in trend.items():
        if isinstance(value, (int, float, str)) or value is None:
            out[key] = value
    return out


def leave_one_out_false_alarms(results: dict, source: str) -> dict:
    """The rule's firings on each run's healthy stretch with limits learned from the other
    runs, at the rule's false-alarm rate; a firing is an excursion of some test's level
    above its limit. Totals over the runs, with the hours monitored."""
    fired = 0
    hours = 0.0
    for name, r in results.items():
        others = [s for k, o in results.items() if k != name for s in healthy_stretches(o)]
        mine = healthy_stretches(r)
        if not mine or not others:
            continue
        try:
            cal = fit_calibration(others)
        except InputError:
            continue  # too few excursions without this run to calibrate on
        x = cal.limit(r.false_alarm_per_hour / len(r.tests))
        above = np.column_stack([np.nan_to_num(z, nan=-np.inf) > x for z, _ in mine])
        from .alarm import crossing_runs

        fired += len(crossing_runs(above.any(axis=1)))
        hours += mine[0][1]
    spacing = float(np.median([r.record_spacing for r in results.values()]))
    per_hour = fired / hours if hours > 0 else None
    return {
        "firings": fired,
        "hours": hours,
        "per_hour": per_hour,
        "per_record": None if per_hour is None else per_hour * spacing / 3600.0,
        "record_spacing_s": spacing,
        "measured_on": (
            f"the healthy first halves of {len(results)} runs, each with limits learned from "
            f"the others (leave one run out), at the rule's rate; {source}"
        ),
    }
