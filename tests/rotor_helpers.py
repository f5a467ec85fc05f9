"""Small deck builders shared by rotor tests."""

from __future__ import annotations

import numpy as np

from spindlesim.deck import parse_deck
from spindlesim.model.build import build_rotor


def uniform_rows(n: int, length_mm: float, od_mm: float, id_mm: float = 0.0, rho: float = 7810.0,
                 E_GPa: float = 211.0, G_GPa: float = 81.2, nu: float = 0.3, fa: float = 0.0) -> str:
    row = f"    - [{od_mm}, {id_mm}, {length_mm / n!r}, {rho}, {E_GPa}, {G_GPa}, {nu}, {fa}]\n"
    return "shaft:\n  elements:\n" + row * n


def deck_text(body: str, speed_rpm: float = 0.0) -> str:
    return f"title: test\n{body}operating:\n  speed_rpm: {speed_rpm}\n"


def rotor_from(body: str, speed_rpm: float = 0.0):
    return build_rotor(parse_deck(deck_text(body, speed_rpm), "test.yaml").deck)


def isotropic_bearing(name: str, node: int, k: float, c: float = 0.0) -> str:
    return (f"  - {{name: {name}, node: {node}, type: linear, K_N_m: [[{k!r}, 0.0], [0.0, {k!r}]], "
            f"C_Ns_m: [[{c!r}, 0.0], [0.0, {c!r}]]}}\n")


def disk_entry(node: int, rho: float, od: float, bore: float, width: float) -> tuple[str, float, float, float]:
    """Steel disk (SI dims): returns deck line and (m, Ip, Id) with Ip = m (ro^2 + ri^2)/2, Id = Ip/2 + m w^2/12."""
    ro, ri = od / 2, bore / 2
    m = rho * np.pi * (ro**2 - ri**2) * width
    Ip = m * (ro**2 + ri**2) / 2
    Id = Ip / 2 + m * width**2 / 12
    return f"  - {{node: {node}, mass_kg: {m!r}, Ip_kg_m2: {Ip!r}, Id_kg_m2: {Id!r}}}\n", m, Ip, Id


def cli_with_result(monkeypatch, args: list[str], exit_code: int = 0):
    """Run the CLI with ``args`` and return (its printed output, what the run handed back: runs.status.Written, of
    an incomplete run too), the run's result caught on its way to the summary (``spindlesim.runs.perform_analysis``
    stays wrapped for the rest of the test)."""
    from click.testing import CliRunner

    import spindlesim.runs as runs
    from spindlesim.cli import main
    from spindlesim.runs.status import IncompleteRun

    caught = []
    perform = runs.perform_analysis

    def catching(*a, **kw):
        try:
            caught.append(perform(*a, **kw))
        except IncompleteRun as exc:
            caught.append(exc.written)
            raise
        return caught[-1]

    monkeypatch.setattr(runs, "perform_analysis", catching)
    res = CliRunner().invoke(main, [str(a) for a in args])
    assert res.exit_code == exit_code, res.output
    written = caught[-1]
    return res.output, written


def printed_summary(output: str, file_name: str) -> list[str]:
    """The summary lines the CLI printed under ``file_name:`` (indented by two spaces), up to the next blank line."""
    lines = output.splitlines()
    start = lines.index(f"{file_name}:") + 1
    out = []
    for ln in lines[start:]:
        if not ln.startswith("  "):
            break
        out.append(ln[2:])
    return out


def speed_tabled(rotor):
    """``rotor`` with each linear bearing's one row of coefficients given at two speeds (the same numbers): the same
    rotor, whose static state the operating points solve at every speed (a rotor on speed-independent bearings is
    solved once, ``analysis.points``)."""
    import dataclasses

    rows = lambda a: np.repeat(np.asarray(a), 2, axis=0)  # noqa: E731
    bearings = tuple(dataclasses.replace(b, speeds_rad_s=np.array([0.0, 1e4]), K_N_m=rows(b.K_N_m),
                                         C_Ns_m=rows(b.C_Ns_m)) for b in rotor.bearings)
    return dataclasses.replace(rotor, bearings=bearings)
