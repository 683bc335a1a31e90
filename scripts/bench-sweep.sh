#!/usr/bin/env bash
# Sweep cost against valence (Catmull–Clark): the criterion benchmark
# benches/sweep.rs times one point by stage at n = 3..1000, then the full
# `subdlab sweep catmull-clark --valences 3..1000` is timed in the same run on
# one thread (the baseline) and on all cores.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo bench --bench sweep -- sweep_point "$@" >&2
cargo build --release --quiet
bin="${CARGO_TARGET_DIR:-target}/release/subdlab"
t0=$(date +%s.%N)
"$bin" sweep catmull-clark --valences 3..1000 --csv --threads 1 > /dev/null
t1=$(date +%s.%N)
"$bin" sweep catmull-clark --valences 3..1000 --csv > /dev/null
t2=$(date +%s.%N)
python3 - "$t0" "$t1" "$t2" <<'PY'
import json, math, os, sys
root = os.path.join(os.environ.get("CARGO_TARGET_DIR", "target"), "criterion", "sweep_point")
def mean(stage, n):
    with open(os.path.join(root, stage, str(n), "new", "estimates.json")) as f:
        return json.load(f)["mean"]["point_estimate"] * 1e-9
stages = ["discover", "assemble", "eigen", "point"]
ns = sorted(int(d) for d in os.listdir(os.path.join(root, "point")) if d.isdigit())
print(f"{'n':>5} " + " ".join(f"{s + ' (ms)':>14}" for s in stages))
for n in ns:
    print(f"{n:>5} " + " ".join(f"{mean(s, n) * 1e3:>14.3f}" for s in stages))
print("\ngrowth exponent p in cost ~ n^p between consecutive valences:")
for a, b in zip(ns, ns[1:]):
    ps = [math.log(mean(s, b) / mean(s, a)) / math.log(b / a) for s in stages]
    print(f"{a:>5}..{b:<5} " + " ".join(f"{p:>14.2f}" for p in ps))
# serial baseline: the per-point cost interpolated log-log over 3..1000
def point_cost(n):
    for a, b in zip(ns, ns[1:]):
        if a <= n <= b:
            t = math.log(n / a) / math.log(b / a)
            return math.exp((1 - t) * math.log(mean("point", a)) + t * math.log(mean("point", b)))
    return mean("point", ns[-1])
predicted = sum(point_cost(n) for n in range(3, 1001))
t0, t1, t2 = (float(a) for a in sys.argv[1:4])
one, all_cores = t1 - t0, t2 - t1
print(f"\nsweep catmull-clark --valences 3..1000: {one:.1f} s on 1 thread "
      f"(sum of the benchmarked point costs, interpolated: {predicted:.1f} s), "
      f"{all_cores:.1f} s on {os.cpu_count()} cores: speed-up {one / all_cores:.2f}")
PY
