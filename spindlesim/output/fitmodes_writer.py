"""fitmodes.h5 and modes.yaml of ``spindlesim fitmodes`` (docs/output-format.md).

/fitmodes (attributes: source, library, max_order, min_peak_share, the stability criteria);
/fitmodes/modes [mode]: direction, frequency_hz, damping_ratio, stiffness_N_m (the chatter section's modal
form), peak_m_N (1 / (2 zeta k)), residue_m_N_s (complex LSFD residue), complexity_deg, stable_orders,
model_order, coherence (NaN: none in the file);
/fitmodes/discarded [discarded]: direction, frequency_hz, damping_ratio, stiffness_N_m, reason;
/fitmodes/<x|y>: frequency_hz, measured_m_N, fitted_m_N (LSFD: modes and residuals), modal_m_N (the modes
alone), coherence; upper_residual_m_N, lower_residual_m_N_s2 (H gets + upper - lower / w^2); attributes band_low_hz,
band_high_hz, fit_error, modal_fit_error, window_decay_1_s, notes;
/fitmodes/<x|y>/stabilisation [order, pole]: order, frequency_hz, damping_ratio, status.
"""

from __future__ import annotations

from dataclasses import asdict
from pathlib import Path

import numpy as np

from .hdf5 import Data, RunInfo, labels, write_h5, write_text_atomic

STATUS = "0 new, 1 frequency stable, 2 frequency and damping stable, 3 stable (and residue); -1: no pole"


def write_fitmodes(path: Path, run: RunInfo, ident) -> Path:
    g = "/fitmodes"
    modes, gone = ident.modes, ident.discarded
    data: dict = {}
    m = f"{g}/modes"
    data[f"{m}/direction"] = Data(np.array([x.direction for x in modes], dtype=object), "1", ("mode",))
    for key, unit, what in (("frequency_hz", "Hz", "undamped natural frequency |lambda| / 2 pi"),
                            ("damping_ratio", "1", "-Re lambda / |lambda|"),
                            ("stiffness_N_m", "N/m", "modal stiffness k of H = 1 / (k (1 - r^2 + 2 j zeta r))"),
                            ("peak_m_N", "m/N", "the mode's peak compliance 1 / (2 zeta k)"),
                            ("complexity_deg", "degree", "angle of the residue from -90 deg (0: a real mode)")):
        data[f"{m}/{key}"] = Data(np.array([getattr(x, key) for x in modes], float), unit, ("mode",), what)
    data[f"{m}/residue_m_N_s"] = Data(np.array([x.residue for x in modes], complex), "m/(N s)", ("mode",),
                                      "LSFD residue A: H = A / (j w - lambda) + conj")
    data[f"{m}/stable_orders"] = Data(np.array([x.stable_orders for x in modes], np.int64), "1", ("mode",),
                                      "stable poles in the mode's track of the stabilisation diagram")
    data[f"{m}/model_order"] = Data(np.array([x.order for x in modes], np.int64), "1", ("mode",),
                                    "LSCF model order of the chosen pole")
    data[f"{m}/coherence"] = Data(np.array([x.coherence for x in modes], float), "1", ("mode",),
                                  "measured coherence at the natural frequency (NaN: the file has none)", fill_nan=True)
    if gone:
        d = f"{g}/discarded"
        data[f"{d}/direction"] = Data(np.array([x.direction for x in gone], dtype=object), "1", ("discarded",))
        for key, unit in (("frequency_hz", "Hz"), ("damping_ratio", "1"), ("stiffness_N_m", "N/m")):
            data[f"{d}/{key}"] = Data(np.array([getattr(x, key) for x in gone], float), unit, ("discarded",),
                                      fill_nan=True)
        data[f"{d}/reason"] = Data(np.array([x.reason for x in gone], dtype=object), "1", ("discarded",),
                                   "why the stable pole is not a mode")
    attrs: dict = {g: {"source": ident.source, "library": ident.library, "max_order": ident.max_order,
                       "min_peak_share": ident.min_peak_share, "modes": len(modes), "discarded": len(gone),
                       **{f"criteria_{k}": v for k, v in asdict(ident.criteria).items()}}}
    for di in ident.directions:
        dg = f"{g}/{di.direction}"
        data[f"{dg}/frequency_hz"] = (di.frequency_hz, "Hz", ("frequency_hz",))
        data[f"{dg}/measured_m_N"] = Data(di.measured_m_N, "m/N", ("frequency_hz",), "the measured direct receptance")
        data[f"{dg}/fitted_m_N"] = Data(di.fitted_m_N, "m/N", ("frequency_hz",),
                                        "LSFD: the modes with their complex residues and both residuals")
        data[f"{dg}/modal_m_N"] = Data(di.modal_m_N, "m/N", ("frequency_hz",),
                                       "the modes alone in the modal form (what chatter.frf: {modes: ...} gets)")
        if di.coherence is not None:
            data[f"{dg}/coherence"] = Data(di.coherence, "1", ("frequency_hz",), "measured coherence")
        data[f"{dg}/upper_residual_m_N"] = Data(np.array(di.upper_residual, complex), "m/N", (),
                                                "upper residual: H gets + upper")
        data[f"{dg}/lower_residual_m_N_s2"] = Data(np.array(di.lower_residual, complex), "m/(N s^2)", (),
                                                   "lower residual: H gets - lower / w^2")
        sd = f"{dg}/stabilisation"
        diag = di.diagram
        data[f"{sd}/order"] = (diag.orders.astype(np.int64), "1", ("order",))
        data[f"{sd}/frequency_hz"] = Data(diag.frequency_hz, "Hz", ("order", "pole"), "candidate pole", fill_nan=True)
        data[f"{sd}/damping_ratio"] = Data(diag.damping_ratio, "1", ("order", "pole"), fill_nan=True)
        data[f"{sd}/status"] = Data(diag.status.astype(np.int8), "1", ("order", "pole"), STATUS)
        attrs[dg] = {"band_low_hz": di.band_hz[0], "band_high_hz": di.band_hz[1], "fit_error": di.fit_error,
                     "modal_fit_error": di.modal_fit_error, "window_decay_1_s": di.window_decay_1_s,
                     "notes": "; ".join(di.notes) if di.notes else "none"}
    return write_h5(path, run, data, attrs)


def modes_yaml(ident) -> str:
    """The kept modes as a YAML list that pastes under ``chatter: frf: {modes: ...}`` (with a comment saying
    where they come from and the fit errors)."""
    lines = [f"# Modes identified by `spindlesim fitmodes` from {ident.source} ({ident.library}: LSCF poles, stable",
             f"# through the model orders, LSFD residues), in the chatter section's modal form "
             "H = 1 / (k (1 - r^2 + 2 j zeta r)).",
             "# Paste the list under a chatter section's frf:",
             "#   chatter:",
             "#     frf:",
             "#       modes:",
             "#         - {direction: x, frequency_hz: ..., damping_ratio: ..., stiffness_N_m: ...}"]
    for d in ident.directions:
        lines.append(f"# {d.direction}: band {d.band_hz[0]:g}-{d.band_hz[1]:g} Hz, fit error {100 * d.fit_error:.2f} % "
                     f"(modes and residuals), {100 * d.modal_fit_error:.2f} % (these modes alone)")
    for m in ident.discarded:
        lines.append(f"# left out: {m.direction} {m.frequency_hz:.1f} Hz, {m.reason}")
    for m in ident.modes:
        lines.append(f"- {{direction: {m.direction}, frequency_hz: {m.frequency_hz:.6g}, damping_ratio: "
                     f"{m.damping_ratio:.5g}, stiffness_N_m: {m.stiffness_N_m:.6g}}}")
    return "\n".join(lines) + "\n"


def write_modes_yaml(path: Path, ident) -> Path:
    return write_text_atomic(path, modes_yaml(ident))
