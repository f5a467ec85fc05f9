"""Chatter benchmark: speed of the lobe diagrams and the validation figures behind the tests.

Prints, in turn:
1. timing: zero-order lobes for one FRF (200 speeds; target < 50 ms), the 200-speed diagram with
   a tool-point model per speed (target < 5 s on one core), the step exponentials in cache-sized stacks
   against one stack, semi-discretization maps;
2. turning: oriented-FRF limits against the closed form 2 k zeta (1 + zeta) / (Ks cos beta);
3. milling, Insperger-Stepan single-DOF example (f_n 922 Hz, zeta 0.011, m 0.03993 kg, Kt 6e8,
   Kn 2e8 N/m^2): zero-order against semi-discretization for 4 and 2 teeth in a slot, and the
   flip islands at a/D = 0.05;
4. semi-discretization convergence with the number of steps per tooth period;
5. time-domain simulation against the boundary (+-10 %), chatter frequencies, decay vs rho;
6. modal fit against noise.

    python benchmarks/bench_chatter.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import logging
import time

import numpy as np

from spindlesim.chatter import (MillingProcess, Mode, ToolPointFrf, ToolPointModel, TurningProcess,
                                fit_tool_point_model, simulate, stability_lobes)
from spindlesim.chatter.semi_discretization import spectral_radius

FN, ZETA, MT = 922.0, 0.011, 0.03993
KX = MT * (2 * np.pi * FN) ** 2
SDOF = ToolPointModel.from_modes([Mode("x", FN, ZETA, KX)])
TAP = [Mode("x", 650.0, 0.035, 2.2e7), Mode("x", 1450.0, 0.02, 4.0e7),
       Mode("y", 720.0, 0.03, 2.6e7), Mode("y", 1600.0, 0.025, 5.0e7)]


def best_of(fn, repeat):
    times, out = [], None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return min(times), out


def spindle_like(speed_rpm: float, n_modes: int = 12) -> ToolPointModel:
    """A 2 x n_modes mode tool point whose frequencies drop with speed (bearing softening),
    x-y coupled and written in a general state basis: stands in for the rotor's reduced model."""
    soft = 1 - 0.15 * (speed_rpm / 30000.0) ** 2
    f0 = np.geomspace(450.0, 9000.0, n_modes)
    modes = [Mode(d, f * soft * (1.0 if d == "x" else 1.07), 0.02 + 0.01 * (i % 3), 3e7 * (1 + i) ** 1.5)
             for i, f in enumerate(f0) for d in ("x", "y")]
    base = ToolPointModel.from_modes(modes)
    c, s = np.cos(0.3), np.sin(0.3)
    R = np.array([[c, -s], [s, c]])
    rng = np.random.default_rng(0)
    T = np.linalg.qr(rng.standard_normal((base.A.shape[0],) * 2))[0]
    return ToolPointModel(T.T @ base.A @ T, T.T @ base.B @ R.T, R @ base.C @ T, "spindle-like")


def timing(repeat: int) -> None:
    print("\n1. timing (one core)")
    tool = ToolPointModel.from_modes(TAP)
    half = MillingProcess(4, 16e-3, 8e-3, "down", 800e6, 0.3)
    speeds = np.linspace(2000.0, 30000.0, 200)
    rows = [("zero-order, modal model (mode-clustered grid)", tool),
            ("zero-order, FRF 1 Hz to 5 kHz (5000 samples)", tool.frf(np.arange(1.0, 5000.0, 1.0))),
            ("zero-order, FRF 0.25 Hz to 5 kHz (20000 samples)", tool.frf(np.arange(0.25, 5000.0, 0.25)))]
    for name, t in rows:
        stability_lobes(half, t, speeds, "zero_order")
        dt, _ = best_of(lambda: stability_lobes(half, t, speeds, "zero_order"), repeat)
        print(f"   {name:52s} 200 speeds {1e3 * dt:7.1f} ms  (target < 50 ms)")
    turn = TurningProcess(2000e6, np.deg2rad(70.0))
    dt, _ = best_of(lambda: stability_lobes(turn, tool, np.linspace(300.0, 6000.0, 200)), repeat)
    print(f"   {'oriented FRF (turning), modal model':52s} 200 speeds {1e3 * dt:7.1f} ms")
    t0 = time.perf_counter()
    models = [spindle_like(n) for n in speeds]
    t_build = time.perf_counter() - t0
    dt, d = best_of(lambda: stability_lobes(half, models, speeds, "zero_order"), max(1, repeat // 2))
    print(f"   zero-order with a model per speed (48 states, 24 modes): {dt:6.2f} s for 200 speeds "
          f"(+ {t_build:.2f} s building the stand-in models)")
    milling_spindle(repeat)
    step_exponentials(repeat)
    low = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    for name, proc, tl, S, D in (("SD map, single DOF, 5 % immersion", low, SDOF, 100, 40),
                                 ("SD map, 4 modes x/y, half immersion", half, tool, 100, 40)):
        t0 = time.perf_counter()
        d = stability_lobes(proc, tl, np.linspace(5000.0, 25000.0, S), "semi_discretization", n_depths=D,
                            stability_map=True)
        dt = time.perf_counter() - t0
        m = d.steps_per_period
        print(f"   {name:40s} {S} x {D} grid + refinement: {dt:6.2f} s (steps/period {m.min()}-{m.max()})")


def step_exponentials(repeat: int) -> None:
    """The semi-discretization's step exponentials (Van Loan's blocks) worked out in cache-sized stacks, as the
    lobes do, against the whole stack at once (the same numbers): a 16-state model (the milling deck's dominant
    modes), 30 and 54 states (a short tool's), thousands of steps as one evaluation batch holds."""
    from spindlesim.chatter import _expm

    rng = np.random.default_rng(0)
    print("   step exponentials, us a step (cache-sized stacks / one stack):")
    for n, k in ((16, 8000), (30, 4000), (54, 1500)):
        F = 0.03 * rng.standard_normal((k, n, n))
        G = 0.01 * rng.standard_normal((k, n, 2))
        norm = float(np.abs(F).sum(axis=-2).max())
        chunked, _ = best_of(lambda: _expm.van_loan_blocks(F, G, norm), repeat)
        saved = _expm.CHUNK_BYTES
        _expm.CHUNK_BYTES = 1 << 40
        try:
            whole, _ = best_of(lambda: _expm.van_loan_blocks(F, G, norm), repeat)
        finally:
            _expm.CHUNK_BYTES = saved
        print(f"      {n:3d} states: {1e6 * chunked / k:6.1f} / {1e6 * whole / k:6.1f}  ({whole / chunked:.2f}x)")


def milling_spindle(repeat: int) -> None:
    """The milling spindle deck (ball bearings, tool on joints), 200 speeds, the tool-point FRF
    recomputed from the rotor at every speed (static state, bearing coefficients, reduced model),
    then the zero-order lobes (target < 5 s on one core) and the semi-discretization that `auto`
    runs for this half-immersion cut (its dominant-mode model, the depth search)."""
    from spindlesim.analysis.tool_point import tool_point_model, tool_point_series
    from spindlesim.deck import default_deck
    from spindlesim.model.build import build_rotor

    rotor = build_rotor(default_deck("milling_spindle").deck)
    proc = MillingProcess(4, 16e-3, 8e-3, "down", 767e6, 168.8 / 767.0)
    speeds = np.linspace(6000.0, 24000.0, 200)
    tool_point_series(rotor, speeds[:3])  # compile/warm

    def per_speed():
        series = tool_point_series(rotor, speeds)
        return series, stability_lobes(proc, list(series.models), speeds, "zero_order")

    dt, (series, d) = best_of(per_speed, max(1, repeat // 2))
    t_frf, _ = best_of(lambda: tool_point_series(rotor, speeds), 1)
    deck = tool_point_model(rotor, 18000.0)
    dt1, d1 = best_of(lambda: stability_lobes(proc, deck, speeds, "zero_order"), repeat)
    dt_sd, sd = best_of(lambda: stability_lobes(proc, list(series.models), speeds), 1)
    s, a = d.minimum
    print(f"   milling spindle deck, FRF from the rotor at each of 200 speeds ({series.model}):")
    print(f"      {dt:6.2f} s in all ({t_frf:.2f} s for the 200 tool-point models; target < 5 s); "
          f"FRF at the deck speed only: {1e3 * dt1:.0f} ms")
    s1, a1 = d1.minimum
    print(f"      minimum limit depth {1e3 * a:.3f} mm at {s:.0f} rpm (deck-speed FRF: {1e3 * a1:.3f} mm at "
          f"{s1:.0f} rpm)")
    s2, a2 = sd.minimum
    print(f"      auto (semi-discretization): {dt_sd:6.1f} s, minimum limit depth {1e3 * a2:.3f} mm at {s2:.0f} rpm")


def turning() -> None:
    print("\n2. turning, single DOF along the feed: b_min = 2 k zeta (1 + zeta) / (Ks cos beta)")
    k, z, fn, ks = 2e7, 0.03, 500.0, 2000e6
    tool = ToolPointModel.from_modes([Mode("x", fn, z, k)])
    r = 1 + z
    G = 1 / (k * (1 - r * r + 2j * z * r))
    eps = 2 * np.pi - 2 * np.arctan(G.real / G.imag)
    print(f"   {'beta':>5} {'lobe':>4} {'speed rpm':>10} {'b_lim mm':>9} {'closed mm':>9} {'err %':>8} "
          f"{'f_c err %':>9}")
    for beta in (0.0, 70.0):
        b_ref = 2 * k * z * (1 + z) / (ks * np.cos(np.deg2rad(beta)))
        speeds = np.array([60 * fn * r / (j + eps / (2 * np.pi)) for j in range(4)])
        d = stability_lobes(TurningProcess(ks, np.deg2rad(beta)), tool, speeds)
        for j in range(4):
            print(f"   {beta:5.0f} {j:4d} {speeds[j]:10.1f} {1e3 * d.limit_depth_m[j]:9.5f} {1e3 * b_ref:9.5f} "
                  f"{100 * (d.limit_depth_m[j] / b_ref - 1):8.4f} "
                  f"{100 * (d.chatter_frequency_hz[j] / (fn * r) - 1):9.5f}")


def milling() -> None:
    print("\n3. milling, Insperger-Stepan single-DOF example, down milling")
    speeds = np.linspace(5000.0, 25000.0, 41)
    for N, ppw in ((4, 20.0), (4, 30.0), (4, 40.0), (2, 30.0)):
        p = MillingProcess(N, 20e-3, 20e-3, "down", 6e8, 1 / 3)
        z = stability_lobes(p, SDOF, speeds, "zero_order")
        s = stability_lobes(p, SDOF, speeds, "semi_discretization", depth_max_m=1.5e-3, n_depths=15,
                            points_per_wave=ppw)
        ok = np.isfinite(s.limit_depth_m)
        err = 100 * (s.limit_depth_m[ok] / z.limit_depth_m[ok] - 1)
        i = int(np.nanargmin(z.limit_depth_m))
        print(f"   slot, {N} teeth, {ppw:.0f} points/wave: SD - ZOA over {ok.sum()} speeds: max |diff| "
              f"{np.abs(err).max():.2f} %, median {np.median(np.abs(err)):.2f} %; minimum ZOA "
              f"{1e3 * z.limit_depth_m[i]:.4f} mm (closed form 8 k zeta (1 + zeta) / (N Kn) = "
              f"{1e3 * 8 * KX * ZETA * (1 + ZETA) / (N * 2e8):.4f}), SD {1e3 * s.limit_depth_m[i]:.4f} mm")
    p = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    sp = np.arange(15000.0, 19001.0, 500.0)
    z = stability_lobes(p, SDOF, sp, "zero_order")
    s = stability_lobes(p, SDOF, sp, "semi_discretization", depth_max_m=6e-3, n_depths=30)
    print("   a/D = 0.05, 2 teeth: flip (period-doubling) islands")
    print(f"   {'rpm':>7} {'ZOA mm':>8} {'SD mm':>8} {'kind':>5} {'f_c Hz':>8} {'f_c / f_tooth':>13}")
    for n, a, b, kd, f in zip(sp, z.limit_depth_m, s.limit_depth_m, s.boundary_kind, s.chatter_frequency_hz):
        print(f"   {n:7.0f} {1e3 * a:8.3f} {1e3 * b:8.3f} {kd:>5} {f:8.1f} {f / (2 * n / 60):13.4f}")


def convergence() -> None:
    print("\n4. semi-discretization convergence, a/D = 0.05 (limit for m steps against m = 1024)")
    p = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3)
    steps = [16, 32, 64, 128, 256]
    for speed, order in ((18000.0, 1), (18000.0, 0), (22000.0, 1), (22000.0, 0)):
        a = {m: stability_lobes(p, SDOF, [speed], "semi_discretization", steps=m, order=order,
                                depths_m=[1.0e-3, 2.3e-3], rtol=1e-11) for m in steps + [1024]}
        err = np.array([abs(a[m].limit_depth_m[0] / a[1024].limit_depth_m[0] - 1) for m in steps])
        slope = -np.polyfit(np.log(steps), np.log(err), 1)[0]
        print(f"   {speed:.0f} rpm ({a[1024].boundary_kind[0]}), order {order}: limit "
              f"{1e3 * a[1024].limit_depth_m[0]:.5f} mm; errors " + " ".join(f"{e:.2e}" for e in err)
              + f"; fitted order {slope:.2f}")


def simulation() -> None:
    print("\n5. time domain against the semi-discretization boundary (slot, 2 teeth; and a/D = 0.05)")
    print(f"   {'case':>10} {'rpm':>7} {'a_lim mm':>9} {'0.9 a':>7} {'1.1 a':>7} {'growth 0.9a':>11} {'rho 0.9a':>9}"
          f" {'f_c sim':>8} {'f_c SD':>8} {'bin Hz':>7}")
    slot = MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3, feed_per_tooth_m=5e-5)
    low = MillingProcess(2, 20e-3, 1e-3, "down", 6e8, 1 / 3, feed_per_tooth_m=5e-5)
    for label, p, speeds, dmax in (("slot", slot, [6000.0, 10000.0, 16000.0, 17000.0], 1.5e-3),
                                   ("a/D 0.05", low, [17500.0, 18000.0, 22000.0], 4e-3)):
        d = stability_lobes(p, SDOF, speeds, "semi_discretization", depth_max_m=dmax, n_depths=16)
        for n, a, fc in zip(speeds, d.limit_depth_m, d.chatter_frequency_hz):
            lo = simulate(p, SDOF, n, 0.9 * a)
            hi = simulate(p, SDOF, n, 1.1 * a)
            rho = spectral_radius(p, SDOF, n, 0.9 * a, steps=120)
            print(f"   {label:>10} {n:7.0f} {1e3 * a:9.4f} {'stable' if lo.stable else 'CHATTER':>7} "
                  f"{'stable' if hi.stable else 'chatter':>7} {lo.growth_per_period:11.4f} {rho:9.4f} "
                  f"{hi.chatter_frequency_hz:8.1f} {fc:8.1f} {hi.fft_bin_hz:7.2f}")


def modal_fit() -> None:
    print("\n6. modal fit of a noisy 4-mode tap test (1 Hz resolution, complex noise relative to the peak)")
    model = ToolPointModel.from_modes(TAP)
    f = np.arange(100.0, 3000.0, 1.0)
    H0 = model.receptance(2 * np.pi * f)
    rng = np.random.default_rng(7)
    print(f"   {'noise':>6} {'max |df| %':>10} {'max |dzeta| %':>13} {'max |dk| %':>10} {'time s':>7}")
    for noise in (0.0, 0.01, 0.02, 0.05):
        H = H0.copy()
        for i in range(2):
            z = rng.standard_normal(len(f)) + 1j * rng.standard_normal(len(f))
            H[:, i, i] += noise * np.abs(H0).max() * z / np.sqrt(2)
        t0 = time.perf_counter()
        fit = fit_tool_point_model(ToolPointFrf(f, H))
        dt = time.perf_counter() - t0
        e = np.array([[b.frequency_hz / a.frequency_hz - 1, b.damping_ratio / a.damping_ratio - 1,
                       b.stiffness_N_m / a.stiffness_N_m - 1] for a, b in zip(TAP, fit.modes)])
        print(f"   {noise:6.2f} {100 * np.abs(e[:, 0]).max():10.4f} {100 * np.abs(e[:, 1]).max():13.3f} "
              f"{100 * np.abs(e[:, 2]).max():10.3f} {dt:7.3f}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    logging.basicConfig(level=logging.ERROR)
    t0 = time.perf_counter()
    simulate(MillingProcess(2, 20e-3, 20e-3, "down", 6e8, 1 / 3), SDOF, 10000.0, 1e-4, tooth_periods=20)
    print(f"(numba kernels of the simulation compiled or loaded from cache in {time.perf_counter() - t0:.2f} s)")
    timing(args.repeat)
    turning()
    milling()
    convergence()
    simulation()
    modal_fit()


if __name__ == "__main__":
    main()
