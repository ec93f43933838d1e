"""Parameter studies: one analysis over a grid of inputs or a table of cases, on dask.

>>> from bearinglab.study import ANALYSES
>>> sorted(ANALYSES)[:3]
['frequencies', 'friction', 'life']

``run_study("stiffness", {"designation": "6205", "radial_load_n": "100:2000:20",
"speed_rpm": [0, 6000]}, output="out")`` writes one Parquet file per partition in ``out``
(a LocalCluster of the machine's cores by default) and returns a :class:`StudyResult`;
``.to_pandas()`` reads the table, ``.plot(output, x, y)`` maps one output over two inputs.
See :mod:`.runner` for the folder layout, :mod:`.cases` for the value forms and
:mod:`bearinglab.engine` for where the partitions run.
"""

from ..engine import open_runner
from .analyses import ANALYSES, Analysis, analysis
from .cases import Option, Uniform, case_rng, case_seed, parse_values
from .plots import plot_study
from .runner import StudyResult, describe_options, read_study, run_study

__all__ = [
    "ANALYSES",
    "Analysis",
    "Option",
    "StudyResult",
    "Uniform",
    "analysis",
    "case_rng",
    "case_seed",
    "describe_options",
    "open_runner",
    "parse_values",
    "plot_study",
    "read_study",
    "run_study",
]
