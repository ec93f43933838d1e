"""The engineer's report: one self-contained HTML page about a bearing at an operating
point (figures embedded as PNG, no external resources), built by :func:`build_report`.

- :mod:`.document`: :class:`Report`, :class:`Section`, tables, figures, the page template;
- :mod:`.mechanics`, :mod:`.vibration`, :mod:`.operation`: one function per section;
- :mod:`.builder`: :func:`build_report` runs the sections, each tolerating failure;
- :mod:`.validation`: the page of ``bearinglab validate --html``.

Command line: ``bearinglab report 6205 --speed-rpm 1797 --radial-load-n 1000 -o r.html``;
documentation: docs/capabilities/report.md.
"""

from .builder import SECTIONS, build_report, default_sample_rate
from .document import Report, Section
from .validation import validation_page

__all__ = [
    "SECTIONS",
    "Report",
    "Section",
    "build_report",
    "default_sample_rate",
    "validation_page",
]
