"""Ball bearing benchmark and studies (issue target: DB pair equilibrium state + 5x5 tangent under 2 ms).

Bearing: the embedded default deck (7014C-size DB pair, 18 x 12.7 mm balls, 15 deg, position
preload 21 um).  Timings are the best of --repeat batches of --number calls, wall and process CPU.

- "state, cold": ``BallBearing.solve(load, speed)`` (set Newton, every ball from its built-in start,
  ISO lives, pressures): what every call does unless given a warm start;
- "state, warm": the same with the previous call's ball centres as starts, passed in (a ``Work``: a sweep);
- "force_and_tangent": reaction and 5x5 tangent at one displacement (transient / static solver use; every
  ball from its built-in start);
- "linearized": the contract's pitch-averaged tangent (4 cage positions, 4 equilibria);
- "spring preload": the state of the pair with one floating row (300 N), cold, and the evaluations of its rows.

Then studies: speed effects under position and spring preload, the model options, the size of the
contact-angle dependence of the Hertz constants that the model neglects, the sensitivity to the
sense of the gyroscopic friction couple, and ball-solver iteration counts.

    python benchmarks/bench_ball.py [--repeat 5] [--number 50]
"""

from __future__ import annotations

import argparse
import logging
import math
import time

import numpy as np
import yaml

from spindlesim.bearings.ball.bearing import BallBearing, Work
from spindlesim.bearings.ball import BallSection, default_deck_text
from spindlesim.bearings.ball import kernel as kn
from spindlesim.bearings.ball.section import build
from spindlesim.bearings.ball.sweeps import speed_sweep
from spindlesim.contact.hertz import point_contact_constant
from timing import best  # benchmarks/timing.py (the script's folder is on sys.path)

RPM = math.pi / 30.0
TARGET_MS = 2.0
LOAD = np.array([2000.0, -800.0, 1000.0, 15.0, -10.0])


def section(**changes) -> BallSection:
    d = yaml.safe_load(default_deck_text())["bearing"]
    d.update(sweeps={}, **changes)
    return BallSection.model_validate(d)


def timings(repeat: int, number: int) -> None:
    print(f"Timings (best of {repeat} x {number}); load {LOAD.tolist()} (N, N m); target {TARGET_MS} ms for state + tangent")
    print(f"{'case':44s} {'wall ms':>8s} {'cpu ms':>8s}")
    for model in ("outer_race_control", "full"):
        b = build(section(model=model))
        b.solve(LOAD, 10000 * RPM)  # compile
        for rpm in (0.0, 10000.0, 20000.0):
            w = rpm * RPM

            def cold():
                return b.solve(LOAD, w)

            wall, cpu = best(cold, repeat, number)
            flag = "ok" if cpu * 1e3 < TARGET_MS else "SLOW"
            print(f"{'state+tangent cold, ' + model + f', {rpm:.0f} rpm':44s} {wall * 1e3:8.3f} {cpu * 1e3:8.3f}  {flag}")
            work = Work(b)  # the balls' warm starts, passed in
            wall, cpu = best(lambda: b.solve(LOAD, w, work=work), repeat, number)
            print(f"{'state+tangent warm, ' + model + f', {rpm:.0f} rpm':44s} {wall * 1e3:8.3f} {cpu * 1e3:8.3f}")
        q = b.solve(LOAD, 15000 * RPM).displacement
        wall, cpu = best(lambda: b.force_and_tangent(q, None, 0.0, 15000 * RPM, 0.0), repeat, 5 * number)
        print(f"{'force_and_tangent cold, ' + model + ', 15000 rpm':44s} {wall * 1e3:8.3f} {cpu * 1e3:8.3f}")
        wall, cpu = best(lambda: b.linearized(15000 * RPM, LOAD), repeat, max(1, number // 5))
        print(f"{'linearized (4 cage positions), ' + model:44s} {wall * 1e3:8.3f} {cpu * 1e3:8.3f}")
    spring_study(repeat, number)
    b = build(section())
    t = time.perf_counter()
    speed_sweep(b, np.linspace(0, 20000, 21) * RPM, LOAD)
    print(f"{'speed sweep 0-20000 rpm, 21 points':44s} {(time.perf_counter() - t) * 1e3:8.3f}")


def spring_study(repeat: int, number: int) -> None:
    """A spring-preloaded pair (one floating row, the rear set of a motor spindle): the state, cold, and the
    evaluations of its rows it takes (the floating row's shift is solved at every evaluation of the set)."""
    b = build(section(preload={"kind": "spring", "axial_N": 300.0, "floating": "-z"}))
    rows, real = [0], BallBearing._rows

    def counted(self, *args, **kwargs):
        rows[0] += 1
        return real(self, *args, **kwargs)

    for rpm in (0.0, 10000.0, 20000.0):
        w = rpm * RPM
        b.solve(LOAD, w)
        BallBearing._rows = counted
        rows[0] = 0
        b.solve(LOAD, w)
        BallBearing._rows = real
        wall, cpu = best(lambda: b.solve(LOAD, w), repeat, number)
        print(f"{'state+tangent cold, spring preload, ' + f'{rpm:.0f} rpm':44s} {wall * 1e3:8.3f} {cpu * 1e3:8.3f}  "
              f"{rows[0]} row evaluations")


def speed_study() -> None:
    print("\nSpeed effects, no external load, ball 0 of row 1 (outer-race control)")
    for pre in ({"kind": "position", "axial_um": 21.0}, {"kind": "spring", "axial_N": 254.0}):
        b = build(section(preload=pre))
        print(f"  {b.preload.label()}")
        print(f"  {'rpm':>6s} {'a_i':>6s} {'a_o':>6s} {'Q_i':>7s} {'Q_o':>7s} {'F_c':>7s} {'M_g':>7s} "
              f"{'thrust':>7s} {'K_xx':>7s} {'K_zz':>7s} {'K_tt':>9s}")
        for rpm in (0, 2500, 5000, 7500, 10000, 15000, 20000):
            st = b.solve(np.zeros(5), rpm * RPM)
            print(f"  {rpm:6d} {st.contact_angle_inner_deg[0, 0]:6.2f} {st.contact_angle_outer_deg[0, 0]:6.2f} "
                  f"{st.element_load_inner_N[0, 0]:7.1f} {st.element_load_outer_N[0, 0]:7.1f} "
                  f"{st.centrifugal_force_N[0, 0]:7.1f} {st.gyroscopic_moment_Nm[0, 0]:7.4f} "
                  f"{st.row_axial_load_N[0]:7.1f} {st.stiffness[0, 0] / 1e6:7.1f} {st.stiffness[2, 2] / 1e6:7.1f} "
                  f"{st.stiffness[3, 3]:9.3e}")
    print("  (N, deg, N m; stiffness N/um and N m/rad)")


def model_study() -> None:
    print(f"\nModel options at 20000 rpm, load {LOAD.tolist()}")
    print(f"  {'variant':52s} {'thrust 1':>8s} {'thrust 2':>8s} {'a_o max':>8s} {'K_xx':>7s} {'K_zz':>7s} "
          f"{'L10r':>9s}")
    variants = [("outer_race_control", None), ("inner_race_control", None), ("full", None),
                ("outer_race_control, friction couple reversed (*)", -1.0),
                ("outer_race_control, no gyroscopic moment (*)", 0.0)]
    for label, factor in variants:
        b = build(section(model=label.split(",")[0]))
        if factor is not None:
            b._p[kn.COUPLE] = factor
        st = b.solve(LOAD, 20000 * RPM)
        print(f"  {label:52s} {st.row_axial_load_N[0]:8.1f} {st.row_axial_load_N[1]:8.1f} "
              f"{st.contact_angle_outer_deg.max():8.2f} {st.stiffness[0, 0] / 1e6:7.1f} {st.stiffness[2, 2] / 1e6:7.1f} "
              f"{st.life_L10r_iso16281_Mrev:9.4g}")
    print("  (*) study variants, not model options; see docs/theory.md (Ball bearings) for the sense of the couple")


def hertz_angle_study() -> None:
    b = build(section())
    g = b.geometry
    D, dm = g.ball_diameter_m, g.pitch_diameter_m
    print("\nHertz constant against the contact angle used in the rolling-plane curvature (the model uses a_f = 15 deg)")
    for deg in (8.0, 15.0, 27.0):
        gam = D * math.cos(math.radians(deg)) / dm
        ki = point_contact_constant((2 / D) / (1 - gam), (2 - 1 / g.inner_conformity) / D, g.E_star_Pa)
        ko = point_contact_constant((2 / D) / (1 + gam), (2 - 1 / g.outer_conformity) / D, g.E_star_Pa)
        print(f"  {deg:5.1f} deg: K_i {ki / g.inner.K - 1:+.4%}, K_o {ko / g.outer.K - 1:+.4%}")


def iteration_study() -> None:
    b = build(section())
    p = b._p
    buf = np.empty(kn.N_BUF)
    counts = []
    for rpm in (1000.0, 10000.0, 20000.0):
        q = b.solve(LOAD, rpm * RPM).displacement
        st = b.at(q, rpm * RPM)
        g = b.geometry
        for k in range(g.rows):
            s = float(g.row_sign[k])
            for j in range(g.balls):
                ps = st.psi_rad[k, j]
                cp, sp = math.cos(ps), math.sin(ps)
                Ri, zc = p[kn.R_I_CENTRE], b._row_zc[k]
                Aa = p[kn.A_AX0] + b._row_offset[k] + s * (q[2] + Ri * (q[3] * sp - q[4] * cp))
                Ar = p[kn.A_RAD0] + (q[0] + zc * q[4]) * cp + (q[1] - zc * q[3]) * sp
                counts.append((rpm, kn.solve_ball(Aa, Ar, rpm * RPM, p, math.nan, math.nan, buf)[2]))
    c = np.array(counts)
    print("\nBall Newton iterations from the built-in start (no warm start), per speed: mean / max")
    for rpm in (1000.0, 10000.0, 20000.0):
        sel = c[c[:, 0] == rpm, 1]
        print(f"  {rpm:7.0f} rpm: {sel.mean():.1f} / {sel.max():.0f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--number", type=int, default=50)
    args = ap.parse_args()
    logging.basicConfig(level=logging.ERROR)
    timings(args.repeat, args.number)
    speed_study()
    model_study()
    hertz_angle_study()
    iteration_study()


if __name__ == "__main__":
    main()
