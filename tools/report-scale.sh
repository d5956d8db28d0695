#!/usr/bin/env bash
# The batch report at 10 000 cases (docs/batch.md, "Report"): plans a 10 000-job curriculum of light cases, runs two
# of its jobs for real (a polyp and a healthy case), gives every other job an ok record copied from the one of its
# template and a package folder that links to that job's package (the report reads records and packages only; every
# row then carries a real organ thumbnail of real size), writes the report and times it, then opens the index and a
# page of cases in headless Chromium and prints the load time of each against an empty page's:
#     bash tools/report-scale.sh build/ci/bin/hysteroscene-cli /tmp/report-scale [JOBS]
# JOBS defaults to 10000. The pages' numbers are the wall time of `chromium --headless --dump-dom` (start, load,
# script, layout, DOM serialised), the median of 3, minus the same for an empty page: what the page itself costs.
set -uo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI OUT_DIR [JOBS]" >&2
    exit 2
fi
cli=$(realpath "$1")
out=$2
jobs=${3:-10000}
here=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$out"
mkdir -p "$out"
half=$((jobs / 2))
cat >"$out/curriculum.json" <<EOF
{
    "format": "hysteroscene-curriculum",
    "schemaVersion": 1,
    "title": "Report at scale: $jobs light cases",
    "seed": 11,
    "variants": 1,
    "templates": [
        {"name": "polyp", "cases": $half, "base": "$here/tests/data/batch/light-case.json",
         "patient": {"ageYears": {"uniform": [25, 45]}},
         "pathologies": [{"id": "polyp-1", "kind": "polyp", "growthModel": "skeleton", "sizeMm": {"uniform": [6, 12]},
                          "attachment": "sessile", "location": {"oneOf": ["fundal", "posterior"]}}]},
        {"name": "healthy", "cases": $((jobs - half)), "base": "$here/tests/data/batch/light-case.json",
         "patient": {"ageYears": {"uniform": [55, 70]}, "menopausal": true}, "pathologies": []}
    ]
}
EOF
folder=$out/batch
start=$(date +%s.%N)
"$cli" batch plan "$out/curriculum.json" -o "$folder" >/dev/null || exit 1
plan_s=$(echo "$(date +%s.%N) - $start" | bc)
"$cli" batch run "$folder" --task-index 0 >/dev/null || exit 1
"$cli" batch run "$folder" --task-index "$half" >/dev/null || exit 1
python3 - "$folder" "$half" <<'EOF'
import json, os, sys
folder, half = sys.argv[1], int(sys.argv[2])
lines = [l.split('\t') for l in open(os.path.join(folder, 'manifest.tsv')).read().splitlines()[2:]]
real = {lines[0][1].rsplit('-', 2)[0]: lines[0], lines[half][1].rsplit('-', 2)[0]: lines[half]}
for index, job, case, seed, output in lines:
    template = job.rsplit('-', 2)[0]
    source = real[template]
    if job == source[1]:
        continue
    record = json.load(open(os.path.join(folder, 'status', source[1] + '.json')))
    record.update(job=job, index=int(index), seed=int(seed), output=output)
    with open(os.path.join(folder, 'status', job + '.json'), 'w') as f:
        json.dump(record, f, indent=4)
    os.symlink(os.path.join(folder, source[4]), os.path.join(folder, output))
EOF
start=$(date +%s.%N)
"$cli" batch report "$folder" >"$out/report.txt" || exit 1
report_s=$(echo "$(date +%s.%N) - $start" | bc)
echo '<!DOCTYPE html><html><body></body></html>' >"$out/empty.html"
load() { # median of 3 wall times (s) of dumping the page's DOM
    for _ in 1 2 3; do
        local t0 t1
        t0=$(date +%s.%N)
        timeout 120 chromium --headless --no-sandbox --disable-gpu --dump-dom "file://$1" >/dev/null 2>&1
        t1=$(date +%s.%N)
        echo "$t1 - $t0" | bc
    done | sort -n | sed -n 2p
}
printf '%-28s %10s %12s %10s\n' what bytes seconds "less empty"
printf '%-28s %10s %12.2f %10s\n' "plan ($jobs jobs)" - "$plan_s" -
printf '%-28s %10s %12.2f %10s\n' "batch report" - "$report_s" -
if ! command -v chromium >/dev/null; then
    echo "chromium is not installed (tools/setup.sh installs it): the pages were not opened"
    exit 0
fi
empty=$(load "$(realpath "$out/empty.html")")
printf '%-28s %10s %12.2f %10s\n' "empty page" 0 "$empty" 0
last=$(ls "$folder/report/pages" | tail -1)
for page in report.html pages/cases-0001.html "pages/$last"; do
    path=$(realpath "$folder/report/$page")
    t=$(load "$path")
    printf '%-28s %10s %12.2f %10.2f\n' "$page" "$(stat -c %s "$path")" "$t" "$(echo "$t - $empty" | bc)"
done
# The same table on one page, as the report was before it was paged.
"$cli" batch report "$folder" --rows-per-page "$jobs" >/dev/null || exit 1
path=$(realpath "$folder/report/pages/cases-0001.html")
t=$(load "$path")
printf '%-28s %10s %12.2f %10.2f\n' "one page of $jobs (before)" "$(stat -c %s "$path")" "$t" "$(echo "$t - $empty" | bc)"
csv=$folder/report/report.csv
printf '%-28s %10s\n' "report.csv" "$(stat -c %s "$csv")"
