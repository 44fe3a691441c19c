#!/usr/bin/env bash
# Install what the browser tests (tests/test_browser.py) and offline HTML
# export (pentanb.export_html(..., offline=True)) need:
#   * Debian's chromium (only if /usr/bin/chromium is missing),
#   * Python's playwright, only when a Python is named (argument or $PYTHON)
#     and it lacks it; it drives that chromium, so no browser download is
#     needed (the test extras of pyproject.toml bring it into a venv anyway),
#   * the npm packages @jupyter-widgets/html-manager and requirejs, at the
#     versions of pentanb/viz/js_versions.json (the one place they are
#     written; pentanb.viz.html reads the same file), in a cache folder
#     outside the repository: $PENTANB_JS_DIR, default
#     ${XDG_CACHE_HOME:-$HOME/.cache}/pentanb/js,
#   * in the same folder, the npm packages that only the documentation site
#     needs (MathJax), at the versions of docs/js_versions.json (docs/conf.py
#     reads it too).
# Safe to run again: each step is skipped when its result is already there.
#
# Usage: bash .ci/browser-setup.sh [python]
set -euo pipefail

PY="${1:-${PYTHON:-}}"
REPO="$(cd "$(dirname "$0")/.." && pwd)"
JS_VERSIONS="$REPO/pentanb/viz/js_versions.json"
DOCS_JS_VERSIONS="$REPO/docs/js_versions.json"
JS_DIR="${PENTANB_JS_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/pentanb/js}"

apt_updated=0
apt_install() {
    if [ "$apt_updated" = 0 ]; then
        apt-get update -qq
        apt_updated=1
    fi
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"
}

if [ ! -x /usr/bin/chromium ]; then
    echo "browser-setup: installing Debian's chromium"
    apt_install chromium fonts-liberation
fi

if [ -n "$PY" ] && ! "$PY" -c "import playwright" 2>/dev/null; then
    echo "browser-setup: installing Python's playwright into $PY"
    "$PY" -m pip install --quiet "playwright>=1.40"
fi

# "name@version" for every package of the js_versions.json files not yet in
# the cache at that version
# (arguments: a versions file, the cache, then any further versions files)
mapfile -t packages < <("${PY:-python3}" - "$JS_VERSIONS" "$JS_DIR" "$DOCS_JS_VERSIONS" <<'PYTHON'
import json, pathlib, sys
wanted = {}
for path in [sys.argv[1], *sys.argv[3:]]:
    if pathlib.Path(path).is_file():
        wanted.update(json.loads(pathlib.Path(path).read_text()))
for name, version in wanted.items():
    installed = pathlib.Path(sys.argv[2], "node_modules", name, "package.json")
    if not installed.is_file() or json.loads(installed.read_text()).get("version") != version:
        print(f"{name}@{version}")
PYTHON
)
if [ "${#packages[@]}" -gt 0 ]; then
    if ! command -v npm >/dev/null 2>&1; then
        echo "browser-setup: installing npm"
        apt_install npm
    fi
    echo "browser-setup: fetching ${packages[*]} into $JS_DIR"
    mkdir -p "$JS_DIR"
    npm install --prefix "$JS_DIR" --no-audit --no-fund --loglevel=error "${packages[@]}"
fi

echo "browser-setup: $(/usr/bin/chromium --version 2>/dev/null | head -1 || echo 'chromium ?');" \
     "widget scripts in $JS_DIR"
