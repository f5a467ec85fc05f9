"""The one registry of analyses and commands: adding an analysis is one :class:`Analysis` entry here.

Every table the layers need is derived from :data:`ANALYSIS_REGISTRY` and :data:`TOOL_COMMANDS`:
the names a deck may list (``deck.loader.ANALYSES``, ``SUPPORTED_ANALYSES``), the runs
(``runs.RUNS``), what ``spindlesim run`` runs by default and in which order (``runs.DEFAULT_RUN``),
the CLI's commands (``cli.COMMANDS``) and their embedded decks (``decks.DEFAULT_DECKS``), the
terminal summaries of the results (``output.summary.SUMMARIES``), the verdicts (``analysis.verdicts``) and a sweep's key results, units and overlays
(``sweep.summary.KEY_SCALARS``, ``DERIVED_UNITS``, ``OVERLAYS``).

Only names and dotted paths live here, no import of spindlesim: the CLI reads the registry at
start-up without importing numpy or a solver.  The code an entry names is written beside it:
``spindlesim/runs/<module>.py`` (the run), ``spindlesim/commands/<name>.py`` (its click command, when
it has ``help``), the summary function in ``spindlesim/output``, and the rule of when ``spindlesim
run`` runs it without an ``analyses`` list in ``runs.default_analyses``.
"""

from __future__ import annotations

from dataclasses import dataclass

#: a sweep overlay: (file, x dataset, y dataset, x label, y label)
Overlay = tuple[str, str, str, str, str]


@dataclass(frozen=True)
class Analysis:
    name: str
    #: ``module:function`` in spindlesim.runs: ``run(loaded_deck, outdir, run_info, options, progress)``
    run: str
    #: the line of ``spindlesim --help``; "" for an analysis without a command of its own
    help: str = ""
    #: the embedded deck its command runs without DECK
    deck: str = "spindle"
    #: what ``spindlesim run`` needs to run it when the deck lists no analyses ("" : never by default);
    #: neighbours with the same text form one row of ``spindlesim run --help``
    needs: str = ""
    #: the same as deck sections: it runs by default when the deck has every section of one alternative
    #: ("rotor": shaft or journal; "fluid_film": a bearing of type three_lobe or plain)
    runs_on: tuple[tuple[str, ...], ...] = ()
    #: an analysis of the rotor on its bearings: the deck's bearings must hold the rotor
    supported: bool = False
    #: other names a deck may list for the same analysis (the same run, file and summary)
    aliases: tuple[str, ...] = ()
    #: ``module:function`` in spindlesim.output summarising its result on the terminal and in the report
    summary: str = ""
    #: ``function`` in spindlesim.analysis.verdicts: its verdicts (``(result, operating range, name) -> [Verdict]``)
    verdicts: str = ""
    #: a sweep's key results, most important first ("*" matches one path part)
    key_scalars: tuple[str, ...] = ()
    #: units of the derived scalars a sweep adds for it (sweep/summary.py)
    derived_units: tuple[tuple[str, str], ...] = ()
    #: the curve a sweep draws side by side for its cases
    overlay: Overlay | None = None
    #: the stem of the file it writes, when not its name (``<file>.h5``; its results in the group ``/<name>``).
    #: Analyses that write one file are alternatives: the command or deck name of that file runs the first of
    #: them the deck has the leading section for, and ``spindlesim run`` runs only the first it has the sections for
    file: str = ""

    @property
    def stem(self) -> str:
        """The stem of the file it writes."""
        return self.file or self.name


@dataclass(frozen=True)
class Command:
    """A command that is not one analysis (``run``, ``sweep``, ``decks``, ``schema``)."""

    name: str
    help: str
    deck: str | None = None  # the embedded deck it runs without DECK (None: it takes no deck)
    #: a command on measurement files instead of a deck: the packaged files it runs without FILE (a glob under
    #: spindlesim/decks/)
    input: str = ""
    #: ``module:function`` in spindlesim.output summarising its file ``<name>.h5`` (as an Analysis's)
    summary: str = ""
    #: the file stem of that summary, when it is not the command's name
    file: str = ""


_ROTOR = "a rotor (shaft or journal) and operating"
_ROTOR_ON = (("rotor", "operating"),)
_FILM = "fluid-film bearings (type three_lobe or plain) and operating"
_FILM_ON = (("fluid_film", "operating"),)
_SPECTRUM: Overlay = ("transient.h5", "transient/spectrum/frequency_hz", "transient/spectrum/amplitude_m",
                      "frequency [Hz]", "spectrum amplitude [m]")

#: every analysis, in the order ``spindlesim run`` runs them
ANALYSIS_REGISTRY: tuple[Analysis, ...] = (
    Analysis("spindle_thermal", "spindle_thermal:run", file="thermal",
             needs="a spindle_thermal section (a shaft on rolling bearings) and operating",
             runs_on=(("spindle_thermal", "operating"),), summary="thermal_summary:spindle_thermal",
             verdicts="thermal_verdicts",
             key_scalars=("spindle_thermal@runaway_speed_rpm", "spindle_thermal/tool_tip_axial_drift_m*")),
    Analysis("thermal", "fluidfilm:run_thermal", needs=_FILM, runs_on=_FILM_ON,
             summary="bearing_summary:thermal",
             help="Thermal equilibrium of fluid-film bearings (film, oil flow, housing) or of a spindle_thermal "
                  "section.",
             key_scalars=("thermal/*/temperature_mean_C", "thermal/*/eccentricity_ratio")),
    Analysis("coefficients", "fluidfilm:run_coefficients", needs=_FILM, runs_on=_FILM_ON,
             summary="bearing_summary:coefficients",
             help="Fluid-film bearing stiffness and damping at thermal equilibrium.",
             key_scalars=("coefficients/*/K_N_m[0,0]", "coefficients/*/K_N_m[1,1]", "coefficients/*/C_Ns_m[0,0]",
                          "coefficients/*/C_Ns_m[1,1]", "coefficients/*/eccentricity_ratio",
                          "coefficients/*/temperature_mean_C")),
    Analysis("static", "rotor:run_static", needs=_ROTOR, runs_on=_ROTOR_ON, supported=True,
             summary="rotor_summary:static",
             help="Static deflection K^-1 Q, bearing reactions, static stiffness.",
             key_scalars=("static/max_displacement_m", "static/static_stiffness_N_m*"),
             derived_units=(("static/max_displacement_m", "m"),)),
    Analysis("modal", "rotor:run_modal", needs=_ROTOR, runs_on=_ROTOR_ON, supported=True,
             summary="rotor_summary:modal",
             help="Damped modes (state-space QR): frequencies, damping, whirl, shapes.",
             key_scalars=("modal/f1_hz", "modal/f2_hz", "modal/f3_hz", "modal/f4_hz", "modal/zeta1", "modal/zeta2"),
             derived_units=(("modal/f{k}_hz", "Hz"), ("modal/zeta{k}", "1"))),
    Analysis("campbell", "rotor:run_campbell", needs=_ROTOR, runs_on=_ROTOR_ON, supported=True,
             verdicts="campbell_verdicts", summary="rotor_summary:campbell",
             help="Campbell diagram with tracked modes and critical speeds.",
             key_scalars=("campbell/first_critical_rpm",), derived_units=(("campbell/first_critical_rpm", "rpm"),)),
    Analysis("frf", "rotor:run_frf", needs=_ROTOR, runs_on=_ROTOR_ON, supported=True,
             summary="rotor_summary:frf",
             help="Complex frequency response (receptance) between two DOFs.",
             key_scalars=("frf/peak_m_N", "frf/peak_frequency_hz"),
             derived_units=(("frf/peak_m_N", "m/N"), ("frf/peak_frequency_hz", "Hz")),
             overlay=("frf.h5", "frf/frequency_hz", "frf/receptance_m_N", "frequency [Hz]", "|receptance| [m/N]")),
    Analysis("unbalance", "rotor:run_unbalance", needs="a rotor, operating and an unbalance section", supported=True,
             runs_on=(("rotor", "operating", "unbalance"),),
             summary="rotor_summary:unbalance", help="Synchronous unbalance response over speed.",
             key_scalars=("unbalance/max_amplitude_m",), derived_units=(("unbalance/max_amplitude_m", "m"),)),
    Analysis("transient", "transient:run", deck="transient", supported=True, aliases=("rotor_transient",),
             needs="a rotor, operating and a rotor_transient section; or a transient section",
             runs_on=(("rotor", "operating", "rotor_transient"), ("transient",)),
             verdicts="transient_verdicts", summary="summary:transient",
             help="Time response of any rotor with its bearings' nonlinear reactions (run-up, whirl, roller pass).",
             key_scalars=("transient/dominant_amplitude_m", "transient/steady_amplitude_x_m",
                          "transient/steady_amplitude_y_m", "transient/dominant_frequency_hz"),
             derived_units=(("transient/dominant_frequency_hz", "Hz"), ("transient/dominant_amplitude_m", "m"),
                            ("transient/steady_amplitude_x_m", "m"), ("transient/steady_amplitude_y_m", "m")),
             overlay=_SPECTRUM),
    Analysis("bearing", "bearing:run", deck="bearing", needs="a bearing section", runs_on=(("bearing",),),
             summary="bearing_summary:bearing",
             help="One bearing (set) under a load: ball bearing stiffness, contact angles, life; or a DTRB."),
    Analysis("dtrb", "dtrb:run_dtrb", deck="dtrb", needs="a dtrb section", runs_on=(("dtrb",),),
             summary="bearing_summary:dtrb",
             help="Double-row tapered roller bearing: load distribution, 5x5 stiffness, preload/load sweeps."),
    Analysis("contact", "contact:run_contact", deck="contact", needs="a contact section", runs_on=(("contact",),),
             summary="bearing_summary:contact",
             help="Roller/ball contact pressure on a raceway (half-space, DC-FFT + CGM).",
             key_scalars=("contact/converged_max_pressure_Pa", "contact@applied_load_N", "contact@max_pressure_Pa"),
             derived_units=(("contact/edge_singular", "1"), ("contact/converged_max_pressure_Pa", "Pa"))),
    Analysis("chatter", "chatter:run", deck="milling_spindle", needs="a chatter section", supported=True,
             runs_on=(("chatter",),),
             verdicts="chatter_verdicts", summary="summary:chatter",
             help="Chatter stability lobes from the tool-point FRF (rotor at every speed, tap test or file)."),
    Analysis("tools", "tools:run", deck="tool_library", needs="a tools section", supported=True,
             runs_on=(("rotor", "operating", "tools"),), summary="tools_summary:tools",
             help="A tool library on the spindle: each tool's tip FRF by receptance coupling, and its lobes."),
)

#: the commands that are not one analysis, listed after the analyses' commands
TOOL_COMMANDS: tuple[Command, ...] = (
    Command("run", "Every analysis the deck lists, or every one it has the sections for (run --help).", "spindle"),
    Command("decks", "The embedded decks (defaults and examples); `decks show NAME` prints one to start from."),
    Command("schema", "The deck's JSON schema (editor completion and checking)."),
    Command("sweep", "Parameter study over any deck value (process pool or Dask), resumable.", "speed_study"),
    Command("calibrate", "Fit deck values (joints, bearing damping ...) to measured FRFs: calibrated deck, 95 % "
                         "intervals.", "tool_library", summary="calibration_summary:calibration", file="calibration"),
    Command("optimize", "Design optimisation over deck values: an optimum, or a Pareto front of stiffness, heat, "
                        "life ... (resumable).", "bearing_span", summary="optimize_summary:optimize"),
    Command("fitmodes", "Modes of a measured FRF file (LSCF/LSFD, stabilisation diagram): modes.yaml for chatter.",
            input="taptest/tap_tip_x.csv"),
    Command("impact", "Tap test FRF from hammer and accelerometer records (H1, coherence, double hits flagged).",
            input="taptest/tap_impact_x_*.csv"),
)


def command_entry(name: str) -> Command:
    """The entry of the command ``name`` that is not one analysis; KeyError for another name."""
    for c in TOOL_COMMANDS:
        if c.name == name:
            return c
    raise KeyError(name)


def file_commands() -> tuple[str, ...]:
    """The commands on measurement files (they take a FILE, not a deck)."""
    return tuple(c.name for c in TOOL_COMMANDS if c.input)


def file_summaries() -> dict[str, str]:
    """analysis (or command file stem) -> ``module:function`` summarising its file: every analysis's, and the
    commands' that write a file of their own."""
    return {**{a.name: a.summary for a in ANALYSIS_REGISTRY if a.summary},
            **{c.file or c.name: c.summary for c in TOOL_COMMANDS if c.summary}}


def study_files() -> tuple[str, ...]:
    """The stems of the files the commands that are not one analysis write and summarise (calibration, optimize)."""
    return tuple(c.file or c.name for c in TOOL_COMMANDS if c.summary)


def file_writers() -> dict[str, tuple[str, ...]]:
    """file stem -> the analyses that write ``<stem>.h5``, in the registry's order (several: alternatives, each
    writing its group ``/<name>``)."""
    out: dict[str, tuple[str, ...]] = {}
    for a in ANALYSIS_REGISTRY:
        out[a.stem] = out.get(a.stem, ()) + (a.name,)
    return out


def analysis(name: str) -> Analysis:
    """The entry of ``name`` (an alias included); KeyError for an unknown name."""
    for a in ANALYSIS_REGISTRY:
        if name == a.name or name in a.aliases:
            return a
    raise KeyError(name)


def analysis_names() -> tuple[str, ...]:
    """Every name a deck may list under ``analyses:``, each followed by its aliases."""
    return tuple(n for a in ANALYSIS_REGISTRY for n in (a.name, *a.aliases))


def commands() -> dict[str, str]:
    """command -> its line of ``spindlesim --help``: the analyses' commands, then the others; each command
    is ``spindlesim/commands/<name>.py``."""
    return {**{a.name: a.help for a in ANALYSIS_REGISTRY if a.help}, **{c.name: c.help for c in TOOL_COMMANDS}}


def default_decks() -> dict[str, str]:
    """command -> the embedded deck it runs when given no DECK."""
    return {**{a.name: a.deck for a in ANALYSIS_REGISTRY if a.help},
            **{c.name: c.deck for c in TOOL_COMMANDS if c.deck is not None}}


def default_rows() -> tuple[tuple[tuple[str, ...], str], ...]:
    """What ``spindlesim run`` runs without an ``analyses`` list, in order: (analyses, what the deck needs
    for them), one row for neighbours that need the same."""
    rows: list[tuple[list[str], str]] = []
    for a in ANALYSIS_REGISTRY:
        if not a.needs:
            continue
        if rows and rows[-1][1] == a.needs:
            rows[-1][0].append(a.name)
        else:
            rows.append(([a.name], a.needs))
    return tuple((tuple(names), needs) for names, needs in rows)
