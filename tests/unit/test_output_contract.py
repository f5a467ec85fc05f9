"""The output contract of every command's files (docs/output-format.md), on one run of each command's
default deck: xarray opens every group with coordinates, every dataset's dimensions are HDF5 dimension
scales, units are UDUNITS strings from one vocabulary, no NaN/Inf unless declared as fill, provenance,
file modes under umask 022, and a non-finite result ends a command with exit 1 and no file.

The writer itself (refusals, atomic writes, complex storage) is tested in test_hdf5_contract.py."""

import dataclasses
import os
import stat

import h5py
import numpy as np
import pytest

from spindlesim.output.hdf5 import RunInfo

xr = pytest.importorskip("xarray")
pytest.importorskip("h5netcdf")

RUN = RunInfo("deck: text", "<test>", "0" * 64)
PROVENANCE = ("spindlesim_version", "created_utc", "platform", "python_version", "numpy_version", "scipy_version",
              "h5py_version", "numba_version", "deck_sha256", "deck_text", "deck_source", "command_line", "complete")
#: every unit the files use; each parses in UDUNITS-2 (cf-units) and in pint
UNITS = {"1", "m", "m/s", "s", "Hz", "rpm", "rad", "rad/m", "degree", "degC", "N", "N m", "N/m", "m/N", "N s/m",
         "N/rad", "N m/m", "N m/rad", "1/s", "Pa", "Pa s", "W", "m^3/s", "um", "megarevolution"}

CHATTER = """
chatter:
  operation: milling
  speeds_rpm: {start: 4000, stop: 12000, count: 12}
  Kt_N_mm2: 767.0
  Kn_N_mm2: 168.8
  teeth: 2
  tool_diameter_mm: 20.0
  radial_depth_mm: 20.0
  mode: down
  frf: rotor
"""

#: analysis -> (deck, options, text appended to the deck)
CASES = {
    "static": ("spindle_linear", {}, ""),
    "modal": ("spindle_linear", {}, ""),
    "campbell": ("spindle_linear", {"speeds_rpm": [0.0, 6000.0, 12000.0]}, ""),
    "frf": ("spindle_linear", {}, ""),
    "unbalance": ("spindle_linear", {}, ""),
    "thermal": ("spindle", {}, ""),
    "coefficients": ("spindle", {}, ""),
    "transient": ("transient", {"duration_s": 0.03}, ""),
    "bearing": ("bearing", {}, ""),
    "dtrb": ("dtrb", {}, ""),
    "contact": ("contact", {"nx": 24, "ny": 48}, ""),
    "chatter": ("spindle_linear", {"simulate": [(8000.0, 0.5)]}, CHATTER),
}

#: analysis -> (group, data variable, {coordinate: label to select}) for the .sel check
SELECT = {
    "static": ("static", "displacement_m", {"node": 1, "dof": "x"}),
    "modal": ("modal", "mode_shape", {"mode": 1, "node": 1, "dof": "theta_x"}),
    "campbell": ("campbell", "frequency_hz", {"speed_rpm": 6000.0, "mode": 1}),
    "frf": ("frf", "receptance_m_N", {"frequency_hz": None}),
    "unbalance": ("unbalance", "response_m", {"speed_rpm": None, "node": 1, "dof": "y"}),
    "thermal": ("thermal/front", "journal_position_m", {"dof": "y"}),
    "coefficients": ("coefficients/front", "K_N_m", {"load": "Fx", "dof": "x"}),
    "transient": ("transient", "displacement_m", {"time_s": None, "dof": "x"}),
    "bearing": ("bearing/sweeps/load", "stiffness", {"fx_N": None, "load": "Fx", "dof": "x"}),
    "dtrb": ("dtrb/preload_sweep", "KXX_N_m", {"preload_m": None}),
    "contact": ("contact", "pressure_Pa", {"x_m": None, "y_m": None}),
    "chatter": ("chatter", "limit_depth_m", {"speed_rpm": None}),
}


@pytest.fixture
def umask022():
    old = os.umask(0o022)
    yield
    os.umask(old)


@pytest.fixture(scope="module")
def outputs(tmp_path_factory):
    """analysis -> (its .h5 file, every file it wrote), written once under umask 022."""
    from spindlesim.deck import default_deck, parse_deck
    from spindlesim.runs import run_analysis

    cache = {}

    def get(name):
        if name not in cache:
            deck, opts, extra = CASES[name]
            loaded = default_deck(deck)
            if extra:
                loaded = parse_deck(loaded.text + extra, f"{deck}.yaml")
            out = tmp_path_factory.mktemp(name)
            old = os.umask(0o022)
            try:
                paths = run_analysis(name, loaded, out, opts)
            finally:
                os.umask(old)
            cache[name] = (out / f"{name}.h5", paths)
        return cache[name]

    return get


def _groups(path):
    out = []
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.append(n) if isinstance(o, h5py.Group) else None)
    return out


def _text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


@pytest.mark.slow
@pytest.mark.parametrize("name", list(CASES))
def test_file_modes_under_umask_022(outputs, name):
    """Every .h5 and .png the command wrote (all files in its folder, returned or not) is 0644 under
    umask 022, and no temporary file is left."""
    path, paths = outputs(name)
    written = sorted(p for p in path.parent.iterdir())
    assert sorted(paths) == written
    assert {p.suffix for p in written} == {".h5", ".png"}, written  # each case draws its figures
    for p in written:
        assert stat.S_IMODE(os.stat(p).st_mode) == 0o644, p


@pytest.mark.parametrize("name", list(CASES))
def test_file_contract(outputs, name):
    """Provenance root attributes; every dataset: units from UNITS (or "" with component_units from
    UNITS), no Inf, NaN only with _FillValue NaN; every non-scalar dataset is a dimension scale or
    has a scale attached to each axis; xarray opens every group with a coordinate for every dimension."""
    path, _ = outputs(name)
    with h5py.File(path, "r") as f:
        for key in PROVENANCE:
            assert key in f.attrs, key
        assert _text(f.attrs["created_utc"]).endswith("+00:00") and bool(f.attrs["complete"])

        def check(ds_name, ds):
            if not isinstance(ds, h5py.Dataset):
                return
            attrs = ds.attrs
            units = _text(attrs["units"])
            if units == "":
                comp = np.asarray(attrs["component_units"]).astype(str)
                assert set(comp.ravel()) <= UNITS, (ds_name, comp)
            else:
                assert units in UNITS, (ds_name, units)
            v = ds[()]
            if isinstance(v, np.ndarray) and v.dtype.kind in "fc":
                assert not np.isinf(v).any(), ds_name
                if np.isnan(v).any():
                    assert "_FillValue" in attrs and np.isnan(attrs["_FillValue"]), ds_name
            if ds.ndim and not ds.is_scale:
                unscaled = [i for i in range(ds.ndim) if len(ds.dims[i]) == 0]
                assert not unscaled, (ds_name, "axes without a dimension scale", unscaled)
            elif ds.ndim:
                assert ds.ndim == 1, ds_name

        f.visititems(check)
    for group in _groups(path):
        with xr.open_dataset(path, group=group, engine="h5netcdf") as ds:
            missing = [d for d in ds.sizes if d not in ds.coords]
            assert not missing, (group, missing)
            assert not [d for d in ds.sizes if str(d).startswith("phony_dim")]


@pytest.mark.parametrize("name", list(SELECT))
def test_select_by_coordinate(outputs, name):
    path, _ = outputs(name)
    group, var, where = SELECT[name]
    with xr.open_dataset(path, group=group, engine="h5netcdf") as ds:
        sel = {k: (ds[k].values[len(ds[k]) // 2] if v is None else v) for k, v in where.items()}
        picked = ds[var].sel(sel)
        assert picked.ndim == ds[var].ndim - len(sel)
        with h5py.File(path, "r") as f:
            raw = f[f"{group}/{var}"][()]
            index = tuple(int(np.flatnonzero(ds[d].values == sel[d])[0]) if d in sel else slice(None)
                          for d in ds[var].dims)
            np.testing.assert_array_equal(picked.values, raw[index])


def test_frf_and_campbell_by_value(outputs):
    """frf: .sel(frequency_hz=1117.0, method="nearest") is the complex receptance h5py reads at the
    nearest frequency, and the coordinate carries units "Hz"; campbell: .sel(speed_rpm=6000.0) gives
    one frequency per mode, equal to the file's row, NaN where a mode is not tracked."""
    path, _ = outputs("frf")
    with xr.open_dataset(path, group="frf", engine="h5netcdf") as ds, h5py.File(path, "r") as f:
        f_hz = f["frf/frequency_hz"][()]
        k = int(np.argmin(np.abs(f_hz - 1117.0)))
        h = ds.receptance_m_N.sel(frequency_hz=1117.0, method="nearest")
        assert h.dtype == np.complex128 and h.values == f["frf/receptance_m_N"][k]
        assert float(h.frequency_hz) == f_hz[k] and ds.frequency_hz.attrs["units"] == "Hz"
        assert ds.receptance_m_N.attrs["units"] == "m/N"
    path, _ = outputs("campbell")
    with xr.open_dataset(path, group="campbell", engine="h5netcdf") as ds, h5py.File(path, "r") as f:
        row = ds.frequency_hz.sel(speed_rpm=6000.0)
        assert row.dims == ("mode",) and list(ds.mode.values) == list(range(1, ds.sizes["mode"] + 1))
        np.testing.assert_array_equal(row.values, f["campbell/frequency_hz"][1])
        assert ds.speed_rpm.attrs["units"] == "rpm"


def test_mixed_units_and_labels(outputs):
    path, _ = outputs("bearing")
    with xr.open_dataset(path, group="bearing", engine="h5netcdf") as ds:
        k = ds["stiffness"]
        assert k.attrs["units"] == "" and list(ds["load"].values) == ["Fx", "Fy", "Fz", "Mx", "My"]
        units = np.asarray(k.attrs["component_units"])
        assert units[0, 0] == "N/m" and units[0, 3] == "N/rad" and units[3, 0] == "N m/m" and units[3, 4] == "N m/rad"
        assert list(ds["displacement"].attrs["component_units"]) == ["m", "m", "m", "rad", "rad"]


def test_campbell_untracked_modes_are_fill(tmp_path, umask022):
    from spindlesim.analysis.results import CampbellResult
    from spindlesim.output.rotor_writers import write_campbell

    F = np.array([[100.0, 200.0], [101.0, np.nan]])
    r = CampbellResult(np.array([0.0, 1000.0]), F, F * 0, F * 0, np.array([["forward", "backward"], ["forward", ""]]),
                       np.zeros(0), np.zeros(0, int))
    path = write_campbell(tmp_path / "campbell.h5", RUN, r, frozen=r, frozen_rpm=0.0)
    with xr.open_dataset(path, group="campbell/frozen", engine="h5netcdf") as ds:
        assert np.isnan(ds.frequency_hz.sel(speed_rpm=1000.0, mode=2))
        assert ds.frequency_hz.encoding["_FillValue"] != ds.frequency_hz.encoding["_FillValue"]  # NaN
    assert stat.S_IMODE(os.stat(path).st_mode) == 0o644


# ----------------------------------------------------------------------------------------------
# a result that is not finite


def _nan_bearing_forces(r):
    return dataclasses.replace(r, bearing_force_N=np.full_like(r.bearing_force_N, np.nan))


def _zero_receptance(r):  # a zero receptance makes the dynamic stiffness 1/H infinite (complex)
    h = r.receptance_m_N.copy()
    h[3] = 0.0
    return dataclasses.replace(r, receptance_m_N=h)


@pytest.mark.parametrize("command, module, solver, spoil, message", [
    ("static", "spindlesim.analysis.static", "solve_static", _nan_bearing_forces,
     "static.h5: refusing to write non-finite results: /static/bearing_force_N has 4 NaN value(s) of 4"),
    ("frf", "spindlesim.analysis.frf", "solve_frf", _zero_receptance,
     "frf.h5: refusing to write non-finite results: /frf/dynamic_stiffness_N_m has 1 infinite value(s) of "),
], ids=["static-nan", "frf-complex-inf"])
def test_non_finite_result_exits_1_with_one_line(tmp_path, monkeypatch, command, module, solver, spoil, message):
    """The CLI on the default deck, its solver's result spoilt as a numerical failure would: exit 1,
    exactly one output line "spindlesim <command>: <file>: refusing to write non-finite results:
    <dataset> has ...", and the output folder holds no file (no .h5, no temporary, no PNG)."""
    import importlib

    from click.testing import CliRunner

    from spindlesim.cli import main

    mod = importlib.import_module(module)
    solve = getattr(mod, solver)
    monkeypatch.setattr(mod, solver, lambda *a, **k: spoil(solve(*a, **k)))
    with np.errstate(divide="ignore", invalid="ignore"):
        res = CliRunner().invoke(main, [command, "-o", str(tmp_path / "out")])
    assert res.exit_code == 1, res.output
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"spindlesim {command}: {message}"), res.output
    assert not (tmp_path / "out").exists() or not list((tmp_path / "out").iterdir())
