#!/usr/bin/env bash
# The visibility buffer's blended-surface benchmark on a GPU (docs/visbuffer.md, "Measured"):
# one `triptych render` process per pipeline and configuration (frame and pass medians,
# memory, the blended lists' counters), courtyard 1920x1080, 1,024 lights at 1x and 4x (fp32
# and fp16 hdr), 65,536 and 1,000,000 lights at 1x; visbuffer with --vis-blended compute and
# forward, deferred beside them; two repetitions. Then `compare` for the errors.
#   tests/bench/vis_blended_h100.sh [PATH/TO/triptych]        (default build-gpu/after/triptych)
#   source tests/bench/vis_blended_h100.sh BIN functions      (only define go, sum, errors)
set -u
B=${1:-build-gpu/after/triptych}
sum() { python3 - "$1" "$2" <<'PY'
import json,sys
r=json.load(open(sys.argv[1]+'/render.json')); run=r['run']
t={x['pass']:x['median_ms'] for x in run['timings']}
mem='%.1f MB'%(run['memory']['total_bytes']/1e6)
c=run['counters']
keys=['blended_fragments','blended_list_capacity','blended_fragments_dropped','blended_fragments_per_pixel_max','lighting_batches']
print(sys.argv[2], 'frame %.2f'%t['frame'], ' '.join('%s %.2f'%(k,v) for k,v in sorted(t.items(), key=lambda kv:-kv[1]) if k!='frame' and v>0.05), '| mem', mem, '|', {k:c[k] for k in keys if k in c})
PY
}
go() { name=$1; shift; $B render builtin:courtyard --res 1920x1080 --frames 9 --warmup 3 "$@" --out /tmp/o/$name >/tmp/o/$name.log 2>&1 || { echo "$name failed"; tail -3 /tmp/o/$name.log; return; }; sum /tmp/o/$name "$name"; }
mkdir -p /tmp/o
errors() { name=$1; shift; $B compare builtin:courtyard --res 1920x1080 --frames 1 --warmup 0 "$@" --out /tmp/o/$name >/tmp/o/$name.log 2>&1; python3 - /tmp/o/$name $name <<'PY'
import json,sys
r=json.load(open(sys.argv[1]+'/report.json'))
for p in r['pipelines']:
    e=p['error_vs_reference']['tonemapped']; c=p.get('error_vs_center_reference',{}).get('tonemapped')
    print(sys.argv[2], p['name'], 'psnr %.2f max %.4f'%(e['psnr'],e['max_abs']), ('centre psnr %.2f max %.4f'%(c['psnr'],c['max_abs']) if c else ''))
PY
}
[ "${2:-}" = functions ] && return 0
for rep in 1 2; do
for L in "1024|--lights 1024" "1024_4x|--lights 1024 --msaa 4" "1024_4x_h16|--lights 1024 --msaa 4 --hdr fp16" "65536|--lights 65536 --light-radius 0.5,1.5" "1M|--lights 1000000 --light-radius 0.1,0.3"; do
  n=${L%%|*}; a=${L#*|}
  go vis_c_$n --pipeline visbuffer $a
  go vis_f_$n --pipeline visbuffer --vis-blended forward $a
  [ $rep = 1 ] && go def_$n --pipeline deferred $a
done
done
errors c1 --lights 1024 --pipelines visbuffer,deferred
errors c1f --lights 1024 --pipelines visbuffer --vis-blended forward
errors c4 --lights 1024 --msaa 4 --pipelines visbuffer,deferred
errors c4f --lights 1024 --msaa 4 --pipelines visbuffer --vis-blended forward
errors c65 --lights 65536 --light-radius 0.5,1.5 --pipelines visbuffer
