#!/usr/bin/env bash
# Draws the README's figures (docs/figures/*.svg) from docs/figures/figures.txt,
# one subdlab run per line, with the release build (or $SUBDLAB when set).
# tests/readme_figures.rs checks that the committed files are what this draws.
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ -z "${SUBDLAB:-}" ]; then
  cargo build --release --quiet --manifest-path "$repo/Cargo.toml"
  SUBDLAB="${CARGO_TARGET_DIR:-$repo/target}/release/subdlab"
fi
list="$repo/docs/figures/figures.txt"
while IFS= read -r line; do
  case "$line" in '' | '#'*) continue ;; esac
  file="${line%%:*}"
  # the arguments, with double quotes grouping (the list is ours, not user input)
  eval "set -- ${line#*:}"
  "$SUBDLAB" "$@" -o "$repo/docs/figures/$file" > /dev/null
  echo "docs/figures/$file"
done < "$list"
