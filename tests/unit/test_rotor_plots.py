"""The rotor plots say what the results hold (issue 16, item 9): checked on the figures' artists."""

import numpy as np

from spindlesim.analysis.results import CampbellResult
from spindlesim.output.rotor_plots import campbell_figure, modes_figure


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
