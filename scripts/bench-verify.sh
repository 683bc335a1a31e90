#!/usr/bin/env bash
# Times the main job, `subdlab verify --check-expected` (release build), in
# wall-clock and CPU seconds, ROUNDS times (default 3). With BASE=path/to/an/
# older/subdlab binary, each round runs the old and the new binary back to
# back, so both see the same machine load (a paired comparison). Then the
# slowest claims of the last run (`verify --slowest`).
#   scripts/bench-verify.sh
#   BASE=/tmp/old/subdlab ROUNDS=5 scripts/bench-verify.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/subdlab
rounds=${ROUNDS:-3}
one() { # prints "wall cpu" of one main-job run of binary $1
  local out
  out=$( { /usr/bin/time -f "%e %U %S" "$1" verify --check-expected > /dev/null; } 2>&1 | tail -1)
  awk '{ printf "%.2f %.2f\n", $1, $2 + $3 }' <<< "$out"
}
printf "%-6s %-8s %8s %8s\n" round binary "wall s" "CPU s"
for r in $(seq 1 "$rounds"); do
  if [[ -n "${BASE:-}" ]]; then
    read -r w c < <(one "$BASE"); printf "%-6s %-8s %8s %8s\n" "$r" base "$w" "$c"
  fi
  read -r w c < <(one "$bin"); printf "%-6s %-8s %8s %8s\n" "$r" new "$w" "$c"
done
"$bin" verify --check-expected --slowest 10 | sed -n '/^slowest/,$p'
