"""Helpers for the browser tests: headless Chromium, a JupyterLab server, pixels.

Used by ``tests/test_browser.py``; no pytest plugin, no conftest.

* :func:`require_browser` finds Debian's Chromium (``/usr/bin/chromium``, or
  ``$PENTANB_CHROMIUM``) and Python's playwright, and skips the test with a
  message when either is missing -- except under CI (``CI=true``), where a
  missing browser fails the run.
* :class:`JupyterLab` runs ``jupyter lab`` on 127.0.0.1 on a free port, with
  no token, in a scratch folder with its own config, data, settings and
  workspaces (a ``python3`` kernel spec for the running Python), and stops it.
* :func:`nonblank` and :func:`changed` compare screenshots.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: Flags for headless Chromium without a GPU, a sandbox or background traffic.
CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--enable-unsafe-swiftshader",
    "--disable-background-networking",
    "--disable-component-update",
    "--no-first-run",
]

#: Console messages known to be harmless (substrings).  None comes from
#: pentanb; see the module docstring of :mod:`pentanb.viz.three`.
HARMLESS_CONSOLE = (
    "GPU stall due to ReadPixels",  # SwiftShader performance note
    "Automatic fallback to software WebGL",  # headless Chromium without GPU
    "WebGL-",  # other GL driver notes
    "allowUnionTypes",  # html-manager's JSON schema (ajv)
    "Unsatisfied version",  # pythreejs built for older Lumino
    "shared singleton module",
    "Failed to load resource: the server responded with a status of 404",  # favicon etc.
    "[Violation]",
    "already frozen",  # pythreejs log when a view is reused
    # pythreejs 2.4 under JupyterLab 4, for lights that cast shadows
    # (PointLight, DirectionalLight, SpotLight); pentanb's views use none
    "Error setting state: t.on is not a function",
)

#: Console text that fails a test whatever its level: WebGL errors mean a
#: buffer was drawn out of step with another (see ``MeshView.update``).
FORBIDDEN_CONSOLE = ("GL_INVALID",)


def in_ci() -> bool:
    return os.environ.get("CI", "").lower() == "true"


def skip_or_fail(message: str):
    """Skip with ``message``; under CI (CI=true) fail instead."""
    if in_ci():
        pytest.fail(f"CI=true but {message}", pytrace=False)
    pytest.skip(message)


def chromium_path() -> str | None:
    """$PENTANB_CHROMIUM when set (only it), else Debian's /usr/bin/chromium."""
    env = os.environ.get("PENTANB_CHROMIUM")
    candidates = (
        (env,)
        if env
        else ("/usr/bin/chromium", shutil.which("chromium"), shutil.which("chromium-browser"))
    )
    for candidate in candidates:
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
    return None


def require_browser():
    """(sync_playwright, chromium path), or skip (fail under CI) saying what is missing."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        skip_or_fail(
            "Python's playwright is not installed (pip install playwright); "
            "browser tests need it and Debian's chromium"
        )
    path = chromium_path()
    if path is None:
        skip_or_fail(
            "no Chromium found at "
            f"{os.environ.get('PENTANB_CHROMIUM') or '/usr/bin/chromium'} "
            "(apt-get install chromium, or bash .ci/browser-setup.sh); "
            "browser tests skipped"
        )
    return sync_playwright, path


def artifact_dir(tmp_path_factory) -> Path:
    """Folder for screenshots: $PENTANB_BROWSER_ARTIFACTS or a new temporary folder
    (kept after the run, so the pictures can be looked at)."""
    env = os.environ.get("PENTANB_BROWSER_ARTIFACTS")
    path = Path(env) if env else Path(tempfile.mkdtemp(prefix="pentanb-browser-"))
    path.mkdir(parents=True, exist_ok=True)
    return path


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class JupyterLab:
    """``jupyter lab`` in a scratch folder (a context manager).

    Parameters
    ----------
    notebooks : list of Path
        Copied into the server's root folder (their kernelspec set to
        ``python3``, which is this Python); files beside them (helper
        modules) are copied too.
    transform : callable, optional
        Applied to each notebook's JSON (a dict) before it is written there,
        e.g. to add cells.
    """

    def __init__(self, notebooks, *, transform=None, startup_timeout: float = 90.0):
        self.notebooks = [Path(p) for p in notebooks]
        self.transform = transform
        self.startup_timeout = startup_timeout
        self.proc = None
        self.scratch = Path(tempfile.mkdtemp(prefix="pentanb-lab-"))
        self.root = self.scratch / "root"
        self.log_path = self.scratch / "server.log"

    def __enter__(self) -> JupyterLab:
        self.root.mkdir()
        for folder in {p.parent for p in self.notebooks}:
            for f in folder.iterdir():
                if f.is_file() and f.suffix in (".py", ".ipynb", ".obj", ".off", ".json"):
                    shutil.copy2(f, self.root / f.name)
        for nb in self.notebooks:
            data = json.loads(nb.read_text())
            if self.transform is not None:
                data = self.transform(data)
            data.setdefault("metadata", {})["kernelspec"] = {
                "name": "python3",
                "display_name": "Python 3 (ipykernel)",
                "language": "python",
            }
            (self.root / nb.name).write_text(json.dumps(data))
        env = self._env()
        self.port = free_port()
        cmd = [
            sys.executable,
            "-m",
            "jupyterlab",
            "--no-browser",
            f"--port={self.port}",
            "--ip=127.0.0.1",
            "--ServerApp.port_retries=0",
            "--IdentityProvider.token=",
            "--ServerApp.password=",
            "--ServerApp.disable_check_xsrf=True",
            f"--ServerApp.root_dir={self.root}",
            "--LabApp.expose_app_in_browser=True",
            "--LabApp.news_url=None",
            "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
            "--LabApp.extension_manager=readonly",
        ]
        if hasattr(os, "geteuid") and os.geteuid() == 0:
            cmd.append("--allow-root")  # CI runs as root
        self.log = open(self.log_path, "w")
        self.proc = subprocess.Popen(
            cmd, stdout=self.log, stderr=subprocess.STDOUT, env=env, cwd=self.root
        )
        self.url = f"http://127.0.0.1:{self.port}"
        deadline = time.monotonic() + self.startup_timeout
        while True:
            if self.proc.poll() is not None:
                raise RuntimeError(f"jupyter lab exited: {self.log_path.read_text()[-3000:]}")
            try:
                with urllib.request.urlopen(self.url + "/api/status", timeout=2) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if time.monotonic() > deadline:
                self.__exit__(None, None, None)
                raise RuntimeError(
                    f"jupyter lab did not answer within {self.startup_timeout:.0f} s"
                )
            time.sleep(0.25)
        return self

    def _env(self) -> dict:
        env = dict(os.environ)
        for name in ("config", "data", "runtime", "settings", "workspaces", "ipython"):
            (self.scratch / name).mkdir()
        env.update(
            JUPYTER_CONFIG_DIR=str(self.scratch / "config"),
            JUPYTER_DATA_DIR=str(self.scratch / "data"),
            JUPYTER_RUNTIME_DIR=str(self.scratch / "runtime"),
            JUPYTERLAB_SETTINGS_DIR=str(self.scratch / "settings"),
            JUPYTERLAB_WORKSPACES_DIR=str(self.scratch / "workspaces"),
            IPYTHONDIR=str(self.scratch / "ipython"),
            PYTHONPATH=os.pathsep.join(
                [str(ROOT)] + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else [])
            ),
        )
        env.pop("JUPYTER_PATH", None)
        # the kernel is this Python (a user-level spec wins over any other)
        spec = self.scratch / "data" / "kernels" / "python3"
        spec.mkdir(parents=True)
        (spec / "kernel.json").write_text(
            json.dumps(
                {
                    "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
                    "display_name": "Python 3 (ipykernel)",
                    "language": "python",
                }
            )
        )
        # no autosave (nothing is written back), no news or update pop-ups
        settings = self.scratch / "settings"
        for plugin, values in {
            "@jupyterlab/docmanager-extension/plugin": {"autosave": False},
            "@jupyterlab/apputils-extension/notification": {
                "fetchNews": "false",
                "checkForUpdates": False,
            },
        }.items():
            path = settings / (plugin + ".jupyterlab-settings")
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(json.dumps(values))
        return env

    def __exit__(self, *exc):
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=5)
        if getattr(self, "log", None):
            self.log.close()
        shutil.rmtree(self.scratch, ignore_errors=True)
        return False


# -- pixels -------------------------------------------------------------------


def image(png: bytes):
    from PIL import Image

    return Image.open(io.BytesIO(png)).convert("RGB")


def nonblank(png: bytes, *, min_fraction: float = 0.01) -> float:
    """Fraction of pixels that differ from the picture's corner (background) colour."""
    import numpy as np

    a = np.asarray(image(png), dtype=np.int16)
    background = a[1, 1]
    differs = np.abs(a - background).max(axis=2) > 16
    return float(differs.mean())


def changed(before: bytes, after: bytes) -> float:
    """Fraction of pixels that differ between two screenshots of the same size."""
    import numpy as np

    a = np.asarray(image(before), dtype=np.int16)
    b = np.asarray(image(after), dtype=np.int16)
    if a.shape != b.shape:
        return 1.0
    return float((np.abs(a - b).max(axis=2) > 16).mean())


def harmless(text: str) -> bool:
    return any(h in text for h in HARMLESS_CONSOLE)


def poll(fn, timeout, interval=0.25):
    """fn() until it returns something truthy, or None after timeout seconds (a hang guard)."""
    deadline = time.monotonic() + timeout
    while True:
        value = fn()
        if value:
            return value
        if time.monotonic() > deadline:
            return None
        time.sleep(interval)
