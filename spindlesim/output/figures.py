"""Figure helpers: matplotlib's object API (no pyplot state), atomic PNG save.

matplotlib is imported inside the functions: a plotting module that takes its helpers from here
can be imported without it (output/drawing.py: the main process of the command line never imports
matplotlib when a figure process draws for it).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.figure import Figure


def new_figure(width_in: float = 8.0, height_in: float = 5.0, layout: str | None = "constrained") -> Figure:
    """A figure on the Agg canvas; ``layout=None`` for :func:`fixed_layout` (no layout engine: saving
    then draws once instead of twice)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width_in, height_in), layout=layout)
    FigureCanvasAgg(fig)
    return fig


def fixed_layout(fig: Figure, left_in: float = 0.9, right_in: float = 0.25, top_in: float = 0.5,
                 bottom_in: float = 0.55, gap_in: float = 0.45) -> Figure:
    """Margins and gaps between stacked panels in inches, instead of the constrained layout engine.

    The engine measures every tick label of every panel twice per save: about 0.2 s for a 2-panel
    figure and 0.4 s for the 8 panels of the mode shapes, more than the analysis behind them.  The
    rotor figures have predictable labels, so fixed margins in inches (the same at any figure size)
    keep them readable.  Call after ``fig.subplots``; legends outside the panels go in the margins.
    """
    w, h = fig.get_size_inches()
    if fig.get_layout_engine() is not None:  # made with a layout engine: keep it from moving the panels
        fig.set_layout_engine("none")
    grid = fig.axes[0].get_subplotspec().get_gridspec()
    rows = grid.nrows
    panel = (h - top_in - bottom_in - (rows - 1) * gap_in) / rows
    grid.update(left=left_in / w, right=1 - right_in / w, top=1 - top_in / h, bottom=bottom_in / h,
                hspace=gap_in / panel if rows > 1 else 0.2)
    for ax in fig.axes:  # GridSpec.update repositions only pyplot's figures
        spec = ax.get_subplotspec()
        if spec is not None and spec.get_gridspec() is grid:
            ax.set_position(spec.get_position(fig))
    return fig


def save_figure(fig: Figure, path: str | Path, dpi: int = 110) -> Path:
    """Save ``fig`` as PNG via a temporary file and rename; the file gets the umask's mode (0644 under 022)."""
    from .hdf5 import atomic

    path = Path(path)
    with atomic(path, ".tmp.png") as tmp:
        # zlib level 3 instead of PIL's 6: a third less time for files about 10 % larger
        fig.savefig(tmp, dpi=dpi, format="png", pil_kwargs={"compress_level": 3})
    return path


def shade_above_speed_limit(axes, limit_rpm: float, label: bool = True, short: bool = False) -> None:
    """Shade the speeds above the spindle's thermal speed limit on axes whose x is the speed [rpm] (the first
    axis gets the legend entry; ``short``: for a narrow legend)."""
    text = f"> {limit_rpm:,.0f} rpm:\nthermal limit" if short else \
        f"above the thermal speed limit ({limit_rpm:,.0f} rpm)"
    for k, ax in enumerate(axes):
        lo, hi = ax.get_xlim()
        if hi > limit_rpm:
            ax.axvspan(limit_rpm, hi, color="tab:red", alpha=0.10, lw=0, label=text if label and k == 0 else None)
            ax.set_xlim(lo, hi)
