"""Writing the students' notebooks never costs the teacher one (issue 38, items 1, 10, 15).

* The teacher's folder is refused however it is reached: by a symbolic link, or
  by a second mount of it (as JupyterHub volumes are), since folders are compared
  by device and inode, not by their resolved names; an empty ``OUT_DIR`` (the
  current folder) is refused too.
* A copy in ``OUT_DIR`` that is a link into the teacher's folder is refused.
* The notebooks are written with the mode the umask gives a new file (the
  students must be able to read them), an existing copy keeps its mode.
* A notebook that is not JSON is named, and nothing is written.
"""

from __future__ import annotations

import importlib.util
import os
import pathlib
import shutil
import stat
import subprocess
from pathlib import Path

import pytest
from test_classroom import _import_nbformat

from pentanb import classroom
from pentanb.cli import main

ROOT = Path(__file__).resolve().parent.parent

pytestmark = pytest.mark.skipif(
    any(importlib.util.find_spec(m) is None for m in ("nbconvert", "nbformat")),
    reason="nbconvert or nbformat is not installed",
)

#: A small teacher's notebook: its exercise section has solution cells.
NOTEBOOK = ROOT / "notebooks" / "01_topology.ipynb"


@pytest.fixture
def teacher(tmp_path) -> Path:
    """A teacher's folder holding a copy of one notebook (with its solutions)."""
    _import_nbformat()
    folder = tmp_path / "teacher"
    folder.mkdir()
    shutil.copyfile(NOTEBOOK, folder / NOTEBOOK.name)
    return folder


def _intact(folder: Path) -> bool:
    return (folder / NOTEBOOK.name).read_bytes() == NOTEBOOK.read_bytes()


def test_the_teachers_folder_through_a_link_is_refused(teacher, tmp_path, capsys):
    link = tmp_path / "students"
    link.symlink_to(teacher, target_is_directory=True)
    with pytest.raises(ValueError, match="holds the teacher's notebooks"):
        classroom.student_version(link, [teacher / NOTEBOOK.name])
    assert _intact(teacher)


def test_the_teachers_folder_is_recognised_without_its_name(teacher, tmp_path, monkeypatch):
    """A second mount reaches the folder by a path that does not resolve to it:
    here a link whose resolution is hidden, as a bind mount hides its source."""
    link = tmp_path / "mounted"
    link.symlink_to(teacher, target_is_directory=True)
    monkeypatch.setattr(pathlib.Path, "resolve", lambda self, strict=False: self.absolute())
    with pytest.raises(ValueError, match="holds the teacher's notebooks"):
        classroom.student_version(link, [teacher / NOTEBOOK.name])
    assert _intact(teacher)


def _bind_mount(source: Path, target: Path) -> bool:
    if os.geteuid() != 0 or shutil.which("mount") is None:
        return False
    done = subprocess.run(
        ["mount", "--bind", str(source), str(target)], capture_output=True, check=False
    )
    return done.returncode == 0


def test_a_second_mount_of_the_teachers_folder_is_refused(teacher, tmp_path, capsys):
    mounted = tmp_path / "volume"
    mounted.mkdir()
    if not _bind_mount(teacher, mounted):
        pytest.skip("cannot bind-mount a folder here (needs root and mount)")
    try:
        assert (mounted / NOTEBOOK.name).exists()
        assert mounted.resolve() != teacher.resolve()  # the names do not tell
        with pytest.raises(ValueError, match="holds the teacher's notebooks"):
            classroom.student_version(mounted, [teacher / NOTEBOOK.name])
    finally:
        subprocess.run(["umount", str(mounted)], check=True)
    assert _intact(teacher)


def test_an_empty_out_dir_is_refused(teacher, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(teacher)
    with pytest.raises(ValueError, match="name is empty"):
        classroom.student_version("", [NOTEBOOK.name])
    assert main(["classroom", ""]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "name is empty" in err
    assert _intact(teacher) and sorted(os.listdir(teacher)) == [NOTEBOOK.name]


def test_a_copy_that_links_into_the_teachers_folder_is_refused(teacher, tmp_path):
    out = tmp_path / "students"
    out.mkdir()
    (out / NOTEBOOK.name).symlink_to(teacher / NOTEBOOK.name)
    with pytest.raises(ValueError, match="is a link into the folder of the teacher's"):
        classroom.student_version(out, [teacher / NOTEBOOK.name])
    assert _intact(teacher)


def test_the_students_notebooks_keep_the_umasks_mode(teacher, tmp_path):
    out = tmp_path / "students"
    old = os.umask(0o022)
    try:
        written = classroom.student_version(out, [teacher / NOTEBOOK.name])
    finally:
        os.umask(old)
    assert written == [out / NOTEBOOK.name]
    assert stat.S_IMODE(written[0].stat().st_mode) == 0o644  # not 0600: students read it
    written[0].chmod(0o664)
    classroom.student_version(out, [teacher / NOTEBOOK.name])
    assert stat.S_IMODE(written[0].stat().st_mode) == 0o664
    assert sorted(os.listdir(out)) == [NOTEBOOK.name]  # no temporary file left
    assert _intact(teacher)


def test_a_read_only_copy_needs_force(teacher, tmp_path, capsys):
    out = tmp_path / "students"
    classroom.student_version(out, [teacher / NOTEBOOK.name])
    (out / NOTEBOOK.name).chmod(0o444)
    with pytest.raises(ValueError, match=r"read-only.*force=True"):
        classroom.student_version(out, [teacher / NOTEBOOK.name])
    classroom.student_version(out, [teacher / NOTEBOOK.name], force=True)
    assert stat.S_IMODE((out / NOTEBOOK.name).stat().st_mode) == 0o444


def test_a_notebook_that_is_not_json_is_named_and_nothing_is_written(teacher, tmp_path, capsys):
    bad = teacher / "02_broken.ipynb"
    bad.write_text("this is not JSON\n" * 100_000)
    out = tmp_path / "students"
    with pytest.raises(ValueError, match=r"02_broken\.ipynb' is not a Jupyter notebook") as info:
        classroom.student_version(out, [teacher / NOTEBOOK.name, bad])
    assert len(str(info.value)) < 400  # an excerpt, not the file
    assert not out.exists()  # the good notebook before it was not written either


def test_two_notebooks_of_one_name_are_refused(teacher, tmp_path):
    other = tmp_path / "other"
    other.mkdir()
    shutil.copyfile(NOTEBOOK, other / NOTEBOOK.name)
    with pytest.raises(ValueError, match="would be written to one file"):
        classroom.student_version(tmp_path / "s", [teacher / NOTEBOOK.name, other / NOTEBOOK.name])
