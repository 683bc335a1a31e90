#!/usr/bin/env bash
# Executes the Jupyter notebooks in notebooks/ (all of them, or the ones given
# as arguments) and fails naming the notebook and the cell when a cell raises.
#
#   scripts/notebooks.sh                                  # every notebooks/*.ipynb
#   scripts/notebooks.sh notebooks/validate-new-weights.ipynb
#   scripts/notebooks.sh --publish                        # also render into reports/notebooks/
#
# The notebooks drive the subdlab CLI: the binary is $SUBDLAB when set (the
# test tests/notebooks.rs passes the one cargo built), else the release build,
# made here with `cargo build --release`.
#
# Everything generated goes under one folder, $SUBDLAB_TARGET_DIR when set, else
# $CARGO_TARGET_DIR when set, else target/ in the repository:
#   notebook-venv/        Python virtual environment with notebooks/requirements.txt
#                         (made once, remade when requirements.txt or python3 changes;
#                         needs network access to PyPI that first time)
#   notebooks-executed/   executed copies of the notebooks, with their outputs
#   notebooks-rendered/   each executed notebook as Markdown with its figures (what
#                         reports/notebooks/ must hold; --publish writes there instead)
#   notebook-figures/     figures the notebooks write ($SUBDLAB_NOTEBOOK_FIGURES overrides)
#   notebook-work/        scheme and claim files the notebooks write
# Other settings: $PYTHON (default python3) makes the environment;
# $NOTEBOOK_CELL_TIMEOUT (seconds, default 300) bounds each cell.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
python="${PYTHON:-python3}"

if [ "${1:-}" = "--publish" ]; then
  shift
  export SUBDLAB_NOTEBOOKS_RENDERED="$repo/reports/notebooks"
fi

die() {
  echo "scripts/notebooks.sh: $*" >&2
  exit 1
}

if ! command -v "$python" > /dev/null 2>&1; then
  die "'$python' not found: executing the notebooks needs Python 3 (3.11 tested) with its venv module"
fi

# The folder for everything generated (absolute: the kernels run elsewhere).
target="${SUBDLAB_TARGET_DIR:-${CARGO_TARGET_DIR:-$repo/target}}"
mkdir -p "$target"
target="$(cd "$target" && pwd)"

# The subdlab binary.
if [ -z "${SUBDLAB:-}" ]; then
  command -v cargo > /dev/null 2>&1 || die "SUBDLAB not set and cargo not found: set SUBDLAB to a subdlab binary"
  echo "scripts/notebooks.sh: SUBDLAB not set; cargo build --release" >&2
  cargo build --release --quiet --manifest-path "$repo/Cargo.toml"
  cargo_target="${CARGO_TARGET_DIR:-$repo/target}"
  SUBDLAB="$(cd "$cargo_target" && pwd)/release/subdlab"
fi
[ -x "$SUBDLAB" ] || die "SUBDLAB=$SUBDLAB is not an executable file"
SUBDLAB="$(cd "$(dirname "$SUBDLAB")" && pwd)/$(basename "$SUBDLAB")"

# One run at a time per folder: runs share the environment and the outputs.
if command -v flock > /dev/null 2>&1; then
  exec 9> "$target/notebooks.lock"
  flock 9
fi

# The virtual environment, re-used while requirements.txt and python3 are unchanged.
venv="$target/notebook-venv"
req="$repo/notebooks/requirements.txt"
stamp="$venv/subdlab-requirements.stamp"
want="$(sha256sum "$req" | cut -d' ' -f1) $("$python" -c 'import os, sys; print(os.path.realpath(sys.executable), sys.version.split()[0])')"
if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2> /dev/null)" != "$want" ]; then
  echo "scripts/notebooks.sh: creating $venv (python3 -m venv, pip install -r notebooks/requirements.txt)" >&2
  start=$SECONDS
  rm -rf "$venv"
  "$python" -m venv "$venv" || die "'$python -m venv' failed (on Debian: apt-get install python3-venv)"
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check --no-input -r "$req" \
    || die "pip could not install notebooks/requirements.txt into $venv (the first run needs network access to PyPI)"
  # The kernel the notebooks run on: this environment's python (kernel.json names it).
  "$venv/bin/python" -m ipykernel install --sys-prefix --name subdlab-notebooks \
    --display-name "Python (subdlab notebooks)" > /dev/null
  echo "$want" > "$stamp"
  echo "scripts/notebooks.sh: environment ready in $((SECONDS - start)) s" >&2
fi

# Keep Jupyter's and IPython's state inside the environment, away from the
# user's own configuration and kernels.
export JUPYTER_PATH="$venv/share/jupyter"
export JUPYTER_DATA_DIR="$venv/jupyter-data"
export JUPYTER_CONFIG_DIR="$venv/jupyter-config"
export JUPYTER_RUNTIME_DIR="$venv/jupyter-runtime"
export JUPYTER_PLATFORM_DIRS=1
export IPYTHONDIR="$venv/ipython"
export PYDEVD_DISABLE_FILE_VALIDATION=1
export SUBDLAB SUBDLAB_TARGET_DIR="$target"
export SUBDLAB_NOTEBOOK_PREFIX="$venv"

exec "$venv/bin/python" "$repo/scripts/run_notebooks.py" "$@"
