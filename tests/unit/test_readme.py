"""Every example of the README and the docs runs as written (issues 22 and 30).

The ```sh lines (``bearinglab ...`` and ``python ...``, continuations joined, in order:
``analyze er16k.npz`` reads what ``simulate ... -o er16k.npz`` wrote) and the ```python
blocks (each saved as a script) of README.md and every page of docs/ run in a scratch
folder laid out as the README assumes: the repository root, with ``../shared`` beside it
when this checkout has one (lines that read ``../shared`` are skipped when it is not).
``BEARINGLAB_README_BIN`` names the ``bearinglab`` to run, and its folder's ``python``
runs the Python lines and blocks (CI points it at a plain ``pip install .`` in a fresh
virtual environment, so every example runs on a plain install); by default this
environment's. A block that needs an extra says so on its first line (``# needs: ross``)
and runs only where that extra is installed.
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
#: The pages whose examples run: the README and every page of docs/.
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
#: Extras a block may need -> the module that tells it is installed.
EXTRAS = {"ross": "ross", "examples": "sklearn"}


def shell_blocks(page: Path) -> list[list[str]]:
    """The ``bearinglab`` and ``python`` lines of each of a page's ```sh blocks,
    continuations joined and comments dropped (a block is self-contained: what a line
    reads, a line of the same block wrote)."""
    text = page.read_text(encoding="utf-8")
    blocks = []
    for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S):
        joined = re.sub(r"\\\n\s*", " ", block)
        lines = [line.split("  #")[0].strip() for line in joined.splitlines()]
        lines = [line for line in lines if line.startswith(("bearinglab ", "python "))]
        if lines:
            blocks.append(lines)
    return blocks


def shell_lines(page: Path) -> list[str]:
    """The ``bearinglab`` and ``python`` lines of a page's ```sh blocks, in order."""
    return [line for block in shell_blocks(page) for line in block]


def python_blocks(page: Path) -> list[str]:
    """The ```python blocks of a page."""
    return re.findall(r"```python\n(.*?)```", page.read_text(encoding="utf-8"), re.S)


def readme_lines() -> list[str]:
    """The README's shell lines."""
    return shell_lines(ROOT / "README.md")


def test_the_readme_has_command_lines():
    lines = readme_lines()
    assert len(lines) > 20 and all(line.startswith(("bearinglab ", "python ")) for line in lines)


def test_every_shell_block_line_is_a_command_that_runs():
    """A line of a ```sh block is a command as written, not a synopsis ([--option])."""
    for page in PAGES:
        for line in shell_lines(page):
            assert "[--" not in line and "|" not in line.split("#")[0], (page.name, line)


def _binaries() -> tuple[str, str]:
    binary = os.environ.get("BEARINGLAB_README_BIN") or shutil.which(
        "bearinglab", path=str(Path(sys.executable).parent)
    )
    assert binary, "no bearinglab executable"
    python = Path(binary).parent / "python"
    return binary, str(python if python.exists() else sys.executable)


def _needs(block: str, python: str) -> str | None:
    """The extra a block names on its first line that ``python`` lacks, else None."""
    first = block.lstrip().splitlines()[0] if block.strip() else ""
    match = re.match(r"#\s*needs:\s*(\w+)", first)
    if match is None:
        return None
    module = EXTRAS[match.group(1)]
    found = subprocess.run(
        [python, "-c", f"import {module}"], capture_output=True, text=True, check=False
    )
    return None if found.returncode == 0 else match.group(1)


def _examples() -> list[tuple[Path, int | None]]:
    """(page, index of its ```sh block) for every block, and (page, None) for a page's
    ```python blocks: one test each, so that the long pages spread over the workers."""
    out = []
    for page in PAGES:
        out += [(page, k) for k in range(len(shell_blocks(page)))]
        if python_blocks(page):
            out.append((page, None))
    return out


@pytest.mark.slow
@pytest.mark.parametrize(
    "page, block",
    _examples(),
    ids=lambda v: (
        str(v.relative_to(ROOT)) if isinstance(v, Path) else ("python" if v is None else f"sh{v}")
    ),
)
def test_every_example_runs_as_written(tmp_path, page, block):
    binary, python = _binaries()
    root = tmp_path / "main"
    root.mkdir()
    (root / "examples").symlink_to(ROOT / "examples")
    if SHARED.is_dir():
        (tmp_path / "shared").symlink_to(SHARED)
    env = {**os.environ, "MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1"}
    env.pop("PYTHONPATH", None)  # the install under test, not this checkout
    failed = []
    for line in [] if block is None else shell_blocks(page)[block]:
        if "../shared" in line and not SHARED.is_dir():
            continue
        program, *args = shlex.split(line)
        command = [binary if program == "bearinglab" else python, *args]
        done = subprocess.run(
            command, cwd=root, env=env, capture_output=True, text=True, timeout=600
        )
        if done.returncode != 0:
            failed.append(f"{line}\n  -> exit {done.returncode}: {done.stderr.strip()[-400:]}")
    for i, code in enumerate(python_blocks(page) if block is None else []):
        if _needs(code, python) is not None:
            continue
        script = root / f"block{i}.py"
        script.write_text(code, encoding="utf-8")
        done = subprocess.run(
            [python, script.name], cwd=root, env=env, capture_output=True, text=True, timeout=600
        )
        if done.returncode != 0:
            failed.append(f"python block {i}:\n  -> {done.stderr.strip()[-600:]}")
    assert not failed, "\n".join(failed)
