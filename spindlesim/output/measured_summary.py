"""Terminal summaries of ``spindlesim fitmodes`` and ``spindlesim impact``, built from their results (issue 34:
every analysis returns its result; the run writes and draws it, the command prints this): ``(lines, data)``,
a few lines an engineer can act on and the same numbers as a JSON-able dict."""

from __future__ import annotations

from pathlib import Path

import numpy as np


def fitmodes_summary(ident, yaml_path: Path | None = None):
    lines = [f"{ident.source}: {len(ident.modes)} mode(s) ({ident.library}: LSCF to order {2 * ident.max_order}, "
             f"stable poles, LSFD)"]
    data: dict = {"source": ident.source, "modes": [], "discarded": [], "fit_error": {}, "modal_fit_error": {}}
    for d in ident.directions:
        lines.append(f"  {d.direction}: band {d.band_hz[0]:g}-{d.band_hz[1]:g} Hz, fit error {100 * d.fit_error:.2f} % "
                     f"rms (modes and residuals), {100 * d.modal_fit_error:.2f} % (the modes alone, as chatter gets "
                     "them)")
        lines.append(f"     {'f [Hz]':>9s} {'zeta':>8s} {'k [N/m]':>10s} {'peak [um/N]':>11s} {'coherence':>9s}"
                     f" {'stable orders':>13s}")
        for m in d.modes:
            coh = f"{m.coherence:9.3f}" if np.isfinite(m.coherence) else f"{'-':>9s}"
            lines.append(f"     {m.frequency_hz:9.2f} {m.damping_ratio:8.5f} {m.stiffness_N_m:10.4g} "
                         f"{1e6 * m.peak_m_N:11.4g} {coh} {m.stable_orders:13d}")
            if np.isfinite(m.coherence) and m.coherence < 0.8:
                lines.append(f"       WARNING: coherence {m.coherence:.2f} at {m.frequency_hz:.1f} Hz: the measurement "
                             "is doubtful there")
            data["modes"].append({"direction": m.direction, "frequency_hz": m.frequency_hz,
                                  "damping_ratio": m.damping_ratio, "stiffness_N_m": m.stiffness_N_m,
                                  "coherence": m.coherence if np.isfinite(m.coherence) else None})
        for m in d.discarded:
            lines.append(f"     left out {m.frequency_hz:.1f} Hz: {m.reason}")
            data["discarded"].append({"direction": m.direction, "frequency_hz": m.frequency_hz, "reason": m.reason})
        lines += [f"     note: {n}" for n in d.notes]
        data["fit_error"][d.direction] = d.fit_error
        data["modal_fit_error"][d.direction] = d.modal_fit_error
    if yaml_path is not None:
        lines.append(f"  {yaml_path}: paste under chatter: frf: modes:")
    return lines, data


def impact_summary(res, csv_path: Path | None = None):
    lines = [f"{res.used} of {len(res.verdicts)} impact(s) averaged (H1, {res.kind} response, {res.samples} samples "
             f"at {1 / res.dt_s:.6g} /s, {res.frequency_hz[1] - res.frequency_hz[0]:.4g} Hz resolution); "
             f"direction {res.direction}"]
    for v in res.rejected:
        lines.append(f"  left out {v.where}: {', '.join(v.reasons)}")
    window = (f"exponential window e^(-{res.window_decay_1_s:.4g} t)" if res.window_decay_1_s
              else "no exponential window")
    lines.append(f"  force window to {1e3 * res.force_window_s:.3g} ms; {window}; response at the records' end "
                 f"{100 * res.tail_share:.2g} % of its peak")
    peaks = res.peaks_hz()
    rows = []
    for f in peaks:
        k = int(np.argmin(np.abs(res.frequency_hz - f)))
        rows.append({"frequency_hz": float(res.frequency_hz[k]), "receptance_m_N": float(abs(res.receptance_m_N[k])),
                     "coherence": float(res.coherence[k])})
    if rows:
        lines.append("  peaks: " + ", ".join(f"{r['frequency_hz']:.0f} Hz |H| {1e6 * r['receptance_m_N']:.3g} um/N "
                                             f"coherence {r['coherence']:.3f}" for r in rows))
    low = [r for r in rows if r["coherence"] < 0.9]
    if low:
        lines.append("  WARNING: coherence under 0.9 at " + ", ".join(f"{r['frequency_hz']:.0f} Hz" for r in low)
                     + ": more impacts, a harder tip or another hammer force may help")
    lines += [f"  note: {n}" for n in res.notes]
    if csv_path is not None:
        lines.append(f"  {csv_path}: the FRF with its coherence (chatter frf: {{file: ...}}, spindlesim fitmodes)")
    return lines, {"used": res.used, "impacts": len(res.verdicts),
                   "rejected": [{"impact": v.where, "reasons": list(v.reasons)} for v in res.rejected],
                   "window_decay_1_s": res.window_decay_1_s, "peaks": rows,
                   "frf_file": str(csv_path) if csv_path is not None else None}
