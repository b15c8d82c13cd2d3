#!/usr/bin/env bash
# `npm run build:wasm`: the planner's WebAssembly module in wasm/pkg/, for the page, the CLI and the tests.
# wasm-pack's own wasm-opt would be downloaded from the network; npm's binaryen (a dev dependency) is used
# instead, after the build: -Oz makes the module 5 % smaller again (gzip 368 -> 347 kB; 411 kB at opt-level 3 without it).
# A function with one caller is inlined into it only when under 50 bytes (Binaryen inlines every such function
# by default): whole phases merged into one function (the knowledge base's index, 43 kB; modification, 124 kB)
# that V8's optimising tier compiled for 110 and 160 ms of CPU during a first load and plan, on the same two
# cores. Separate, only the hot functions are optimised (TurboFan 540-590 -> 110-120 ms under Node), and the
# module compresses better (gzip 495 -> 440 kB).
set -euo pipefail
cd "$(dirname "$0")/.."
wasm-pack build wasm/bindings --target web --profile wasm-release --no-opt --out-dir ../pkg
npx --no-install wasm-opt -Oz --one-caller-inline-max-function-size=50 wasm/pkg/foon_wasm_bg.wasm -o wasm/pkg/foon_wasm_bg.wasm
