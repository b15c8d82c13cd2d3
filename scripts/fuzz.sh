#!/usr/bin/env bash
# `npm run fuzz [-- SECONDS [TARGET ...]]`: libFuzzer runs of the cargo-fuzz targets in wasm/fuzz, each for
# SECONDS (default 600), after installing what is missing (a nightly toolchain and cargo-fuzz). The seed
# corpus is built from the starter knowledge base, the bad-input corpus and the hand-made seeds in
# wasm/fuzz/seeds/; what libFuzzer adds stays in wasm/fuzz/corpus/ (not committed). A crash is saved in
# wasm/fuzz/artifacts/<target>/ and ends the run with a non-zero status: turn it into a regression test.
# Figures of each run (executions, seconds, corpus, findings) are appended to wasm/fuzz/runs.log.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

SECONDS_EACH="${1:-600}"
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=($(sed -n 's/^name = "\(.*\)"$/\1/p' wasm/fuzz/Cargo.toml | grep -v '^foon-fuzz$'))

rustup toolchain list | grep -q '^nightly' || rustup toolchain install nightly --profile minimal
command -v cargo-fuzz >/dev/null 2>&1 || cargo install cargo-fuzz --locked

bash scripts/fuzz-seeds.sh

cd wasm/fuzz
status=0
for target in "${TARGETS[@]}"; do
  printf '\n== fuzz %s for %ss\n' "$target" "$SECONDS_EACH"
  log="artifacts/$target.log"
  mkdir -p "artifacts/$target"
  set +e
  cargo +nightly fuzz run -O "$target" "corpus/$target" -- \
    -max_total_time="$SECONDS_EACH" -dict=foon.dict -max_len=16384 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 2>&1 | tee "$log" | grep -E '^#[0-9]+ +(pulse|DONE)|ERROR|panicked|Test unit written' 
  rc=${PIPESTATUS[0]}
  set -e
  runs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 \2/p' "$log" | tail -1)
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  corpus=$(ls "corpus/$target" | wc -l)
  crashes=$(ls "artifacts/$target" | grep -c -E '^(crash|timeout|oom|leak|slow-unit)-' || true)
  line="$(date -u +%FT%TZ) $target seconds=$SECONDS_EACH executions=${execs:-?} done='${runs:-?}' corpus=$corpus findings=$crashes exit=$rc"
  echo "$line" | tee -a runs.log
  [ "$rc" = 0 ] || status=1
done
exit $status
