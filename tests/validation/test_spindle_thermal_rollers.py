"""The spindle's thermal model with roller bearings (issue 22, items 1-4: "cylindrical roller and tapered roller
bearings: Palmgren with the family's coefficients", their nodes in the network, the DTRB's preload and the
roller bearing's clearance from the solved temperatures).

References written here, independent of the code under test:
- Palmgren's moments by hand (Harris and Kotzalas 2007, friction-torque chapter): M = f1 P1 d_m + 1e-7 f0 (nu n)^(2/3)
  d_m^3 [N mm]; tapered f1 0.0004, P1 = max(2 Y Fa, Fr) with ISO 281's Y = 0.4 cot(alpha); cylindrical f1 0.0003,
  P1 = Fr; f0 for oil-air (taken as oil mist) 3 (tapered) and 2.15 (cylindrical, 1.5-2.8);
- the rows of a DTRB in equilibrium: their thrusts differ by the axial load, their radial forces add to the radial
  load (statics, not the bearing model);
- Hertz's line contact (Johnson 1985, eq. 4.43): b = sqrt(4 P R / (pi E*)), P the load per length;
- Holm's constriction of a long ellipse: K(e) -> ln(4 a / b), R = ln(4 a / b) / (2 pi k a);
- conservation: at a steady state the heat generated leaves through the boundaries;
- one spindle two ways: the DTRB at the solved temperatures prescribed in a deck (temperatures_C, no network) has the
  stiffness of the solved thermal state.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from spindlesim.bearings.base import Lubrication
from spindlesim.bearings.dtrb.bearing import DOFS_5, DtrbBearing
from spindlesim.bearings.dtrb.section import geometry_from
from spindlesim.bearings.roller.bearing import RigidRaceBearing
from spindlesim.bearings.roller.kinematics import CageKinematics
from spindlesim.deck import default_deck, load_deck
from spindlesim.bearings.conductance import ellipse_constriction_resistance, line_contact_half_width
from spindlesim.thermal.friction import Lubricant

ROOT = Path(__file__).parents[2]
LATHE = ROOT / "decks" / "lathe_headstock.yaml"
RPM = math.pi / 30.0
LUB = Lubrication(Lubricant.from_grade("ISO VG 32"), "oil_air")


def _palmgren_Nm(f1, P1_N, f0, dm_m, nu_m2_s, n_rpm):
    """Palmgren by hand, in its own units (N mm, cSt, rpm, mm) -> N m."""
    dm = dm_m * 1e3
    nun = nu_m2_s * 1e6 * n_rpm
    m0 = 1e-7 * f0 * nun ** (2.0 / 3.0) * dm ** 3 if nun >= 2000.0 else 160e-7 * f0 * dm ** 3
    return (f1 * P1_N * dm + m0) * 1e-3


@pytest.fixture(scope="module")
def dtrb():
    return DtrbBearing(geometry_from(default_deck("dtrb").deck.dtrb.bearing), 30e-6, dof_names=DOFS_5)


def test_dtrb_heat_is_palmgren_per_row_by_hand(dtrb):
    load = np.array([4000.0, 0.0, 3000.0, 0.0, 0.0])
    n = 3000.0
    h = dtrb.heat(n * RPM, load, LUB, 40.0)
    Fr, Fa = h.detail["radial_N"], h.detail["axial_N"]
    # statics of the two rows (not the model): thrusts differ by FZ, radial forces add up to FX
    assert Fa[0] - Fa[1] == pytest.approx(3000.0, rel=1e-6)
    assert Fr[0] + Fr[1] == pytest.approx(4000.0, rel=1e-6)
    Y = 0.4 / math.tan(math.radians(15.64))  # 1.4288: the default deck's cup angle
    assert Y == pytest.approx(1.4288, abs=1e-4)
    nu = LUB.lubricant.kinematic_m2_s(40.0)
    assert nu == pytest.approx(32e-6, rel=0.03)  # ISO VG 32 at 40 C: 32 cSt (the grade's definition)
    M = sum(_palmgren_Nm(0.0004, max(2.0 * Y * fa, fr), 3.0, 0.070, nu, n) for fr, fa in zip(Fr, Fa))
    assert h.total_W == pytest.approx(M * n * RPM, rel=1e-9)
    # by hand: rows' P1 = 2 Y Fa = 16.5 and 7.93 kN -> f1 P1 d_m = 462 and 222 N mm; M_v = 1e-7 x 3 x (32 x 3000)^(2/3)
    # x 70^3 = 216 N mm a row; 1116 N mm at 314 rad/s: 351 W.  The split: 1/4, 1/2 + viscous, 1/4
    assert 340.0 < h.total_W < 360.0
    load_W = sum(0.0004 * max(2.0 * Y * fa, fr) * 0.070 for fr, fa in zip(Fr, Fa)) * n * RPM
    assert h.inner_W == pytest.approx(0.25 * load_W, rel=1e-9) and h.outer_W == pytest.approx(0.25 * load_W, rel=1e-9)


def test_cylindrical_roller_heat_is_palmgren_by_hand():
    kin = CageKinematics(57.5e-3, 72.5e-3, 7.5e-3)
    b = RigidRaceBearing("rear", 0, 20, 1.0e9, 10.0 / 9.0, kin, 5e-6)
    W = np.array([1200.0, -1600.0])  # 2 kN radial
    n = 2000.0
    h = b.heat(n * RPM, W, LUB, 35.0)
    assert h.detail["radial_N"] == pytest.approx(2000.0, rel=1e-6)  # the pitch-averaged reaction carries the load
    nu = LUB.lubricant.kinematic_m2_s(35.0)
    M = _palmgren_Nm(0.0003, 2000.0, 2.15, 0.065, nu, n)
    assert h.total_W == pytest.approx(M * n * RPM, rel=1e-6)
    assert h.row_thrust_N is None  # no rows' thrust: the network's outputs show none (NaN), not 0
    ring = at_temperatures_clearance(b, 50.0, 30.0, 40.0)
    # by hand: d_o' - d_i' - 2 D' with 11.5e-6 /K: 72.5 mm x 10 K - 57.5 mm x 30 K - 2 x 7.5 mm x 20 K = -19.95 mm K
    assert ring == pytest.approx(5e-6 + 0.5 * 11.5e-6 * (72.5e-3 * 10 - 57.5e-3 * 30 - 2 * 7.5e-3 * 20), rel=1e-9)


def at_temperatures_clearance(b, inner, outer, rollers):
    from spindlesim.thermal.growth_bearings import BearingTemperatures

    warm = b.at_temperatures(BearingTemperatures(inner, outer, rollers))
    assert warm.at_temperatures(BearingTemperatures(inner, outer, rollers)).radial_clearance_m == \
        pytest.approx(warm.radial_clearance_m, rel=1e-12)  # from the cold assembly every time
    return warm.radial_clearance_m


def test_line_contact_half_width_and_its_constriction():
    E, nu = 208e9, 0.3
    e_star = E / (2.0 * (1.0 - nu ** 2))  # two equal bodies
    Q, L, R = 1000.0, 10e-3, 5e-3
    b = float(line_contact_half_width(Q, R, L, 2.0 * e_star))
    assert b == pytest.approx(math.sqrt(4.0 * (Q / L) * R / (math.pi * e_star)), rel=1e-12)
    assert b == pytest.approx(74.6e-6, rel=2e-3)
    a = 0.5 * L  # a long ellipse: Holm's K(e) -> ln(4 a / b)
    assert a / b > 60
    k = 40.0
    assert ellipse_constriction_resistance(a, b, k) == pytest.approx(math.log(4 * a / b) / (2 * math.pi * k * a),
                                                                     rel=2e-4)


@pytest.fixture(scope="module")
def lathe():
    from spindlesim.analysis.points import OperatingPoints
    from spindlesim.model.thermal import build_spindle_thermal
    from spindlesim.runs.common import operating_points

    loaded = load_deck(LATHE)
    pts = operating_points(loaded)
    model = build_spindle_thermal(loaded.deck, pts.rotor)
    pts = pts if pts.thermal is not None else OperatingPoints(pts.rotor, model)
    return loaded, pts


def test_lathe_headstock_steady_state_conserves_heat_and_preloads_the_dtrb(lathe):
    loaded, pts = lathe
    st = pts.thermal_state(1000.0)
    assert st.converged
    generated = st.total_heat_W
    assert generated > 100.0
    assert sum(st.removed_W.values()) == pytest.approx(generated, rel=1e-4)
    assert abs(st.stored_W) < 1e-4 * generated
    # the DTRB's cones run warmer than its cup: its position preload rises (seed 001's delta0 grows)
    p = st.parts_C["front_dtrb"]
    assert p.inner_ring_C > p.outer_ring_C > 20.0
    cold = next(b for b in pts.rotor.bearings if b.name == "front_dtrb")
    warm = next(b for b in st.operating.bearings if b.name == "front_dtrb")
    assert warm.preload_m > cold.preload_m + 1e-6
    # every network node of the rear cylindrical roller bearing is there and warmer than the ambient
    for node in ("bearing:rear_roller:inner", "bearing:rear_roller:rollers", "bearing:rear_roller:outer"):
        assert st.temperatures_C[node] > 20.0
    # its heat is Palmgren at the radial load the rotor's statics put on it, rollers' temperature for the oil
    rear = st.bearings["rear_roller"]
    nu = LUB.lubricant.kinematic_m2_s(st.temperatures_C["bearing:rear_roller:rollers"])
    M = _palmgren_Nm(0.0003, float(rear.detail["radial_N"]), 2.15, 0.065, nu, 1000.0)
    assert rear.total_W == pytest.approx(M * 1000.0 * RPM, rel=1e-9)


def test_prescribing_the_solved_temperatures_gives_the_solved_bearing(lathe, tmp_path):
    """The DTRB at its solved part temperatures, prescribed in a deck without the thermal section, is the bearing
    of the thermal state: same preload, same stiffness (a second path through the deck)."""
    from spindlesim.analysis.points import OperatingPoints

    loaded, pts = lathe
    st = pts.thermal_state(1000.0)
    p = st.parts_C["front_dtrb"]
    doc = yaml.safe_load(LATHE.read_text())
    doc.pop("spindle_thermal")
    doc["operating"]["speed_rpm"] = 1000.0
    entry = next(e for e in doc["bearings"] if e["name"] == "front_dtrb")
    entry["temperatures_C"] = {"inner_ring": p.inner_ring_C, "outer_ring": p.outer_ring_C,
                               "rolling_elements": p.rolling_elements_C, "reference": p.reference_C}
    rear = next(e for e in doc["bearings"] if e["name"] == "rear_roller")
    r = st.parts_C["rear_roller"]
    rear["temperatures_C"] = {"inner_ring": r.inner_ring_C, "outer_ring": r.outer_ring_C,
                              "rolling_elements": r.rolling_elements_C, "reference": r.reference_C}
    path = tmp_path / "prescribed.yaml"
    path.write_text(yaml.safe_dump(doc))
    from spindlesim.model.build import build_rotor

    rotor = build_rotor(load_deck(path).deck)
    warm = next(b for b in st.operating.bearings if b.name == "front_dtrb")
    given = next(b for b in rotor.bearings if b.name == "front_dtrb")
    assert given.preload_m == pytest.approx(warm.inner.preload_m if hasattr(warm, "inner") else warm.preload_m,
                                            rel=1e-12)
    given_rear = next(b for b in rotor.bearings if b.name == "rear_roller")
    warm_rear = next(b for b in st.operating.bearings if b.name == "rear_roller")
    assert given_rear.radial_clearance_m == pytest.approx(warm_rear.radial_clearance_m, rel=1e-12)
    state = OperatingPoints(rotor).state(1000.0)
    k_given = dict(zip((b.name for b in state.bearings), state.coefficients))["front_dtrb"][0]
    k_solved = dict(zip((b.name for b in st.operating.bearings), st.operating.coefficients))["front_dtrb"][0]
    assert np.allclose(k_given, k_solved, rtol=1e-6, atol=1e-6 * np.abs(k_solved).max())


def test_the_lathe_dtrb_runs_away_above_its_speed_limit(lathe):
    from spindlesim.analysis.spindle_thermal import ThermalRunawayError

    _, pts = lathe
    with pytest.raises(ThermalRunawayError, match=r"'front_dtrb' at 2000 rpm"):
        pts.thermal.steady(2000.0)


def _lathe_doc():
    return yaml.safe_load(LATHE.read_text())


def test_roller_entries_the_network_cannot_take_are_located_deck_errors():
    from spindlesim.deck import DeckError, parse_deck

    d = _lathe_doc()
    rear = next(i for i, e in enumerate(d["bearings"]) if e["name"] == "rear_roller")
    d["bearings"][rear]["model"] = "flexible_race"
    with pytest.raises(DeckError) as exc:
        parse_deck(yaml.safe_dump(d), "lathe.yaml")
    assert any(f"bearings[{rear}].model" in str(i) and "rigid_race" in str(i) for i in exc.value.issues)
    d = _lathe_doc()
    front = next(i for i, e in enumerate(d["bearings"]) if e["name"] == "front_dtrb")
    d["bearings"][front]["temperatures_C"] = {"inner_ring": 40, "outer_ring": 30, "rolling_elements": 35}
    with pytest.raises(DeckError) as exc:
        parse_deck(yaml.safe_dump(d), "lathe.yaml")
    assert any(f"bearings[{front}].temperatures_C" in str(i) and "exclude each other" in str(i)
               for i in exc.value.issues)


def test_a_warm_up_that_runs_away_says_so(lathe):
    """Above the speed limit a warm-up's temperatures climb until a fluid leaves its property tables (the coolant
    boils): a thermal runaway naming the instant and the speed, not a property-table error."""
    from spindlesim.analysis.spindle_thermal import ThermalRunawayError

    _, pts = lathe
    with pytest.raises(ThermalRunawayError, match=r"warm-up ran away at [0-9.]+ min \(4000 rpm\)"):
        pts.thermal.warm_up((0.0,), (4000.0,), 7200.0, samples=3)


def test_the_transient_starts_from_the_thermal_equilibrium(lathe, tmp_path):
    """Item 5: a transient of a deck whose analyses take the thermal state runs on the bearings of the thermal
    equilibrium of its speed: its static start is that state's displacement, not the cold rotor's."""
    import h5py
    from click.testing import CliRunner

    from spindlesim.cli import main

    _, pts = lathe
    res = CliRunner().invoke(main, ["transient", str(LATHE), "--duration", "0.004", "-o", str(tmp_path)])
    assert res.exit_code == 0, res.output
    assert "thermal equilibrium of 1200 rpm" in res.output
    with h5py.File(tmp_path / "transient.h5") as f:
        start = f["transient/static_displacement"][:]
        assert float(f["transient"].attrs["thermal_equilibrium_rpm"]) == 1200.0
    warm = pts.thermal_state(1200.0).operating.q[: start.size]
    from spindlesim.analysis.operating import operating_state

    cold = operating_state(pts.rotor, 1200.0, pts.shaft).q[: start.size]
    scale = np.abs(warm).max()
    # the same equilibrium to the loop's tolerance (0.01 K: this module solved neighbouring speeds first, the run
    # starts from the ambient)
    assert np.abs(start - warm).max() < 1e-4 * scale
    assert np.abs(cold - warm).max() > 1e-3 * scale  # the thermal state is not the cold one here


def test_analyses_at_an_instant_of_the_warm_up(tmp_path):
    """Item 5's "or a time in the warm-up": with `analyses: warm_up` and `warm_up_at_min`, every analysis takes
    the temperatures the warm-up has reached then (at its own speed); at 0 min these are the cold spindle's, so
    the static state is the rotor without a thermal model; at 45 min (1000 rpm since 30 min) the DTRB's preload
    is that of the warm-up's instant, between the cold one and the 1000 rpm equilibrium."""
    from spindlesim.analysis.operating import operating_state
    from spindlesim.runs.common import operating_points

    def deck(at_min):
        d = _lathe_doc()
        d["spindle_thermal"]["analyses"] = "warm_up"
        d["spindle_thermal"]["warm_up_at_min"] = at_min
        path = tmp_path / f"lathe_{at_min:g}.yaml"
        path.write_text(yaml.safe_dump(d))
        return load_deck(path)

    pts0 = operating_points(deck(0.0))
    cold = operating_state(pts0.rotor, 1000.0, pts0.shaft)
    assert np.allclose(pts0.state(1000.0).q, cold.q, rtol=0, atol=1e-12)
    pts = operating_points(deck(45.0))
    ts = pts.thermal_state(1000.0)
    assert ts.time_s == 2700.0
    w = pts.thermal.model.warm_up
    ref = pts.thermal.warm_up(w.times_s, w.speeds_rpm, 2700.0, samples=2)[-1]  # the warm-up itself, to 45 min
    assert ts.temperatures_C == pytest.approx(ref.temperatures_C, abs=1e-9)

    def preload(state):
        b = next(b for b in state.bearings if b.name == "front_dtrb")
        return getattr(b, "inner", b).preload_m

    steady = pts.thermal.steady(1000.0)
    assert preload(cold) < preload(ts.operating) < preload(steady.operating)


def test_a_warm_up_instant_needs_its_warm_up():
    from spindlesim.deck import DeckError, parse_deck

    d = _lathe_doc()
    d["spindle_thermal"]["analyses"] = "warm_up"
    with pytest.raises(DeckError, match="warm_up_at_min"):
        parse_deck(yaml.safe_dump(d), "lathe.yaml")
    d["spindle_thermal"]["warm_up_at_min"] = 500.0
    with pytest.raises(DeckError, match="beyond the warm-up's duration_min 120"):
        parse_deck(yaml.safe_dump(d), "lathe.yaml")


def test_the_mirror_image_spindle_has_the_mirrored_temperatures(tmp_path):
    """Invariance: the lathe headstock numbered from the other end (tests/mirror.py for the rotor; the housing,
    jacket and motor reflected z -> L - z) is the same machine: every node has its mirror's temperature, every
    bearing the same heat and the DTRB the same thrusts (its rows swapped).  The jacket has one coolant node here,
    since its flow runs along +z in either numbering and would otherwise differ."""
    from spindlesim.model.build import build_rotor
    from spindlesim.model.thermal import build_spindle_thermal
    from spindlesim.analysis.spindle_thermal import SpindleThermal
    from tests.mirror import mirror_deck

    d = _lathe_doc()
    st = d["spindle_thermal"]
    st["tolerance_K"] = 1e-6
    st["cooling_jacket"].update(start_mm=110, segments=1)
    L = sum(e[2] for e in d["shaft"]["elements"])
    m = mirror_deck(d)
    h = m["spindle_thermal"]["housing"]
    h["segments"] = list(reversed(h["segments"]))
    h["start_mm"] = L - (st["housing"]["start_mm"] + sum(r[2] for r in st["housing"]["segments"]))
    for key in ("cooling_jacket", "motor"):
        sec = m["spindle_thermal"][key]
        sec["start_mm"] = L - (st[key]["start_mm"] + st[key]["length_mm"])

    def solve(doc, name):
        path = tmp_path / name
        path.write_text(yaml.safe_dump(doc))
        deck = load_deck(path).deck
        rotor = build_rotor(deck)
        return SpindleThermal(rotor, build_spindle_thermal(deck, rotor)).steady(1000.0)

    a, b = solve(d, "a.yaml"), solve(m, "b.yaml")
    n_s, n_h = len(d["shaft"]["elements"]), len(st["housing"]["segments"])

    def mirrored(name):
        for part, n in (("shaft", n_s), ("housing", n_h)):
            if name.startswith(part + "["):
                return f"{part}[{n - 1 - int(name[len(part) + 1:-1])}]"
        return name

    assert set(a.temperatures_C) == {mirrored(n) for n in b.temperatures_C}
    for n, t in a.temperatures_C.items():
        assert b.temperatures_C[mirrored(n)] == pytest.approx(t, abs=1e-4), n
    for n in ("front_dtrb", "rear_roller"):
        assert b.bearings[n].total_W == pytest.approx(a.bearings[n].total_W, rel=1e-5)
    assert b.bearings["front_dtrb"].row_thrust_N[::-1] == pytest.approx(a.bearings["front_dtrb"].row_thrust_N, rel=1e-5)
    assert a.temperatures_C["bearing:front_dtrb:inner"] > 25.0  # a warm state, not a trivial one
