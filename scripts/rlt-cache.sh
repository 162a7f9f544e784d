# Sourced by the benchmark scripts: whether a cached .rlt must be precomputed again.
# needs_precompute SCENE.json FILE.rlt: true when FILE.rlt is missing, older than the scene, or
# of another format version than this checkout's (bytes 8-11, docs/rlt-format.md "Versioning").
needs_precompute() {
  local scene=$1 rlt=$2 ours
  [[ -f "$rlt" && ! "$scene" -nt "$rlt" ]] || return 0
  ours=$(sed -n 's/.*kRltFormatVersion = \([0-9]*\);.*/\1/p' src/store/rlt_format.h)
  [[ $(od -An -tu4 -j8 -N4 "$rlt" | tr -d ' ') != "$ours" ]]
}
