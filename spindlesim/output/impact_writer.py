"""impact.h5 and the FRF file of ``spindlesim impact`` (docs/output-format.md).

/impact: frequency_hz, receptance_m_N (complex, H1), coherence; attributes direction, response, force_window_s,
window_decay_1_s, tail_share, used, rejected, library, notes;
/impact/records [impact, sample]: time_s [sample], force_N, the response (acceleration_m_s2, velocity_m_s or
displacement_m), used (1/0), reasons, source.
The FRF file (``frf_<direction>.csv``) is the single-direction CSV layout the chatter readers take, with the
coherence column and, when a window was applied, its decay (``# exponential_window_decay_1_s``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .hdf5 import Data, RunInfo, write_h5, write_text_atomic

#: the response kind -> its dataset name and unit
RESPONSE = {"acceleration": ("acceleration_m_s2", "m/s^2"), "velocity": ("velocity_m_s", "m/s"),
            "displacement": ("displacement_m", "m")}


def write_impact(path: Path, run: RunInfo, res) -> Path:
    g, r = "/impact", "/impact/records"
    name, unit = RESPONSE[res.kind]
    data = {f"{g}/frequency_hz": (res.frequency_hz, "Hz", ("frequency_hz",)),
            f"{g}/receptance_m_N": Data(res.receptance_m_N, "m/N", ("frequency_hz",),
                                        "H1 over the accepted impacts (with the exponential window, if any)"),
            f"{g}/coherence": Data(res.coherence, "1", ("frequency_hz",), "ordinary coherence")}
    if res.records:
        data[f"{r}/time_s"] = (res.dt_s * np.arange(res.samples), "s", ("time_s",))
        data[f"{r}/force_N"] = Data(np.array([x.force_N for x in res.records]), "N", ("impact", "time_s"),
                                    "as recorded (before the windows)")
        data[f"{r}/{name}"] = Data(np.array([x.response for x in res.records]), unit, ("impact", "time_s"),
                                   "as recorded (before the windows)")
        data[f"{r}/used"] = Data(np.array([v.used for v in res.verdicts], np.int8), "1", ("impact",),
                                 "1: averaged, 0: left out")
        data[f"{r}/reasons"] = Data(np.array(["; ".join(v.reasons) or "-" for v in res.verdicts], dtype=object), "1",
                                    ("impact",), "why an impact was left out")
        data[f"{r}/source"] = Data(np.array([v.where for v in res.verdicts], dtype=object), "1", ("impact",))
    attrs = {g: {"direction": res.direction, "response": res.kind, "force_window_s": res.force_window_s,
                 "window_decay_1_s": res.window_decay_1_s, "tail_share": res.tail_share, "used": res.used,
                 "rejected": len(res.rejected), "library": res.library,
                 "notes": "; ".join(res.notes) if res.notes else "none"}}
    return write_h5(path, run, data, attrs)


def frf_csv(res, sources: list[str]) -> str:
    """The text of the FRF file: its header says where it comes from."""
    from ..chatter.frf import ToolPointFrf
    from ..chatter.readers import frf_csv_text

    i = 0 if res.direction == "x" else 1
    H = np.zeros((len(res.frequency_hz), 2, 2), complex)
    C = np.full(H.shape, np.nan)
    H[:, i, i], C[:, i, i] = res.receptance_m_N, res.coherence
    decay = (res.window_decay_1_s, 0.0) if i == 0 else (0.0, res.window_decay_1_s)
    frf = ToolPointFrf(res.frequency_hz, H, "impacts", C, decay)
    header = (f"tool-point receptance {res.direction}{res.direction} [m/N] and coherence: H1 of {res.used} of "
              f"{len(res.verdicts)} impacts ({res.kind} response; `spindlesim impact`, {res.library})",
              "records: " + ", ".join(sources))
    return frf_csv_text(frf, res.direction, header)


def write_frf_file(path: Path, res, sources: list[str]) -> Path:
    return write_text_atomic(path, frf_csv(res, sources))
