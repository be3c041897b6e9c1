# one H100 call: render per configuration (frame + pass medians, memory, blended counters)
set -u
B=build-gpu/after/triptych
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
[ "${1:-}" = functions ] && return 0
for rep in 1 2; do
for L in "1024|--lights 1024" "1024_4x|--lights 1024 --msaa 4" "1024_4x_h16|--lights 1024 --msaa 4 --hdr fp16" "65536|--lights 65536 --light-radius 0.5,1.5" "1M|--lights 1000000 --light-radius 0.1,0.3"; do
  n=${L%%|*}; a=${L#*|}
  go vis_c_$n --pipeline visbuffer $a
  go vis_f_$n --pipeline visbuffer --vis-blended forward $a
  [ $rep = 1 ] && go def_$n --pipeline deferred $a
done
done
