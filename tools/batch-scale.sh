#!/usr/bin/env bash
# A local batch at scale (docs/batch.md, "A 1 000-case local run"): plans JOBS light cases (the light base case:
# 3000-vertex meshes, 256 px maps; polyps, FIGO 1-2 myomas and postmenopausal uteri in equal parts), runs them with
# the local runner (--jobs N, the default limits), then measures what a batch user meets next: a resume with every
# job done, five case files edited and run again (exactly those five regenerate), and the report. Prints one table:
#     bash tools/batch-scale.sh build/ci/bin/hysteroscene-cli /tmp/batch-scale [JOBS] [N]
# JOBS defaults to 1000, N to 2. The executable is copied first, so that rebuilding it does not change a running
# batch.
set -uo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI OUT_DIR [JOBS] [N]" >&2
    exit 2
fi
here=$(cd "$(dirname "$0")/.." && pwd)
out=$2
jobs=${3:-1000}
parallel=${4:-2}
rm -rf "$out"
mkdir -p "$out"
cp "$1" "$out/hysteroscene-cli"
cli=$(realpath "$out/hysteroscene-cli")
third=$((jobs / 3))
base=$here/tests/data/batch/light-case.json
cat >"$out/curriculum.json" <<EOF
{
    "format": "hysteroscene-curriculum",
    "schemaVersion": 1,
    "title": "A local batch at scale: $jobs light cases",
    "seed": 2026,
    "variants": 1,
    "templates": [
        {"name": "polyp", "cases": $third, "base": "$base",
         "patient": {"ageYears": {"uniform": [25, 50]}, "parity": {"oneOf": [0, 1, 2]}, "gravidity": {"uniform": [2, 4]}},
         "pathologies": [{"id": "polyp-1", "kind": "polyp", "growthModel": "skeleton", "sizeMm": {"uniform": [6, 12]},
                          "attachment": "sessile", "location": {"oneOf": ["fundal", "posterior", "anterior"]}}]},
        {"name": "myoma", "cases": $third, "base": "$base",
         "patient": {"ageYears": {"uniform": [30, 50]}, "parity": {"oneOf": [1, 2]}, "gravidity": {"uniform": [2, 4]}},
         "pathologies": [{"id": "myoma-1", "kind": "myoma", "growthModel": "skeleton", "sizeMm": {"uniform": [12, 20]},
                          "figo": {"oneOf": [1, 2]}, "location": {"oneOf": ["left-lateral", "right-lateral", "fundal"]}}]},
        {"name": "postmenopausal", "cases": $((jobs - 2 * third)), "base": "$base",
         "patient": {"ageYears": {"uniform": [55, 70]}, "menopausal": true}, "pathologies": []}
    ]
}
EOF
folder=$out/batch
"$cli" batch plan "$out/curriculum.json" -o "$folder" >/dev/null || exit 1
now() { date +%s.%N; }
t0=$(now)
"$cli" batch run "$folder" --jobs "$parallel" --json >"$out/run.json" 2>"$out/run.log"
t1=$(now)
"$cli" batch run "$folder" --jobs "$parallel" --json >"$out/resume.json" 2>/dev/null
t2=$(now)
# Five cases edited by hand: their jobs, and only those, run again.
python3 - "$folder" <<'EOF'
import json, os, re, sys
folder = sys.argv[1]
cases = sorted(os.listdir(os.path.join(folder, 'cases')))[:5]
for name in cases:
    path = os.path.join(folder, 'cases', name)
    text = open(path).read()
    text = re.sub(r'"heightCm": [0-9.]+', '"heightCm": 171.0', text, count=1)
    open(path, 'w').write(text)
EOF
"$cli" batch run "$folder" --jobs "$parallel" --json >"$out/edited.json" 2>/dev/null
t3=$(now)
"$cli" batch status "$folder" --json >"$out/status.json"
"$cli" batch report "$folder" --json >"$out/report.json"
t4=$(now)
"$cli" batch report "$folder" --json >/dev/null
t5=$(now)
disk=$(du -sb "$folder/packages" | cut -f1)
python3 - "$out" "$jobs" "$parallel" "$disk" "$t0" "$t1" "$t2" "$t3" "$t4" "$t5" <<'EOF'
import json, os, sys
out, jobs, parallel, disk = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
t = [float(x) for x in sys.argv[5:]]
run, resume, edited = (json.load(open(os.path.join(out, f))) for f in ('run.json', 'resume.json', 'edited.json'))
status = json.load(open(os.path.join(out, 'status.json')))
folder = os.path.join(out, 'batch', 'status')
records = [json.load(open(os.path.join(folder, f))) for f in os.listdir(folder) if f.endswith('.json')]
ok = [r for r in records if r['state'] == 'ok']
peak = max(r['peakMemoryMb'] for r in records)
mean = sum(r['seconds'] for r in ok) / max(len(ok), 1)
packages = len(ok)
rows = [
    ('jobs', '%d (%d at a time)' % (jobs, parallel)),
    ('ok / failed', '%d / %d' % (run['ok'], run['failed'])),
    ('wall time', '%.0f s' % (t[1] - t[0])),
    ('scenes/hour', '%.0f' % run['scenesPerHour']),
    ('seconds per job (mean of ok)', '%.1f' % mean),
    ('peak resident memory of a job', '%.0f MiB' % peak),
    ('disk, packages', '%.2f GB (%.1f MB a package)' % (disk / 1e9, disk / 1e6 / max(packages, 1))),
    ('resume, every job done', '%.1f s (%d already done, %d run)' % (t[2] - t[1], resume['alreadyDone'],
                                                                     resume['ok'] + resume['failed'])),
    ('5 cases edited, run again', '%.1f s (%d run: %s)' % (t[3] - t[2], edited['ok'] + edited['failed'],
                                                            ', '.join(sorted(set(r['reason'] for r in edited['rerunJobs']))))),
    ('batch report (first, thumbnails drawn)', '%.1f s' % (t[4] - t[3])),
    ('batch report (again, thumbnails kept)', '%.1f s' % (t[5] - t[4])),
]
for key, value in rows:
    print('%-40s %s' % (key, value))
failures = {}
for r in records:
    if r['state'] != 'ok':
        failures[r['error']['code']] = failures.get(r['error']['code'], 0) + 1
for code, n in sorted(failures.items()):
    print('%-40s %d' % ('failed: ' + code, n))
EOF
