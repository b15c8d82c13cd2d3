#!/usr/bin/env bash
# Installs everything foon-planner needs on a fresh machine; safe to run again (skips what is present).
set -euo pipefail
cd "$(dirname "$0")/.."

WASM_BINDGEN_VERSION=0.2.130   # keep equal to the "=x.y.z" pin in wasm/bindings/Cargo.toml
export PATH="$HOME/.cargo/bin:$PATH"

step() { printf '\n== %s\n' "$*"; }

step "Rust wasm32 target"
rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown

step "wasm-pack"
command -v wasm-pack >/dev/null 2>&1 || cargo install wasm-pack --locked

step "wasm-bindgen-cli $WASM_BINDGEN_VERSION"
if ! wasm-bindgen --version 2>/dev/null | grep -q " $WASM_BINDGEN_VERSION"; then
  # no --locked: the CLI's lockfile pins a crate version the registry lacks
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --force
fi

step "Chromium (end-to-end tests)"
if [ ! -x /usr/bin/chromium ] && [ "${FOON_SKIP_CHROMIUM:-0}" != 1 ]; then
  SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq && $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
fi

step "Python venv with Fast Downward (the PDDL planner test)"
if ! .venv/bin/python -c "import unified_planning, up_fast_downward" 2>/dev/null; then
  if ! python3 -m venv --help >/dev/null 2>&1 || ! python3 -c "import ensurepip" 2>/dev/null; then
    SUDO=""; [ "$(id -u)" = 0 ] || SUDO="sudo"
    $SUDO apt-get update -qq && $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-venv >/dev/null
  fi
  python3 -m venv .venv
  .venv/bin/pip install --quiet --disable-pip-version-check -r scripts/requirements-pddl.txt
fi

step "npm packages"
if [ -f package-lock.json ]; then npm ci --no-audit --no-fund --loglevel=warn; else npm install --no-audit --no-fund --loglevel=warn; fi

step "WebAssembly build and knowledge-base bundle"
npm run build:wasm
npm run build:kb
echo "setup done"
