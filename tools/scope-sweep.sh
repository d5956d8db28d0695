#!/usr/bin/env bash
# Generates the default case and the 20-case sweep (tools/sweep-cases.py) with a hysteroscene-cli and prints, per
# scene, the scope passage that `validate` measures (docs/scene-format.md, "Scope passage") and how much of each tubal
# ostium is in sight from the cavity's middle (a dash: the ostium has no faces, a pathology covers it; hidden-by: what
# hides an ostium less than a quarter in sight, the pathology's id or the wall):
#     bash tools/scope-sweep.sh build/ci/bin/hysteroscene-cli /tmp/scope-sweep [SCOPE_DIAMETER_MM]
# OUT/table.txt has the table; OUT/<case>.gen.log and OUT/<case>.validate.json the reports. A case that fails to
# generate is listed with its exit code.
set -uo pipefail
if [ $# -lt 2 ] || [ $# -gt 3 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI OUT_DIR [SCOPE_DIAMETER_MM]" >&2
    exit 2
fi
cli=$(realpath "$1")
out=$2
diameter=${3:-2.9}
here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=tools/sweep-lib.sh
source "$here/tools/sweep-lib.sh"
sweep_cases "$here" "$out"
printf '%-10s %8s %-12s %8s %6s %9s %-12s %6s %9s %7s %7s %s\n' case canal-mm part along-mm fits fundus-mm part fits \
    straight-mm left-% right-% hidden-by > "$out/table.txt"
for c in "$out"/cases/*.json; do
    n=$(basename "$c" .json)
    sweep_generate "$cli" "$c" "$out" "$n" || continue
    "$cli" validate --json --scope-diameter "$diameter" "$out/scenes/$n" > "$out/$n.validate.json" 2>&1
    python3 - "$n" "$out/$n.validate.json" >> "$out/table.txt" <<'PY'
import json, sys
name, path = sys.argv[1], sys.argv[2]
j = json.load(open(path))
s = j.get("scopePassage", {})
if not s.get("checked"):
    print(f"{name:<10} not checked: {j.get('warnings', [{}])[0].get('detail', j.get('error'))}")
    sys.exit()
c, f, t = s["canal"], s["toFundus"], s["straightStretch"]
yes = lambda b: "yes" if b else "no"
sight = {o["side"]: f'{o["inSightPercent"]:.0f}' for o in s.get("ostia", [])}
hidden = sorted({h for o in s.get("ostia", []) if o["inSightPercent"] < 25 for h in o["hiddenBy"][:1]})
print(f"{name:<10} {c['narrowest']['widthMm']:8.2f} {c['narrowest']['part']:<12} {c['narrowest']['arcLengthMm']:8.1f} "
      f"{yes(c['passes']):>6} {f['narrowest']['widthMm']:9.2f} {f['narrowest']['part']:<12} {yes(f['passes']):>6} "
      f"{t['widthMm']:9.2f} {sight.get('left', '-'):>7} {sight.get('right', '-'):>7} {','.join(hidden) or '-'}")
PY
done
cat "$out/table.txt"
