#!/usr/bin/env bash
# A pipeline is a plug-in: outside its own folder (and the tests), no source file compares
# against or spells its name as a string. Pipelines are the top-level folders with a
# register.cpp; their name is the folder's name. Usage: no_pipeline_names.sh SOURCE_DIR
set -u
cd "$1" || exit 2
fail=0
for reg in */register.cpp; do
  name=$(dirname "$reg")
  hits=$(grep -rIn --include='*.cpp' --include='*.h' --include='*.glsl' --include='*.comp' \
           --include='*.frag' --include='*.vert' "\"$name\"" core compare shaders viewer | grep -v "^shaders/$name/")
  if [ -n "$hits" ]; then echo "pipeline name \"$name\" spelled outside $name/:"; echo "$hits"; fail=1; fi
done
[ $fail = 0 ] && echo "no pipeline name outside its folder ($(ls */register.cpp | wc -l) pipelines)"
exit $fail
