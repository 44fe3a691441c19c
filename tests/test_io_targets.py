"""What a write replaces: read-only files, symbolic links, FIFOs, a full disk.

:func:`pentanb.write` (and every ``write_*``) and :func:`pentanb.export_html`
share one rule (``pentanb.io._common.write_atomically``):

* a read-only file (mode ``0444``, or one this process may not write) is
  refused unless ``force=True``, which keeps its mode;
* a symbolic link is kept, and the file it points to is replaced, by a
  temporary file beside that file (a dangling link's target is created);
* a target that is not a regular file (a FIFO, a device, a folder) is refused
  before any work;
* a failure (a full disk) leaves the old file whole and no temporary file.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import textwrap

import pytest

import pentanb
from pentanb import read, shapes, write
from pentanb.io import write_obj, write_off, write_ply, write_stl

WRITERS = {
    "obj": write_obj,
    "off": write_off,
    "ply": write_ply,
    "stl": lambda mesh, path, **kw: write_stl(mesh, path, ascii=True, **kw),
}


def names(folder):
    return sorted(p.name for p in folder.iterdir())


# ====================================================================== read-only files
@pytest.mark.parametrize("fmt", sorted(WRITERS))
def test_a_read_only_file_is_refused_and_kept(tmp_path, fmt):
    target = tmp_path / f"m.{fmt}"
    write(shapes.tetrahedron(), target, **({"ascii": True} if fmt == "stl" else {}))
    old = target.read_bytes()
    target.chmod(0o444)
    for call in (
        lambda: write(shapes.cube(), target, **({"ascii": True} if fmt == "stl" else {})),
        lambda: WRITERS[fmt](shapes.cube(), target),
    ):
        with pytest.raises(ValueError, match=r"read-only \(mode 0444\).*force=True"):
            call()
        assert target.read_bytes() == old
        assert names(tmp_path) == [target.name]


def test_force_replaces_a_read_only_file_and_keeps_its_mode(tmp_path):
    target = tmp_path / "m.obj"
    write(shapes.tetrahedron(), target)
    target.chmod(0o444)
    write(shapes.cube(), target, force=True)
    assert read(target).n_faces == 6
    assert stat.S_IMODE(target.stat().st_mode) == 0o444
    write_ply(shapes.cube(), tmp_path / "m.ply")
    (tmp_path / "m.ply").chmod(0o400)
    write_ply(shapes.tetrahedron(), tmp_path / "m.ply", force=True)
    assert read(tmp_path / "m.ply").n_faces == 4
    assert names(tmp_path) == ["m.obj", "m.ply"]


def test_force_must_be_a_bool(tmp_path):
    with pytest.raises(TypeError, match="force must be True or False"):
        write(shapes.cube(), tmp_path / "m.obj", force="yes")
    assert names(tmp_path) == []


def test_a_file_writable_by_its_group_only_is_not_read_only(tmp_path):
    target = tmp_path / "m.off"
    write(shapes.tetrahedron(), target)
    target.chmod(0o464)  # someone may write it: the usual permission check decides
    if not os.access(target, os.W_OK):
        pytest.skip("this process may not write a 0464 file it owns")
    write(shapes.cube(), target)
    assert read(target).n_faces == 6


# ====================================================================== symbolic links
def test_a_link_is_kept_and_its_target_replaced(tmp_path):
    data = tmp_path / "data"
    data.mkdir()
    target = data / "model.obj"
    write(shapes.tetrahedron(), target)
    link = tmp_path / "link.obj"
    link.symlink_to(os.path.join("data", "model.obj"))  # relative, from the link's folder
    write(shapes.cube(), link)
    assert link.is_symlink() and os.readlink(link) == os.path.join("data", "model.obj")
    assert read(target).n_faces == 6  # the file the link points to holds the new mesh
    assert names(tmp_path) == ["data", "link.obj"]
    assert names(data) == ["model.obj"]  # no temporary file left beside the target


def test_a_chain_of_links_is_followed_to_the_file(tmp_path):
    target = tmp_path / "model.off"
    write(shapes.tetrahedron(), target)
    target.chmod(0o640)
    (tmp_path / "b.off").symlink_to("model.off")
    (tmp_path / "a.off").symlink_to(tmp_path / "b.off")  # absolute
    write(shapes.cube(), tmp_path / "a.off")
    assert (tmp_path / "a.off").is_symlink() and (tmp_path / "b.off").is_symlink()
    assert read(target).n_faces == 6
    assert stat.S_IMODE(target.stat().st_mode) == 0o640


def test_a_dangling_link_gets_its_target_created(tmp_path):
    (tmp_path / "out").mkdir()
    link = tmp_path / "link.ply"
    link.symlink_to(tmp_path / "out" / "new.ply")
    write(shapes.cube(), link)
    assert link.is_symlink()
    assert read(tmp_path / "out" / "new.ply").n_faces == 6
    assert names(tmp_path / "out") == ["new.ply"]


def test_a_link_to_a_read_only_file_is_refused(tmp_path):
    target = tmp_path / "model.obj"
    write(shapes.tetrahedron(), target)
    target.chmod(0o444)
    (tmp_path / "link.obj").symlink_to("model.obj")
    with pytest.raises(ValueError, match=r"link\.obj \(a link to .*model\.obj\) is read-only"):
        write(shapes.cube(), tmp_path / "link.obj")
    assert read(target).n_faces == 4
    write(shapes.cube(), tmp_path / "link.obj", force=True)
    assert read(target).n_faces == 6 and (tmp_path / "link.obj").is_symlink()


def test_a_loop_of_links_is_an_error(tmp_path):
    (tmp_path / "a.obj").symlink_to("b.obj")
    (tmp_path / "b.obj").symlink_to("a.obj")
    with pytest.raises(OSError, match="symbolic links"):
        write(shapes.cube(), tmp_path / "a.obj")
    assert names(tmp_path) == ["a.obj", "b.obj"]


def test_a_link_to_a_fifo_is_refused(tmp_path):
    os.mkfifo(tmp_path / "pipe")
    (tmp_path / "m.obj").symlink_to("pipe")
    with pytest.raises(ValueError, match="is not a regular file"):
        write(shapes.cube(), tmp_path / "m.obj")
    assert stat.S_ISFIFO((tmp_path / "pipe").stat().st_mode)


# ====================================================================== export_html
pytest.importorskip("pythreejs")
from pentanb.viz import html  # noqa: E402


def test_export_html_refuses_a_fifo_before_making_the_page(tmp_path):
    fifo = tmp_path / "page.html"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)  # the old code wrote into it
    try:
        with pytest.raises(ValueError, match="is not a regular file"):
            html.export_html(shapes.cube(), fifo, offline=False)
        assert os.read(reader, 100) == b""  # nothing was written into the pipe
    finally:
        os.close(reader)
    assert stat.S_ISFIFO(fifo.stat().st_mode)
    assert names(tmp_path) == ["page.html"]


def test_export_html_refuses_a_device(tmp_path):
    with pytest.raises(ValueError, match="is not a regular file"):
        html.export_html(shapes.cube(), "/dev/null", offline=False)


def test_export_html_keeps_a_link_and_a_read_only_page(tmp_path):
    page = tmp_path / "page.html"
    page.write_text("old page")
    (tmp_path / "link.html").symlink_to("page.html")
    html.export_html(shapes.cube(), tmp_path / "link.html", offline=False)
    assert (tmp_path / "link.html").is_symlink()
    assert page.read_text().startswith("<!DOCTYPE html>")
    page.chmod(0o444)
    with pytest.raises(ValueError, match="read-only"):
        html.export_html(shapes.tetrahedron(), page, offline=False)
    html.export_html(shapes.tetrahedron(), page, offline=False, force=True)
    assert stat.S_IMODE(page.stat().st_mode) == 0o444
    assert names(tmp_path) == ["link.html", "page.html"]


_FULL_DISK = """
import os, resource, signal, sys
import pentanb
from pentanb import shapes
from pentanb.viz import html
signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write beyond the limit fails (EFBIG)
resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))  # as a disk that fills up
try:
    if sys.argv[2] == "html":
        html.export_html(shapes.cube(), sys.argv[1], offline=False)
    else:
        pentanb.write(shapes.rabbit(), sys.argv[1])
except OSError as exc:
    print("failed:", exc.errno)
else:
    print("written")
"""


@pytest.mark.parametrize("what", ["html", "obj"])
def test_a_full_disk_leaves_the_old_file_whole(tmp_path, what):
    target = tmp_path / f"out.{what}"
    target.write_text("the old content, whole\n")
    script = tmp_path / "full.py"
    script.write_text(textwrap.dedent(_FULL_DISK))
    out = subprocess.run(
        [sys.executable, str(script), str(target), what],
        capture_output=True,
        text=True,
        check=True,
        cwd=tmp_path,
    )
    assert out.stdout.startswith("failed:"), out.stdout + out.stderr
    assert target.read_text() == "the old content, whole\n"
    assert names(tmp_path) == ["full.py", target.name]


def test_export_html_is_exported_from_pentanb():
    assert pentanb.export_html is html.export_html
