"""``bearinglab validate``: verdicts, JSON, HTML and the exit code, on a few cheap cases
(the full list runs simulations; tests/literature/test_published_cases.py runs it)."""

import json
import math
import re

import pytest

from bearinglab import validation
from bearinglab.cli import main
from bearinglab.validation import Case, datasets, seed000, seed004
from bearinglab.validation.run import run_case, summarize, verdict

CASE_KEYS = {
    "source",
    "quantity",
    "published",
    "computed",
    "unit",
    "error_percent",
    "passed",
    "known_failure",
    "tolerance_percent",
}


def _case(quantity, computed, published=10.0, known=None):
    def compute():
        if isinstance(computed, Exception):
            raise computed
        return computed

    return Case(
        "test source",
        quantity,
        published,
        "Hz",
        compute,
        0.01,
        "1 % for the test",
        known_failure=known,
    )


GOOD = [_case("passes", 10.05), _case("known, fails as documented", 12.0, known="a reason")]
BAD = {
    "fail": _case("fails", 11.0),
    "unexpected pass": _case("known but passes", 10.0, known="a reason"),
    "error": _case("raises", ValueError("no convergence")),
    "nan": _case("not finite", math.nan),
}


def run(monkeypatch, capsys, cases, *args):
    monkeypatch.setattr(validation, "all_cases", lambda: list(cases))
    code = main(["validate", *args])
    out, err = capsys.readouterr()
    return code, out, err


def test_verdicts():
    assert verdict(True, None) == "pass" and verdict(False, None) == "fail"
    assert verdict(False, "why") == "known failure" and verdict(True, "why") == "unexpected pass"
    assert verdict(None, None) == "error" and verdict(None, "why") == "error"


def test_all_good_json_and_exit_0(monkeypatch, capsys):
    code, out, _ = run(monkeypatch, capsys, GOOD, "--json")
    assert code == 0
    d = json.loads(out)
    assert len(d["cases"]) == 2
    for c in d["cases"]:
        assert CASE_KEYS <= c.keys()
    first, second = d["cases"]
    assert first["passed"] is True and first["known_failure"] is None
    assert first["error_percent"] == pytest.approx(0.5) and first["tolerance_percent"] == 1.0
    assert second["passed"] is False and second["known_failure"] == "a reason"
    assert second["verdict"] == "known failure"
    s = d["summary"]
    assert (s["total"], s["passed"], s["known_failures"], s["failed"]) == (2, 1, 1, 0)
    assert s["ok"] is True


@pytest.mark.parametrize("bad", list(BAD))
def test_a_case_that_does_not_behave_as_documented_exits_1(monkeypatch, capsys, bad):
    code, out, _ = run(monkeypatch, capsys, [*GOOD, BAD[bad]], "--json")
    assert code == 1
    d = json.loads(out)  # still one valid JSON object (NaN and errors become null)
    last = d["cases"][-1]
    assert last["verdict"] == ("fail" if bad == "nan" else bad)
    assert last["passed"] is False or bad == "unexpected pass"
    assert d["summary"]["ok"] is False
    if bad == "error":
        assert last["computed"] is None and last["error"] == "ValueError: no convergence"
    if bad == "nan":
        assert last["computed"] is None and last["error_percent"] is None


def test_table_shows_verdicts_reasons_and_summary(monkeypatch, capsys):
    code, out, _ = run(monkeypatch, capsys, [*GOOD, BAD["fail"]])
    assert code == 1
    text = " ".join(out.split())
    for word in ("test source", "passes", "known failure [1]", "fail", "[1] a reason"):
        assert word in text, word
    assert "3 cases: 1 pass, 1 known failures (documented), 1 fail" in text


def test_html_is_self_contained(monkeypatch, capsys, tmp_path):
    path = tmp_path / "validate.html"
    code, out, _ = run(monkeypatch, capsys, [*GOOD, BAD["error"]], "--html", str(path), "--json")
    assert code == 1 and json.loads(out)["summary"]["errors"] == 1
    page = path.read_text(encoding="utf-8")
    assert page.startswith("<!DOCTYPE html>") and "test source" in page
    for verdict_text in ("pass", "known failure", "error"):
        assert f">{verdict_text}</span>" in page
    assert "a reason" in page and "ValueError: no convergence" in page
    for attribute in re.findall(r'\b(?:src|href)\s*=\s*"([^"]*)"', page):
        assert attribute.startswith(("data:", "#")), attribute
    assert "<script" not in page and "<link" not in page


def test_bad_html_path_exits_2_before_running(monkeypatch, capsys, tmp_path):
    ran = []
    monkeypatch.setattr(validation, "all_cases", lambda: ran.append(1) or GOOD)
    code = main(["validate", "--html", str(tmp_path / "missing" / "v.html")])
    _, err = capsys.readouterr()
    assert code == 2 and err.startswith("error: --html = ") and not ran


def test_real_cheap_cases_pass_or_fail_as_documented(monkeypatch, capsys):
    cases = [*seed004.CASES, *datasets.CASES[:3], *seed000.CASES]
    code, out, _ = run(monkeypatch, capsys, cases, "--json")
    d = json.loads(out)
    assert code == 0, [c for c in d["cases"] if c["verdict"] not in ("pass", "known failure")]
    # every documented non-reproduction fails as documented, and only those
    assert d["summary"]["known_failures"] == sum(1 for c in cases if c.known_failure)


def test_run_case_and_summary_directly():
    results = [run_case(c) for c in (*GOOD, *BAD.values())]
    s = summarize(results, 1.5)
    assert (s["passed"], s["known_failures"], s["failed"], s["unexpected_passes"], s["errors"]) == (
        1,
        1,
        2,
        1,
        1,
    )
    assert s["duration_s"] == 1.5 and s["ok"] is False


def test_registry_is_the_one_list():
    ids = [c.id for c in validation.all_cases()]
    assert len(ids) == len(set(ids))  # every case once
    assert len(ids) > 40
