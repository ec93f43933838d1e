"""The engineer's report: one self-contained HTML page about a bearing at an operating
point (figures embedded as PNG, no external resources), built by :func:`build_report`.

- :mod:`.document`: :class:`Report`, :class:`Section`, tables, figures, the page template;
- :mod:`.mechanics`, :mod:`.vibration`, :mod:`.operation`: one function per section;
- :mod:`.builder`: :func:`build_report` runs the sections, each tolerating failure;
- :mod:`.validation`, :mod:`.benchmark`, :mod:`.trend`: the pages of ``bearinglab validate
  --html``, ``benchmark --html`` and ``trend --html`` (each takes its result as data).

Command line: ``bearinglab report 6205 --speed-rpm 1797 --radial-load-n 1000 -o r.html``;
documentation: docs/capabilities/report.md.
"""

from .benchmark import benchmark_page, write_benchmark_page
from .builder import SECTIONS, build_report, default_sample_rate
from .document import Report, Section
from .trend import trend_page, write_trend_page
from .validation import validation_page

__all__ = [
    "SECTIONS",
    "Report",
    "Section",
    "benchmark_page",
    "build_report",
    "default_sample_rate",
    "trend_page",
    "validation_page",
    "write_benchmark_page",
    "write_trend_page",
]
