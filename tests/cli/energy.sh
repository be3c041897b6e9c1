#!/usr/bin/env bash
# Energy per frame and --pass-statistics end to end on the default device (docs/efficiency.md):
# compare, render and sweep write each run's "energy" (joules per frame over the window, or
# null with the reason in one line), say once on stderr why when the device has no counter, and
# sweep.csv has a joules_per_frame column (empty when unknown). With --pass-statistics off the
# runs still time their frames, and the reports say the counts were not collected: no work
# counts, no efficiency (with the reason), never zeros; the viewer's stats say so too. Every
# command that times frames explains the option in its --help; a bad value is a one-line refusal.
# Runs with validation on: the layers must stay silent. Nothing asserts a speed or a wattage.
# Usage: energy.sh TRIPTYCH
set -u
bin=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$(dirname "$0")/cli_lib.sh"
small=(builtin:courtyard-small --res 64x36 --lights 4 --frames 1 --warmup 0 --validate)

for cmd in compare sweep render view; do
    run_triptych "$cmd" --help
    problem=""
    grep -q -- "--pass-statistics" "$work/stdout" || problem="no --pass-statistics in its --help"
    report "$cmd --help explains --pass-statistics" "$problem"
done

run_triptych compare "${small[@]}" --pipelines forwardplus --pass-statistics maybe --out "$work/bad"
report "--pass-statistics maybe is refused" "$(error_problem "$work/bad" "--pass-statistics" 2)"

# check_energy JSON_RUN: what is wrong with a run's "energy" object ("" if nothing).
energy_check='
def energy_problem(run, where):
    e = run.get("energy")
    if not isinstance(e, dict) or "joules_per_frame" not in e: return where + ": no energy object"
    j = e["joules_per_frame"]
    if j is None:
        if not e.get("reason") or "\n" in e["reason"]: return where + ": null without a one-line reason"
    elif not (j > 0 and e["window_ms"] > 0 and e["frames"] >= 1 and e["source"] in ("nvml", "rapl")):
        return where + ": energy " + str(e)
    return ""
'

# compare, statistics on (the default): every run has its energy, counts and a work list.
run_triptych compare "${small[@]}" --pipelines forwardplus --no-reference-cache --out "$work/on"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 -c "$energy_check
import json, sys
r = json.load(open(sys.argv[1]))
src = r['energy_source']
p = r['pipelines'][0]['run']
out = [energy_problem(r['reference']['run'], 'reference'), energy_problem(p, 'forwardplus')]
if not src['available'] and p['energy']['joules_per_frame'] is not None: out.append('a figure without a source')
if p['pass_statistics'] != {'collected': True}: out.append('pass_statistics ' + str(p['pass_statistics']))
if not isinstance(p['work'], list) or not any('pipeline_statistics' in w for w in p['work']): out.append('no counted work')
if r['settings']['pass_statistics'] != 'on': out.append('settings.pass_statistics ' + str(r['settings']['pass_statistics']))
print('; '.join(o for o in out if o))" "$work/on/report.json" 2>&1)
# The device without a counter: its reason once on stderr, as report.json has it.
if [ -z "$problem" ] && ! python3 -c "import json,sys; sys.exit(json.load(open(sys.argv[1]))['energy_source']['available'])" "$work/on/report.json"; then
    [ "$(grep -c '^triptych: energy left out: ' "$work/stderr")" -eq 1 ] || problem="no single 'energy left out' line on stderr"
fi
[ -z "$problem" ] && ! grep -q "Energy per frame" "$work/on/report.html" && problem="report.html has no energy section"
report "compare reports each run's energy per frame or why not" "$problem"

# compare with --pass-statistics off: timed, counts and efficiency left out with the reason.
run_triptych compare "${small[@]}" --pipelines forwardplus --no-reference-cache --pass-statistics off --calibration measure --out "$work/off"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
p = r['pipelines'][0]['run']
out = []
ps = p['pass_statistics']
if ps.get('collected') is not False or '--pass-statistics off' not in ps.get('reason', ''): out.append('pass_statistics ' + str(ps))
if p['work'] is not None: out.append('work is not null')
if 'efficiency' in p: out.append('efficiency without counts')
if r['calibration']['available'] or '--pass-statistics off' not in r['calibration']['why']: out.append('calibration ' + str(r['calibration']))
if not any('pipeline statistics' in l['what'] for l in p['left_out']): out.append('left_out does not list the statistics')
if 'fragment_shader_invocations' in p['counters']: out.append('a fragment count without statistics')
if r['settings']['pass_statistics'] != 'off': out.append('settings.pass_statistics')
if not p['timings'] or p['timings'][0]['median_ms'] <= 0: out.append('no frame time')
print('; '.join(out))" "$work/off/report.json" 2>&1)
[ -z "$problem" ] && ! grep -q "efficiency left out: --pass-statistics off" "$work/stderr" && problem="stderr does not say why the efficiency is left out"
report "compare --pass-statistics off times the frames and says the counts are off" "$problem"

# render: render.json likewise, and the energy line on stderr.
run_triptych render "${small[@]}" --pipeline forwardplus --pass-statistics off --out "$work/r"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 -c "$energy_check
import json, sys
r = json.load(open(sys.argv[1]))
out = [energy_problem(r['run'], 'render')]
if r['run']['pass_statistics']['collected'] is not False: out.append('pass_statistics collected')
print('; '.join(o for o in out if o))" "$work/r/render.json" 2>&1)
[ -z "$problem" ] && ! grep -Eq "J/frame|energy unknown: |^triptych: energy left out: " "$work/stderr" && problem="no energy line on stderr"
[ -z "$problem" ] && [ "$(grep -c 'energy left out: \|energy unknown: ' "$work/stderr")" -gt 1 ] && problem="the reason said twice on stderr"
report "render --pass-statistics off: render.json has the energy and says the counts are off" "$problem"

# sweep: a joules_per_frame column beside the times (empty when unknown), energy per run.
run_triptych sweep builtin:courtyard-small --res 64x36 --lights 4 --frames 1 --warmup 0 --validate --pipelines forwardplus --no-reference-cache --pass-statistics off --out "$work/s"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 -c "$energy_check
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
s = json.load(open(sys.argv[2]))
out = []
if not rows or 'joules_per_frame' not in rows[0]: out.append('no joules_per_frame column')
for row, run in zip(rows, s['runs']):
    j = run['run']['energy']['joules_per_frame']
    if (row['joules_per_frame'] == '') != (j is None): out.append('csv and json disagree: ' + row['joules_per_frame'])
    out.append(energy_problem(run['run'], row['pipeline']))
    if run['run']['pass_statistics']['collected'] is not False: out.append('pass_statistics collected')
if s['pass_statistics'] != 'off' or 'energy_source' not in s: out.append('header')
print('; '.join(o for o in out if o))" "$work/s/sweep.csv" "$work/s/sweep.json" 2>&1)
report "sweep writes joules_per_frame and each run's energy" "$problem"

# The viewer: its stats hold the render's energy and say the statistics were off.
printf 'reference off\npipeline a forwardplus\nwait\nstats s.json\n' > "$work/view.txt"
run_triptych view builtin:courtyard-small --res 64x36 --lights 4 --validate --headless --script "$work/view.txt" --pass-statistics off --out "$work/view"
problem=""
[ "$code" -ne 0 ] && problem="exit code $code"
[ -z "$problem" ] && problem=$(python3 -c "$energy_check
import json, sys
a = json.load(open(sys.argv[1]))['pipeline_a']
out = [energy_problem(a, 'view')]
if a.get('pass_statistics') != 'off': out.append('pass_statistics ' + str(a.get('pass_statistics')))
print('; '.join(o for o in out if o))" "$work/view/s.json" 2>&1)
report "view --pass-statistics off: its stats hold the energy and say the counts are off" "$problem"

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
