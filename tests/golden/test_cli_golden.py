"""Self-regression of full command-line results (JSON) against stored files.

These are not literature checks: they catch unintended changes anywhere in the chain
(designation -> catalogue -> geometry -> analyses -> JSON). After an intended change,
regenerate and review the diff:

    BEARINGLAB_REGENERATE_GOLDEN=1 .venv/bin/python -m pytest tests/golden
"""

import json
import math
import os
from pathlib import Path

import pytest

from bearinglab.cli import main

HERE = Path(__file__).parent
CASES = {
    "info_6205": ["info", "6205"],
    "info_180205": ["info", "180205"],
    "info_er16k": ["info", "ER-16K"],
    "frequencies_6205_1797rpm": ["frequencies", "6205-2RS", "--speed-rpm", "1797"],
    "contact_6205_1000n": ["contact", "6205", "--ball-load-n", "1000"],
    "contact_7206_hamrock_brewe": [
        "contact",
        "7206",
        "--ball-load-n",
        "1500",
        "--method",
        "hamrock-brewe",
    ],
}


def _close(a, b, path="") -> list[str]:
    if isinstance(a, dict) and isinstance(b, dict):
        diffs = [f"{path}.{k}: missing" for k in a.keys() ^ b.keys()]
        return diffs + [d for k in a.keys() & b.keys() for d in _close(a[k], b[k], f"{path}.{k}")]
    if isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        return [
            d
            for i, (x, y) in enumerate(zip(a, b, strict=True))
            for d in _close(x, y, f"{path}[{i}]")
        ]
    if isinstance(a, float) or isinstance(b, float):
        ok = (
            isinstance(a, (int, float))
            and isinstance(b, (int, float))
            and math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
        )
        return [] if ok else [f"{path}: {a!r} != {b!r}"]
    return [] if a == b else [f"{path}: {a!r} != {b!r}"]


@pytest.mark.parametrize("name", CASES)
def test_golden(name, capsys):
    assert main([*CASES[name], "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    path = HERE / f"{name}.json"
    if os.environ.get("BEARINGLAB_REGENERATE_GOLDEN"):
        path.write_text(json.dumps(got, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    expected = json.loads(path.read_text(encoding="utf-8"))
    diffs = _close(got, expected)
    assert not diffs, "\n".join(diffs[:20])
