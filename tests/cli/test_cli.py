"""Every subcommand on the embedded default deck, and bad decks (exit 2, located message, nothing written)."""

import subprocess
import sys

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.cli import main

EXPECTED = {
    "static": ["static.h5", "static_deflection.png"],
    "modal": ["modal.h5", "modal_shapes.png"],
    "campbell": ["campbell.h5", "campbell.png"],
    "frf": ["frf.h5", "frf_magnitude_phase.png", "frf_real_imag.png"],
    "unbalance": ["unbalance.h5", "unbalance.png"],
}
REQUIRED = {
    "static": ["/static/node_z_m", "/static/displacement_m", "/static/slope_rad", "/static/bearing_force_N"],
    "modal": ["/modal/frequency_hz", "/modal/damping_ratio", "/modal/log_dec", "/modal/whirl", "/modal/mode_shape"],
    "campbell": ["/campbell/speed_rpm", "/campbell/frequency_hz", "/campbell/log_dec", "/campbell/whirl"],
    "frf": ["/frf/frequency_hz", "/frf/receptance_m_N"],
    "unbalance": ["/unbalance/speed_rpm", "/unbalance/response_m"],
}


def _datasets(f):
    out = []
    f.visititems(lambda name, obj: out.append(obj) if isinstance(obj, h5py.Dataset) else None)
    return out


@pytest.mark.parametrize("cmd", list(EXPECTED))
def test_subcommand_on_default_deck(cmd, tmp_path):
    args = [cmd, "-o", str(tmp_path)]
    if cmd == "campbell":
        args += ["--speeds", "500:12000:6"]
    res = CliRunner().invoke(main, args)
    assert res.exit_code == 0, res.output
    for name in EXPECTED[cmd]:
        assert (tmp_path / name).stat().st_size > 1000
    with h5py.File(tmp_path / f"{cmd}.h5") as f:
        for key in ("spindlesim_version", "deck_sha256", "deck_text", "command_line"):
            assert key in f.attrs
        for ds in REQUIRED[cmd]:
            assert ds in f
        assert all("units" in d.attrs for d in _datasets(f))
    assert not list(tmp_path.glob("*.tmp*"))


def test_modal_options_and_attrs(tmp_path):
    res = CliRunner().invoke(main, ["modal", "--speed", "1000", "--modes", "4", "-o", str(tmp_path)])
    assert res.exit_code == 0, res.output
    with h5py.File(tmp_path / "modal.h5") as f:
        assert f["/modal"].attrs["speed_rpm"] == 1000
        assert f["/modal/frequency_hz"].shape == (4,)
        assert f["/modal/mode_shape"].shape == (4, 26, 4)
        assert np.all(np.diff(f["/modal/frequency_hz"][()]) >= 0)


@pytest.mark.slow
def test_run_writes_every_analysis(tmp_path):
    res = CliRunner().invoke(main, ["run", "-o", str(tmp_path)])
    assert res.exit_code == 0, res.output
    for files in EXPECTED.values():
        for name in files:
            assert (tmp_path / name).exists()


BAD = """title: bad
shaft:
  elements:
    - [52.6, 22.0, 28.0, 7833, 206.8, 80.0, 0.3, 0.0]
bearings:
  - {name: a, node: 5, type: linear, K_N_m: [[1.0e8, 0], [0, 1.0e8]]}
operating: {speed_rpm: 100, colour: blue}
"""


@pytest.mark.parametrize("cmd", list(EXPECTED) + ["run"])
def test_bad_deck_exit_2_nothing_written(cmd, tmp_path):
    deck = tmp_path / "bad.yaml"
    deck.write_text(BAD)
    out = tmp_path / "out"
    res = CliRunner().invoke(main, [cmd, str(deck), "-o", str(out)])
    assert res.exit_code == 2
    assert f"{deck}:7:29: operating.colour: unknown key" in res.output
    assert not out.exists()


def test_out_of_range_node_is_located(tmp_path):
    deck = tmp_path / "bad.yaml"
    deck.write_text(BAD.replace(", colour: blue", ""))
    res = CliRunner().invoke(main, ["static", str(deck), "-o", str(tmp_path / "out")])
    assert res.exit_code == 2
    assert f"{deck}:6:15: bearings[0].node: node 5 is out of range: the rotor has nodes 1..2" in res.output


def test_missing_deck_file(tmp_path):
    res = CliRunner().invoke(main, ["modal", str(tmp_path / "nope.yaml"), "-o", str(tmp_path / "o")])
    assert res.exit_code == 2
    assert "cannot read deck" in res.output


def test_bad_speed_range_is_a_usage_error(tmp_path):
    res = CliRunner().invoke(main, ["campbell", "--speeds", "100:50:3", "-o", str(tmp_path)])
    assert res.exit_code == 2


def test_version_and_help_do_not_import_numerics():
    code = ("import sys; from spindlesim.cli import main; "
            "sys.argv=['spindlesim','--help']\n"
            "try:\n main()\nexcept SystemExit: pass\n"
            "bad=[m for m in ('numpy','scipy','h5py','matplotlib') if m in sys.modules]\n"
            "sys.stderr.write(repr(bad)); sys.exit(1 if bad else 0)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    r = subprocess.run([sys.executable, "-m", "spindlesim", "--version"], capture_output=True, text=True)
    assert r.returncode == 0 and "0.1.0" in r.stdout


ROTOR_DECKS = ["seed001_dtrb_rotor", "milling_spindle", "seed003_three_lobe", "seed003_spindle_linear"]


@pytest.mark.slow
@pytest.mark.parametrize("deck", ROTOR_DECKS)
def test_unbalance_sweep_on_every_rotor_deck(deck, tmp_path):
    """The example rotor decks through a speed sweep that re-solves every bearing's state at each speed
    (the path `make run` takes): seed 001's ball pair under a 0.25 N load at 6000 rpm once failed its
    set equilibrium below the noise of its own ball solutions (1.4e-9 N residual vs a 1e-10 N tolerance)."""
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "decks" / f"{deck}.yaml"
    r = CliRunner().invoke(main, ["unbalance", str(path), "-o", str(tmp_path), "-q"])
    assert r.exit_code == 0, r.output
    with h5py.File(tmp_path / "unbalance.h5") as f:
        assert f.attrs["complete"]
        assert np.all(np.isfinite(f["unbalance/response_m"][()].view(float)))


def test_log_lines_read_as_warnings_and_vv_shows_only_spindlesim_debug(tmp_path):
    """Issue 23: warnings print as "warning: ..." without logger names; -vv shows spindlesim's debug lines,
    not matplotlib's, h5py's or numba's."""
    import os
    from pathlib import Path

    exe = Path(__file__).parents[2] / ".venv" / "bin" / "spindlesim"
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
    warn = subprocess.run([str(exe), "campbell", "--speeds", "0:3000:3", "-o", str(tmp_path / "w"), "-q"],
                          env=env, capture_output=True, text=True, timeout=300)
    assert warn.returncode == 0, warn.stderr
    assert "warning: Campbell diagram: 0 rpm left out" in warn.stderr
    assert "WARNING" not in warn.stderr and "spindlesim.analysis" not in warn.stderr
    debug = subprocess.run([str(exe), "-vv", "modal", "-o", str(tmp_path / "d"), "-q"], env=env,
                           capture_output=True, text=True, timeout=300)
    assert debug.returncode == 0, debug.stderr
    lines = [ln for ln in debug.stderr.splitlines() if ln.strip()]
    assert any(ln.startswith("debug spindlesim.") for ln in lines)
    others = [ln for ln in lines if ln.startswith("debug ") and not ln.startswith("debug spindlesim.")]
    assert not others, others[:5]
