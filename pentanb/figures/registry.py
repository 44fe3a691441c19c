"""The figure registry: one table of every image of ``figures/``.

:data:`FIGURES` maps a file stem (``"fig07"``) to a :class:`FigureSpec`,
built from the figure's module (:mod:`~pentanb.figures.fig07`): its title
and caption, the panel labels, and three functions: ``panels()`` builds
the meshes the figure draws, ``draw(meshes)`` and ``claims(meshes)`` take
them.  :func:`render` and :func:`claims` build a figure's meshes once per
call and pass them on; no mesh is cached between calls.  The one thing kept
is the continuity table that ``spectra`` and ``characteristic_maps`` draw
and check (:func:`pentanb.figures._continuity.table`, about 6-10 s): it is
computed once per process, so a figures run computes it once.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

import numpy as np

from ..mesh import Mesh
from . import (
    boundary_curve,
    characteristic_maps,
    convergence,
    fig01,
    fig02,
    fig03,
    fig04,
    fig05,
    fig06,
    fig07,
    fig08,
    fig09,
    fig10,
    fig11,
    fig12,
    fig13,
    formulas,
    lateral,
    open_surfaces,
    scale,
    section4,
    spectra,
)
from .claim import Claim, format_report

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "FigureSpec",
    "FIGURES",
    "get",
    "panels",
    "claims",
    "render",
    "render_all",
    "check_all",
    "report",
]


@dataclass(frozen=True)
class FigureSpec:
    """One image of ``figures/``: how to build, draw and check it.

    Attributes
    ----------
    name : str
        File stem, e.g. ``"fig07"``.
    title : str
        Short title.
    caption : str
        The paper's caption (or a description for images beyond the paper).
    draw : callable
        ``draw(meshes=None) -> matplotlib.figure.Figure``; builds
        ``panels()`` itself when not given them.
    claims : callable
        ``claims(meshes=None) -> list[Claim]``; likewise.
    labels : tuple of str
        The panel letters drawn, e.g. ``("A", "B")``.
    panels : callable
        ``panels() -> {label: Mesh}``: the meshes the figure draws (empty
        for figures whose panels are charts).
    """

    name: str
    title: str
    caption: str
    draw: Callable[..., Figure]
    claims: Callable[..., list[Claim]]
    labels: tuple[str, ...]
    panels: Callable[[], dict[str, Mesh]]

    @property
    def filename(self) -> str:
        """``"<name>.png"``."""
        return f"{self.name}.png"


def _spec(name: str, module: ModuleType) -> FigureSpec:
    return FigureSpec(
        name,
        module.TITLE,
        module.CAPTION,
        module.draw,
        module.claims,
        tuple(module.LABELS),
        module.panels,
    )


#: Every image, in the order of the paper: file stem -> :class:`FigureSpec`.
FIGURES: dict[str, FigureSpec] = {
    "fig01": _spec("fig01", fig01),
    "fig02": _spec("fig02", fig02),
    "fig03": _spec("fig03", fig03),
    "fig04": _spec("fig04", fig04),
    "fig05": _spec("fig05", fig05),
    "fig06": _spec("fig06", fig06),
    "fig07": _spec("fig07", fig07),
    "fig08": _spec("fig08", fig08),
    "fig09": _spec("fig09", fig09),
    "fig10": _spec("fig10", fig10),
    "fig11": _spec("fig11", fig11),
    "fig12": _spec("fig12", fig12),
    "fig13": _spec("fig13", fig13),
    "equation1": _spec("equation1", section4),
    "lateral": _spec("lateral", lateral),
    "convergence": _spec("convergence", convergence),
    "spectra": _spec("spectra", spectra),
    "characteristic_maps": _spec("characteristic_maps", characteristic_maps),
    "scale": _spec("scale", scale),
    "open_surfaces": _spec("open_surfaces", open_surfaces),
}


def get(name: int | str) -> FigureSpec:
    """The :class:`FigureSpec` of a figure: ``get(7)``, ``get("7")``, ``get("fig07")``,
    ``get("equation1")``.

    Parameters
    ----------
    name : int or str
        A figure's number (``7``, ``"7"``) or name (``"fig07"``, ``"equation1"``,
        ``"lateral"``, ...; the keys of :data:`FIGURES`).

    Returns
    -------
    FigureSpec

    Raises
    ------
    ValueError
        For an unknown figure; the message lists the known ones.
    TypeError
        For a name that is neither an int nor a str.
    """
    if isinstance(name, bool) or not isinstance(name, (int, np.integer, str)):
        raise TypeError(
            f"a figure is named by its number or a name such as 'fig07', got "
            f"{type(name).__name__} {name!r}"
        )
    numeric = not isinstance(name, str) or (name.isascii() and name.isdecimal())
    key = f"fig{int(name):02d}" if numeric else str(name)
    try:
        return FIGURES[key]
    except KeyError:
        raise ValueError(f"unknown figure {key!r}; known: {', '.join(FIGURES)}") from None


def panels(name: int | str) -> dict[str, Mesh]:
    """The meshes a figure draws, by panel label: ``panels(11)["A"]``.

    Built afresh on every call (nothing is cached).  Figures whose panels are
    charts (``"equation1"``, ``"lateral"``, ``"convergence"``, ``"spectra"``,
    ``"characteristic_maps"``) have no meshes: ``{}``.  The
    flat diagrams (Figures 6 and 10) start from a two-faced "pillow": their
    meshes are closed, but keep its 2-valent corners, which the
    :class:`~pentanb.Mesh` constructor refuses: draw and measure them, but
    do not feed them to other operators (the dual of a 2-valent vertex is a
    2-sided face).

    Parameters
    ----------
    name : int or str
        As for :func:`get`.

    Returns
    -------
    dict
        ``{label: Mesh}`` in panel order; the labels are the figure's
        (:attr:`FigureSpec.labels`).
    """
    return get(name).panels()


def claims(name: int | str, meshes: Mapping[str, Mesh] | None = None) -> list[Claim]:
    """The claims of one figure: ``claims(7)``, ``claims("fig07")``, ``claims("equation1")``.

    Parameters
    ----------
    name : int or str
        As for :func:`get`.
    meshes : dict, optional
        The figure's :func:`panels`, if already built (they are built here
        otherwise); a claims function also takes, under their own names, the
        source meshes it compares with (e.g. ``"source"``), so that a test can
        give it a wrong one.

    Returns
    -------
    list of Claim
        Each with the paper's words, the measurement and a verdict
        (:data:`~pentanb.figures.claim.VERDICTS`).
    """
    return get(name).claims(meshes)


def render(
    name: int | str, out_dir: str | Path = "figures", *, meshes: Mapping[str, Mesh] | None = None
) -> Path:
    """Draw one figure and write it to ``out_dir/<name>.png``.

    Parameters
    ----------
    name : int or str
        As for :func:`get`.
    out_dir : str or Path
        Created if missing.
    meshes : dict, optional
        The figure's :func:`panels`, if already built.

    Returns
    -------
    Path
        The PNG written.
    """
    from ..viz import mpl as vz

    spec = get(name)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / spec.filename
    vz.save_figure(spec.draw(meshes), path)
    return path


def render_all(
    out_dir: str | Path = "figures",
    names: Iterable[int | str] | None = None,
    progress: Callable[[int, int, str], None] | None = None,
) -> dict[str, float]:
    """Draw every figure (or ``names``) into ``out_dir``.

    Parameters
    ----------
    out_dir : str or Path
    names : iterable of int or str, optional
        As for :func:`get`; default: every figure of :data:`FIGURES`.
    progress : callable, optional
        ``progress(done, total, message)`` after every figure.

    Returns
    -------
    dict
        ``{name: seconds}``.
    """
    keys = list(FIGURES) if names is None else [get(n).name for n in names]
    times = {}
    for i, key in enumerate(keys):
        t = time.perf_counter()
        path = render(key, out_dir)
        times[key] = time.perf_counter() - t
        if progress:
            progress(i + 1, len(keys), f"{path} ({times[key]:.1f} s)")
    return times


def check_all(names: Iterable[int | str] | None = None) -> dict[str, list[Claim]]:
    """``{figure name: claims}`` for every figure (or ``names``), then ``"schemes"``
    (:func:`~pentanb.figures.scheme_claims`) and ``"boundary"`` (the boundary curve of
    open meshes, :func:`pentanb.figures.boundary_curve.boundary_claims`).

    Parameters
    ----------
    names : iterable of int or str, optional
        The figures, as :func:`get` names them (default: all of :data:`FIGURES`).

    Returns
    -------
    dict
        ``{figure name: list of Claim}``, in the order asked, then
        ``"schemes"``: :func:`~pentanb.figures.scheme_claims`, then ``"boundary"``.
    """
    keys = list(FIGURES) if names is None else [get(n).name for n in names]
    out = {k: FIGURES[k].claims() for k in keys}
    out["schemes"] = formulas.scheme_claims()
    out["boundary"] = boundary_curve.boundary_claims()
    return out


def report(results: Mapping[str, list[Claim]]) -> str:
    """The claims as text: one block per figure, four lines per claim, the findings,
    then the totals (:func:`~pentanb.figures.claim.format_report`).

    Parameters
    ----------
    results : dict
        As :func:`check_all` returns.

    Returns
    -------
    str
        The report, lines joined by newlines.
    """
    titles = {name: spec.title for name, spec in FIGURES.items()}
    titles["schemes"] = formulas.TITLE
    titles["boundary"] = boundary_curve.TITLE
    return format_report(results, titles)
