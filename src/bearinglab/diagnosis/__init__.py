"""Bearing fault diagnosis of vibration records: a verdict with a stated false-alarm
probability, by the three methods of Smith & Randall's benchmark study.

Layer 3 (see docs/architecture.md). :func:`analyze_signal` takes a record and the bearing's
kinematic frequencies and returns a :class:`Diagnosis`: for each fault family (outer race,
inner race, ball, cage) the significance of its harmonic series and sidebands above the
local noise floor of the squared envelope spectrum, and the verdict - a fault, a compound
fault, or ``no fault detected``. :func:`run_benchmark` runs it over a folder of labelled
recordings.

Modules, one sub-problem each:

- :mod:`.families`: which lines each fault makes, and their tolerances (literature);
- :mod:`.methods`: Smith & Randall's three routes to a squared envelope spectrum (raw,
  cepstral pre-whitening, discrete/random separation + fast kurtogram band);
- :mod:`.statistics`: the noise floor and its chi-square law, Fisher's combination;
- :mod:`.series`: the harmonic series test of a family (nested templates, the scan and
  its chain bound, :mod:`.chain`);
- :mod:`.tail`: a line's p-value against the spectrum's own positions (its rank, and a
  fitted peaks-over-threshold law beyond);
- :mod:`.speed`: the shaft speed the signal shows;
- :mod:`.verdict`: masking of discrete lines, the greedy decision, labelled lines;
- :mod:`.residual`: a second look once a fault is accepted - its impacts removed from the
  squared envelope, the other families read again on the rest (a compound fault);
- :mod:`.result`: :class:`Diagnosis`; :mod:`.analysis`: :func:`analyze_signal`;
- :mod:`.benchmark`: :func:`run_benchmark` and :class:`BenchmarkResult`;
- :mod:`.sizing`: :func:`size_defect`, the width of a race defect found, from the entry
  and exit events of its passages (Sawalhi & Randall, MSSP 25 (2011) 846-870).

Sources: Randall R. B., Antoni J., "Rolling element bearing diagnostics - A tutorial",
MSSP 25(2) (2011) 485-520; Smith W. A., Randall R. B., "Rolling element bearing diagnostics
using the Case Western Reserve University data: a benchmark study", MSSP 64-65 (2015)
100-131; Antoni J., "Cyclic spectral analysis in practice", MSSP 21 (2007) 597-630; the
others in each module. docs/capabilities/diagnosis.md says what was measured.
"""

from ..signal.peaks import peak_label
from .analysis import (
    COUNT,
    DEFAULT_METHODS,
    FALSE_ALARM,
    HARMONICS,
    MAX_FREQUENCY_FACTOR,
    PREFERRED_CHANNELS,
    SIMULATED_METHODS,
    analyze_signal,
)
from .benchmark import BenchmarkResult, run_benchmark
from .families import FAMILIES, TOLERANCES
from .methods import METHODS
from .recording import analyze_file
from .result import Diagnosis, measured_ball_defect_frequency
from .sizing import DefectSize, size_defect
from .verdict import NO_FAULT

__all__ = [
    "COUNT",
    "DEFAULT_METHODS",
    "FALSE_ALARM",
    "FAMILIES",
    "HARMONICS",
    "MAX_FREQUENCY_FACTOR",
    "METHODS",
    "NO_FAULT",
    "PREFERRED_CHANNELS",
    "SIMULATED_METHODS",
    "TOLERANCES",
    "BenchmarkResult",
    "DefectSize",
    "Diagnosis",
    "analyze_file",
    "analyze_signal",
    "measured_ball_defect_frequency",
    "peak_label",
    "run_benchmark",
    "size_defect",
]
