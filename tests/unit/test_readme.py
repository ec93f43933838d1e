"""Every ``bearinglab`` line of the README's shell blocks runs as written (issue 22).

The lines run in order (``analyze er16k.npz`` reads what ``simulate ... -o er16k.npz``
wrote) in a scratch folder laid out as the README assumes: the repository root, with
``../shared`` beside it when this checkout has one. ``BEARINGLAB_README_BIN`` names the
``bearinglab`` to run (CI points it at a plain ``pip install .`` in a fresh virtual
environment); by default the one of this environment. Lines that read ``../shared`` are
skipped when it is not there.
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SHARED = ROOT.parent / "shared"


def readme_lines() -> list[str]:
    """The ``bearinglab`` command lines of the README's ```sh blocks, continuations joined."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    lines = []
    for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S):
        joined = re.sub(r"\\\n\s*", " ", block)
        for line in joined.splitlines():
            line = line.split("  #")[0].strip()
            if line.startswith("bearinglab "):
                lines.append(line)
    return lines


def test_the_readme_has_command_lines():
    lines = readme_lines()
    assert len(lines) > 20 and all(line.startswith("bearinglab ") for line in lines)


@pytest.mark.slow
def test_every_readme_command_line_runs_as_written(tmp_path):
    binary = os.environ.get("BEARINGLAB_README_BIN") or shutil.which(
        "bearinglab", path=str(Path(sys.executable).parent)
    )
    assert binary, "no bearinglab executable"
    root = tmp_path / "main"
    root.mkdir()
    (root / "examples").symlink_to(ROOT / "examples")
    if SHARED.is_dir():
        (tmp_path / "shared").symlink_to(SHARED)
    env = {**os.environ, "MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1"}
    failed = []
    for line in readme_lines():
        if "../shared" in line and not SHARED.is_dir():
            continue
        args = shlex.split(line)[1:]
        done = subprocess.run(
            [binary, *args], cwd=root, env=env, capture_output=True, text=True, timeout=600
        )
        if done.returncode != 0:
            failed.append(f"{line}\n  -> exit {done.returncode}: {done.stderr.strip()[-400:]}")
    assert not failed, "\n".join(failed)
