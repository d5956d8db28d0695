#!/usr/bin/env bash
# The 18 pairs of tools/crowded-cavity.sh (a FIGO 0 or 1 myoma of 20, 24 or 28 mm on the left, fundal or posterior
# wall with a 10 mm pedunculated right cornual polyp on a 6 mm stalk) through the whole chain: one line per case with
# the FIGO type and sizes measured on the final tets and the polyp's seating (scene-format.md, "Polyp seating"), or
# the error. Maps at 256 px (the geometry is the default scene's).
#     bash tools/crowded-scenes.sh build/ci/bin/hysteroscene-cli
set -uo pipefail
if [ $# -ne 1 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI" >&2
    exit 2
fi
cli=$(realpath "$1")
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for figo in 0 1; do
    for size in 20 24 28; do
        for wall in left-lateral fundal posterior; do
            python3 - "$here/resources/cases/default.json" "$work/case.json" "$figo" "$size" "$wall" <<'PY'
import json, sys
default, out, figo, size, wall = sys.argv[1:6]
case = json.load(open(default))
case["texture"]["sizePx"] = 256
case["pathologies"] = [{"id": "myoma-1", "kind": "myoma", "growthModel": "skeleton", "sizeMm": float(size),
                        "figo": int(figo), "placement": {"location": wall}},
                       {"id": "polyp-1", "kind": "polyp", "growthModel": "skeleton", "sizeMm": 10.0,
                        "attachment": "pedunculated", "stalkLengthMm": 6.0,
                        "placement": {"location": "cornual-right"}}]
json.dump(case, open(out, "w"), indent=4)
PY
            rm -rf "$work/out"
            if "$cli" generate "$work/case.json" -o "$work/out" --threads 2 > "$work/log" 2>&1; then
                line=$(python3 -c "
import json, sys
p = json.load(open(sys.argv[1]))['clinical']['pathologies']
print('myoma FIGO %s %.1f mm; polyp %.1f mm, %.0f %% against tissue' % (p[0]['figo'], p[0]['sizeMm'], p[1]['sizeMm'],
      100 * p[1].get('tissueContactFraction', float('nan'))))" "$work/out/scene.json")
            else
                line="refused: $(tail -1 "$work/log" | sed 's/.*invalid-input: [^:]*: //' | cut -c1-110)"
            fi
            printf 'FIGO %s %2s mm %-12s %s\n' "$figo" "$size" "$wall" "$line"
        done
    done
done
