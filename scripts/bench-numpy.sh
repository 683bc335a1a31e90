#!/usr/bin/env bash
# subdlab against NumPy on the same local subdivision matrices, in one run:
#
#   subdlab        the whole process `subdlab spectrum SCHEME -n N --no-exact --json`
#                  (discovery, assembly, Fourier blocks, eigenvalues, JSON), wall time
#   numpy dense    np.linalg.eig of the dense S (right vectors), in-process
#   numpy blocks   the ideal Fourier-block computation given S: the rows of
#                  sector 0 (read from the vertex labels in the .mtx comments),
#                  C[τ] = S[(0,a),(τ,b)], B_m = Σ_τ C[τ] ω^{mτ} by one FFT over τ
#                  (block 0 bordered by the fixed centre), then batched
#                  np.linalg.eig of all blocks and np.linalg.inv for the left
#                  vectors, in-process
#
# S comes from `subdlab matrix SCHEME -n N --format mtx --no-exact` (reading the
# file is not timed). Every time is the minimum over $REPEAT runs (default 3).
# The table ends with the ratios subdlab/dense and subdlab/blocks, and checks
# that both NumPy routes find subdlab's subdominant eigenvalue.
#
#   scripts/bench-numpy.sh                                   # the default schemes, n = 125 250 500 1000
#   SCHEMES="catmull-clark loop" VALENCES="125 250" scripts/bench-numpy.sh
#   SCHEMES="unified-sqrt3:alpha=1" VALENCES="125 250" scripts/bench-numpy.sh
#
# Settings: $SUBDLAB (the binary; default: cargo build --release), $SCHEMES
# (names, with :NAME=VALUE parameters), $VALENCES, $REPEAT, $DENSE_MAX (largest
# matrix given to the dense solver, default 1600: its time grows like size³,
# about a minute at 6001), $PYTHON (default python3).
# NumPy (pinned below) goes into a virtual environment under target/
# (bench-numpy-venv/, made once, remade when the pin or python3 changes; the
# first run needs network access to PyPI), the matrices into target/bench-numpy/.
# NumPy runs on one BLAS thread; subdlab solves its Fourier blocks on every core (rayon).
set -euo pipefail

# the newest NumPy for CPython 3.11 (2.5 needs 3.12)
NUMPY_PIN="numpy==2.4.6"

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
python="${PYTHON:-python3}"
die() {
  echo "scripts/bench-numpy.sh: $*" >&2
  exit 1
}
command -v "$python" > /dev/null 2>&1 || die "'$python' not found: the NumPy baselines need Python 3 with its venv module"

target="${CARGO_TARGET_DIR:-$repo/target}"
mkdir -p "$target"
target="$(cd "$target" && pwd)"

if [ -z "${SUBDLAB:-}" ]; then
  cargo build --release --quiet --manifest-path "$repo/Cargo.toml"
  SUBDLAB="$target/release/subdlab"
fi
[ -x "$SUBDLAB" ] || die "SUBDLAB=$SUBDLAB is not an executable file"

venv="$target/bench-numpy-venv"
stamp="$venv/subdlab-numpy.stamp"
want="$NUMPY_PIN $("$python" -c 'import os, sys; print(os.path.realpath(sys.executable), sys.version.split()[0])')"
if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2> /dev/null)" != "$want" ]; then
  echo "scripts/bench-numpy.sh: creating $venv ($NUMPY_PIN)" >&2
  rm -rf "$venv"
  "$python" -m venv "$venv" || die "'$python -m venv' failed (on Debian: apt-get install python3-venv)"
  "$venv/bin/python" -m pip install --quiet --disable-pip-version-check --no-input "$NUMPY_PIN" \
    || die "pip could not install $NUMPY_PIN into $venv (the first run needs network access to PyPI)"
  echo "$want" > "$stamp"
fi

work="$target/bench-numpy"
mkdir -p "$work"
export SUBDLAB WORK="$work"
export SCHEMES="${SCHEMES:-catmull-clark loop doo-sabin sqrt3 non-box four-three pgs polar-bi2 tps}"
export VALENCES="${VALENCES:-125 250 500 1000}"
export REPEAT="${REPEAT:-3}"
export DENSE_MAX="${DENSE_MAX:-1600}"
# one BLAS thread: the comparison is per core
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1 MKL_NUM_THREADS=1

exec "$venv/bin/python" - << 'PY'
import json, os, re, subprocess, sys, time
import numpy as np

subdlab, work = os.environ["SUBDLAB"], os.environ["WORK"]
repeat, dense_max = int(os.environ["REPEAT"]), int(os.environ["DENSE_MAX"])
LABEL = re.compile(r"^% row/col (\d+): (\S+)$")
NAME = re.compile(r"^(\w+)\[r(\d+),s(\d+),(\d+)\]$")


def scheme_args(spec):
    name, *params = spec.split(":")
    return name, sum((["--param", p] for p in params), [])


def best(f):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - t)
    return min(times), out


def read_mtx(path):
    """Dense S, and per row its orbit key and sector (None for the fixed centre)."""
    labels = {}
    with open(path) as fh:
        for line in fh:
            if not line.startswith("%"):
                size, _, nnz = map(int, line.split())
                break
            m = LABEL.match(line.strip())
            if m:
                labels[int(m.group(1)) - 1] = m.group(2)
        data = np.loadtxt(fh, ndmin=2) if nnz else np.zeros((0, 3))
    s = np.zeros((size, size))
    s[data[:, 0].astype(int) - 1, data[:, 1].astype(int) - 1] = data[:, 2]
    keys = []
    for k in range(size):
        m = NAME.match(labels[k])
        # (kind, ring, index) names an orbit; the sector is the position in it
        keys.append(None if m is None else ((m.group(1), int(m.group(2)), int(m.group(4))), int(m.group(3))))
    return s, keys


def block_setup(s, keys, n):
    """Index arrays of the Fourier blocks: orbits, their members by sector, the centre."""
    orbits = sorted({k[0] for k in keys if k is not None})
    pos = {o: a for a, o in enumerate(orbits)}
    member = np.zeros((len(orbits), n), dtype=int)
    for idx, k in enumerate(keys):
        if k is not None:
            member[pos[k[0]], k[1]] = idx
    centre = [i for i, k in enumerate(keys) if k is None]
    return member, centre


def blocks_eig(s, member, centre, n):
    """All n blocks from the sector-0 rows, their eigenvalues and left vectors."""
    rep = member[:, 0]
    # C[τ][a][b] = S[(0,a), (τ,b)]
    c = s[rep][:, member]  # (b, b, n): a, b, τ
    c = np.transpose(c, (2, 0, 1))
    blocks = n * np.fft.ifft(c, axis=0)  # B_m = Σ_τ C[τ] e^{2πi mτ/n}
    vals = []
    w, v = np.linalg.eig(blocks[1:])
    np.linalg.inv(v)  # left eigenvectors of every block
    vals.append(w.ravel())
    b0 = blocks[0]
    if centre:
        c0 = centre[0]
        top = np.concatenate([[s[c0, c0]], s[c0, member].sum(axis=1)])
        left = s[rep, c0][:, None]
        b0 = np.block([[top[None, :]], [left, b0]])
    w0, v0 = np.linalg.eig(b0)
    np.linalg.inv(v0)
    vals.append(w0)
    return np.concatenate(vals)


def dense_eig(s):
    w, _ = np.linalg.eig(s)
    return w


def subdominant(vals):
    m = np.sort(np.abs(vals))[::-1]
    return m[m < 1 - 1e-9][0]


rows = []
for spec in os.environ["SCHEMES"].split():
    name, params = scheme_args(spec)
    for n in map(int, os.environ["VALENCES"].split()):
        common = [name, "--valence", str(n), *params]
        mtx = os.path.join(work, f"{spec.replace(':', '_').replace('/', '_')}-{n}.mtx")
        subprocess.run([subdlab, "matrix", *common, "--format", "mtx", "--no-exact", "-o", mtx], check=True)
        run = lambda: subprocess.run([subdlab, "spectrum", *common, "--no-exact", "--json"], check=True,
                                     capture_output=True).stdout
        t_sub, out = best(run)
        lam_sub = json.loads(out)["verdict"]["subdominant"]
        s, keys = read_mtx(mtx)
        member, centre = block_setup(s, keys, n)
        t_blk, vals = best(lambda: blocks_eig(s, member, centre, n))
        assert len(vals) == s.shape[0], f"{spec} n={n}: blocks hold {len(vals)} of {s.shape[0]} eigenvalues"
        ok = abs(subdominant(vals) - lam_sub) < 1e-8
        t_den = None
        if s.shape[0] <= dense_max:
            t_den, dvals = best(lambda: dense_eig(s))
            ok = ok and abs(subdominant(dvals) - lam_sub) < 1e-8
        rows.append((spec, n, s.shape[0], t_sub, t_den, t_blk, ok))
        print(f"  {spec} n={n}: done", file=sys.stderr)


def fmt(t):
    return "–" if t is None else (f"{t * 1e3:.1f} ms" if t < 1 else f"{t:.2f} s")


print("| scheme | n | size | subdlab spectrum --no-exact (process) | NumPy dense eig | NumPy DFT blocks | subdlab / dense | subdlab / blocks | λ1 agrees |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---|")
for spec, n, size, t_sub, t_den, t_blk, ok in rows:
    ratio_d = "–" if t_den is None else f"{t_sub / t_den:.3g}"
    print(f"| {spec} | {n} | {size} | {fmt(t_sub)} | {fmt(t_den)} | {fmt(t_blk)} | {ratio_d} | {t_sub / t_blk:.3g} | {'yes' if ok else 'NO'} |")
PY
