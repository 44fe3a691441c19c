"""The README's tour runs as written (up to its Jupyter-only lines).

The tour is the first ``python`` block of ``README.md``; its lines from
``# in Jupyter`` on need a notebook's front end and are left out.  It runs in
a temporary folder (it writes ``dodeca.obj``).
"""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def tour() -> str:
    text = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the README has no python block"
    code = blocks[0]
    assert "# in Jupyter" in code, "the tour's Jupyter part is no longer marked '# in Jupyter'"
    return code.split("# in Jupyter")[0]


def test_the_readme_tour_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    exec(compile(tour(), "README.md (tour)", "exec"), namespace)
    # what the tour's comments promise
    assert namespace["mesh"].n_faces == 4 and namespace["mesh"].genus == 0
    assert namespace["dod"].face_sizes.tolist() == [5] * 12
    assert namespace["disk"].n_boundary_loops == 3
    assert (tmp_path / "dodeca.obj").is_file()
