#!/usr/bin/env bash
# Motion Panel set-up: `bash resources/setup.sh run` starts the panel on the simulated device;
# `bash resources/setup.sh test` runs lint (ruff, mypy on drivers/, import-linter) and the whole
# test suite (under Xvfb with Mesa).
# Both create .venv and install the project into it when needed; as root, `test` also installs
# the Debian packages for Xvfb, Mesa and Qt's xcb platform where they are missing.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
VENV="$ROOT/.venv"
PY=${PYTHON:-python3}

DEBIAN_PACKAGES=(
  xvfb xauth libgl1 libgl1-mesa-dri libglx-mesa0 libegl1 libopengl0
  libxkbcommon0 libxkbcommon-x11-0 libxcb-cursor0 libxcb-icccm4 libxcb-keysyms1
  libxcb-shape0 libxcb-render-util0 libxcb-image0 libxcb-xinerama0 libxcb-randr0
  libfontconfig1 libdbus-1-3 libglib2.0-0
  fonts-droid-fallback desktop-file-utils
  openbox xdotool x11-utils imagemagick
  ser2net
)  # fonts-droid-fallback: Chinese glyphs for the zh_CN interface; desktop-file-utils: the
   # launcher file's check; openbox, xdotool, x11-utils (xprop), imagemagick (import): the
   # real-input acceptance tier (tests/acceptance); ser2net: a device served over RFC 2217
   # (tests/app/cli/test_ser2net.py, bench/ser2net_latency.py)

say() { printf 'setup: %s\n' "$*" >&2; }

install_debian_packages() {
  command -v dpkg >/dev/null 2>&1 || { say "not a Debian system: install Xvfb and Mesa yourself"; return 0; }
  local missing=()
  for pkg in "${DEBIAN_PACKAGES[@]}"; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    say "missing Debian packages (run as root to install): ${missing[*]}"
    return 0
  fi
  say "installing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

install_venv() {
  local extras=$1 stamp="$VENV/.installed-$1"
  if [ ! -x "$VENV/bin/python" ]; then
    say "creating $VENV"
    "$PY" -m venv "$VENV"
    "$VENV/bin/python" -m pip install -q --upgrade pip
  fi
  if [ ! -f "$stamp" ] || [ pyproject.toml -nt "$stamp" ]; then
    say "installing Motion Panel into $VENV"
    "$VENV/bin/python" -m pip install -q -e ".$extras" 2>&1 | grep -v -e '^WARNING: Location' >&2 || true
    "$VENV/bin/python" -c "import PySide6, pyqtgraph, serial, numpy" || { say "installation failed"; exit 1; }
    touch "$stamp"
  fi
}

run_tests() {
  install_debian_packages
  install_venv "[test]"
  "$VENV/bin/ruff" check .
  "$VENV/bin/ruff" format --check .
  "$VENV/bin/mypy" drivers
  "$VENV/bin/lint-imports"  # the layers and no import circles (pyproject.toml)
  export LIBGL_ALWAYS_SOFTWARE=1
  # The hundreds of motionctl, motionsim and motionpanel processes the tests start each compile
  # the project's modules again unless their bytecode is kept: kept in .venv, not the tree.
  unset PYTHONDONTWRITEBYTECODE
  export PYTHONPYCACHEPREFIX="$VENV/pycache"
  # Three test files at a time (pytest-xdist, each worker on an X server of its own): on two
  # cores the tests wait on devices and timers often enough that a third worker fills the gaps
  # (12 min against 15.5 with two). MOTIONPANEL_TEST_WORKERS=N runs N, 0 one process.
  if [ "${MOTIONPANEL_TEST_WORKERS:-3}" != "0" ]; then
    set -- -n "${MOTIONPANEL_TEST_WORKERS:-3}" --dist loadfile "$@"
  fi
  if command -v xvfb-run >/dev/null 2>&1; then
    exec xvfb-run -a -s "-screen 0 1600x1000x24 +extension GLX" "$VENV/bin/python" -m pytest "$@"
  fi
  say "xvfb-run not found: running offscreen, OpenGL tests will be skipped"
  QT_QPA_PLATFORM=offscreen exec "$VENV/bin/python" -m pytest "$@"
}

case "${1:-}" in
  run) shift; install_venv ""; exec "$VENV/bin/motionpanel" "$@" ;;
  test) shift; run_tests "$@" ;;
  *) echo "usage: bash resources/setup.sh run [motionpanel options] | test [pytest options]" >&2; exit 2 ;;
esac
