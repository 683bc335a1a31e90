#!/usr/bin/env bash
# Runs the certified-verdict benchmarks (benches/certify.rs) and prints, per
# group (certify_spectrum, certify_charmap, certify_charmap_difference), the mean time per scheme and
# valence as the README's tables. Criterion arguments pass through, e.g.
# `scripts/bench-certify.sh certify_charmap` runs one group.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench --bench certify -- "$@" >&2
python3 - <<'PY'
import json, os
for group in ["certify_spectrum", "certify_charmap", "certify_charmap_difference"]:
    root = os.path.join("target/criterion", group)
    if not os.path.isdir(root):
        continue
    # the schemes the bench measured, in its own order (benches/certify.rs)
    order = ["catmull-clark", "loop", "doo-sabin", "non-box", "four-three", "sqrt3", "unified-sqrt3", "pgs", "tps", "polar-bi2"]
    schemes = [s for s in order if os.path.isdir(os.path.join(root, s))]
    if not schemes:
        continue
    ns = sorted(int(d) for d in os.listdir(os.path.join(root, schemes[0])) if d.isdigit())
    def mean(s, n):
        path = os.path.join(root, s, str(n), "new", "estimates.json")
        if not os.path.exists(path):
            return None
        with open(path) as f:
            return json.load(f)["mean"]["point_estimate"] * 1e-9
    print(f"{group}\n")
    print("| n | " + " | ".join(schemes) + " |")
    print("|---:|" + "---:|" * len(schemes))
    for n in ns:
        cells = [mean(s, n) for s in schemes]
        print(f"| {n} | " + " | ".join("-" if t is None else f"{t * 1e3:.2f} ms" for t in cells) + " |")
    print()
PY
