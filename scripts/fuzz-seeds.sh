#!/usr/bin/env bash
# Builds the fuzz seed corpora in wasm/fuzz/corpus/<target>/ (not committed): the starter knowledge base,
# the small files of the bad-input corpus, and the hand-made seeds in wasm/fuzz/seeds/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."
reader=wasm/fuzz/corpus/foon_reader
mkdir -p "$reader"
cp -n public/kb/starter/*.txt wasm/fuzz/seeds/foon_reader/* "$reader"/
find tests/data/bad-inputs -type f -size -16k ! -name '*.tsv' ! -name '*.md' ! -name '.*' -exec cp -n {} "$reader"/ \;
# plan requests: the public recipe queries of ../shared (read there, never committed)
shared="${FOON_SHARED:-../shared}/recipes/dev"
if [ -d "$shared" ]; then
  mkdir -p wasm/fuzz/corpus/plan_request
  for dish in "$shared"/*/; do find "$dish" -name "*.json" | sort | head -n 40; done | while read -r q; do
    printf '{"query": %s}' "$(cat "$q")" > "wasm/fuzz/corpus/plan_request/$(basename "$q")"
  done
fi
for dir in wasm/fuzz/seeds/*/; do
  target=$(basename "$dir")
  mkdir -p "wasm/fuzz/corpus/$target"
  cp -n "$dir"* "wasm/fuzz/corpus/$target"/ 2>/dev/null || true
done
echo "fuzz seeds: $(for d in wasm/fuzz/corpus/*/; do printf '%s=%s ' "$(basename "$d")" "$(ls "$d" | wc -l)"; done)"
