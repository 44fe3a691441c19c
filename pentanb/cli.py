"""The command line: ``python -m pentanb [demo | figures --out DIR | docs | classroom OUT_DIR]``.

``demo`` (the default) runs every scheme of :data:`pentanb.SCHEMES` on the
Platonic solids and a torus and prints V, E, F, face sizes and valences.
``figures`` redraws every figure of the paper into a folder, then prints what
the paper claims of each figure next to what our meshes measure, with a
verdict (holds; holds within a stated tolerance; does not hold as stated).
A claim that does not hold is a finding, printed as one; the command exits
with status 1 only when a verdict differs from the one recorded with the
claim (a regression), and 2 for a usage or output error.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

from . import shapes
from .schemes import SCHEMES

__all__ = ["main", "demo_table"]

#: Meshes of the demo table.
DEMO_SHAPES = ("tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron", "torus")


def _hist(h: dict) -> str:
    return " ".join(f"{k}:{v}" for k, v in h.items())


def demo_table(
    shape_names: Sequence[str] = DEMO_SHAPES, scheme_names: Sequence[str] | None = None
) -> str:
    """Every scheme once on every shape: a text table of V, E, F, face sizes, valences.

    Rows are grouped by scheme; each group starts with the scheme's label,
    Conway name and count formula.  Face sizes and valences are written
    ``size:count``.
    """
    scheme_names = list(SCHEMES) if scheme_names is None else list(scheme_names)
    meshes = {name: shapes.get(name) for name in shape_names}
    width = max(len(n) for n in shape_names)
    head = (
        f"  {'shape':<{width}}  {'V':>6} {'E':>6} {'F':>6}  {'faces (sides:count)':<24} "
        "valences (valence:count)"
    )
    lines = [f"{'input':<{width + 2}}"]
    lines.append(head)
    for name, m in meshes.items():
        lines.append(
            f"  {name:<{width}}  {m.n_vertices:>6} {m.n_edges:>6} {m.n_faces:>6}  "
            f"{_hist(m.face_size_histogram()):<24} {_hist(m.valence_histogram())}"
        )
    for key in scheme_names:
        s = SCHEMES[key]
        conway = f", Conway {s.conway}" if s.conway else ""
        lines.append("")
        lines.append(f"{key}: {s.label} ({s.paper}{conway}); (V, E, F) -> {s.formula}")
        lines.append(head)
        for name, m in meshes.items():
            r = s(m)
            lines.append(
                f"  {name:<{width}}  {r.n_vertices:>6} {r.n_edges:>6} "
                f"{r.n_faces:>6}  {_hist(r.face_size_histogram()):<24} "
                f"{_hist(r.valence_histogram())}"
            )
    return "\n".join(lines)


def _progress(done: int, total: int, message: str) -> None:
    print(f"[{done:>2}/{total}] {message}", file=sys.stderr, flush=True)


def _figures(args) -> int:
    if "matplotlib" not in sys.modules:  # no display needed (figures never use pyplot)
        os.environ.setdefault("MPLBACKEND", "Agg")
    from . import figures

    names = []
    for name in args.only or list(figures.FIGURES):
        try:
            names.append(figures.get(name).name)
        except (ValueError, TypeError) as exc:
            # the registry's message when it is one ("unknown figure 'fig14'; known: ..."),
            # else (e.g. int("²") inside it) one naming the argument as given
            known = ", ".join(figures.FIGURES)
            message = str(exc)
            if not message.startswith("unknown figure"):
                message = f"unknown figure {name!r}; known: {known} (or their numbers)"
            _usage_error(message)
            return 2
    out = _output_folder(args.out)
    if out is None:
        return 2
    print(f"drawing {len(names)} figures into {out}", file=sys.stderr, flush=True)
    t0 = time.perf_counter()
    try:
        figures.render_all(out, names, progress=_progress)
    except OSError as exc:
        _usage_error(f"cannot write into {out}: {exc.strerror or exc}")
        return 2
    t1 = time.perf_counter()
    print("checking the paper's claims ...", file=sys.stderr, flush=True)
    results = figures.check_all(names)
    t2 = time.perf_counter()
    print(figures.report(results))
    print(f"drawn in {t1 - t0:.1f} s, checked in {t2 - t1:.1f} s", file=sys.stderr)
    regressed = any(c.regressed for cl in results.values() for c in cl)
    return 1 if regressed else 0


def _usage_error(message: str, command: str = "figures") -> None:
    """One line on standard error (the caller exits with status 2)."""
    print(f"pentanb {command}: {message}", file=sys.stderr)


def _output_folder(name: str, command: str = "figures") -> Path | None:
    """The output folder, created if needed and checked writable; None after
    printing a one-line error (an empty name, a file in the way, a read-only or
    virtual file system such as /proc or /sys, no permission)."""
    if not name.strip():
        _usage_error("--out needs a folder name (use --out . for the current folder)", command)
        return None
    out = Path(name)
    if out.exists() and not out.is_dir():
        _usage_error(f"cannot write into {name}: it is a file, not a folder", command)
        return None
    try:
        out.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=out):  # can a file be made there?
            pass
    except OSError as exc:
        _usage_error(f"cannot write into {name}: {exc.strerror or exc}", command)
        return None
    return out


def _demo(args) -> int:
    print(demo_table())
    return 0


def _docs(args) -> int:
    """Build the documentation site (docs/conf.py) with warnings as errors."""
    import importlib.util
    import subprocess

    root = Path(__file__).resolve().parent.parent
    if not (root / "docs" / "conf.py").is_file():
        print(f"pentanb docs: no docs/conf.py in {root}; run it from a clone", file=sys.stderr)
        return 2
    missing = [m for m in ("sphinx", "myst_nb", "numpydoc") if importlib.util.find_spec(m) is None]
    if missing:
        print(
            f'pentanb docs: {", ".join(missing)} missing; pip install -e ".[docs]"',
            file=sys.stderr,
        )
        return 2
    if args.out is not None and not args.out.strip():
        _usage_error("--out needs a folder name", "docs")
        return 2
    out = Path(args.out) if args.out else root / "docs" / "_build" / "html"
    if out.exists() and not out.is_dir():
        _usage_error(f"cannot write into {out}: it is a file, not a folder", "docs")
        return 2
    missing_scripts = _site_scripts_missing(root)
    if missing_scripts:
        print(f"pentanb docs: {missing_scripts}", file=sys.stderr)
        return 2
    if _output_folder(str(out), "docs") is None:
        return 2
    cmd = [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-b", "html"]
    cmd += ["-c", str(root / "docs"), str(root), str(out)]
    if args.force:  # the executed notebooks are kept beside the output folder
        import shutil

        shutil.rmtree(out.parent / ".jupyter_cache", ignore_errors=True)
    print(" ".join(cmd), file=sys.stderr, flush=True)
    status = subprocess.call(cmd, cwd=root)
    if status == 0:
        print(f"open {out / 'index.html'}", file=sys.stderr)
    return status


#: Run in a child process (docs/conf.py sets environment variables as it loads):
#: exits 3 after printing what is missing when the site's scripts are not there.
_SITE_SCRIPTS_CHECK = """
import runpy, sys
try:
    runpy.run_path(sys.argv[1])["site_scripts"]()
except FileNotFoundError as exc:
    print(str(exc).splitlines()[0] if str(exc) else "a script of the site is missing")
    sys.exit(3)
"""


def _site_scripts_missing(root: Path) -> str | None:
    """What the site's scripts miss (the npm cache not filled), in one line, or
    None when they are all there (or docs/conf.py cannot tell: Sphinx will say)."""
    import subprocess

    conf = root / "docs" / "conf.py"
    done = subprocess.run(
        [sys.executable, "-c", _SITE_SCRIPTS_CHECK, str(conf)],
        capture_output=True,
        text=True,
        check=False,
        cwd=root,
    )
    if done.returncode == 3:
        return done.stdout.strip() or "a script of the site is missing"
    return None


def _classroom(args) -> int:
    """Write the students' notebooks (the solution cells removed) into a folder."""
    from .classroom import student_version

    try:
        written = student_version(args.out_dir, force=args.force)
    except (ImportError, ValueError, OSError) as exc:
        print(f"pentanb classroom: {exc}", file=sys.stderr)
        return 2
    for path in written:
        print(path)
    print(f"{len(written)} notebooks without their solutions in {args.out_dir}", file=sys.stderr)
    return 0


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="pentanb",
        description="Semiregular pentagonal subdivisions (Akleman et al.): the paper's "
        "schemes, figures and claims.",
    )
    sub = p.add_subparsers(dest="command")
    d = sub.add_parser(
        "demo", help="run every scheme on the Platonic solids and a torus (the default)"
    )
    d.set_defaults(func=_demo)
    f = sub.add_parser("figures", help="redraw every figure of the paper and check its claims")
    f.add_argument("--out", default="figures", help="folder for the PNGs (default: figures)")
    f.add_argument(
        "--only",
        nargs="+",
        metavar="NAME",
        help=(
            "only these figures (fig01 ... fig13, equation1, lateral, convergence, spectra,"
            " characteristic_maps, or numbers)"
        ),
    )
    f.set_defaults(func=_figures)
    s = sub.add_parser(
        "docs", help="build the documentation site (Sphinx, notebooks executed, offline)"
    )
    s.add_argument("--out", help="output folder (default: docs/_build/html)")
    s.add_argument("--force", action="store_true", help="execute every notebook again")
    s.set_defaults(func=_docs)
    c = sub.add_parser(
        "classroom", help="write the students' notebooks: the teacher's without the solutions"
    )
    c.add_argument("out_dir", metavar="OUT_DIR", help="folder for the students' notebooks")
    c.add_argument("--force", action="store_true", help="replace read-only copies in OUT_DIR too")
    c.set_defaults(func=_classroom)
    return p


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of ``python -m pentanb`` and the ``pentanb`` script.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        Exit status: 0 when every claim's verdict is the recorded one
        (findings included); 1 when one is not (a regression); 2 for an
        unknown figure or an output folder that cannot be written, a
        standard output that is closed or cannot be written (a full disk),
        and for ``docs`` without the npm cache's scripts (one line on
        standard error each);
        :data:`PIPE_CLOSED` (141, as a shell reports a program that
        SIGPIPE ended) when the output's reader went away early
        (``python -m pentanb demo | head``), without a word on standard error.
    """
    command = "pentanb"
    try:
        args = _parser().parse_args(argv)
        command = f"pentanb {args.command or 'demo'}"
        if sys.stdout is None:  # started with standard output closed (>&-)
            print(
                f"{command}: standard output is closed; give it a file (> out.txt)", file=sys.stderr
            )
            return 2
        status = _demo(args) if args.command is None else args.func(args)
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
    except BrokenPipeError:
        _silence()
        return PIPE_CLOSED
    except OSError as exc:  # writing the output: a full disk (> /dev/full), an I/O error
        print(f"{command}: cannot write the output: {exc.strerror or exc}", file=sys.stderr)
        _silence(streams=(sys.stdout,))  # what is left in its buffer goes nowhere
        return 2
    return status


#: The exit status when the reader of the output closed it early.
PIPE_CLOSED = 141


def _silence(streams: tuple | None = None) -> None:
    """Point standard output and error (or ``streams``) at the null device, so
    that nothing more is written to a closed pipe or a full disk (the
    interpreter flushes both at exit, which would fail again and print
    "Exception ignored ... BrokenPipeError")."""
    for stream in (sys.stdout, sys.stderr) if streams is None else streams:
        try:
            null = os.open(os.devnull, os.O_WRONLY)
            try:
                os.dup2(null, stream.fileno())
            finally:
                os.close(null)
        except (OSError, ValueError, AttributeError):  # no file descriptor (captured)
            pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
