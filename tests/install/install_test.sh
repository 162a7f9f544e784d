#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then the installed relight serves the installed
# studio client (index.html and three.js) — not the checkout's. Usage: install_test.sh BUILD RLT
set -euo pipefail
build=$1
rlt=$2
prefix=$(mktemp -d)
log="$prefix/serve.log"
server=
cleanup() {
  [[ -n "$server" ]] && kill "$server" 2>/dev/null && wait "$server" 2>/dev/null
  rm -rf "$prefix"
}
trap cleanup EXIT

cmake --install "$build" --prefix "$prefix" > "$prefix/install.log"
client="$prefix/share/relight/studio"
for f in bin/relight share/relight/studio/index.html share/relight/studio/src/main.js \
         share/relight/studio/node_modules/three/build/three.module.js; do
  [[ -f "$prefix/$f" ]] || { echo "FAIL: $f not installed"; exit 1; }
done

"$prefix/bin/relight" serve "$rlt" --port 0 > "$log" 2>&1 &
server=$!
url=
for _ in $(seq 1 300); do
  url=$(grep -o 'http://[^ ]*' "$log" | head -1 || true)
  grep -q 'client files from' "$log" && [[ -n "$url" ]] && break
  sleep 0.1
done
[[ -n "$url" ]] || { echo "FAIL: no URL"; cat "$log"; exit 1; }
grep -qF "client files from $client" "$log" || {
  echo "FAIL: the installed relight serves another client:"; cat "$log"; exit 1
}
node -e '
  const base = process.argv[1];
  const get = async (path) => {
    const r = await fetch(base + path);
    if (r.status !== 200) throw new Error(path + ": HTTP " + r.status);
    return r.text();
  };
  (async () => {
    const index = await get("");
    const three = await get("vendor/three/build/three.module.js");
    if (!index.includes("<html")) throw new Error("/ is not the studio page");
    if (three.length < 100000) throw new Error("three.module.js is short: " + three.length);
    console.log("installed client served: index.html " + index.length + " B, three.module.js " +
                three.length + " B");
  })().catch((e) => { console.error("FAIL: " + e.message); process.exit(1); });
' "$url"
