#!/usr/bin/env bash
# Times `subdlab verify` (release build) on all five built-in papers and on
# each paper alone, in the same run on the same machine. Target: under 5 s
# for all five papers, characteristic maps included.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/subdlab
t() { local s e; s=$EPOCHREALTIME; "$@" > /dev/null; e=$EPOCHREALTIME; awk -v a="$s" -v b="$e" 'BEGIN { print b - a }'; }
echo "paper                 seconds"
for p in $($bin verify --json | python3 -c 'import json,sys; print(" ".join(x["paper"] for x in json.load(sys.stdin)))'); do
  printf "%-20s %8.2f\n" "$p" "$(t $bin verify --paper "$p")"
done
printf "%-20s %8.2f\n" "all five" "$(t $bin verify)"
