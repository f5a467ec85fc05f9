"""numba's compiled-code cache: a loop that inlines another file's kernel is recompiled when that file changes
(analysis/transient/kernel_cache.py), and a read-only installation caches elsewhere instead of failing at
import (spindlesim/_cachedirs.py)."""

import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import spindlesim
from spindlesim import _cachedirs

PACKAGE = Path(spindlesim.__file__).parent


def _python(code: str, cwd: Path, **env) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", code], cwd=cwd, capture_output=True, text=True, timeout=300,
                          env={**os.environ, **env})


def test_a_cached_loop_is_recompiled_when_a_kernel_it_inlines_changes(tmp_path):
    # numba alone keys the cache by the loop's own file: the second run would print 1.0 (the old kernel)
    (tmp_path / "dep.py").write_text("from numba import njit\n\n@njit(inline='always')\ndef k():\n    return 1.0\n")
    (tmp_path / "main.py").write_text(textwrap.dedent("""\
        from numba import njit
        import dep
        from spindlesim.analysis.transient.kernel_cache import track
        track(__file__, "loop", [dep.__file__])

        @njit(cache=True)
        def loop():
            return dep.k()
        """))
    code = "import main; print(main.loop(), sum(main.loop.stats.cache_hits.values()))"
    first = _python(code, tmp_path, PYTHONPATH=str(tmp_path))
    assert first.returncode == 0, first.stderr
    assert _python(code, tmp_path, PYTHONPATH=str(tmp_path)).stdout.split() == ["1.0", "1"]  # from the cache
    (tmp_path / "dep.py").write_text("from numba import njit\n\n@njit(inline='always')\ndef k():\n    return 2.0\n")
    again = _python(code, tmp_path, PYTHONPATH=str(tmp_path))
    assert again.stdout.split() == ["2.0", "0"], again.stderr


def test_the_engines_loop_is_tracked_with_every_compiled_bearing_family():
    from spindlesim.analysis.transient import explicit_kernel
    from spindlesim.bearings import compiled

    locator = explicit_kernel.rk4._cache._impl.locator
    assert set(locator.dependencies) == {str(Path(f).resolve()) for f in compiled.KERNEL_FILES}
    assert {Path(f).name for f in compiled.KERNEL_FILES} >= {"compiled.py", "rigid_race_kernel.py",
                                                             "flexible_race_kernel.py"}


def test_numba_and_matplotlib_get_writable_caches_where_the_defaults_are_not(tmp_path, monkeypatch):
    blocked = tmp_path / "file"
    blocked.write_text("")  # nothing can be made below a file, whoever runs the test
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "__pycache__").write_text("")
    for var in ("NUMBA_CACHE_DIR", "MPLCONFIGDIR"):
        monkeypatch.delenv(var, raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocked / "cache"))
    monkeypatch.setenv("XDG_CONFIG_HOME", str(blocked / "config"))
    monkeypatch.setenv("SPINDLESIM_CACHE", str(tmp_path / "own"))
    _cachedirs.ensure(str(package))
    assert os.environ["NUMBA_CACHE_DIR"] == str(tmp_path / "own" / "numba")
    assert os.environ["MPLCONFIGDIR"] == str(tmp_path / "own" / "matplotlib")
    # spindlesim's own cache blocked too: the temporary directory
    for var in ("NUMBA_CACHE_DIR", "MPLCONFIGDIR"):
        monkeypatch.delenv(var)
    monkeypatch.setenv("SPINDLESIM_CACHE", str(blocked / "own"))
    monkeypatch.setattr(_cachedirs.tempfile, "gettempdir", lambda: str(tmp_path / "tmp"))
    _cachedirs.ensure(str(package))
    assert Path(os.environ["NUMBA_CACHE_DIR"]).is_relative_to(tmp_path / "tmp")
    # a writable installation and user directories: nothing is set
    for var in ("NUMBA_CACHE_DIR", "MPLCONFIGDIR"):
        monkeypatch.delenv(var)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path / "config"))
    _cachedirs.ensure(str(tmp_path))
    assert "NUMBA_CACHE_DIR" not in os.environ and "MPLCONFIGDIR" not in os.environ


def test_a_read_only_installation_imports_its_kernels_without_a_word(tmp_path):
    # the package copied where no __pycache__ can be made, with no usable home: numba alone raises
    # "cannot cache function ...: no locator available" at the import of the first cached kernel
    root = tmp_path / "install"
    shutil.copytree(PACKAGE, root / "spindlesim", ignore=shutil.ignore_patterns("__pycache__", "*.nb?"))
    for d in (root / "spindlesim").rglob("*"):
        if d.is_dir():
            (d / "__pycache__").write_text("")
    (root / "spindlesim" / "__pycache__").write_text("")
    blocked = tmp_path / "file"
    blocked.write_text("")
    env = dict(PYTHONPATH=str(root), HOME=str(blocked / "home"), XDG_CACHE_HOME=str(blocked / "cache"),
               XDG_CONFIG_HOME=str(blocked / "config"), SPINDLESIM_CACHE=str(tmp_path / "own"),
               PYTHONWARNINGS="default")
    code = ("import os, spindlesim\n"
            "assert spindlesim.__file__.startswith(os.environ['PYTHONPATH'])\n"
            "import spindlesim.bearings.roller.flexible_race_kernel, spindlesim.analysis.transient.explicit_kernel\n"
            "print(os.environ['NUMBA_CACHE_DIR'])\n")
    r = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=300,
                       env={k: v for k, v in {**os.environ, **env}.items() if k not in ("NUMBA_CACHE_DIR",
                                                                                         "MPLCONFIGDIR")})
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == str(tmp_path / "own" / "numba") and r.stderr == ""
