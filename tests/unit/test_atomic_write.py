"""The atomic writer (spindlesim/output/hdf5.py, ``atomic``) leaves no temporary file whenever a Ctrl-C arrives:
while the file is written, and in the instant after the temporary file is created and before the writer has
its name (where ``tempfile.mkstemp`` left one behind: tests/cli/test_figure_process.py found a 0-byte
``campbell.h5.<random>.tmp`` after a Ctrl-C on a fresh clone)."""

import os

import pytest

import spindlesim.output.hdf5 as hdf5
from spindlesim.runs.status import _STALE


class _InterruptedClose:
    """The writer's ``os`` with a Ctrl-C in ``close`` (the descriptor is left to the process's end); the real
    ``os.close`` stays untouched for everything else (a finalizer of another test's worker processes may run
    meanwhile)."""

    def __getattr__(self, name):
        return getattr(os, name)

    @staticmethod
    def close(fd):
        raise KeyboardInterrupt


def test_a_ctrl_c_right_after_the_file_is_created_leaves_nothing(tmp_path, monkeypatch):
    monkeypatch.setattr(hdf5, "os", _InterruptedClose())
    with pytest.raises(KeyboardInterrupt):
        with hdf5.atomic(tmp_path / "campbell.h5"):
            pytest.fail("the body must not run")
    assert list(tmp_path.iterdir()) == []


def test_a_ctrl_c_while_writing_leaves_nothing_and_success_publishes(tmp_path):
    with pytest.raises(KeyboardInterrupt):
        with hdf5.atomic(tmp_path / "a.h5") as tmp:
            assert _STALE.match(os.path.basename(tmp))  # the next run's cleaner knows the name
            open(tmp, "w").write("half")
            raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []
    with hdf5.atomic(tmp_path / "b.h5", ".tmp.png") as tmp:
        assert _STALE.match(os.path.basename(tmp))
        open(tmp, "w").write("whole")
    assert [p.name for p in tmp_path.iterdir()] == ["b.h5"]
    assert (tmp_path / "b.h5").stat().st_mode & 0o777 == hdf5.file_mode()
