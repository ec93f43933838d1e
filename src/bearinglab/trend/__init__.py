"""The trend of a machine over a series of recordings: health indicators per record, a
baseline learned from the start of the series, an alarm at a stated false-alarm rate that
stays raised, the diagnosis at and after it, ISO 20816 severity and the remaining life.

Layer 3 (see docs/architecture.md). :func:`trend_records` reads a folder (PRONOSTIA
snapshots as published, or the records ``analyze`` reads with their times) and returns a
:class:`TrendResult` (``to_dict``, ``to_pandas``, ``plot``; its HTML page is
:func:`bearinglab.report.trend.write_trend_page`).

Modules, one sub-problem each:

- :mod:`.series`: the folder layouts, each record's time, the readers;
- :mod:`.indicators`: rms, peak, crest factor, kurtosis, spectral kurtosis, velocity;
- :mod:`.severity`: the ISO 20816 zones;
- :mod:`.alarm`: the robust baseline, the levels over the persistence window;
- :mod:`.calibration`: the limits from the excursion rates of healthy operation;
- :mod:`.rule`: the rule applied to a series (baseline, alarm, short crossings, the rate
  measured on it); :mod:`.reading`: a folder read into indicators, checked, in order;
- :mod:`.learning`: what is learned from runs to failure (:func:`learn_runs`);
  :mod:`.life`: the remaining useful life;
- :mod:`.blocks`: the diagnosis over blocks of consecutive records, at and after the alarm;
- :mod:`.tasks`: the work run on the workers; :mod:`.result`: :class:`TrendResult`;
  :mod:`.figure`: its figure;
- :mod:`.analysis`: :func:`trend_records`; :mod:`.simulated`: :func:`simulate_series`.

Sources are cited in each module; docs/capabilities/trend.md says what was measured.
"""

from .alarm import FALSE_ALARM_PER_HOUR, PERSISTENCE, plain_rule
from .analysis import BASELINE, SETTLE, trend_records
from .indicators import INDICATORS
from .learning import LearnedRuns, learn_runs
from .result import Alarm, TrendResult
from .severity import MACHINES

__all__ = [
    "BASELINE",
    "FALSE_ALARM_PER_HOUR",
    "INDICATORS",
    "LearnedRuns",
    "MACHINES",
    "PERSISTENCE",
    "SETTLE",
    "Alarm",
    "TrendResult",
    "learn_runs",
    "plain_rule",
    "trend_records",
]
