#!/usr/bin/env bash
# `npm test`: every check of the project, in the order a failure is cheapest to find.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

step() { printf '\n== %s\n' "$*"; }

step "cargo fmt --check"
cargo fmt --manifest-path wasm/Cargo.toml --all -- --check

step "cargo clippy -D warnings"
cargo clippy --manifest-path wasm/Cargo.toml --workspace --all-targets --quiet -- -D warnings

step "cargo test (native core, including FOON-111 from ../shared)"
cargo test --manifest-path wasm/Cargo.toml --workspace --quiet

step "robustness, bounded: the bad-input corpus at full size, property tests with more cases"
# The libFuzzer targets need a nightly toolchain (npm run fuzz); this is their bounded stand-in: random
# bytes, near-FOON text, random graphs and queries, random JSON through the reader, merge and planner.
FOON_HEAVY=1 PROPTEST_CASES="${FOON_PROPTEST_CASES:-512}" cargo test --manifest-path wasm/Cargo.toml -p foon-core --quiet \
  --test bad_inputs --test prop_reader --test prop_merge --test prop_plan

step "WebAssembly build"
npm run --silent build:wasm

step "tsc --noEmit"
npx tsc --noEmit

step "knowledge-base bundle (starter KB; unit tests read it too)"
npm run --silent build:kb

step "vitest (unit tests on the real WASM build)"
npx vitest run

step "recipe drafter: units right unaided on the project's recipes (docs/authoring.md)"
npm run --silent eval:draft | grep -E '^(## |units right|drafts whose)'

step "evaluation: dev queries with FOON-111 (fails on duplicated, out-of-order or dead units)"
SHARED="${FOON_SHARED:-../shared}"
npm run --silent eval -- --kb "$SHARED/foon/subgraphs-plain" --queries "$SHARED/recipes/dev" --both --quiet --out test-results/eval

step "app build (vite, starter knowledge base)"
npx vite build --logLevel warn

step "end-to-end tests (headless Chromium)"
npx vitest run --config tests/e2e/vitest.config.ts

step "end-to-end: a build bundling FOON-111 from ../shared plans a dev query"
FOON_DIR="$SHARED/foon/subgraphs-plain" npm run --silent build:kb
npx vite build --logLevel warn --outDir "$PWD/dist-foon111"
E2E_DIST=dist-foon111 npx vitest run --config tests/e2e/vitest.config.ts
npm run --silent build:kb   # back to the starter knowledge base

echo
echo "npm test: all checks passed"
