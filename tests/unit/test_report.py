"""The engineer's report: built through the command line for a 6205 with short simulations,
then checked for structure (every section, embedded images, nothing loaded from outside),
failure isolation and the command's input checks."""

import base64
import contextlib
import io
import json
import math
import re

import pytest
from conftest import README_REPORT

from bearinglab.cli import main
from bearinglab.report import SECTIONS, build_report
from bearinglab.report import builder as report_builder

REPORT = [*README_REPORT, "--duration-s", "0.3", "--slip-duration-s", "0.03"]
INNER = ["--defect", "inner:width_mm=1.0,depth_mm=0.2"]


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """(JSON printed by the command, the page) of one report."""
    path = tmp_path_factory.mktemp("report") / "6205.html"
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main([*REPORT, *INNER, "-o", str(path), "--json"])
    assert code == 0
    return json.loads(out.getvalue()), path.read_text(encoding="utf-8")


def test_command_reports_sections_and_no_failures(built):
    d, _ = built
    assert d["sections"] == [key for key, _, _ in SECTIONS]
    assert d["failed_sections"] == []
    assert d["output"].endswith("6205.html")


def test_every_section_is_present_with_its_heading(built):
    _, page = built
    assert page.startswith("<!DOCTYPE html>")
    for key, title, _ in SECTIONS:
        assert f'<section id="{key}">' in page, key
        assert f"<h2>{title} </h2>" in page, title
        assert f'<a href="#{key}">{title}</a>' in page, f"contents entry for {key}"
    assert "This analysis failed" not in page
    assert "bearinglab report: 6205" in page and "At a glance" in page


def test_content_of_the_sections(built):
    _, page = built
    # geometry with sources, the designation decoded, the GOST reading mentioned
    assert "catalog [1]" in page and "estimated" in page and "GOST equivalent" in page
    # the defect given is simulated (no example defect) and found
    assert "No defect was given" not in page
    assert "inner 1 mm wide, 0.2 mm deep" in page
    assert "Likely fault: inner race" in page
    # slip model ran; friction by both models; life and bands
    assert "mean cage speed is" in page
    assert "SKF four-component model" in page and "constant coefficient" in page
    assert "basic rating life L10" in page and "RMS velocity [um/s]" in page


def test_no_library_markup_leaks_onto_the_page(built):
    """Issue 30: backquoted input names (`system`) and library parameter names leaked
    into the page; the squared envelope's lines were labelled m/s2."""
    import html as html_module
    import re

    _, page = built
    text = html_module.unescape(re.sub(r"<[^>]+>", " ", re.sub(r"data:[^\"]+", "", page)))
    assert "`" not in text
    assert "<code>--system</code>" in page
    assert "amplitude [(m/s²)²]" in page and "amplitude [m/s2]" not in page


def test_images_are_embedded_png(built):
    _, page = built
    images = re.findall(r'<img src="([^"]*)"', page)
    assert len(images) >= 10  # one figure per section except the identity
    for src in images:
        assert src.startswith("data:image/png;base64,")
        data = base64.b64decode(src.split(",", 1)[1], validate=True)
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000


def test_nothing_is_loaded_from_outside(built):
    _, page = built
    for attribute in re.findall(r'\b(?:src|href|action|poster)\s*=\s*"([^"]*)"', page):
        assert attribute.startswith(("data:", "#")), attribute
    lowered = page.lower()
    for forbidden in ("<link", "<script", "<iframe", "@import", "url("):
        assert forbidden not in lowered, forbidden


def test_a_failing_section_shows_its_error_and_the_rest_runs(monkeypatch):
    def broken(ctx):
        raise RuntimeError("boom <b>not markup</b>")

    sections = [s for s in SECTIONS if s[0] in ("identity", "load-distribution", "contact")]
    monkeypatch.setattr(
        report_builder, "SECTIONS", (sections[0], ("broken", "Broken", broken), *sections[1:])
    )
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.operating import OperatingCondition

    bearing, des = bearing_from_designation("6205")
    seen = []
    r = build_report(
        bearing,
        OperatingCondition(radial_load=500.0, shaft_speed=100.0),
        designation=des,
        progress=lambda title, i, n: seen.append((title, i, n)),
    )
    assert [s.key for s in r.failed] == ["broken"]
    assert r.failed[0].error == "RuntimeError: boom <b>not markup</b>"
    page = r.to_html()
    assert "This analysis failed" in page and "boom &lt;b&gt;not markup&lt;/b&gt;" in page
    assert '<span class="badge fail">failed</span>' in page
    assert "1 of 4 analyses failed: Broken" in page
    assert not any(s.failed for s in r.sections if s.key != "broken")
    assert seen[0] == ("Identity and geometry", 0, 4) and seen[-1] == ("done", 4, 4)


def test_a_section_that_needs_a_failed_one_says_so(monkeypatch):
    from bearinglab.catalog import bearing_from_designation
    from bearinglab.operating import OperatingCondition

    def broken(ctx):
        raise RuntimeError("no equilibrium")

    contact = next(s for s in SECTIONS if s[0] == "contact")
    monkeypatch.setattr(
        report_builder, "SECTIONS", (("load-distribution", "Load distribution", broken), contact)
    )
    bearing, _ = bearing_from_designation("6205")
    r = build_report(bearing, OperatingCondition(radial_load=500.0, shaft_speed=100.0))
    assert [s.key for s in r.failed] == ["load-distribution", "contact"]
    assert "needs the load distribution, which failed" in r.failed[1].error


def _report_json(path, radial_load_n: str) -> int:
    """The command's exit code for the 6205 at 1797 rpm with default durations, written to
    ``path`` with --json."""
    return main(
        [
            "report",
            "6205",
            "--speed-rpm",
            "1797",
            "--radial-load-n",
            radial_load_n,
            "-o",
            str(path),
            "--json",
        ]
    )


def test_failed_sections_exit_1_with_the_page_written(monkeypatch, capsys, tmp_path):
    """A report with failed sections is still written and lists them, but the command's
    exit code says it is incomplete (issue 14)."""

    def broken(ctx):
        raise RuntimeError("no equilibrium")

    contact = next(s for s in SECTIONS if s[0] == "contact")
    monkeypatch.setattr(
        report_builder, "SECTIONS", (("load-distribution", "Load distribution", broken), contact)
    )
    path = tmp_path / "r.html"
    code = _report_json(path, "1000")
    d = json.loads(capsys.readouterr().out)
    assert code == 1 and path.exists()
    assert [f["section"] for f in d["failed_sections"]] == ["load-distribution", "contact"]


def test_plausibility_warnings_on_the_page_and_in_json(capsys, tmp_path):
    monkey_sections = [s for s in SECTIONS if s[0] == "identity"]
    path = tmp_path / "r.html"
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(report_builder, "SECTIONS", tuple(monkey_sections))
        code = _report_json(path, "10000")
    d = json.loads(capsys.readouterr().out)
    assert code == 0
    assert any("s0 = C0/P0 = 0.789" in w for w in d["warnings"])
    assert "s0 = C0/P0 = 0.789" in path.read_text(encoding="utf-8")


@pytest.mark.parametrize(
    "args, option",
    [
        (["-o", "x.pdf"], "--output"),
        (["-o", "/no/such/dir/r.html"], "--output"),
        (["-o", "r.html", "--defect", "outer:width_mm=9"], "--defect"),
        (["-o", "r.html", "--defect", "rim:width_mm=1"], "--defect"),
        (["-o", "r.html", "--lubricant", "water"], "--lubricant"),
        (["-o", "r.html", "--viscosity-mm2-s", "20", "--lubricant", "foo"], "--lubricant"),
        (["-o", "r.html", "--duration-s", "0"], "--duration-s"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(capsys, tmp_path, monkeypatch, args, option):
    monkeypatch.chdir(tmp_path)
    code = main([*REPORT, *args])
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    assert err.startswith(f"error: {option} = ") and err.count("\n") == 1, err
    assert not list(tmp_path.iterdir())  # nothing written


def test_default_sample_rate_resolves_the_iso_bands():
    assert report_builder.default_sample_rate(1797 * math.pi / 30) == 25600.0
    fast = report_builder.default_sample_rate(9000 * math.pi / 30)
    assert fast > 2 * 10e3 * 9000 / 1800
