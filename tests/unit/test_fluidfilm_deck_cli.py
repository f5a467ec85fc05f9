"""Deck entries three_lobe / plain and the thermal / coefficients commands."""

import math
import textwrap

import h5py
import numpy as np
import pytest
from click.testing import CliRunner

from spindlesim.deck import DeckError, parse_deck


@pytest.fixture
def fluidfilm_types():
    """The family's deck module (deck models and the builder)."""
    import spindlesim.bearings.fluidfilm.section as ff

    return ff

DECK = textwrap.dedent("""\
    title: fluid-film test
    bearings:
      - name: front
        node: 1
        type: three_lobe
        diameter_mm: 69.965
        width_mm: 69.965
        clearance_mm: 0.012
        preload: 0.5
        load_N: 400
        lobes: {count: 3, groove_width_deg: 20, orientation: on_lobe}
        oil: {viscosity_Pa_s: 0.002, density_kg_m3: 805, specific_heat_J_kgK: 1940.681, inlet_C: 25}
        ambient: {temperature_C: 20, air_velocity_m_s: 0.1}
        grid: {circumferential: 96, axial: 8}
      - name: rear
        node: 2
        type: plain
        diameter_mm: 50
        width_mm: 25
        clearance_mm: 0.04
        load_N: 3000
        grooves: {count: 2, width_deg: 20}
        oil: {grade: ISO VG 32, density_kg_m3: 870, specific_heat_J_kgK: 1900, inlet_C: 40}
        grid: {circumferential: 96, axial: 8}
    operating:
      speed_rpm: 2170
    """)


def test_deck_builds_si_bearings(fluidfilm_types):
    ff = fluidfilm_types
    d = parse_deck(DECK, "t.yaml").deck
    front, rear = (ff.build(b) for b in d.bearings)
    assert front.node == 0 and front.geometry.clearance_m == pytest.approx(12e-6)
    assert front.geometry.machined_clearance_m == pytest.approx(24e-6)
    assert front.viscosity(80.0) == 0.002
    assert len(rear.geometry.lands) == 2 and rear.geometry.preload == 0.0
    assert rear.viscosity.kinematic_cst(40.0) == pytest.approx(32.0)
    K, C = front.linearized(2170 * math.pi / 30)
    assert K.shape == (2, 2) and np.all(np.diag(C) > 0)


@pytest.mark.parametrize("oil, message", [
    ("{grade: ISO VG 3, viscosity_Pa_s: 0.002, density_kg_m3: 805, specific_heat_J_kgK: 1, inlet_C: 25}",
     "exactly one"),
    ("{grade: ISO VG 3, inlet_C: 25}", "density_kg_m3"),
    ("{walther_m: 3.9, density_kg_m3: 805, specific_heat_J_kgK: 1940, inlet_C: 25}", "together"),
])
def test_bad_oil_is_located(oil, message):
    bad = DECK.replace(
        "{viscosity_Pa_s: 0.002, density_kg_m3: 805, specific_heat_J_kgK: 1940.681, inlet_C: 25}", oil)
    with pytest.raises(DeckError) as exc:
        parse_deck(bad, "bad.yaml")
    text = str(exc.value)
    assert "bad.yaml:" in text and message in text


def test_plain_bearing_rejects_preload():
    bad = DECK.replace("    load_N: 3000\n", "    load_N: 3000\n    preload: 0.3\n")
    with pytest.raises(DeckError):
        parse_deck(bad, "bad.yaml")


def test_thermal_and_coefficients_commands(tmp_path):
    from spindlesim.commands.coefficients import command as coefficients
    from spindlesim.commands.thermal import command as thermal

    deck = tmp_path / "ff.yaml"
    deck.write_text(DECK)
    out = tmp_path / "out"
    r = CliRunner().invoke(thermal, [str(deck), "-o", str(out)])
    assert r.exit_code == 0, r.output
    with h5py.File(out / "thermal.h5") as f:
        g = f["thermal/front"]
        for key in ("temperature_mean_C", "temperature_out_C", "viscosity_Pa_s", "sommerfeld",
                    "eccentricity_ratio", "attitude_angle_deg", "min_film_m",
                    "friction_torque_Nm", "oil_flow_m3_s", "reynolds_number"):
            assert "units" in g[key].attrs
        assert g["viscosity_Pa_s"][()] == 0.002
        assert g["sommerfeld"][()] == pytest.approx(1.881, rel=2e-3)
        assert f["thermal/rear/temperature_mean_C"][()] > 40.0
    r = CliRunner().invoke(coefficients, [str(deck), "-o", str(out), "--speed", "3000"])
    assert r.exit_code == 0, r.output
    with h5py.File(out / "coefficients.h5") as f:
        K = f["coefficients/front/K_N_m"][()]
        assert K.shape == (2, 2) and f["coefficients/front/K_N_m"].attrs["units"] == "N/m"
        assert f["coefficients"].attrs["speed_rpm"] == pytest.approx(3000.0)
        W, Cp = 400.0, 24e-6
        np.testing.assert_allclose(f["coefficients/front/k"][()], K * Cp / W)
    assert (out / "coefficients_front.png").stat().st_size > 1000


def test_command_without_load_and_without_rotor_is_a_located_deck_error(tmp_path):
    from spindlesim.commands.thermal import command as thermal

    deck = tmp_path / "ff.yaml"
    deck.write_text(DECK.replace("    load_N: 400\n", ""))
    r = CliRunner().invoke(thermal, [str(deck), "-o", str(tmp_path / "o")])
    assert r.exit_code == 2
    assert "ff.yaml:3:" in r.output and "bearings[0]" in r.output and "load_N" in r.output
    assert not (tmp_path / "o" / "thermal.h5").exists()


def test_without_load_N_the_load_comes_from_the_rotor_static_equilibrium(tmp_path):
    """Jeffcott rotor on two plain bearings, weight only (decks/validation/jeffcott_plain.yaml): each
    bearing carries half the weight of the 14.80 kg disk and the 11.56 kg shaft (50 mm x 300 mm steel,
    7850 kg/m3), (14.80 + 11.56) x 9.80665 / 2 = 129.2 N, vertically."""
    from pathlib import Path

    from spindlesim.commands.thermal import command as thermal

    deck = Path(__file__).parents[2] / "decks" / "validation" / "jeffcott_plain.yaml"
    r = CliRunner().invoke(thermal, [str(deck), "-o", str(tmp_path / "o"), "-q"])
    assert r.exit_code == 0, r.output
    shaft = 7850.0 * math.pi / 4 * 0.05**2 * 0.3
    with h5py.File(tmp_path / "o" / "thermal.h5") as f:
        for name in ("left", "right"):
            np.testing.assert_allclose(f[f"thermal/{name}/load_N"][()], [0.0, -(14.80 + shaft) * 9.80665 / 2],
                                       rtol=1e-6, atol=1e-6)
            assert "temperature_mean_C" not in f[f"thermal/{name}"]  # isoviscous, no density: no heat balance
            assert "temperature_mean_C" in f[f"thermal/{name}"].attrs["not_computed"]


def test_coefficient_chart_legends_sit_off_the_curves():
    """The characteristic charts' legends used to sit on the curves (issue 23); cyx lay hidden under cxy."""
    import numpy as np

    from spindlesim.bearings.fluidfilm.plots import characteristics_figure

    S = np.logspace(-1, 2, 12)
    M = np.zeros((12, 2, 2))
    M[:, 0, 0], M[:, 1, 1], M[:, 0, 1], M[:, 1, 0] = 3 * S, 5 * S, 0.1 * S, 0.1 * S
    curves = {"S": S, "eccentricity_ratio": 0.7 / (1 + S), "inlet_flow": 5 + 0 * S, "side_flow": 0.5 / (1 + S),
              "attitude_angle_deg": 55 + 0 * S, "friction_ratio": 10 * S, "k": M, "c": M}
    fig = characteristics_figure(curves, mark_S=2.0)
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    assert len(legends) == 3
    for ax in fig.axes:
        if ax.get_legend() is not None:
            box, leg = ax.get_window_extent(r), ax.get_legend().get_window_extent(r)
            assert leg.y1 <= box.y0, ax.get_title()  # under the panel, not on its curves
    texts = [t.get_text() for t in legends[0].get_texts()]
    assert texts == ["e / Cb", "inlet Q/(R Cp N L)", "side Qs/(R Cp N L)"]  # one legend for both axes
    c_lines = {ln.get_label(): ln.get_linestyle() for ln in fig.axes[3].get_lines() if ln.get_label().startswith("c")}
    assert c_lines["cyx"] == "--" and c_lines["cxy"] == "-"
