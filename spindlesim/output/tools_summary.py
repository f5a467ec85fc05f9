"""Terminal summary of tools.h5: per tool its nose-to-tip length, mass, largest tip compliance and the most negative real
part of H_xx (what sets a chatter limit), and with lobes its minimum limit depth and recommended speed."""

from __future__ import annotations

import numpy as np


def tools(f):
    g = f["tools"]
    names = [str(n) for n in g.attrs["tools"]]
    speed = float(g.attrs["speed_rpm"])
    states = int(g["spindle/receptance"].shape[0])
    lines = [f"{len(names)} tool(s) coupled onto node {int(g.attrs['nose_node'])} at {speed:g} rpm by receptance "
             f"coupling ({states} spindle state(s): each tool's weight loads the bearings)"]
    data: dict = {"speed_rpm": speed, "tools": {}}
    lob = g["lobes"] if "lobes" in g else None
    lob_names = [str(n) for n in lob["tool"][:].astype(str)] if lob is not None else []
    for name in names:
        t = g[name]
        f_hz, H = t["frequency_hz"][:], t["receptance_m_N"][:]
        mag = np.abs(H[:, 0, 0])
        k = int(np.argmax(mag))
        kr = int(np.argmin(H[:, 0, 0].real))
        row = {"nose_to_tip_m": float(t["nose_to_tip_m"][()]), "mass_kg": float(t["mass_kg"][()]),
               "peak_m_N": float(mag[k]), "peak_frequency_hz": float(f_hz[k]),
               "min_real_m_N": float(H[kr, 0, 0].real), "min_real_frequency_hz": float(f_hz[kr])}
        line = (f"  {name:16s} {row['nose_to_tip_m'] * 1e3:5.0f} mm {row['mass_kg']:5.2f} kg: |H_xx| {mag[k] * 1e6:.3g} "
                f"um/N at {f_hz[k]:.0f} Hz, Re H_xx {H[kr, 0, 0].real * 1e6:.3g} um/N at {f_hz[kr]:.0f} Hz")
        if name in lob_names:
            i = lob_names.index(name)
            dmin, smin = float(lob["min_depth_m"][i]), float(lob["min_speed_rpm"][i])
            rs, rd = float(lob["recommended_speed_rpm"][i]), float(lob["recommended_depth_m"][i])
            line += f"; min depth {dmin * 1e3:.3g} mm at {smin:,.0f} rpm"
            line += f", best {rs:,.0f} rpm at {rd * 1e3:.3g} mm" if np.isfinite(rs) else ", no stability pocket"
            row.update(min_depth_m=dmin, min_speed_rpm=smin, recommended_speed_rpm=rs, recommended_depth_m=rd)
        data["tools"][name] = row
        lines.append(line)
    if lob is not None:
        lines.append(f"  lobes: {lob.attrs['method']}, {lob.attrs['frf']}")
    return lines, data
