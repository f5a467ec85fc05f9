"""Terminal summary of the tool library (``analysis.tool_library.ToolLibraryStudy``; tools.h5): per tool its nose-to-tip length, mass, largest tip compliance and the most negative real
part of H_xx (what sets a chatter limit), and with lobes its minimum limit depth and recommended speed."""

from __future__ import annotations

import numpy as np


def tools(study):
    lib = study.library
    speed = float(lib.speed_rpm)
    states = int(np.shape(lib.spindle_receptance)[0])
    lines = [f"{len(lib.tools)} tool(s) coupled onto node {int(lib.nose_node)} at {speed:g} rpm by receptance "
             f"coupling ({states} spindle state(s): each tool's weight loads the bearings)"]
    data: dict = {"speed_rpm": speed, "tools": {}}
    lobes = {x.name: x for x in study.lobes}
    f_hz = np.asarray(lib.frequency_hz)
    for t in lib.tools:
        H = np.asarray(t.receptance_m_N)
        mag = np.abs(H[:, 0, 0])
        k = int(np.argmax(mag))
        kr = int(np.argmin(H[:, 0, 0].real))
        row = {"nose_to_tip_m": float(t.nose_to_tip_m), "mass_kg": float(t.mass_kg),
               "peak_m_N": float(mag[k]), "peak_frequency_hz": float(f_hz[k]),
               "min_real_m_N": float(H[kr, 0, 0].real), "min_real_frequency_hz": float(f_hz[kr])}
        line = (f"  {t.name:16s} {row['nose_to_tip_m'] * 1e3:5.0f} mm {row['mass_kg']:5.2f} kg: |H_xx| "
                f"{mag[k] * 1e6:.3g} um/N at {f_hz[k]:.0f} Hz, Re H_xx {H[kr, 0, 0].real * 1e6:.3g} um/N at "
                f"{f_hz[kr]:.0f} Hz")
        x = lobes.get(t.name)
        if x is not None:
            dmin, smin = float(x.min_depth_m), float(x.min_speed_rpm)
            rs, rd = float(x.recommended_speed_rpm), float(x.recommended_depth_m)
            line += f"; min depth {dmin * 1e3:.3g} mm at {smin:,.0f} rpm"
            line += f", best {rs:,.0f} rpm at {rd * 1e3:.3g} mm" if np.isfinite(rs) else ", no stability pocket"
            row.update(min_depth_m=dmin, min_speed_rpm=smin, recommended_speed_rpm=rs, recommended_depth_m=rd)
        data["tools"][t.name] = row
        lines.append(line)
    if study.lobes:
        lines.append(f"  lobes: {study.lobes[0].method}, {study.lobes_frf}")
    return lines, data
