"""docs/references.md: every reference key the docs use resolves, every seed has an entry.

A "reference key" is a bracketed word of the grammar docs/references.md states (seed
numbers, author-year keys, standards, cat-/web-/data-/sw- names); unit brackets such as
[Hz], [N·mm] or [m/s²] do not match it. Keys are defined as list items that start with
``**[key]**``.
"""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
REFERENCES = ROOT / "docs" / "references.md"
SEEDS = ROOT.parent / "shared" / "seeds"

#: What a reference key looks like (the grammar of docs/references.md).
KEY = re.compile(
    r"seed\d{3}"  # seed documents
    r"|[A-Z][A-Za-z]*(?:\d{4}[a-z]?|-nd)"  # author-year (Harris2007a) or no year (Rao-nd)
    r"|(?:ISO|GOST|DIN|GB|JB|ASTM|ANSI)[-A-Za-z0-9.]*\d[-A-Za-z0-9.]*"  # standards: ISO281
    r"|(?:cat|web|data|sw)-[A-Za-z0-9.-]+"  # catalogues, web pages, data, software
)
BRACKETED = re.compile(r"\[([^\[\]\s]+)\]")
DEFINITION = re.compile(r"^- \*\*\[([^\]]+)\]\*\*", re.MULTILINE)


def defined_keys(text):
    return DEFINITION.findall(text)


def unresolved(text, keys):
    """(line number, key) of every bracketed reference key in ``text`` not in ``keys``."""
    return [
        (n, k)
        for n, line in enumerate(text.splitlines(), 1)
        for k in BRACKETED.findall(line)
        if KEY.fullmatch(k) and k not in keys
    ]


@pytest.fixture(scope="module")
def references():
    return REFERENCES.read_text(encoding="utf-8")


def test_keys_are_defined_once_and_follow_the_grammar(references):
    keys = defined_keys(references)
    assert len(keys) > 50
    assert sorted(k for k in set(keys) if keys.count(k) > 1) == []
    assert [k for k in keys if not KEY.fullmatch(k)] == []


def test_unit_brackets_are_not_keys_and_missing_keys_are_found():
    units = [
        "Hz",
        "K",
        "Pa",
        "dB",
        "um",
        "rad",
        "N·mm",
        "kg/m^3",
        "1/K",
        "-",
        "m/s²",
        "MPa",
        "OUT_DIR",
        "BallBearing",
        "Python3.11",
        "2",
        "--quick",
        "test",
    ]
    assert [u for u in units if KEY.fullmatch(u)] == []
    text = "see [Nobody1999] eq. 3, [Nobody-nd], [ISO9999], [seed123], in [Hz]\n[seed000]"
    assert unresolved(text, {"seed000"}) == [
        (1, "Nobody1999"),
        (1, "Nobody-nd"),
        (1, "ISO9999"),
        (1, "seed123"),
    ]


def test_every_key_used_in_the_docs_resolves(references):
    keys = set(defined_keys(references))
    pages = sorted((ROOT / "docs").glob("*.md")) + sorted(
        (ROOT / "docs" / "capabilities").glob("*.md")
    )
    assert REFERENCES in pages
    missing = [
        f"{page.relative_to(ROOT)}:{n}: [{k}]"
        for page in pages
        for n, k in unresolved(page.read_text(encoding="utf-8"), keys)
    ]
    assert missing == [], "keys not defined in docs/references.md:\n" + "\n".join(missing)


def test_every_seed_file_has_its_entry(references):
    if not SEEDS.is_dir():
        pytest.skip(f"{SEEDS} not present")
    files = sorted(p.name for p in SEEDS.iterdir() if p.is_file())
    assert files
    entries = dict(
        re.findall(
            r"^- \*\*\[(seed\d{3})\]\*\*(.*?)(?=^- \*\*\[|^## )",
            references,
            re.MULTILINE | re.DOTALL,
        )
    )
    for name in files:
        key = "seed" + name[:3]
        assert key in entries, f"no entry [{key}] for {name}"
        assert name in entries[key], f"entry [{key}] does not name the file {name}"
