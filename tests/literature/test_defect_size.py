"""The width of a race defect on real recordings (issue 29): seeded defects of known width
and the CWRU faults, too small to size.

Sources: the HIT-SM SpectraQuest records of ../shared/data/defect-size (seeded outer- and
inner-race defects of 2, 5 and 8 deg; ``labels.csv`` gives each one's width along the
rolling direction, ``defect_width_mm``, from its extent on the raceway) and the CWRU
records of ../shared/data/real (electro-discharge machined holes of 0.007-0.028 in,
0.18-0.71 mm: too short for a ball to drop into, so no separate entry event; the issue's
trial found none). Each record goes through the benchmark's path (``run_record``: the
diagnosis by the default method, then the width of the race fault it finds, under the
assumed load: the labels give none).

What is asserted, for every row the folders hold:
- every 5 and 8 deg defect is sized within 25 % of its labelled width (measured
  2026-11-28: +4 % to +17 %, docs/capabilities/defect_size.md; the errors are systematic,
  from the load assumed for what the ball bridges at the edges);
- no 2 deg defect and no healthy record gets a width;
- no CWRU record gets a width.
The tolerance is the issue's: the width of a seeded defect on another rig is asked within
25 %; a method tuned to these 12 records to a tighter band would say nothing more about it.
"""

from pathlib import Path

import pytest

from bearinglab.diagnosis.benchmark import read_labels, run_record

SHARED = Path(__file__).resolve().parents[3] / "shared" / "data"
SIZES = SHARED / "defect-size"
REAL = SHARED / "real"


def _rows(folder):
    return read_labels(folder) if (folder / "labels.csv").is_file() else []


def _sizes(folder, row) -> list[dict]:
    out = run_record(str(folder), row, ("cpw",), keep_spectra=False)
    assert out["error"] is None, out["error"]
    return out["defect_sizes"]


def _param(row):
    return pytest.param(row, id=f"{row['file']} [{row['fault']} {row.get('fault_size_deg') or ''}]")


@pytest.mark.skipif(not (SIZES / "labels.csv").is_file(), reason="no shared/data/defect-size")
@pytest.mark.parametrize(
    "row", [_param(r) for r in _rows(SIZES) if r.get("fault_size_deg") in ("5", "8")]
)
def test_5_and_8_deg_defects_are_sized_within_25_percent(row):
    sizes = _sizes(SIZES, row)
    race = {"inner": "inner_race", "outer": "outer_race"}[row["fault"]]
    size = next(s for s in sizes if s["race"] == race)
    assert size["status"] == "sized", size["reason"]
    assert size["width_mm"] == pytest.approx(float(row["defect_width_mm"]), rel=0.25)


@pytest.mark.skipif(not (SIZES / "labels.csv").is_file(), reason="no shared/data/defect-size")
@pytest.mark.parametrize(
    "row", [_param(r) for r in _rows(SIZES) if r.get("fault_size_deg") not in ("5", "8")]
)
def test_2_deg_defects_and_healthy_records_get_no_width(row):
    assert all(s["status"] != "sized" for s in _sizes(SIZES, row))


@pytest.mark.skipif(not (REAL / "labels.csv").is_file(), reason="no shared/data/real")
@pytest.mark.parametrize("row", [_param(r) for r in _rows(REAL) if r["dataset"] == "CWRU"])
def test_no_cwru_fault_gets_a_width(row):
    assert all(s["status"] != "sized" for s in _sizes(REAL, row))
