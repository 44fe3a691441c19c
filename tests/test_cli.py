"""The command line: ``python -m pentanb`` (demo) and its argument handling.

The ``figures`` subcommand is run end to end in :mod:`test_figures`.
"""

from __future__ import annotations

import importlib.util
import inspect
import os
import subprocess
import sys

import pytest

import pentanb.cli
from pentanb import SCHEMES, shapes
from pentanb.cli import DEMO_SHAPES, demo_table, main


def _block(table: str, scheme: str) -> dict[str, list[str]]:
    """The rows of one scheme's block of the demo table, by shape."""
    lines = table.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(f"{scheme}:"))
    rows = {}
    for line in lines[start + 2 :]:
        if not line.strip():
            break
        cells = line.split()
        rows[cells[0]] = cells[1:]
    return rows


@pytest.fixture(scope="module")
def table() -> str:
    return demo_table()


def test_demo_pentagonalize_cube_row(table):
    # V + 2E + F, 5E, 2E with V, E, F = 8, 12, 6
    row = _block(table, "pentagonalize")["cube"]
    assert row[:3] == ["38", "60", "24"]
    assert row[3] == "5:24"
    assert row[4:] == ["3:32", "4:6"]


def test_demo_lists_every_scheme_and_shape_with_its_formula(table):
    for name, scheme in SCHEMES.items():
        rows = _block(table, name)
        assert list(rows) == list(DEMO_SHAPES)
        for shape, row in rows.items():
            out = scheme(shapes.get(shape))
            assert [int(x) for x in row[:3]] == [out.n_vertices, out.n_edges, out.n_faces]
    assert "pentagonalize: Pentagonalization" in table
    assert "(V, E, F) -> (V+2E+F, 5E, 2E)" in table
    assert "Conway gyro" in table


def test_main_without_arguments_runs_the_demo(capsys):
    assert main([]) == 0
    out = capsys.readouterr().out
    assert _block(out, "pentagonalize")["cube"][:3] == ["38", "60", "24"]
    assert main(["demo"]) == 0
    assert capsys.readouterr().out == out


@pytest.mark.slow
def test_python_dash_m_runs(tmp_path):
    done = subprocess.run(
        [sys.executable, "-m", "pentanb"], capture_output=True, text=True, check=True, cwd=tmp_path
    )
    assert _block(done.stdout, "pentagonalize")["cube"][:3] == ["38", "60", "24"]


def test_unknown_figure_is_refused(capsys, tmp_path):
    assert main(["figures", "--out", str(tmp_path), "--only", "fig99"]) == 2
    err = capsys.readouterr().err
    assert "unknown figure 'fig99'" in err and "fig07" in err
    assert not list(tmp_path.iterdir())


@pytest.mark.slow
def test_only_one_figure(capsys, tmp_path):
    assert main(["figures", "--out", str(tmp_path / "x"), "--only", "7"]) == 0
    assert [p.name for p in (tmp_path / "x").iterdir()] == ["fig07.png"]
    from pentanb.figures import claim

    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == claim.KIND_HEADINGS[claim.CLAIM]  # the paper's claims come first
    assert lines[1].startswith("fig07  Tetrahedron to dodecahedron")


def test_help_names_the_subcommands(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    assert "demo" in out and "figures" in out


def test_figures_into_a_path_that_is_a_file_is_refused(tmp_path, capsys):
    target = tmp_path / "not-a-folder"
    target.write_text("x")
    assert main(["figures", "--out", str(target), "--only", "7"]) == 2
    err = capsys.readouterr().err
    assert f"cannot write into {target}" in err
    assert target.read_text() == "x"


@pytest.mark.slow
def test_only_takes_numbers_and_names(capsys, tmp_path):
    assert main(["figures", "--out", str(tmp_path), "--only", "6", "fig10"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["fig06.png", "fig10.png"]
    lines = capsys.readouterr().out.splitlines()
    assert lines[1].startswith("fig06  ") and any(x.startswith("fig10  ") for x in lines)
    assert any(x.startswith("schemes  ") for x in lines)


def test_unknown_figure_number_is_refused(capsys, tmp_path):
    assert main(["figures", "--out", str(tmp_path), "--only", "7", "14"]) == 2
    assert "unknown figure 'fig14'" in capsys.readouterr().err
    assert not list(tmp_path.iterdir())


def test_cli_uses_only_public_names_of_figures():
    source = inspect.getsource(pentanb.cli)
    assert "figures._" not in source


def _swap_claims(monkeypatch, name, claims):
    import dataclasses

    from pentanb import figures

    spec = figures.FIGURES[name]
    monkeypatch.setitem(
        figures.FIGURES, name, dataclasses.replace(spec, claims=lambda meshes=None: claims)
    )


def test_a_finding_as_recorded_exits_0(monkeypatch, tmp_path, capsys):
    from pentanb.figures import FAILS, claim

    finding = claim.exact("fig02.finding", "Section 3", "words", "x", 1, 2, recorded=FAILS)
    _swap_claims(monkeypatch, "fig02", [finding])
    assert main(["figures", "--out", str(tmp_path), "--only", "2"]) == 0
    out = capsys.readouterr().out
    assert "[does not hold as stated] fig02.finding  FINDING" in out
    assert out.splitlines()[-1].endswith("(findings); all as recorded")


def test_a_regression_exits_1(monkeypatch, tmp_path, capsys):
    from pentanb.figures import claim

    regressed = claim.exact("fig02.regressed", "Section 3", "words", "x", 1, 2)
    _swap_claims(monkeypatch, "fig02", [regressed])
    assert main(["figures", "--out", str(tmp_path), "--only", "2"]) == 1
    last = capsys.readouterr().out.splitlines()[-1]
    assert (
        "1 REGRESSIONS: fig02.regressed (recorded: holds, measured: does not hold as stated)"
        in last
    )


def test_a_finding_that_starts_to_hold_is_a_regression_too(monkeypatch, tmp_path, capsys):
    from pentanb.figures import FAILS, claim

    now_holds = claim.exact("fig02.was_a_finding", "Section 3", "words", "x", 1, 1, recorded=FAILS)
    _swap_claims(monkeypatch, "fig02", [now_holds])
    assert main(["figures", "--out", str(tmp_path), "--only", "2"]) == 1
    assert "REGRESSION (recorded: does not hold as stated)" in capsys.readouterr().out


# -- output that cannot be written (issue 38, item 15): one line, a non-zero exit --------


def _run_shell(command: str) -> subprocess.CompletedProcess:
    """``python -m pentanb`` with shell redirections (``>&-``, ``> /dev/full``)."""
    import shlex

    return subprocess.run(
        ["sh", "-c", f"{shlex.quote(sys.executable)} -m pentanb {command}"],
        capture_output=True,
        text=True,
        check=False,
    )


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full here")
def test_a_full_disk_is_one_line_and_status_2():
    done = _run_shell("demo > /dev/full")
    assert done.returncode == 2
    assert done.stderr == "pentanb demo: cannot write the output: No space left on device\n"


def test_a_closed_standard_output_is_one_line_and_status_2():
    done = _run_shell("demo >&-")
    assert done.returncode == 2
    assert done.stderr == ("pentanb demo: standard output is closed; give it a file (> out.txt)\n")


def test_an_os_error_while_printing_is_one_line(monkeypatch, capsys):
    def full(args):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(pentanb.cli, "_demo", full)
    silenced = []
    monkeypatch.setattr(pentanb.cli, "_silence", lambda streams=None: silenced.append(streams))
    assert main([]) == 2
    assert capsys.readouterr().err == (
        "pentanb demo: cannot write the output: No space left on device\n"
    )
    assert silenced == [(sys.stdout,)]


needs_sphinx = pytest.mark.skipif(
    importlib.util.find_spec("sphinx") is None or importlib.util.find_spec("myst_nb") is None,
    reason="the docs extra is not installed",
)


@needs_sphinx
def test_docs_out_naming_a_file_is_one_line(tmp_path, capsys):
    target = tmp_path / "site.html"
    target.write_text("a page")
    assert main(["docs", "--out", str(target)]) == 2
    err = capsys.readouterr().err
    assert err == f"pentanb docs: cannot write into {target}: it is a file, not a folder\n"
    assert target.read_text() == "a page"


@needs_sphinx
def test_docs_without_the_npm_cache_is_one_line(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("PENTANB_JS_DIR", str(tmp_path / "no-npm-cache"))
    out = tmp_path / "site"
    assert main(["docs", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("pentanb docs: ")
    assert "npm install --prefix" in err and "Traceback" not in err
    assert not out.exists()  # refused before anything was made
