"""Terminal summary of a spindle's thermal model (the ``spindle_thermal`` analysis): read from its result, the
:class:`~spindlesim.analysis.thermal_study.ThermalStudy`, with the numbers its file (thermal.h5, group
/spindle_thermal) holds."""

from __future__ import annotations

import numpy as np


def spindle_thermal(study):
    """Heat, bearing temperatures, operating preload and tool-tip drift at each speed; the runaway."""
    lines, data = [], {}
    sources = _sources(study)
    if study.states:
        lines += _speed_lines(study, sources, data)
    if study.limit_rpm is not None:
        lo, hi = (float(v) for v in study.limit_rpm)
        lines.append(f"  THERMAL SPEED LIMIT: stable up to {lo:.0f} rpm, runs away from {hi:.0f} rpm")
        data["speed_limit_rpm"] = [lo, hi]
    if study.runaway is not None:
        rpm, message = study.runaway
        lines.append(f"  THERMAL RUNAWAY: {message}")
        data["runaway"] = str(message)
        if np.isfinite(rpm):
            data["runaway_speed_rpm"] = float(rpm)
    if study.warm_up is not None:
        lines += _warm_up_lines(study.warm_up, data)
    return lines, data


def _sources(study) -> list[str]:
    """The heat sources of every state, the warm-up's included, sorted (thermal.h5's ``source``)."""
    states = tuple(study.states) + (tuple(study.warm_up.states) if study.warm_up is not None else ())
    return sorted({k for s in states for k in s.heat_W})


def _speed_lines(study, sources: list[str], data: dict) -> list[str]:
    """The heading and one line per equilibrium: the motor's and each bearing's heat, its rings, its preload,
    the tool tip's drift."""
    states, setting = study.states, study.setting
    sp = np.array([s.speed_rpm for s in states])
    names = list(setting.bearings)
    heat = np.array([[s.heat_W.get(src, 0.0) for src in sources] for s in states])
    drift, radial = _drift(states), _radial(states)
    lines = [f"thermal equilibrium at {len(sp)} speed(s), ambient {float(setting.ambient_C):g} C, "
             f"{setting.lubrication}, motor load {float(setting.motor_load_fraction):g}"]
    for i, (s, st) in enumerate(zip(sp, states)):
        motor = sum(heat[i, k] for k, n in enumerate(sources) if n.startswith("motor"))
        parts = [f"{n} {heat[i, sources.index('bearing:' + n)]:.0f} W, rings {float(st.parts_C[n].inner_ring_C):.1f}/"
                 f"{float(st.parts_C[n].outer_ring_C):.1f} C" + _preload(_thrust(st, n))
                 for n in names if f"bearing:{n}" in sources]
        tip = "" if not np.isfinite(drift[i]) else f"; tool tip {drift[i] * 1e6:+.1f} um axially"
        if np.isfinite(radial[i]).all():
            tip += f", x {radial[i, 0] * 1e6:+.2f} / y {radial[i, 1] * 1e6:+.2f} um radially"
        lines.append(f"  {s:7.0f} rpm: motor {motor:.0f} W; " + "; ".join(parts) + tip)
    data.update(speed_rpm=sp.tolist(), heat_W=heat.tolist(), tool_tip_axial_drift_m=drift.tolist())
    return lines


def _warm_up_lines(warm, data: dict) -> list[str]:
    """The warm-up: its length, the tool tip's drift, the first natural frequency, the stable depth of cut."""
    t = np.array([s.time_s for s in warm.states])
    drift, radial = _drift(warm.states), _radial(warm.states)
    fr = np.asarray(warm.frequency_hz, float)
    line = f"  warm-up over {t[-1] / 60:.0f} min ({len(t)} instants)"
    if np.isfinite(drift).any():
        line += f": tool tip axial drift {np.nanmin(drift) * 1e6:+.1f} .. {np.nanmax(drift) * 1e6:+.1f} um"
    if np.isfinite(radial).all():
        change = np.hypot(*(radial - radial[0]).T)
        line += f", radial drift from the first instant up to {np.max(change) * 1e6:.2f} um"
    if fr.size and np.isfinite(fr[:, 0]).all():
        line += f"; first natural frequency {fr[0, 0]:.1f} -> {fr[-1, 0]:.1f} Hz"
    data["warm_up_final_drift_m"] = float(drift[-1])
    lines = [line]
    if warm.stable_depth is not None:
        lines.extend(_warm_up_depth(warm.stable_depth, t, data))
    return lines


def _warm_up_depth(sd, t, data) -> list[str]:
    """The stable depth of cut at the running speed through a warm-up (``sd``: its ``StableDepth``): cold, at the
    end of the last cutting step, the lowest, and the instants not computed."""
    dm, rpm = np.asarray(sd.depth_m, float), np.asarray(sd.speed_rpm, float)
    capped = np.asarray(sd.capped, np.int8).astype(bool)
    method = str(sd.method).split(" (")[0]
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


def _drift(states) -> np.ndarray:
    """The tool tip's axial drift [m] of each state, NaN without a tool."""
    return np.array([np.nan if s.tool_tip_axial_drift_m is None else s.tool_tip_axial_drift_m for s in states])


def _radial(states) -> np.ndarray:
    """The tool tip's radial drift (x, y) [m] of each state, NaN without a tool."""
    return np.array([(np.nan, np.nan) if s.tool_tip_radial_m is None else s.tool_tip_radial_m for s in states],
                    float).reshape(len(states), 2)


def _thrust(state, name: str):
    """The row thrust [N] of bearing ``name`` at ``state`` (None: a bearing without rows' thrust)."""
    return getattr(state.bearings.get(name), "row_thrust_N", None)


def _preload(row_thrust) -> str:
    """", preload N N" of a bearing's rows' thrust; nothing for a bearing without one (a cylindrical roller)."""
    t = np.asarray(np.nan if row_thrust is None else row_thrust, float)
    return f", preload {np.nanmax(t):.0f} N" if np.isfinite(t).any() else ""
