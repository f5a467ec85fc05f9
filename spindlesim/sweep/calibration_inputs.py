"""The ``calibration:`` section checked before anything is computed: every parameter's path, bounds and start,
every measurement's file; each problem a located deck issue naming the entry (``DeckError``, exit 2)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import yaml

from .calibration import MIN_POINTS, Measured, Parameter

SECTION = "calibration"


def check_parameters(loaded: Any) -> list[Parameter]:
    """The parameters with the deck's values as their start; DeckError listing every problem."""
    from ..deck import DeckError, parse_deck
    from ..deck.yamlmarks import DeckLoader
    from ..deck.paths import get_path, replace_in_text

    data = yaml.load(loaded.text, Loader=DeckLoader)
    issues, params, seen = [], [], {}
    for i, p in enumerate(loaded.deck.calibration.parameters):
        at = (SECTION, "parameters", i)
        if p.path in seen:
            issues.append(loaded.issue(at + ("path",), f"{p.path} is fitted twice (also parameters[{seen[p.path]}])"))
            continue
        seen[p.path] = i
        if p.path.split(".")[0] in (SECTION, "sweep", "optimize"):
            issues.append(loaded.issue(at + ("path",), f"{p.path}: a study's own settings are not a model value"))
            continue
        try:
            value = get_path(data, p.path)
        except KeyError as exc:
            issues.append(loaded.issue(at + ("path",), f"{exc.args[0]} (calibration parameter {p.path})"))
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            issues.append(loaded.issue(at + ("path",), f"{p.path} holds {value!r}, not a number"))
            continue
        if not p.min < p.max:
            issues.append(loaded.issue(at + ("max",), f"max {p.max:g} must be greater than min {p.min:g}"))
            continue
        if not p.min <= value <= p.max:
            issues.append(loaded.issue(at + ("path",), f"the deck's value of {p.path}, {value:g}, is outside its "
                                                       f"bounds {p.min:g} .. {p.max:g}: the fit starts from it"))
            continue
        for bound, key in ((p.min, "min"), (p.max, "max")):  # the deck must accept the value at each bound
            try:
                parse_deck(replace_in_text(loaded.text, {p.path: float(bound)}), loaded.source)
            except KeyError as exc:
                issues.append(loaded.issue(at + ("path",), f"{exc.args[0]}"))
                break
            except DeckError as exc:
                first = exc.issues[0]
                issues.append(loaded.issue(at + (key,), f"the deck refuses {p.path} = {bound:g}: {first.message}"))
        params.append(Parameter(p.path, float(p.min), float(p.max), float(value)))
    if issues:
        raise DeckError(issues)
    return params


def read_measurements(loaded: Any, base_dir: Path) -> list[Measured]:
    """Every measurement in the band, its direct FRF; DeckError listing every problem."""
    from ..chatter.frf import DIRECTIONS
    from ..chatter.readers import FrfFileError, read_frf
    from ..deck import DeckError

    sec = loaded.deck.calibration
    issues, out = [], []
    for i, m in enumerate(sec.measurements):
        at = (SECTION, "measurements", i, "file")
        path = Path(m.file.path)
        path = path if path.is_absolute() else Path(base_dir) / path
        try:
            frf = read_frf(path, m.file.format, m.file.direction)
        except (FrfFileError, OSError, ValueError) as exc:
            issues.append(loaded.issue(at + ("path",), f"measurement file: {exc}"))
            continue
        d = m.file.direction
        if d is None:
            flexible = [k for k, name in enumerate(DIRECTIONS) if np.any(frf.H[:, k, k])]
            if len(flexible) != 1:
                issues.append(loaded.issue(at, "the file holds both directions: give direction: x or y (the one "
                                               "the direct FRF was measured in)"))
                continue
            d = DIRECTIONS[flexible[0]]
        k = DIRECTIONS.index(d)
        f = frf.frequency_hz
        keep = np.ones(len(f), bool) if sec.band_hz is None else (f >= sec.band_hz[0]) & (f <= sec.band_hz[1])
        keep &= f > 0
        H = frf.H[keep, k, k]
        if keep.sum() < MIN_POINTS:
            issues.append(loaded.issue(at + ("path",), f"{path.name}: {int(keep.sum())} measured points in the band, "
                                                       f"at least {MIN_POINTS} are needed"))
            continue
        if not np.any(H):
            issues.append(loaded.issue(at, f"{path.name}: the {d}{d} receptance is zero in the band"))
            continue
        out.append(Measured(path.name, m.node, d, float(m.speed_rpm), f[keep].copy(), H.copy()))
    if issues:
        raise DeckError(issues)
    return out
