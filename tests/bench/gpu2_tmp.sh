set -u
source tests/bench/vis_blended_h100.sh functions
for rep in 1 2; do
  go vis_c_1024 --pipeline visbuffer --lights 1024
  go vis_c_1M --pipeline visbuffer --lights 1000000 --light-radius 0.1,0.3
done
cmp() { name=$1; shift; $B compare builtin:courtyard --res 1920x1080 --frames 1 --warmup 0 "$@" --out /tmp/o/$name >/tmp/o/$name.log 2>&1; python3 - /tmp/o/$name $name <<'PY'
import json,sys
r=json.load(open(sys.argv[1]+'/report.json'))
for p in r['pipelines']:
    e=p['error_vs_reference']['tonemapped']; c=p.get('error_vs_center_reference',{}).get('tonemapped')
    print(sys.argv[2], p['name'], 'psnr %.2f max %.4f'%(e['psnr'],e['max_abs']), ('centre psnr %.2f max %.4f'%(c['psnr'],c['max_abs']) if c else ''))
PY
}
cmp c1 --lights 1024 --pipelines visbuffer,deferred
cmp c1f --lights 1024 --pipelines visbuffer --vis-blended forward
cmp c4 --lights 1024 --msaa 4 --pipelines visbuffer,deferred
cmp c4f --lights 1024 --msaa 4 --pipelines visbuffer --vis-blended forward
cmp c65 --lights 65536 --light-radius 0.5,1.5 --pipelines visbuffer
build-gpu/after/triptych_gpu_tests --gtest_filter='Visbuffer*:Stress*' 2>&1 | grep -E "^\[  (PASSED|FAILED) |OK \]|FAILED  \]|visbuffer \]|Failure|actual" | head -40
