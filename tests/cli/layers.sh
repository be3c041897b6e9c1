#!/usr/bin/env bash
# The layers are one-way (docs/architecture.md, "Layers"): a file includes only what sits below
# its own folder. Checked here, on every C++ and GLSL include and every shader list:
#   core/       its folders in the declared order below; a folder includes only lower ranks
#               (same rank: neither includes the other), and never compare/, viewer/, app/ or a
#               pipeline. A new folder under core/ must be given a rank here.
#   compare/, viewer/  include core/, not each other, not app/, not a pipeline.
#   pipelines   (every top-level folder with a register.cpp) include core/, not compare/,
#               viewer/, app/ or another pipeline's folder, C++ or shaders.
#   shaders/    shaders/<pipeline>/ includes no other pipeline's shader folder (GLSL
#               `#include "x/..."`, or `../x/` in its shaders.cmake); the shared folders
#               (shaders/include, shaders/passes, the core modules' shader folders, the loose
#               files) include no pipeline's.
#   app/, tests/  nothing includes them.
# Usage: layers.sh SOURCE_DIR
set -u
cd "$1" || exit 2
fail=0

# core/'s folders, lowest first. Each line is one rank; folders on one line are beside each
# other. Derived from the code (docs/architecture.md, "Layers", says what each one is).
core_ranks=(
  "util"
  "image scene energy"
  "gpu camera"
  "renderer gpuscene"
  "calibrate lightassign"
  "passes"
  "runner reference"
  "cli"
)

# Known violations, each with its reason, one line each as "FILE|INCLUDED" (INCLUDED: the
# include's path or the shader list's relative path). None today: keep it that way.
allowlist=()
used_allow=""

cpp=(--include='*.cpp' --include='*.h')
glsl=(--include='*.h' --include='*.glsl' --include='*.comp' --include='*.frag' --include='*.vert')

# report WHY HITS: HITS are grep -n lines "FILE:LINE:TEXT"; those the allowlist names pass.
report() {
  local why=$1 hits=$2 line file text entry bad=""
  while IFS= read -r line; do
    [ -z "$line" ] && continue
    file=${line%%:*}
    text=${line#*:*:}
    for entry in "${allowlist[@]}"; do
      if [ "$file" = "${entry%%|*}" ] && [[ "$text" == *"${entry#*|}"* ]]; then
        used_allow+="$entry"$'\n'
        continue 2
      fi
    done
    bad+="$line"$'\n'
  done <<<"$hits"
  if [ -n "$bad" ]; then echo "$why:"; printf '%s' "$bad"; fail=1; fi
}

# forbid WHO KIND WHAT...: no file under WHO (a folder or a file) includes a path under any
# folder WHAT; KIND is cpp or glsl (which files are looked at).
forbid() {
  local who=$1 kind=$2; shift 2
  local -n exts=$kind
  for what in "$@"; do
    [ -e "$who" ] || continue
    report "$who includes $what/ (a layer above it or beside it)" \
      "$(grep -rIn "${exts[@]}" "#include \"$what/" "$who")"
  done
}

pipelines=$(for reg in */register.cpp; do dirname "$reg"; done)

# core/: the declared order.
declare -A rank
for r in "${!core_ranks[@]}"; do
  for folder in ${core_ranks[$r]}; do rank[$folder]=$r; done
done
for dir in core/*/; do
  x=$(basename "$dir")
  if [ -z "${rank[$x]+set}" ]; then
    echo "core/$x/ has no rank in layers.sh (core_ranks): place it in the order"; fail=1; continue
  fi
  for y in "${!rank[@]}"; do
    [ "$y" = "$x" ] && continue
    if [ "${rank[$y]}" -ge "${rank[$x]}" ]; then
      report "core/$x/ includes core/$y/ (rank ${rank[$y]}, not below its own ${rank[$x]})" \
        "$(grep -rIn "${cpp[@]}" "#include \"core/$y/" "core/$x")"
    fi
  done
done
forbid core cpp compare viewer app tests $pipelines

# compare/'s rooms, lowest first (docs/architecture.md, "Rooms inside compare/"): a room
# includes only the rooms below it; a new room or a loose file must be placed.
compare_rooms=(cache measure report commands)
for r in "${!compare_rooms[@]}"; do
  x=${compare_rooms[$r]}
  [ -d "compare/$x" ] || { echo "compare/$x/ is in compare_rooms but not in the tree"; fail=1; continue; }
  for y in "${compare_rooms[@]:$r}"; do
    [ "$y" = "$x" ] && continue
    report "compare/$x/ includes compare/$y/ (a room above it)" \
      "$(grep -rIn "${cpp[@]}" "#include \"compare/$y/" "compare/$x")"
  done
done
for f in compare/*; do
  [[ " ${compare_rooms[*]} " == *" $(basename "$f") "* ]] ||
    { echo "$f is in no room of compare/ (compare_rooms in layers.sh)"; fail=1; }
done

# The front ends and the composition root.
forbid compare cpp viewer app tests $pipelines
forbid viewer cpp compare app tests $pipelines
forbid app cpp tests

# Pipelines: none includes another (its C++ folder or its shaders), nor a front end.
for p in $pipelines; do
  others=$(for q in $pipelines; do [ "$q" != "$p" ] && echo "$q"; done)
  forbid "$p" cpp compare viewer app tests $others
done

# Shaders: a folder of shaders/ may include only its own pipeline's folder, never another's.
for f in shaders/*; do
  owner=$(basename "$f")
  others=$(for q in $pipelines; do [ "$q" != "$owner" ] && echo "$q"; done)
  forbid "$f" glsl $others
  if [ -d "$f" ]; then
    for q in $others; do
      report "$f/ compiles a shader of shaders/$q/ (a pipeline beside it)" \
        "$(grep -rIn --include='*.cmake' --include='CMakeLists.txt' "\.\./$q/" "$f")"
    done
  fi
done

for entry in "${allowlist[@]}"; do
  grep -qxF "$entry" <<<"$used_allow" ||
    echo "note: allowlist entry '$entry' matches nothing any more: remove it from layers.sh"
done
if [ $fail = 0 ]; then
  echo "layers one-way: core/ ($(echo "${core_ranks[@]}" | wc -w) folders in ${#core_ranks[@]} ranks) < compare/ (${#compare_rooms[@]} rooms), viewer/ < app/;" \
       "$(echo $pipelines | wc -w) pipelines beside one another, C++ and shaders (${#allowlist[@]} allowed, listed)"
fi
exit $fail
