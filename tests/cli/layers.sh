#!/usr/bin/env bash
# The layers are one-way (docs/architecture.md, "Layers"): app/ (the composition root) may
# include everything; compare/ and viewer/ include core/ and not each other; core/ includes
# neither, nor any pipeline folder; nothing includes app/. Usage: layers.sh SOURCE_DIR
set -u
cd "$1" || exit 2
fail=0
# forbid WHO WHAT...: no file under WHO includes a header under any folder WHAT.
forbid() {
  local who=$1; shift
  for what in "$@"; do
    hits=$(grep -rIn --include='*.cpp' --include='*.h' "#include \"$what/" "$who")
    if [ -n "$hits" ]; then echo "$who/ includes $what/ (a layer above it or beside it):"; echo "$hits"; fail=1; fi
  done
}
pipelines=$(for reg in */register.cpp; do dirname "$reg"; done)
forbid core compare viewer app $pipelines
forbid compare viewer app $pipelines
forbid viewer compare app $pipelines
[ $fail = 0 ] && echo "layers one-way: core/ < compare/, viewer/ < app/ ($(echo $pipelines | wc -w) pipelines beside them)"
exit $fail
