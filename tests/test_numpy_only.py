"""``import pentanb`` and the whole core (operators, subdivide, read/write,
topology, shapes, pickling) work with numpy as the only third-party package.

The check runs in a fresh interpreter in which matplotlib, ipywidgets,
pythreejs and scipy cannot be imported, and then also asserts that nothing
outside the standard library, numpy and pentanb was imported.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BLOCKED = ("matplotlib", "ipywidgets", "pythreejs", "scipy")

CORE = textwrap.dedent(
    """
    import sys
    before = set(sys.modules)
    for name in BLOCKED:
        sys.modules[name] = None  # "import name" now raises ImportError

    import copy, pathlib, pickle, tempfile
    import numpy as np
    import pentanb
    from pentanb import shapes, topology

    meshes = [shapes.get(name) for name in shapes.SHAPES]
    cube = shapes.cube()
    outs = [s(cube) for s in pentanb.SCHEMES.values()]
    outs += [pentanb.dual(cube), pentanb.smooth(cube, 3), pentanb.dual(pentanb.pentagonalize(cube))]
    outs += [
        pentanb.subdivide(cube, "pentagonalize", 2),
        pentanb.subdivide(cube, "preserve_pentagons", 1, 2, scale=0.6),
        pentanb.subdivide(cube, pentanb.honeycomb, 1, 0),
    ]
    assert pentanb.max_iterations(cube, "pentagonalize") >= 2
    assert pentanb.predict_counts((8, 12, 6), "pentagonalize", 1, 0) == [(38, 60, 24)]
    for out in outs + meshes:
        back = pickle.loads(pickle.dumps(out))
        assert np.array_equal(back.corners, out.corners) and np.array_equal(back.twin, out.twin)
        copy.deepcopy(out)
        out.vertex_ring, out.face_normals, out.fan_triangles(), out.genus, out.counts()
    with tempfile.TemporaryDirectory() as folder:
        for name in ("m.obj", "m.OFF", "m.v2"):
            path = pathlib.Path(folder) / name
            pentanb.write(outs[0], path, format="obj" if name == "m.v2" else None)
            back = pentanb.read(path, format="obj" if name == "m.v2" else None)
            assert back.vertices.tobytes() == outs[0].vertices.tobytes()
    assert topology.min_vertices(5, 0) == 20 and topology.min_faces(3, 0) == 4
    assert topology.vertex_range(5, 1) is not None and topology.face_range(3, 1) is not None
    assert topology.can_tile(5, 0, 20) and topology.ngonalization_exists(5)
    assert topology.ngon_preservation_exists(5) and not topology.limit_valence_is_integer(5)
    assert topology.average_valence(5, 0, 20) == 3 and topology.average_face_size(3, 0, 4) == 3
    assert topology.limit_valence(5) == topology.limit_face_size(5)
    assert topology.ngon_mesh_counts(5, 0, 20) == (20, 30, 12)
    assert topology.mvalent_mesh_counts(3, 0, 12) == (20, 30, 12)
    assert len(topology.schlafli_chart()) > 0

    loaded = {m.split(".")[0] for m, mod in sys.modules.items() if mod is not None}
    allowed = set(sys.stdlib_module_names) | {"numpy", "pentanb"}
    foreign = sorted(loaded - allowed - {m.split(".")[0] for m in before})
    assert not foreign, f"imported beyond numpy and the standard library: {foreign}"
    print("core ok")
    """
)


def run_core(blocked: tuple[str, ...]) -> subprocess.CompletedProcess:
    code = f"BLOCKED = {blocked!r}\n" + CORE
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}
    return subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT
    )


def test_core_works_with_only_numpy():
    done = run_core(BLOCKED)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "core ok"


@pytest.mark.parametrize("drawing", ["pentanb.view", "pentanb.explore"])
def test_the_block_stops_drawing_code(drawing):
    # the check can fail: drawing code does need a blocked package
    module, _, attr = drawing.rpartition(".")
    code = (
        f"import sys\nfor n in {BLOCKED!r}: sys.modules[n] = None\n"
        f"import importlib, pentanb\ngetattr(importlib.import_module({module!r}), {attr!r})"
    )
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert done.returncode != 0 and "ModuleNotFoundError" in done.stderr


def test_the_foreign_import_check_can_fail():
    # a core that imported matplotlib would be reported, not pass silently
    done = run_core(())
    assert done.returncode == 0, done.stderr  # nothing foreign is imported even unblocked
    code = f"BLOCKED = ()\n{CORE}".replace("import pentanb\n", "import pentanb, matplotlib\n", 1)
    bad = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"},
    )
    assert bad.returncode != 0 and "matplotlib" in bad.stderr
