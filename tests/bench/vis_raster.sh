#!/usr/bin/env bash
# The visibility buffer's compute rasterizer (--vis-raster; docs/visbuffer.md, "The compute
# rasterizer"): one `triptych render` process per raster mode, culling mode and MSAA, built-in
# courtyard, the visibility work's pass medians (meshlet_cull, vis_raster_clear, vis_raster,
# vis_raster_big, visibility, vis_raster_hw, vis_raster_merge), the frame and the raster_*
# counters; then `compare` for the error against the reference of each mode.
#   tests/bench/vis_raster.sh [PATH/TO/triptych] [RES] [LIGHTS] [FRAMES]
#   H200:     tests/bench/vis_raster.sh build/triptych 1920x1080 1024 9
#   lavapipe: tests/bench/vis_raster.sh build/triptych 1280x720 128 5
set -u
B=${1:-build/triptych}
RES=${2:-1920x1080}
LIGHTS=${3:-1024}
FRAMES=${4:-9}
OUT=${OUT:-/tmp/vis_raster}
mkdir -p "$OUT"
sum() { python3 - "$1" "$2" <<'PY'
import json,sys
run=json.load(open(sys.argv[1]+'/render.json'))['run']
t={x['pass']:x['median_ms'] for x in run['timings']}
c=run['counters']
passes=['meshlet_cull','vis_raster_clear','vis_raster','vis_raster_big','visibility','vis_raster_hw','vis_raster_merge']
vis=sum(t.get(p,0) for p in passes)
print('%-22s frame %7.2f  visibility work %7.2f  (%s)  %s' % (sys.argv[2], t['frame'], vis,
      ' '.join('%s %.2f'%(p,t[p]) for p in passes if p in t),
      ' '.join('%s=%d'%(k[len('raster_'):],v) for k,v in c.items() if k.startswith('raster_'))))
PY
}
go() { name=$1; shift; $B render builtin:courtyard --pipeline visbuffer --res $RES --lights $LIGHTS --frames $FRAMES --warmup 1 "$@" --out $OUT/$name >$OUT/$name.log 2>&1 || { echo "$name failed"; tail -3 $OUT/$name.log; return; }; sum $OUT/$name "$name"; }
errors() { name=$1; shift; $B compare builtin:courtyard --res $RES --lights $LIGHTS --frames 1 --warmup 0 --pipelines visbuffer "$@" --out $OUT/$name >$OUT/$name.log 2>&1; python3 - $OUT/$name "$name" <<'PY'
import json,sys
r=json.load(open(sys.argv[1]+'/report.json'))
for p in r['pipelines']:
    e=p['error_vs_reference']['tonemapped']
    print('%-22s %s psnr %.2f max %.4f' % (sys.argv[2], p['name'], e['psnr'], e['max_abs']))
PY
}
for msaa in 1 4; do
  for cull in none frustum; do
    for raster in hardware compute hybrid; do
      go ${raster}_${cull}_${msaa}x --msaa $msaa --cull-geometry $cull --vis-raster $raster
    done
  done
done
for msaa in 1 4; do
  for raster in hardware compute hybrid; do
    errors err_${raster}_${msaa}x --msaa $msaa --vis-raster $raster
  done
done
