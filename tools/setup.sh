#!/usr/bin/env bash
# Set up everything floatpage needs on a fresh Debian machine, idempotently:
# TeX Live and poppler from Debian's packages (only those missing), then a
# virtual environment with the Python packages. Safe to run again: it skips
# what is already there.
set -euo pipefail
cd "$(dirname "$0")/.."

DEBIAN_PACKAGES=(
  texlive-latex-base texlive-latex-recommended texlive-latex-extra
  texlive-luatex texlive-xetex texlive-fonts-recommended texlive-fonts-extra
  lmodern fonts-texgyre poppler-utils
  # fallback fonts for the scripts and emoji the three faces lack (typeset/fonts.py)
  fonts-noto-core fonts-noto-cjk fonts-noto-color-emoji
  # GNU FriBidi, the tests' independent reference for right-to-left order (typeset/bidi.py)
  libfribidi0
  # a C compiler and the Python headers: pip builds the snap's compiled units (physics/*_kernel.c)
  gcc python3-dev
  # the tests drive the real editor in a tmux pane (tests/tui/test_editor_walk7.py); a fresh
  # Debian has none, and without it that test fails (FileNotFoundError)
  tmux
)

missing=()
if command -v dpkg-query >/dev/null 2>&1; then
  for package in "${DEBIAN_PACKAGES[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$package")
  done
fi

if ((${#missing[@]})); then
  command=(apt-get install -y --no-install-recommends "${missing[@]}")
  if [[ $(id -u) -eq 0 ]]; then
    echo "setup: installing from Debian's packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    "${command[@]}" -qq >/dev/null
  else
    echo "setup: Debian packages are missing. Run this as root, then run make again:" >&2
    echo "  sudo apt-get update && sudo ${command[*]}" >&2
    exit 1
  fi
fi

PYTHON=${PYTHON:-python3}
if [[ ! -x .venv/bin/python ]]; then
  echo "setup: creating .venv with $($PYTHON --version)"
  "$PYTHON" -m venv .venv
fi
# A strict editable install: a tree of links under build/ that type checkers can follow, with
# floatpage.physics -> physics/ and so on. It links files, not folders, so a new or removed
# module means installing again; the stamp holds the list of files it was made from. A C source
# or header newer than the stamp is built again (a compiled module is a copy, not a link).
stamp=.venv/.floatpage-installed
package_files=$(find physics model typeset tui cli starters latex_templates merge -type f \
  \( -name '*.py' -o -name '*.c' -o -name '*.h' -o -name '*.j2' -o -name '*.tcss' \
     -o -path 'starters/bundled/*' \) | LC_ALL=C sort)
if [[ ! -f $stamp || pyproject.toml -nt $stamp ]]; then
  echo "setup: installing Python packages into .venv"
  .venv/bin/python -m pip install -q --upgrade pip
  .venv/bin/python -m pip install -q -e '.[test]' --config-settings editable_mode=strict
  printf '%s\n' "$package_files" > "$stamp"
elif [[ "$(cat "$stamp")" != "$package_files" \
      || -n $(find physics \( -name '*.c' -o -name '*.h' \) -newer "$stamp") ]]; then
  echo "setup: package files were added, removed or compiled ones changed; installing them again"
  .venv/bin/python -m pip install -q --no-deps -e . --config-settings editable_mode=strict
  printf '%s\n' "$package_files" > "$stamp"
fi
