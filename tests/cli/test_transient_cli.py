"""`spindlesim transient`: files, datasets, units, attributes; incomplete runs are still written."""


from pathlib import Path

import h5py
import pytest
from click.testing import CliRunner

from spindlesim.commands.transient import command


def test_rigid_race_run_writes_contract(tmp_path):
    out = tmp_path / "out"
    r = CliRunner().invoke(command, ["--rollers", "8", "--model", "rigid_race", "--duration", "0.12", "-o", str(out)])
    assert r.exit_code == 0, r.output
    for name in ("transient.h5", "transient_time.png", "transient_orbit.png", "transient_spectrum.png",
                 "transient_poincare.png", "transient_bearing_roller_load_N.png"):
        assert (out / name).stat().st_size > 0
    with h5py.File(out / "transient.h5") as f:
        g = f["transient"]
        assert g.attrs["rollers"] == 8
        assert g.attrs["cage_frequency_hz"] == pytest.approx(33.22, abs=0.005)
        assert g.attrs["roller_pass_frequency_hz"] == pytest.approx(265.8, abs=0.05)
        assert bool(f.attrs["complete"])
        t = g["time_s"][()]
        assert g["displacement_m"].shape == (t.size, 2)
        assert g["spectrum/amplitude_m"].shape == (g["spectrum/frequency_hz"].size, 2)
        assert g["poincare/x_m"].shape == g["poincare/y_m"].shape and g["poincare/x_m"].size > 5
        for ds in ("time_s", "displacement_m", "spectrum/frequency_hz", "spectrum/amplitude_m", "poincare/x_m"):
            assert g[ds].attrs["units"] in ("s", "m", "Hz")
        assert "transient" in f.attrs["deck_text"]


def test_bad_deck_exits_2(tmp_path):
    deck = tmp_path / "bad.yaml"
    deck.write_text("transient:\n  rollers: 2\n")
    r = CliRunner().invoke(command, [str(deck), "-o", str(tmp_path / "o")])
    assert r.exit_code == 2
    assert "rollers" in r.output
    assert not (tmp_path / "o").exists()


def test_incomplete_result_is_written_and_marked(tmp_path):
    from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
    from spindlesim.output.hdf5 import RunInfo
    from spindlesim.output.transient_writer import write_transient
    from tests.unit.test_rolling_transient_driver import Sabotage, oscillator_rotor

    res = simulate(oscillator_rotor(Sabotage(0.26, "interrupt")),
                   TransientSettings(0.5, sample_rate_hz=1000, step_s=1e-4, perturbation=Perturbation(0, 1.0)))
    path = write_transient(tmp_path / "transient.h5", RunInfo("deck", "<test>", "0" * 64), res)
    with h5py.File(path) as f:
        assert not bool(f.attrs["complete"])
        assert "interrupted" in f.attrs["incomplete_reason"]
        assert f["transient/time_s"][-1] <= 0.3


def _texts(fig) -> str:
    return " ".join([t.get_text() for t in fig.texts] + [t.get_text() for ax in fig.axes for t in ax.texts]
                    + [ax.get_title() for ax in fig.axes]).replace("\n", " ")


def test_run_stopped_before_the_steady_part_has_no_blank_panels():
    from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
    from spindlesim.output.transient_plots import orbit_figure, poincare_figure, spectrum_figure
    from tests.unit.test_rolling_transient_driver import Sabotage, oscillator_rotor

    res = simulate(oscillator_rotor(Sabotage(0.1505, "interrupt")),
                   TransientSettings(0.5, sample_rate_hz=1000, step_s=1e-4, settle_s=0.3,
                                     perturbation=Perturbation(0, 1.0)))
    assert not res.complete and res.time_s[-1] < res.settle_s
    assert res.spectrum.frequency_hz.size == 0 and not any(p.time_s.size for p in res.poincare)

    spec = spectrum_figure(res)
    assert all(ax.lines for ax in spec.axes)  # the spectrum of what was computed, drawn
    assert "before the steady part" in _texts(spec) and "INCOMPLETE: interrupted" in _texts(spec)
    orbit = orbit_figure(res)
    assert orbit.axes[0].lines and "before the steady part" in _texts(orbit)
    poincare = poincare_figure(res)
    assert "not enough steady data" in _texts(poincare) and "0.15 s" in _texts(poincare)

    short = simulate(oscillator_rotor(Sabotage(0.0055, "interrupt")),
                     TransientSettings(0.5, sample_rate_hz=1000, step_s=1e-4, settle_s=0.3,
                                       perturbation=Perturbation(0, 1.0)))
    assert "not enough steady data" in _texts(spectrum_figure(short))  # too few samples even for that


def test_help_names_the_node_the_file_records():
    """`transient --help` says where the response is recorded, and the engine records there: the rig's
    journal, else rotor_transient.record_node or the node of the first entry under bearings: (seed 001
    lists its ball pair at node 1 before the DTRB at node 5: the old help said "at the DTRB node")."""
    from spindlesim.analysis.transient.engine import record_node
    from spindlesim.deck import default_deck, load_deck
    from spindlesim.runs.transient import rig_setup, rotor_setup

    text = " ".join(CliRunner().invoke(command, ["--help"]).output.split())
    assert "DTRB node" not in text
    assert "rotor_transient.record_node" in text and "node of the first entry under bearings:" in text
    assert "journal" in text and "centre recorded" in text

    deck = load_deck(Path(__file__).parents[2] / "decks" / "seed001_dtrb_rotor.yaml").deck
    rotor, settings = rotor_setup(deck, {})
    assert settings.record_node is None  # the deck leaves it to the default
    first, dtrb = deck.bearings[0], next(b for b in deck.bearings if b.type == "dtrb")
    assert first.type == "ball" and dtrb.node != first.node
    assert record_node(rotor, settings) == first.node - 1  # 0-based
    chosen = rotor_setup(deck.model_copy(update={"rotor_transient": deck.rotor_transient.model_copy(
        update={"record_node": dtrb.node})}), {})
    assert record_node(*chosen) == dtrb.node - 1

    rig_rotor, rig_settings = rig_setup(default_deck("transient").deck.transient, {})
    assert rig_rotor.dofs.n_nodes == 1 and record_node(rig_rotor, rig_settings) == 0


def test_short_rig_run_is_periodic_but_too_short_for_the_cage(tmp_path):
    """50 ms of the rig (8 rollers, rigid race): the steady part (after 40 %, 30 ms) is period-1 once per
    roller pass and settled, but its 1/T bins (33 Hz) cannot resolve the 33.2 Hz cage: the file, the
    summary and the spectrum say so; the numbers are recomputed here from the file's own time grid."""
    import numpy as np

    out = tmp_path / "out"
    r = CliRunner().invoke(command, ["--rollers", "8", "--model", "rigid_race", "--duration", "0.05", "-o", str(out)])
    assert r.exit_code == 0, r.output
    with h5py.File(out / "transient.h5") as f:
        g = f["transient"]
        a = g.attrs
        t, d = g["time_s"][()], g["displacement_m"][()]
        steady = t >= a["settle_s"] - 1e-12
        n = int(steady.sum())
        assert a["steady_duration_s"] == pytest.approx(n / a["sample_rate_hz"])
        assert a["frequency_resolution_hz"] == pytest.approx(a["sample_rate_hz"] / n)
        assert a["frequency_resolution_hz"] == pytest.approx(1 / (0.05 - a["settle_s"]), rel=0.01)
        cage = a["cage_frequency_hz"]
        assert cage < 2 * a["frequency_resolution_hz"] < a["roller_pass_frequency_hz"]
        assert a["unresolved_frequencies"] == "bearing.cage" and "window too short" in a["resolution_note"]
        assert bool(a["settled"])
        p = g["poincare"].attrs
        assert p["sampling"] == "once per bearing.roller_pass" and p["periodicity"] == "period-1"
        extent = np.ptp(d[steady], axis=0).max()
        assert p["orbit_extent_m"] == pytest.approx(extent) and p["tolerance_m"] == pytest.approx(0.01 * extent)
        xy = np.column_stack([g["poincare/x_m"][()], g["poincare/y_m"][()]])
        assert p["spread_m"] == pytest.approx(np.max(np.linalg.norm(xy - xy.mean(axis=0), axis=1)))
        assert p["spread_m"] < p["tolerance_m"] and xy.shape[0] == p["classified_points"] >= 2
    assert "WINDOW TOO SHORT" in r.output and "cage (33.2" in r.output and "bearing.cage" not in r.output
    assert "Poincare once per roller pass: period-1" in r.output and "NOT SETTLED" not in r.output


@pytest.mark.slow
def test_rotor_released_from_a_perturbation_is_not_settled(tmp_path):
    """decks/validation/roller_rotor.yaml: a 5 N force released at the disk, no unbalance, rigid-race
    roller bearings without damping (`damping: {stiffness_proportional_s: 0}` in a copy: the deck's own
    bearings are damped since issue 30, which settles the run).  What the 0.1 s run calls its steady part is
    the free vibration of the first mode: the summary says NOT SETTLED and names the mode, which the file's own
    linear modes (solved separately by the modal analysis) confirm."""
    import numpy as np

    text = (Path(__file__).parents[2] / "decks" / "validation" / "roller_rotor.yaml").read_text()
    deck = tmp_path / "roller_rotor.yaml"
    deck.write_text(text.replace("model: rigid_race}", "model: rigid_race, damping: {stiffness_proportional_s: 0}}"))
    assert deck.read_text().count("stiffness_proportional_s: 0") == 2
    out = tmp_path / "out"
    r = CliRunner().invoke(command, [str(deck), "-o", str(out)])
    assert r.exit_code == 0, r.output
    with h5py.File(out / "transient.h5") as f:
        a = f["transient"].attrs
        assert not bool(a["settled"]) and "free vibration" in a["settling_note"]
        modal = f["transient/linearized_frequency_hz"][()]
        assert np.min(np.abs(modal - a["ringing_mode_hz"])) < 0.02 * a["ringing_mode_hz"]
        fr, amp = f["transient/spectrum/frequency_hz"][()], f["transient/spectrum/amplitude_m"][()]
        dominant = fr[np.argmax(amp.max(axis=1)[1:]) + 1]
        assert abs(dominant - a["ringing_mode_hz"]) <= 2 * a["frequency_resolution_hz"]
    assert "NOT SETTLED: the free vibration of the start has not died out" in r.output
    assert "(of a response that has NOT SETTLED)" in r.output


@pytest.mark.slow
def test_figures_from_the_figure_process_equal_those_drawn_in_the_main_process(tmp_path):
    # the command sends its result (without the rotor's DOFs) to the figure process: the same PNGs
    import os
    import subprocess

    exe = Path(__file__).parents[2] / ".venv" / "bin" / "spindlesim"
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1", MPLBACKEND="Agg")
    args = [str(exe), "transient", "--rollers", "8", "--duration", "0.05", "-q", "-o"]
    a = subprocess.run(args + [str(tmp_path / "a")], env=env, capture_output=True, text=True, timeout=300)
    b = subprocess.run(args + [str(tmp_path / "b")], env={**env, "SPINDLESIM_FIGURE_PROCESS": "0"},
                       capture_output=True, text=True, timeout=300)
    assert a.returncode == b.returncode == 0, a.stderr + b.stderr
    pngs = sorted(p.name for p in (tmp_path / "a").glob("*.png"))
    assert len(pngs) == 5 and pngs == sorted(p.name for p in (tmp_path / "b").glob("*.png"))
    for name in pngs:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name
