"""The explorer's controls, without widgets: their ranges, the checks that turn
:func:`~pentanb.viz.explorer.explore`'s arguments into a scheme and a shape
(a shape name, a :class:`pentanb.Mesh`, a mesh file), the reading of an
uploaded file (:func:`read_upload`), and what a stand-alone page keeps of an
explorer (:class:`ExportPlan`, chosen by
:meth:`pentanb.viz.explorer.Explorer.export_plan`).

Needs no widget library.  Every public name here is importable from
:mod:`pentanb.viz.explorer` too.
"""

from __future__ import annotations

import io
import itertools
import os
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from .. import shapes
from ..io import read
from ..mesh import Mesh
from ..schemes.registry import SCHEMES, Scheme
from ..subdivision import get_scheme

__all__ = [
    "ExportPlan",
    "MAX_DUALS",
    "MAX_ITERATIONS",
    "SCALE_RANGE",
    "SCALE_STEP",
    "MESH_SUFFIXES",
    "YOUR_MESH",
    "CONTROLS",
    "read_upload",
]

#: Largest value of the duals slider.
MAX_DUALS = 4
#: Largest ``max_iterations`` (the iterations slider's top).  The explorer
#: builds one level at a time, so this bounds its steps, as
#: :data:`pentanb.subdivision.MAX_STEPS` bounds :func:`pentanb.subdivide`'s:
#: every scheme passes ``max_faces`` within a few levels, but one that keeps
#: the counts (triangulate on triangles) never does.
MAX_ITERATIONS = 1000
#: Range of the scale slider (the scheme's ``scale`` option).
SCALE_RANGE = (0.05, 0.95)
#: Step of the scale slider.
SCALE_STEP = 0.05
#: The file endings the explorer reads (its upload button accepts these).
MESH_SUFFIXES = (".obj", ".off", ".ply", ".stl")
#: The drop-down's name for a mesh given as a :class:`pentanb.Mesh`.
YOUR_MESH = "your mesh"
#: Default ``iterations`` (lowered to ``max_iterations`` when that is smaller).
DEFAULT_ITERATIONS = 1

#: (shape, scheme, duals, options, iterations): the settings of one mesh.
Key = tuple[str, str, int, tuple, int]

#: The controls a stand-alone page keeps, in the order their values nest.
CONTROLS = ("shape", "scheme", "scale", "duals", "iterations")


def scheme_argument(scheme: object) -> Scheme:
    s = get_scheme(scheme)  # type: ignore[arg-type]
    if not isinstance(s, Scheme):
        raise TypeError(
            f"scheme must be the name of a scheme of pentanb.SCHEMES ({', '.join(SCHEMES)}) "
            f"or Conway notation such as 'dg', not {type(scheme).__name__}"
        )
    return s


def _is_path(value: object) -> bool:
    """Whether ``value`` names a file rather than a shape: a path object, or a
    string ending in one of :data:`MESH_SUFFIXES` or holding a folder separator."""
    if isinstance(value, os.PathLike):
        return True
    if not isinstance(value, str):
        return False
    return Path(value).suffix.lower() in MESH_SUFFIXES or os.sep in value or "/" in value


def shape_argument(shape: object) -> tuple[str, Mesh | None]:
    """(drop-down name, mesh) of ``explore``'s ``shape``: mesh None for a shape name.

    A path is read here, so that a file that cannot be read fails before
    any widget is made, with the reader's message.
    """
    if isinstance(shape, Mesh):
        return YOUR_MESH, shape
    if isinstance(shape, str) and shape in shapes.SHAPES:
        return shape, None
    if _is_path(shape):
        return Path(os.fsdecode(shape)).name, read(shape)  # type: ignore[arg-type]
    if isinstance(shape, str):
        raise ValueError(
            f"unknown shape {shape!r}; known shapes: {', '.join(shapes.SHAPES)}; "
            f"or give a pentanb.Mesh or the path of a {', '.join(MESH_SUFFIXES)} file"
        )
    raise TypeError(
        "shape must be a pentanb.Mesh, a shape name or the path of a mesh file, "
        f"got {type(shape).__name__}"
    )


def read_upload(name: str, content: bytes) -> Mesh:
    """Read an uploaded file's bytes as a mesh, its format told by its name's ending.

    Parameters
    ----------
    name : str
        The file's name (its ending, any case, tells the format: one of
        :data:`MESH_SUFFIXES`).
    content : bytes
        The file's content.

    Returns
    -------
    Mesh

    Raises
    ------
    ValueError
        A name without one of :data:`MESH_SUFFIXES`.
    MeshError
        The reader's refusal (a malformed file, a mesh that is not
        manifold), naming the file and line.
    """
    suffix = Path(name).suffix.lower()
    if suffix not in MESH_SUFFIXES:
        raise ValueError(
            f"{name}: the explorer reads {', '.join(MESH_SUFFIXES)} files, "
            f"not {suffix or 'a file without an ending'}"
        )
    buffer = io.BytesIO(content)
    buffer.name = name  # the readers' messages name the file
    return read(buffer, format=suffix[1:])


@dataclass
class ExportPlan:
    """What a stand-alone page keeps of an explorer (:meth:`Explorer.export_plan`).

    Attributes
    ----------
    values : dict of str to list
        For each control of :data:`CONTROLS`, the values the page offers, in
        the order its control lists them (shape and scheme in drop-down
        order, the numbers ascending).
    current : dict of str to object
        The value of each control shown first (the explorer's).
    meshes : dict of Key to Mesh
        The mesh of every combination of those values the page shows.
    left_out : dict of Key to str
        Combinations offered by the controls but not drawn, with the reason
        (a mesh over the page's ``max_faces``, or refused by the explorer).
    dropped : dict of str to list
        For each control, the values the explorer offers that the page does
        not (kept out by the size budget).
    labels : dict of str to str
        The drop-down's label of every scheme value.
    estimate : int
        Predicted bytes of the page's widget state.
    """

    values: dict[str, list]
    current: dict[str, object]
    meshes: dict[Key, Mesh] = field(default_factory=dict)
    left_out: dict[Key, str] = field(default_factory=dict)
    dropped: dict[str, list] = field(default_factory=dict)
    labels: dict[str, str] = field(default_factory=dict)
    estimate: int = 0

    def keys(self) -> Iterator[Key]:
        """Every combination the page's controls can select, as explorer keys."""
        for shape, scheme in itertools.product(self.values["shape"], self.values["scheme"]):
            scales = self.values["scale"] if has_scale(scheme) else [None]
            for scale, duals, it in itertools.product(
                scales, self.values["duals"], self.values["iterations"]
            ):
                opts = () if scale is None else (("scale", float(scale)),)
                yield (shape, scheme, duals, opts, it)


def has_scale(scheme: str) -> bool:
    return "scale" in scheme_argument(scheme).options
