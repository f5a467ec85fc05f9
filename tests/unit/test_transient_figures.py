"""The transient's figures drawn at the figure's resolution: time series decimated to the pixel columns
(at most two points a column, the extremes kept), what the figure process is sent, what the command imports."""

import subprocess
import sys

import numpy as np
import pytest

from spindlesim.analysis.transient.engine import Perturbation, TransientSettings, simulate
from spindlesim.output import transient_plots as tp
from tests.unit.test_rolling_transient_driver import A, M, W, oscillator_rotor


def test_column_extremes_keep_every_columns_extremes_in_time_order():
    rng = np.random.default_rng(3)
    n, columns = 100_003, 437
    t = np.arange(n) * 1e-5
    y = np.sin(2 * np.pi * 80 * t) + 0.3 * rng.standard_normal(n)
    y[54_321] = 9.0  # a single spike
    xd, yd = tp.column_extremes(t, y, columns)
    assert yd.size <= 2 * columns
    assert np.all(np.diff(xd) > 0)  # samples in time order, each once
    assert yd.max() == y.max() == 9.0 and yd.min() == y.min()
    # every run of consecutive samples the points stand for keeps its own minimum and maximum
    k = -(-n // columns)
    for j in range(0, n, k):
        block = y[j:j + k]
        inside = (xd >= t[j]) & (xd <= t[min(j + k, n) - 1])
        assert yd[inside].min() == block.min() and yd[inside].max() == block.max()
    short = np.arange(10.0)
    assert tp.column_extremes(short, short, columns)[1] is short  # a short series as it is


@pytest.fixture(scope="module")
def long_run():
    # 2 s of a 50 Hz whirl sampled at 20 kHz: 40,001 samples, far more than any axes has pixel columns
    return simulate(oscillator_rotor(rpm=3000.0),
                    TransientSettings(2.0, method="rk4", step_s=5e-5, settle_s=0.2, sample_rate_hz=20000,
                                      perturbation=Perturbation(0, A * M * W ** 2), initial_velocity=((1, A * W),),
                                      speed_rpm=(3000.0, 6000.0)))


def test_drawn_lines_have_at_most_two_points_a_pixel_column(long_run):
    res = long_run
    assert res.time_s.size > 40_000
    figures = [tp.time_figure(res), tp.spectrum_figure(res), tp.run_up_figure(res)]
    for fig in figures:
        for ax in fig.axes:
            for line in ax.get_lines():
                n = len(line.get_xdata())
                assert n <= 2 * tp.pixel_columns(ax) + 2, (ax.get_title(), n)
    # the run-up line holds the largest |x| of the run, the whole-run band of the time figure its range
    up = figures[2].axes[0]
    scale = tp.length_unit(float(np.max(np.abs(res.displacement_m))))[0]
    assert np.max(up.get_lines()[0].get_ydata()) == pytest.approx(np.max(np.abs(res.displacement_m[:, 0])) / scale)
    band = figures[0].axes[0].collections[0].get_paths()[0].vertices[:, 1]
    d = res.displacement_m[:, 0]
    steady = res.time_s >= res.settle_s
    scale = tp.length_unit(float(np.ptp(d)))[0]
    mean = np.mean(d[steady])
    assert band.max() == pytest.approx((d.max() - mean) / scale) and band.min() == pytest.approx((d.min() - mean) / scale)


def test_the_figure_process_is_sent_what_the_figures_draw(long_run):
    import pickle

    shown = tp.for_figures(long_run)
    assert shown.rotor_displacement.size == 0 and shown.bearing_force_N == ()
    assert len(pickle.dumps(shown)) < 0.6 * len(pickle.dumps(long_run))
    assert shown.displacement_m is long_run.displacement_m and shown.poincare == long_run.poincare


def test_the_transient_command_imports_no_plotting_or_optimisation_library():
    code = ("import sys\n"
            "import spindlesim.cli, spindlesim.runs.transient, spindlesim.output.transient_plots\n"
            "import spindlesim.analysis.transient.engine, spindlesim.model.rig, spindlesim.output.transient_writer\n"
            "print(sorted(m for m in ('matplotlib', 'scipy.optimize', 'scipy.integrate', 'scipy.interpolate')"
            " if m in sys.modules))\n")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]"


# Transient figures an engineer reads at a glance (issue 23, section 5)

@pytest.fixture(scope="module")
def rig_run():
    """0.1 s of the transient rig (8 rollers, rigid race; its one bearing is named "bearing" inside)."""
    from spindlesim.deck import default_deck
    from spindlesim.runs.transient import rig_setup

    rotor, settings = rig_setup(default_deck("transient").deck.transient, {"duration_s": 0.1})
    return simulate(rotor, settings)


def _all_texts(fig):
    out = [t.get_text() for t in fig.texts] + [fig._suptitle.get_text() if fig._suptitle else ""]
    for ax in fig.axes:
        out += [ax.get_title(), ax.get_xlabel(), ax.get_ylabel()] + [t.get_text() for t in ax.texts]
        leg = ax.get_legend()
        out += [t.get_text() for t in leg.get_texts()] if leg else []
    return out


def test_spectrum_shows_100_db_below_its_peak_not_the_numerical_floor(rig_run):
    fig = tp.spectrum_figure(rig_run)
    for ax in fig.axes[:2]:
        line = ax.get_lines()[0]
        bottom, top = ax.get_ylim()
        peak = float(np.max(line.get_ydata()))
        assert bottom == pytest.approx(peak * 1e-5, rel=1e-6)  # 100 dB (old: 8-9 decades of round-off)
        assert top > peak  # the dominant line's marker and label inside the panel


def test_transient_figures_have_no_developer_labels_and_one_time_unit(rig_run):
    res = rig_run
    assert res.bearing_names == ("bearing",)
    figures = [tp.spectrum_figure(res), tp.poincare_figure(res), tp.orbit_figure(res), tp.time_figure(res),
               tp.bearing_output_figure(res, 0, "roller_load_N")]
    texts = [t for fig in figures for t in _all_texts(fig)]
    assert not [t for t in texts if "bearing.roller_pass" in t or "bearing.cage" in t or "Bearing 'bearing'" in t]
    assert any(t.startswith("roller pass 265.8 Hz") for t in texts)
    assert any(t.startswith("once per roller pass (265.8 Hz)") for t in texts)
    assert any(t.startswith("267 +/- 8 Hz") for t in texts)  # the dominant line to its 16.7 Hz bin (old: 266.7 +/- 8.3)
    for fig in figures[3:]:  # time figure and bearing output: every time axis in one unit
        units = {ax.get_xlabel() for ax in fig.axes if ax.get_xlabel().startswith("time")}
        assert units == {"time [ms]"}, units
    assert figures[4]._suptitle.get_text().startswith("Bearing: roller load")


def test_frequency_labels_name_the_bearing_only_among_several():
    from spindlesim.output.labels import bearing_label, frequency_label, readable_keys

    assert frequency_label("bearing.roller_pass", ["bearing"]) == "roller pass"
    assert frequency_label("front.ball_pass_outer", ["front", "rear"]) == "ball pass (outer race) (front)"
    assert frequency_label("revolution", ["front", "rear"]) == "revolution"
    assert bearing_label("rear", ["front", "rear"]) == "bearing 'rear'" and bearing_label("bearing", ["bearing"]) == "bearing"
    assert readable_keys("too short: bearing.cage (33.2 Hz)", ["bearing"]) == "too short: cage (33.2 Hz)"


def test_race_deflection_is_drawn_in_micrometres(rig_run):
    import dataclasses

    t = rig_run.time_s
    race = 2e-6 * np.sin(np.outer(t * 2 * np.pi * 33.0, np.ones(12)) + np.arange(12))  # +-2 um on 12 race nodes
    outputs = ({**rig_run.bearing_outputs[0], "race_deflection_m": (race, "m")},)
    fig = tp.bearing_output_figure(dataclasses.replace(rig_run, bearing_outputs=outputs), 0, "race_deflection_m")
    assert fig.axes[1].get_ylabel() == "race deflection [um]" and fig.axes[0].get_ylabel() == "race node"
    assert np.max(np.abs(fig.axes[1].get_lines()[0].get_ydata())) == pytest.approx(2.0, rel=0.05)  # old: 2e-06 m
