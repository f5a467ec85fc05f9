"""The rotor plots say what the results hold (issue 16, item 9): checked on the figures' artists."""

import dataclasses

import numpy as np
import pytest

from spindlesim.analysis.results import CampbellResult
from spindlesim.output.campbell_plots import campbell_figure
from spindlesim.output.rotor_plots import modes_figure


def _campbell(log_dec_shift=0.0, critical=()):
    s = np.linspace(0, 12000, 13)
    f = np.stack([300 + 0 * s, 800 - 0.01 * s, 800 + 0.01 * s], axis=1)
    ld = np.full_like(f, 0.05)
    ld[8:, 1] = -0.02 + log_dec_shift  # mode 2 unstable from 8000 rpm unless shifted
    whirl = np.array([["forward", "backward", "forward"]] * len(s))
    return CampbellResult(speed_rpm=s, frequency_hz=f, log_dec=ld, damping_ratio=ld / (2 * np.pi), whirl=whirl,
                          critical_speeds_rpm=np.array([c for c, _ in critical], float),
                          critical_modes=np.array([k for _, k in critical], int))


def _texts(fig):
    return [t.get_text() for ax in fig.axes for t in ax.texts] + [ax.get_title() for ax in fig.axes]


def test_campbell_title_claims_critical_speeds_only_when_there_are_some():
    fig = campbell_figure(_campbell(log_dec_shift=0.1))
    assert "no critical speed" in fig.axes[0].get_title()
    fig = campbell_figure(_campbell(critical=[(9000.0, 0)]))
    assert "critical speeds 9000 rpm" in fig.axes[0].get_title()
    stars = [ln for ln in fig.axes[0].lines if ln.get_marker() == "*"]
    assert len(stars) == 1 and stars[0].get_xdata()[0] == 9000.0
    assert any("9000 rpm" in t for t in _texts(fig))


def test_campbell_excitation_lines_legends_and_unstable_region():
    fig = campbell_figure(_campbell(), operating_rpm=6000.0)
    labels = [t.get_text() for leg in fig.legends for t in leg.get_texts()]
    for want in ("0.5x", "1x", "2x", "forward", "backward", "mode 1", "mode 3", "unstable"):
        assert want in labels, (want, labels)
    ax1 = fig.axes[0]
    assert ax1.get_ylim()[1] < 1.2 * 920  # scaled to the modes, not to the 2x line's end (400 Hz here anyway)
    spans = [p for p in ax1.patches]  # the unstable speeds are shaded
    assert spans and min(p.get_x() for p in spans) == 8000.0


def test_campbell_stable_rotor_has_no_unstable_shading():
    fig = campbell_figure(_campbell(log_dec_shift=0.1))
    assert not fig.axes[0].patches
    labels = [t.get_text() for leg in fig.legends for t in leg.get_texts()]
    assert "unstable" not in labels


def test_mode_shapes_in_axial_order_with_bearings_marked():
    from spindlesim.analysis.modal import solve_modal
    from spindlesim.deck import default_deck
    from spindlesim.model.build import build_rotor

    rotor = build_rotor(default_deck("milling_spindle").deck)
    m = solve_modal(rotor, 0.0, n_modes=3)
    fig = modes_figure(m, 3, (("front", 0.0525), ("rear", 0.39)))
    line = fig.axes[1].lines[0]
    z = np.asarray(line.get_xdata())
    assert np.all(np.diff(z) >= 0)  # the tool (negative z, nodes 20-26) is drawn ahead of the nose
    assert z[0] < 0
    dashed = [ln for ln in fig.axes[1].lines if ln.get_linestyle() == "--"]
    assert sorted(round(ln.get_xdata()[0], 1) for ln in dashed) == [52.5, 390.0]
    assert fig.legends and not fig.axes[0].get_legend()  # the legend sits outside the data


def test_frf_phase_is_unwrapped():
    from spindlesim.analysis.frf import solve_frf
    from spindlesim.deck import default_deck
    from spindlesim.model.build import build_rotor
    from spindlesim.output.rotor_plots import frf_magnitude_phase_figure

    rotor = build_rotor(default_deck("spindle_linear").deck)
    r = solve_frf(rotor, np.linspace(10, 5000, 800), 1, "x", 1, "x")
    phase = frf_magnitude_phase_figure(r).axes[1].lines[0].get_ydata()
    assert np.max(np.abs(np.diff(phase))) < 180.0  # no false +-360 jumps (a light mode turns 100 deg in a step)


# Campbell diagrams read at a glance (issue 23, section 5)

def _split_pair_campbell():
    """Like seed 003: a low mode, a split pair (backward 1117, forward 1119 Hz) and two pairs far above
    every excitation line (1830, 3153 Hz); orders 1x, 2x and a 4-tooth cutter."""
    from spindlesim.analysis.resonance import find_crossings

    s = np.linspace(200, 12000, 30)
    f = np.stack([17 + 0 * s, 1117 - 1e-4 * s, 1119 + 1e-4 * s, 1829 + 0 * s, 1832 + 0 * s, 3153 + 0 * s], axis=1)
    whirl = np.array([["forward", "backward", "forward", "backward", "forward", "backward"]] * len(s))
    ld = np.stack([3.85 + 0 * s, 0.003 + 1e-6 * s, 0.004 + 1e-6 * s, 0.03 + 0 * s, 0.03 + 0 * s, 0.05 + 0 * s], axis=1)
    zeta = ld / (2 * np.pi)
    cross = find_crossings(s, f, zeta, whirl, (1.0, 2.0, 4.0), (2170.0, 2170.0))
    return CampbellResult(speed_rpm=s, frequency_hz=f, log_dec=ld, damping_ratio=zeta, whirl=whirl,
                          critical_speeds_rpm=np.zeros(0), critical_modes=np.zeros(0, int), crossings=cross)


def test_campbell_split_pair_markers_do_not_merge():
    fig = campbell_figure(_split_pair_campbell(), operating_rpm=2170.0, teeth=4)
    ax = fig.axes[0]
    fwd = next(ln for ln in ax.lines if ln.get_gid() == "whirl:forward:3")
    bwd = next(ln for ln in ax.lines if ln.get_gid() == "whirl:backward:2")
    assert fwd.get_marker() == "^" and bwd.get_marker() == "v"
    xf, xb = set(fwd.get_xdata()), set(bwd.get_xdata())
    assert xf and xb and not xf & xb  # never on top of each other (a star): forward and backward alternate
    assert len(xf | xb) == 30
    assert bwd.get_markerfacecolor() in ("white", (1.0, 1.0, 1.0, 1.0)) and fwd.get_markerfacecolor() != "white"


def test_campbell_frequency_axis_shows_the_excitation_lines_and_names_the_modes_above():
    fig = campbell_figure(_split_pair_campbell(), operating_rpm=2170.0, teeth=4)
    ax = fig.axes[0]
    top = ax.get_ylim()[1]
    assert 1119 * 1.05 < top < 1400  # the pair nearest the 4x line whole, not the 3153 Hz mode (old: 3405)
    assert 200.0 / top > 0.15  # the 1x line ends at 200 Hz: a sixth of the height at least
    note = [t.get_text() for t in ax.texts if t.get_gid() == "hidden-modes"]
    assert note == ["above the axis: modes 4-6 (1829-3153 Hz; log dec below)"]
    labels = [t.get_text() for leg in fig.legends for t in leg.get_texts()]
    assert "4x tooth passing" in labels and "mode 6" in labels


def test_campbell_log_dec_panel_neither_clipped_nor_collapsed():
    r = _split_pair_campbell()
    fig = campbell_figure(r)
    ax2 = fig.axes[1]
    bottom, top = ax2.get_ylim()
    assert top >= 2 * 3.85  # the largest log dec is not on the edge (old: 1.3 x)
    to_axes = lambda y: ax2.transLimits.transform(ax2.transScale.transform((1.0, y)))[1]  # noqa: E731
    assert to_axes(0.0) < 0.15  # every mode stable: no empty negative half (old: 0 at 0.4 of the height)
    assert to_axes(0.003) - to_axes(0.0) > 0.1  # the least damped mode well clear of the zero line
    unstable = dataclasses.replace(r, log_dec=r.log_dec - 0.02)
    b, t = campbell_figure(unstable).axes[1].get_ylim()
    assert b <= 2 * np.min(unstable.log_dec) and t >= 2 * np.max(unstable.log_dec)


def test_frf_magnitude_starts_at_the_static_compliance():
    from spindlesim.analysis.frf import solve_frf
    from spindlesim.analysis.points import OperatingPoints
    from spindlesim.deck import default_deck
    from spindlesim.model.build import build_rotor
    from spindlesim.output.rotor_plots import frf_magnitude_phase_figure

    points = OperatingPoints(build_rotor(default_deck("spindle_linear").deck))
    r = solve_frf(points, np.linspace(50, 5000, 200), 1, "x", 1, "x", speed_rpm=2170.0)
    assert r.static_compliance_m_N is not None
    ax = frf_magnitude_phase_figure(r).axes[0]
    dot = [ln for ln in ax.get_lines() if ln.get_gid() == "static"]
    assert len(dot) == 1 and list(dot[0].get_xdata()) == [0.0]  # the grid starts at 50 Hz, the axis at 0
    assert dot[0].get_ydata()[0] == pytest.approx(abs(r.static_compliance_m_N) * 1e6)
    assert ax.get_xlim()[0] == 0.0


def test_static_title_states_the_axial_load():
    from spindlesim.analysis.points import OperatingPoints
    from spindlesim.analysis.static import solve_static
    from spindlesim.deck import load_deck
    from spindlesim.model.build import build_rotor
    from spindlesim.output.rotor_plots import static_figure

    from pathlib import Path

    deck = load_deck(Path(__file__).parents[2] / "decks" / "seed001_dtrb_rotor.yaml").deck
    r = solve_static(OperatingPoints(build_rotor(deck)))
    title = static_figure(r).axes[0].get_title()
    assert title.startswith("Static deflection under Fx 0 N, Fy -2000 N, Fz 2000 N (applied"), title  # old: no Fz
