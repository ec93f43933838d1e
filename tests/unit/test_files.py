"""Atomic writes: a whole file with an ordinary file's mode, or none."""

import os
import stat

import pytest

from bearinglab.files import write_atomically


def test_written_file_has_the_umask_mode(tmp_path):
    old = os.umask(0o022)
    try:
        path = write_atomically(tmp_path / "out.txt", lambda tmp: open(tmp, "w").close())
    finally:
        os.umask(old)
    assert stat.S_IMODE(path.stat().st_mode) == 0o644


def test_failed_write_leaves_no_file(tmp_path):
    def fail(tmp):
        with open(tmp, "w") as f:
            f.write("half")
        raise RuntimeError("disk full")

    with pytest.raises(RuntimeError):
        write_atomically(tmp_path / "out.txt", fail)
    assert list(tmp_path.iterdir()) == []


def test_a_ctrl_c_just_after_the_file_is_created_leaves_no_file(tmp_path, monkeypatch):
    # CI once found a temporary part file left by a Ctrl-C that came inside the call that
    # created it (tempfile.mkstemp, before its name was returned)
    real_open = os.open

    def open_then_interrupt(*args, **kwargs):
        os.close(real_open(*args, **kwargs))
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "open", open_then_interrupt)
    with pytest.raises(KeyboardInterrupt):
        write_atomically(tmp_path / "out.txt", lambda tmp: None)
    monkeypatch.undo()
    assert list(tmp_path.iterdir()) == []
