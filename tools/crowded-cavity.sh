#!/usr/bin/env bash
# The stress set of docs/pathology.md ("Known gaps"): a FIGO 0 or 1 myoma of 20, 24 or 28 mm (skeleton) on the left,
# fundal or posterior wall of the default patient, alone and with a 10 mm pedunculated right cornual polyp on a 6 mm
# stalk; one line per case with what the pathology stage measures, or its error.
#     bash tools/crowded-cavity.sh build/ci/bin/hysteroscene-cli
# With --scenes, the 18 pairs through the whole chain (maps at 256 px): the FIGO type and sizes measured on the final
# tets and the polyp's seating (scene-format.md, "Polyp seating"), or the error.
#     bash tools/crowded-cavity.sh --scenes build/ci/bin/hysteroscene-cli
set -uo pipefail
scenes=0
if [ "${1:-}" = "--scenes" ]; then
    scenes=1
    shift
fi
if [ $# -ne 1 ]; then
    echo "usage: $0 [--scenes] HYSTEROSCENE_CLI" >&2
    exit 2
fi
cli=$(realpath "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
refused=0
for figo in 0 1; do
    for size in 20 24 28; do
        for wall in left-lateral fundal posterior; do
            for with in polyp alone; do
                [ "$scenes" = 1 ] && [ "$with" = alone ] && continue
                python3 - "$here/resources/cases/default.json" "$work/case.json" "$figo" "$size" "$wall" "$with" <<'PY'
import json, sys
default, out, figo, size, wall, with_ = sys.argv[1:7]
case = json.load(open(default))
case["texture"]["sizePx"] = 256
case["pathologies"] = [{"id": "myoma-1", "kind": "myoma", "growthModel": "skeleton", "sizeMm": float(size),
                        "figo": int(figo), "placement": {"location": wall}}]
if with_ == "polyp":
    case["pathologies"].append({"id": "polyp-1", "kind": "polyp", "growthModel": "skeleton", "sizeMm": 10.0,
                                "attachment": "pedunculated", "stalkLengthMm": 6.0,
                                "placement": {"location": "cornual-right"}})
json.dump(case, open(out, "w"), indent=4)
PY
                rm -rf "$work/out"
                if [ "$scenes" = 1 ]; then
                    if "$cli" generate "$work/case.json" -o "$work/out" --threads 2 > "$work/log" 2>&1; then
                        line=$(python3 -c "
import json, sys
p = json.load(open(sys.argv[1]))['clinical']['pathologies']
print('myoma FIGO %s %.1f mm; polyp %.1f mm, %.0f %% against tissue' % (p[0]['figo'], p[0]['sizeMm'], p[1]['sizeMm'],
      100 * p[1].get('tissueContactFraction', float('nan'))))" "$work/out/scene.json")
                    else
                        refused=$((refused + 1))
                        line="refused: $(tail -1 "$work/log" | sed 's/.*invalid-input: [^:]*: //' | cut -c1-110)"
                    fi
                elif "$cli" pathology --case "$work/case.json" -o "$work/out" --json > "$work/out.json" 2> "$work/err"; then
                    line=$(python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
print('; '.join('%s %.1f mm%s, %.0f %% in the wall' % (d['id'], d['sizeMm'],
      ' FIGO ' + d['figo'] if 'figo' in d else '', 100 * d['intramuralFraction']) for d in j['descriptors'])
      + ('; %d warning(s)' % len(j['warnings']) if j['warnings'] else ''))" "$work/out.json")
                else
                    refused=$((refused + 1))
                    line="refused: $(tail -1 "$work/err" | sed 's/.*invalid-input: [^:]*: //' | cut -c1-110)"
                fi
                printf 'FIGO %s %2s mm %-12s %-5s %s\n' "$figo" "$size" "$wall" "$with" "$line"
            done
        done
    done
done
echo "refused: $refused of $([ "$scenes" = 1 ] && echo 18 || echo 36)"
