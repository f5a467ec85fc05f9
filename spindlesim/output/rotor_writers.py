"""Map rotor-analysis results onto the HDF5 layout of docs/output-format.md.

Dimensions (netCDF coordinates, see output/hdf5.py): ``node`` (1-based node number), ``mode``
(1-based), ``speed_rpm``, ``frequency_hz``; string coordinates ``dof`` (x, y[, theta_x, theta_y])
and ``load`` (Fx, Fy) name the components of displacement-like and force-like axes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..analysis.results import CampbellResult, FrfResult, ModalResult, StaticResult, UnbalanceResult
from .hdf5 import Data, RunInfo, labels, write_h5

XY = ("x", "y")
FXY = ("Fx", "Fy")
NOT_TRACKED = "NaN where the mode is not tracked at that speed"


def write_static(path: Path, run: RunInfo, r: StaticResult) -> Path:
    g = "/static"
    data = {
        f"{g}/node_z_m": (r.node_z_m, "m", ("node",)),
        f"{g}/displacement_m": (r.displacement_m, "m", ("node", "dof")),
        f"{g}/slope_rad": (r.slope_rad, "rad", ("node", "rotation")),
        f"{g}/bearing_name": (np.array(r.bearing_names, dtype=object), "1", ("bearing_name",)),
        f"{g}/bearing_node": (r.bearing_nodes + 1, "1", ("bearing_name",)),
        f"{g}/bearing_force_N": Data(r.bearing_force_N, "N", ("bearing_name", "load"),
                                     "force exerted by the bearing on the shaft"),
        f"{g}/applied_force_N": Data(r.applied_force_N, "N", ("load",),
                                     "sum of the applied loads, gravity included when on (attribute gravity_m_s2)"),
        f"{g}/static_stiffness_N_m": Data(r.static_stiffness_N_m, "N/m", (),
                                          "1 / compliance at (stiffness_node, stiffness_dof)"),
        **labels(g, "dof", XY), **labels(g, "rotation", ("theta_x", "theta_y")), **labels(g, "load", FXY),
    }
    attrs = {"speed_rpm": r.speed_rpm, "stiffness_node": r.stiffness_node + 1, "stiffness_dof": r.stiffness_dof,
             "bearing_force_convention": "force exerted by the bearing on the shaft", "gravity_m_s2": r.gravity_m_s2}
    if r.axial_displacement_m is not None:
        data[f"{g}/axial_displacement_m"] = (r.axial_displacement_m, "m", ("node",))
        data[f"{g}/applied_axial_force_N"] = Data(r.applied_axial_force_N, "N", (), "sum of the applied axial (z) loads")
    if r.tool_tip_node is not None:
        tip = r.tool_tip_stiffness_N_m or {}
        data[f"{g}/tool_tip_stiffness_N_m"] = Data(np.array([tip[d] for d in tip]), "N/m", ("tip_dof",),
                                                   "1 / direct static compliance at the tool tip")
        data.update(labels(g, "tip_dof", tuple(tip)))
        attrs["tool_tip_node"] = r.tool_tip_node + 1
    if r.damping_only:
        attrs["damping_only"] = ", ".join(r.damping_only)
    return write_h5(path, run, data, {g: attrs})


def write_modal(path: Path, run: RunInfo, r: ModalResult) -> Path:
    g = "/modal"
    dofs = ("x", "y", "theta_x", "theta_y", "z")[: r.mode_shape.shape[2]]  # z (last) where the rotor has it
    m = ("mode",)
    return write_h5(path, run, {
        f"{g}/frequency_hz": Data(r.frequency_hz, "Hz", m, "damped natural frequency w_d / 2 pi"),
        f"{g}/undamped_frequency_hz": Data(r.undamped_frequency_hz, "Hz", m, "|lambda| / 2 pi"),
        f"{g}/damping_ratio": (r.damping_ratio, "1", m),
        f"{g}/log_dec": Data(r.log_dec, "1", m, "logarithmic decrement -2 pi Re(lambda) / Im(lambda)"),
        f"{g}/eigenvalue": Data(r.eigenvalues, "1/s", m, "lambda = -zeta w_n + j w_d"),
        f"{g}/whirl": (np.array(r.whirl, dtype=object), "1", m),
        f"{g}/forward_fraction": Data(r.forward_fraction, "1", m, "share of nodes whirling forward"),
        f"{g}/mode_shape": Data(r.mode_shape, "", ("mode", "node", "dof"),
                                "complex mode shape normalised so that its largest translation (x, y or z) is 1",
                                component_units=["1", "1", "rad/m", "rad/m", "1"][:len(dofs)]),
        f"{g}/node_z_m": (r.node_z_m, "m", ("node",)),
        f"{g}/overdamped_roots": Data(r.overdamped_roots, "1/s", ("overdamped_root",),
                                      "complex roots with zeta >= 0.999, real roots included"),
        f"{g}/rigid_body_roots": Data(r.rigid_body_roots, "1/s", ("rigid_body_root",),
                                      "roots below the rigid-body threshold (1 mHz)"),
        **labels(g, "dof", dofs),
    }, {g: {"speed_rpm": r.speed_rpm, "mode_shape_dofs": ", ".join(dofs)}})


def _campbell_data(g: str, r: CampbellResult, full: bool) -> dict:
    sm = ("speed_rpm", "mode")
    data = {
        f"{g}/speed_rpm": (r.speed_rpm, "rpm", ("speed_rpm",)),
        f"{g}/frequency_hz": Data(r.frequency_hz, "Hz", sm, NOT_TRACKED, fill_nan=True),
        f"{g}/log_dec": Data(r.log_dec, "1", sm, NOT_TRACKED, fill_nan=True),
        f"{g}/whirl": Data(np.asarray(r.whirl, dtype=object), "1", sm),
        f"{g}/critical_speed_rpm": Data(r.critical_speeds_rpm, "rpm", ("critical",),
                                        "1x crossing with AF >= 2.5 (API 684) of a mode other than backward "
                                        "lateral; every crossing: crossings/"),
    }
    if r.crossings is not None:
        data.update(crossing_data(f"{g}/crossings", r.crossings))
    if full:
        data[f"{g}/damping_ratio"] = Data(r.damping_ratio, "1", sm, NOT_TRACKED, fill_nan=True)
        data[f"{g}/critical_mode"] = Data(r.critical_modes, "1", ("critical",),
                                          "0-based column of frequency_hz (mode coordinate - 1)")
    return data


def write_campbell(path: Path, run: RunInfo, r: CampbellResult, frozen: CampbellResult | None = None,
                   frozen_rpm: float | None = None, cold: CampbellResult | None = None,
                   stiffness: dict | None = None, operating_rpm: float | None = None) -> Path:
    """campbell.h5; with the spindle's thermal model (``cold``): /campbell/cold, the diagram of the bearings as
    assembled at the same speeds, and /campbell/bearing_stiffness_{thermal,cold}_N_m [speed, bearing] (K_xx).
    /campbell's attributes hold the stability threshold (``stable``; ``first_unstable`` [speed index, mode
    index] when a mode is unstable) and the deck's operating speed (``operating_speed_rpm``, when positive)."""
    data = _campbell_data("/campbell", r, True)
    attrs = {"/campbell": {"tracking": "MAC between consecutive speeds",
                           "bearings": "linearised at the static state of every speed",
                           "model": r.model, "stable": r.first_unstable is None}}
    if r.first_unstable is not None:
        attrs["/campbell"]["first_unstable"] = np.array(r.first_unstable, dtype=np.int64)
    if operating_rpm is not None and operating_rpm > 0:
        attrs["/campbell"]["operating_speed_rpm"] = float(operating_rpm)
    if r.crossings is not None:
        attrs["/campbell/crossings"] = crossing_attrs(r.crossings)
    if frozen is not None:
        data.update(_campbell_data("/campbell/frozen", frozen, False))
        if frozen.crossings is not None:
            attrs["/campbell/frozen/crossings"] = crossing_attrs(frozen.crossings)
        attrs["/campbell/frozen"] = {"bearings": f"coefficients frozen at {frozen_rpm:g} rpm", "frozen_rpm": frozen_rpm}
    if cold is not None:
        attrs["/campbell"]["bearings"] = "at the spindle's thermal equilibrium of every speed (spindle_thermal)"
        data.update(_campbell_data("/campbell/cold", cold, False))
        if cold.crossings is not None:
            attrs["/campbell/cold/crossings"] = crossing_attrs(cold.crossings)
        attrs["/campbell/cold"] = {"bearings": "as assembled (cold), linearised at the static state of every speed"}
    if stiffness is not None:
        g = "/campbell/bearing_stiffness"
        data[f"{g}/speed_rpm"] = (stiffness["speed_rpm"], "rpm", ("speed_rpm",))
        data.update(labels(g, "bearing", stiffness["bearing"]))
        for key in ("thermal", "cold"):
            data[f"{g}/{key}_N_m"] = Data(stiffness[key], "N/m", ("speed_rpm", "bearing"),
                                          f"radial stiffness K_xx of each bearing, {key}")
    return write_h5(path, run, data, attrs)


def write_frf(path: Path, run: RunInfo, r: FrfResult, tool_point=None) -> Path:
    """``tool_point``: the tool tip's sampled 2 x 2 receptance (chatter.ToolPointFrf), when the rotor has a tool."""
    f = ("frequency_hz",)
    data = {
        "/frf/frequency_hz": (r.frequency_hz, "Hz", f),
        "/frf/receptance_m_N": (r.receptance_m_N, "m/N", f),
        "/frf/dynamic_stiffness_N_m": (r.dynamic_stiffness_N_m, "N/m", f),
    }
    attrs = {"/frf": {"input_node": r.input_node, "input_dof": r.input_dof, "output_node": r.output_node,
                      "output_dof": r.output_dof, "speed_rpm": r.speed_rpm}}
    if r.added is not None:
        data["/frf/added"] = Data(r.added.astype(np.int8), "1", f, ADDED.format(what="frequency", near="a mode"))
    if r.static_compliance_m_N is not None:
        data["/frf/static_compliance_m_N"] = Data(r.static_compliance_m_N, "m/N", (),
                                                  "K^-1 [output, input]: the receptance at 0 Hz")
    if r.modes is not None:
        m = ("mode",)
        data.update({
            "/frf/modes/frequency_hz": Data(r.modes.frequency_hz, "Hz", m, "damped natural frequency"),
            "/frf/modes/undamped_frequency_hz": Data(r.modes.undamped_frequency_hz, "Hz", m, "|lambda| / 2 pi"),
            "/frf/modes/damping_ratio": (r.modes.damping_ratio, "1", m),
            "/frf/modes/whirl": (np.array(r.modes.whirl, dtype=object), "1", m),
        })
        attrs["/frf/modes"] = {"selection": "modes whose band f_n (1 +- 3 zeta) reaches into the frequency range; "
                                            "the grid is refined around each"}
    if tool_point is not None:
        data.update(tool_point_frf("/frf/tool_point", tool_point.frequency_hz, tool_point.H))
        attrs["/frf/tool_point"] = {"layout": "[frequency, output (x, y), input (x, y)]"}
    return write_h5(path, run, data, attrs)


RIGID = "NaN in the rows and columns of a direction the model holds rigid (no receptance in it)"


def dynamic_stiffness(H: np.ndarray) -> np.ndarray:
    """Inverse of a 2 x 2 receptance [frequency, 2, 2] over its flexible directions.

    A direction whose row and column of H are zero at every frequency (a modal table with modes
    along x only, say) is rigid: its entries are NaN and the other direction's stiffness is
    1 / H_dd.  A frequency where the flexible block is singular gets NaN too."""
    H = np.asarray(H)
    flex = np.flatnonzero(np.any(H != 0, axis=(0, 2)) | np.any(H != 0, axis=(0, 1)))
    Z = np.full(H.shape, np.nan, dtype=np.result_type(H.dtype, float))
    sub = H[:, flex][:, :, flex]
    with np.errstate(all="ignore"):
        if len(flex) == 2:
            det = sub[:, 0, 0] * sub[:, 1, 1] - sub[:, 0, 1] * sub[:, 1, 0]
            inv = np.stack([np.stack([sub[:, 1, 1], -sub[:, 0, 1]], -1),
                            np.stack([-sub[:, 1, 0], sub[:, 0, 0]], -1)], -2) / det[:, None, None]
        else:
            inv = 1.0 / sub
    inv = np.where(np.isfinite(inv), inv, np.nan)
    Z[np.ix_(np.arange(len(H)), flex, flex)] = inv
    return Z


def tool_point_frf(g: str, frequency_hz: np.ndarray, H: np.ndarray) -> dict:
    """A 2 x 2 receptance [frequency, output, input] and its inverse, with their coordinates."""
    Z = dynamic_stiffness(H)
    return {
        f"{g}/frequency_hz": (np.asarray(frequency_hz, float), "Hz", ("frequency_hz",)),
        f"{g}/receptance_m_N": Data(H, "m/N", ("frequency_hz", "dof", "load"),
                                    "displacement along dof per unit force along load"),
        f"{g}/dynamic_stiffness_N_m": Data(Z, "N/m", ("frequency_hz", "load", "dof"),
                                           "inverse of the receptance matrix at each frequency; " + RIGID,
                                           fill_nan=True),
        **labels(g, "dof", XY), **labels(g, "load", FXY),
    }


def write_unbalance(path: Path, run: RunInfo, r: UnbalanceResult) -> Path:
    g = "/unbalance"
    data = {
        f"{g}/speed_rpm": (r.speed_rpm, "rpm", ("speed_rpm",)),
        f"{g}/response_m": Data(r.response_m, "m", ("speed_rpm", "node", "dof"),
                                "complex phasor: q(t) = Re(q e^{j W t}); |q| is the 0-peak amplitude"),
        f"{g}/node_z_m": (r.node_z_m, "m", ("node",)),
        **labels(g, "dof", XY),
    }
    attrs = {g: {"unbalance_kg_m": r.unbalance_kg_m, "unbalance_node": r.unbalance_node,
                 "output_node": r.output_node, "output_dof": r.output_dof,
                 "response_convention": "complex phasor: q(t) = Re(q e^{j W t})",
                 "amplitude": AMPLITUDE}}
    if r.added is not None:
        data[f"{g}/added"] = Data(r.added.astype(np.int8), "1", ("speed_rpm",),
                                  ADDED.format(what="speed", near="a 1x crossing"))
    if r.resonances is not None:
        res, h = r.resonances, f"{g}/resonances"
        data.update(crossing_data(h, res.crossings))
        data.update({
            f"{h}/peak_speed_rpm": Data(res.peak_speed_rpm, "rpm", ("crossing",), NO_PEAK, fill_nan=True),
            f"{h}/peak_amplitude_m": Data(res.peak_amplitude_m, "m", ("crossing",),
                                          "0-peak amplitude at the output DOF; " + NO_PEAK, fill_nan=True),
            f"{h}/half_power_amplification_factor": Data(
                res.half_power_af, "1", ("crossing",), "API 684 AF = N_peak / (N_2 - N_1) from the half-power speeds "
                "of the response at the output DOF; NaN where the peak or a half-power speed is not in the sweep",
                fill_nan=True),
        })
        attrs[h] = crossing_attrs(res.crossings)
    return write_h5(path, run, data, attrs)


ADDED = ("1 where the {what} was added around {near} (refinement, docs/theory.md), 0 on the user's grid: "
         "the user's grid is where this is 0")
AMPLITUDE = "0-peak (single amplitude) = |response_m|; peak-to-peak = 2 |response_m|"
NO_PEAK = "NaN where the output shows no response peak at the crossing"


def crossing_data(g: str, c) -> dict:
    """The datasets of a Crossings (analysis.resonance) in group ``g``, one entry per crossing."""
    x = ("crossing",)
    return {
        f"{g}/speed_rpm": Data(c.speed_rpm, "rpm", x, "speed where n N / 60 equals the mode's damped frequency"),
        f"{g}/order": Data(c.order, "1", x, "excitation order n (1: unbalance, 2, the tooth-passing order)"),
        f"{g}/mode": Data(c.mode + 1, "1", x, "tracked mode: the 1-based mode coordinate of the sweep's arrays"),
        f"{g}/frequency_hz": Data(c.frequency_hz, "Hz", x, "n N_c / 60"),
        f"{g}/damping_ratio": (c.damping_ratio, "1", x),
        f"{g}/whirl": (np.array(c.whirl, dtype=object), "1", x),
        f"{g}/amplification_factor": Data(c.amplification_factor, "1", x,
                                          "API 684 AF = 1 / (2 zeta); NaN for an unstable mode", fill_nan=True),
        f"{g}/critical": Data(c.critical.astype(np.int8), "1", x, "1 where AF >= 2.5 (API 684: a critical speed)"),
        f"{g}/required_separation_margin": Data(
            c.required_margin, "1", x, "API 684 SP6.8.2.10, fraction of the operating-range edge; 0 where AF < 2.5"),
        f"{g}/separation_margin": Data(
            c.separation_margin, "1", x, "distance from the nearer edge of the operating range, fraction of that "
            "edge; negative inside the range; NaN without an operating range", fill_nan=True),
        f"{g}/meets_api684": Data(c.meets_api684.astype(np.int8), "1", x, "1 where separation >= required"),
    }


def crossing_attrs(c) -> dict:
    a = {"orders": np.asarray(c.orders, float),
         "margins": "fractions; below the minimum operating speed of it, above the maximum continuous speed of it"}
    if c.min_operating_rpm is not None:
        a.update(min_operating_rpm=c.min_operating_rpm, max_continuous_rpm=c.max_continuous_rpm)
    return a
