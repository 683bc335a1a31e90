#!/usr/bin/env bash
# Runs the certified characteristic-map benchmark (benches/certify_charmap.rs)
# and prints the time of `certify_charmap` per scheme and valence.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench --bench certify_charmap -- "$@" >&2
python3 - <<'PY'
import json, os
root = "target/criterion/certify_charmap"
schemes = ["catmull-clark", "loop", "doo-sabin"]
ns = sorted(int(d) for d in os.listdir(os.path.join(root, schemes[0])) if d.isdigit())
def mean(s, n):
    with open(os.path.join(root, s, str(n), "new", "estimates.json")) as f:
        return json.load(f)["mean"]["point_estimate"] * 1e-9
print("| n | " + " | ".join(schemes) + " |")
print("|---:|" + "---:|" * len(schemes))
for n in ns:
    print(f"| {n} | " + " | ".join(f"{mean(s, n) * 1e3:.1f} ms" for s in schemes) + " |")
PY
