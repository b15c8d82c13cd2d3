#!/usr/bin/env bash
# `npm run build:wasm`: the planner's WebAssembly module in wasm/pkg/, for the page, the CLI and the tests.
# wasm-pack's own wasm-opt would be downloaded from the network; npm's binaryen (a dev dependency) is used
# instead, after the build: -Oz makes the module 5 % smaller again (gzip 368 -> 347 kB; 411 kB at opt-level 3 without it).
set -euo pipefail
cd "$(dirname "$0")/.."
wasm-pack build wasm/bindings --target web --profile wasm-release --no-opt --out-dir ../pkg
npx --no-install wasm-opt -Oz wasm/pkg/foon_wasm_bg.wasm -o wasm/pkg/foon_wasm_bg.wasm
