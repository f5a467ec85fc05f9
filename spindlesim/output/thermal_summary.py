"""Terminal summary of a spindle's thermal model (the ``spindle_thermal`` analysis; thermal.h5, group
/spindle_thermal)."""

from __future__ import annotations

import numpy as np


def spindle_thermal(f):
    """Heat, bearing temperatures, operating preload and tool-tip drift at each speed; the runaway."""
    g = f["spindle_thermal"]
    a = g.attrs
    lines, data = [], {}
    if "speed_rpm" in g:
        sp = g["speed_rpm"][:]
        names = [str(n) for n in g["bearing"][:].astype(str)]
        sources = [str(n) for n in g["source"][:].astype(str)]
        heat, inner, outer = g["heat_W"][:], g["inner_ring_C"][:], g["outer_ring_C"][:]
        thrust = g["row_thrust_N"][:]
        drift = g["tool_tip_axial_drift_m"][:]
        radial = g["tool_tip_radial_drift_m"][:] if "tool_tip_radial_drift_m" in g else None
        lines.append(f"thermal equilibrium at {len(sp)} speed(s), ambient {float(a['ambient_C']):g} C, "
                     f"{a['lubrication']}, motor load {float(a['motor_load_fraction']):g}")
        for i, s in enumerate(sp):
            motor = sum(heat[i, k] for k, n in enumerate(sources) if n.startswith("motor"))
            parts = [f"{n} {heat[i, sources.index('bearing:' + n)]:.0f} W, rings {inner[i, j]:.1f}/{outer[i, j]:.1f} C"
                     + _preload(thrust[i, j]) for j, n in enumerate(names) if f"bearing:{n}" in sources]
            tip = "" if not np.isfinite(drift[i]) else f"; tool tip {drift[i] * 1e6:+.1f} um axially"
            if radial is not None and np.isfinite(radial[i]).all():
                tip += f", x {radial[i, 0] * 1e6:+.2f} / y {radial[i, 1] * 1e6:+.2f} um radially"
            lines.append(f"  {s:7.0f} rpm: motor {motor:.0f} W; " + "; ".join(parts) + tip)
        data.update(speed_rpm=sp.tolist(), heat_W=heat.tolist(), tool_tip_axial_drift_m=drift.tolist())
    if "speed_limit_rpm" in a:
        lo, hi = (float(v) for v in a["speed_limit_rpm"])
        lines.append(f"  THERMAL SPEED LIMIT: stable up to {lo:.0f} rpm, runs away from {hi:.0f} rpm")
        data["speed_limit_rpm"] = [lo, hi]
    if "runaway" in a:
        lines.append(f"  THERMAL RUNAWAY: {a['runaway']}")
        data["runaway"] = str(a["runaway"])
        if "runaway_speed_rpm" in a:
            data["runaway_speed_rpm"] = float(a["runaway_speed_rpm"])
    if "warm_up" in g:
        w = g["warm_up"]
        t = w["time_s"][:]
        drift = w["tool_tip_axial_drift_m"][:]
        radial = w["tool_tip_radial_drift_m"][:] if "tool_tip_radial_drift_m" in w else None
        fr = w["natural_frequency_hz"][:]
        line = f"  warm-up over {t[-1] / 60:.0f} min ({len(t)} instants)"
        if np.isfinite(drift).any():
            line += f": tool tip axial drift {np.nanmin(drift) * 1e6:+.1f} .. {np.nanmax(drift) * 1e6:+.1f} um"
        if radial is not None and np.isfinite(radial).all():
            change = np.hypot(*(radial - radial[0]).T)
            line += f", radial drift from the first instant up to {np.max(change) * 1e6:.2f} um"
        if fr.size and np.isfinite(fr[:, 0]).all():
            line += f"; first natural frequency {fr[0, 0]:.1f} -> {fr[-1, 0]:.1f} Hz"
        lines.append(line)
        data["warm_up_final_drift_m"] = float(drift[-1])
        if "chatter" in w:
            dm = w["chatter"]["min_limit_depth_m"][:]
            if np.isfinite(dm).any():
                k = int(np.nanargmin(dm))
                lines.append(f"  minimum stable depth of cut (zero order) {dm[0] * 1e3:.3g} mm cold -> "
                             f"{dm[-1] * 1e3:.3g} mm at the end; lowest {dm[k] * 1e3:.3g} mm at {t[k] / 60:.0f} min")
                data["warm_up_min_depth_m"] = [float(v) for v in dm]
            missing = int(np.sum(~np.isfinite(dm)))
            if missing:
                lines.append(f"  minimum stable depth of cut NOT COMPUTED at {missing} of {len(dm)} instants "
                             f"(thermal.h5: warm_up/chatter, attribute not_computed)")
    return lines, data


def _preload(row_thrust) -> str:
    """", preload N N" of a bearing's rows' thrust; nothing for a bearing without one (a cylindrical roller)."""
    t = np.asarray(row_thrust, float)
    return f", preload {np.nanmax(t):.0f} N" if np.isfinite(t).any() else ""
