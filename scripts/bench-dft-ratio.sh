#!/usr/bin/env bash
# Runs the Catmull–Clark spectrum benchmark (DFT blocks vs full matrix, same
# run, same machine) and prints the time of each and their ratio per valence.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench --bench spectrum -- cc_spectrum "$@" >&2
python3 - <<'PY'
import json, os
root = "target/criterion/cc_spectrum"
def mean(kind, n):
    with open(os.path.join(root, kind, str(n), "new", "estimates.json")) as f:
        return json.load(f)["mean"]["point_estimate"] * 1e-9
ns = sorted(int(d) for d in os.listdir(os.path.join(root, "dft")) if d.isdigit())
print(f"{'n':>5} {'dft (s)':>12} {'full (s)':>12} {'full/dft':>10}")
for n in ns:
    d, f = mean("dft", n), mean("full", n)
    print(f"{n:>5} {d:>12.6f} {f:>12.6f} {f/d:>10.1f}")
PY
