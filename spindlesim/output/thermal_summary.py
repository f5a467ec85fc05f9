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
            lines.extend(_warm_up_depth(w["chatter"], t, data))
    return lines, data


def _warm_up_depth(c, t, data) -> list[str]:
    """The stable depth of cut at the running speed through a warm-up: cold, at the end of the last cutting
    step, the lowest, and the instants not computed."""
    dm, rpm = c["limit_depth_m"][:], c["speed_rpm"][:]
    capped = c["capped"][:].astype(bool) if "capped" in c else np.zeros(len(dm), bool)
    method = str(c.attrs.get("method", "")).split(" (")[0]
    lines = []

    def at(i: int) -> str:
        return f"{dm[i] * 1e3:.3g} mm at {rpm[i]:,.0f} rpm ({t[i] / 60:.0f} min)"

    ok = np.flatnonzero(np.isfinite(dm))
    if len(ok):
        k = int(ok[np.argmin(dm[ok])])
        lines.append(f"  stable depth of cut at the running speed ({method}): {at(ok[0])} -> {at(ok[-1])}; "
                     f"lowest {at(k)}")
        data["warm_up_limit_depth_m"] = [float(v) for v in dm]
    if capped.any():
        lines.append(f"  stable up to the depth cap at {int(capped.sum())} instant(s)")
    missing = int(np.sum(~np.isfinite(dm) & ~capped & (rpm > 0)))
    if missing:
        lines.append(f"  stable depth of cut NOT COMPUTED at {missing} of {len(dm)} instants "
                     f"(thermal.h5: warm_up/chatter, attribute not_computed)")
    return lines


def _preload(row_thrust) -> str:
    """", preload N N" of a bearing's rows' thrust; nothing for a bearing without one (a cylindrical roller)."""
    t = np.asarray(row_thrust, float)
    return f", preload {np.nanmax(t):.0f} N" if np.isfinite(t).any() else ""
