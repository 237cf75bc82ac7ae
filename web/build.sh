#!/usr/bin/env bash
# Builds the web page into web/dist/: the library compiled to WebAssembly (web/wasm), its
# JavaScript glue by wasm-bindgen, the page (web/static) and the sheets' font. Everything
# comes from the package registries: the wasm32 target by rustup, wasm-bindgen-cli by cargo
# at the version web/wasm/Cargo.lock pins, wasm-opt (binaryen) only if it is installed.
# Serve the folder with any static server, e.g. `python3 -m http.server -d web/dist 8000`.
set -euo pipefail
cd "$(dirname "$0")"
root=$(cd .. && pwd)

rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown ||
  rustup target add wasm32-unknown-unknown

# wasm-bindgen-cli must be the exact version of the wasm-bindgen crate the module links.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3 }' wasm/Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ]; then
  echo "== cargo install wasm-bindgen-cli $want"
  # Its own lock file first; the registry may lack a crate it pins, then the newest that fit.
  cargo install wasm-bindgen-cli --version "$want" --locked ||
    cargo install wasm-bindgen-cli --version "$want"
fi

echo "== cargo build (wasm32-unknown-unknown, release)"
cargo build --manifest-path wasm/Cargo.toml --release --locked --target wasm32-unknown-unknown
wasm=wasm/target/wasm32-unknown-unknown/release/tmm_web.wasm

rm -rf dist
mkdir -p dist/pkg
wasm-bindgen "$wasm" --target web --no-typescript --out-dir dist/pkg
if command -v wasm-opt >/dev/null 2>&1; then
  echo "== wasm-opt -O2"
  wasm-opt -O2 --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals dist/pkg/tmm_web_bg.wasm -o dist/pkg/tmm_web_bg.wasm
fi
cp static/* dist/
cp "$root/assets/fonts/DejaVuSansCondensed.ttf" dist/
size=$(wc -c < dist/pkg/tmm_web_bg.wasm)
gz=$(gzip -9 -c dist/pkg/tmm_web_bg.wasm | wc -c)
echo "web/dist: module $((size / 1024)) KiB ($((gz / 1024)) KiB gzipped)"
