#!/usr/bin/env bash
# The hysteroscopic picture over the default case and the 20-case sweep (tools/sweep-cases.py): for each scene, the
# fixed views of `bench_render --views` (the tip halfway down the canal and at a quarter, half and three quarters of
# the cavity, four rolls each; the camera's exposure settled on each) and the tubal ostia in sight from the cavity's
# middle (`validate`, as tools/scope-sweep.sh):
#     bash tools/picture-sweep.sh build/ci/bin/hysteroscene-cli build/ci/bin/bench_render /tmp/picture-sweep \
#         [WIDTHxHEIGHT] [--full | --light]
# Scenes already in OUT/scenes/<case> (with scene.json) are reused, so a second run only draws. OUT/table.txt has the
# table, OUT/<case>.views.txt each view's figures. The bench needs a display: run it under xvfb-run -a.
set -uo pipefail
if [ $# -lt 3 ] || [ $# -gt 5 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI BENCH_RENDER OUT_DIR [WIDTHxHEIGHT] [--full | --light]" >&2
    exit 2
fi
cli=$(realpath "$1")
bench=$(realpath "$2")
out=$3
size=${4:-640x480}
detail=${5:-}
here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=tools/sweep-lib.sh
source "$here/tools/sweep-lib.sh"
mkdir -p "$out/cases" "$out/scenes"
python3 "$here/tools/sweep-cases.py" "$out/cases"
cp "$here/resources/cases/default.json" "$out/cases/default.json"
printf '%-10s %7s %6s %6s %6s %9s %10s %6s %7s %7s %5s\n' case luma min max band clipped% nearWhite% fps \
    left-% right-% both > "$out/table.txt"
for c in "$out"/cases/*.json; do
    n=$(basename "$c" .json)
    if [ ! -f "$out/scenes/$n/scene.json" ]; then
        sweep_generate "$cli" "$c" "$out" "$n" || continue
    fi
    "$cli" validate --json "$out/scenes/$n" > "$out/$n.validate.json" 2>&1
    # shellcheck disable=SC2086 # the detail flag is one word or none
    "$bench" "$out/scenes/$n" --views --sizes "$size" $detail > "$out/$n.views.txt" 2>&1
    python3 - "$n" "$out/$n.views.txt" "$out/$n.validate.json" >> "$out/table.txt" <<'PY'
import json, re, sys
name, views, validate = sys.argv[1:4]
summary = [l for l in open(views) if l.startswith("views ")]
if not summary:
    print(f"{name:<10} bench_render failed: {open(views).read().strip().splitlines()[-1:]}")
    sys.exit()
m = re.search(r"luma mean ([\d.]+) min ([\d.]+) max ([\d.]+), in 0.35-0.65 (\d+); clipped max ([\d.]+) %; "
              r"near white mean ([\d.]+) %; ([\d.]+) fps", summary[0])
total = int(re.match(r"views (\d+)", summary[0]).group(1))
try:
    s = json.load(open(validate)).get("scopePassage", {})
    sight = {o["side"]: o["inSightPercent"] for o in s.get("ostia", [])}
except (ValueError, OSError):
    sight = {}
both = "yes" if len(sight) == 2 and min(sight.values()) >= 25 else "no"
fmt = lambda side: f'{sight[side]:.0f}' if side in sight else "-"
print(f"{name:<10} {m.group(1):>7} {m.group(2):>6} {m.group(3):>6} {m.group(4) + '/' + str(total):>6} "
      f"{m.group(5):>9} {m.group(6):>10} {m.group(7):>6} {fmt('left'):>7} {fmt('right'):>7} {both:>5}")
PY
done
python3 - "$out/table.txt" >> "$out/table.txt" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1]).read().splitlines()[1:] if l and "failed" not in l]
if rows:
    band = sum(int(r[4].split("/")[0]) for r in rows)
    views = sum(int(r[4].split("/")[1]) for r in rows)
    print(f"{len(rows)} scenes: {band} of {views} views with mean luma in 0.35-0.65; clipped at most "
          f"{max(float(r[5]) for r in rows):.2f} %; near white {min(float(r[6]) for r in rows):.3f}-"
          f"{max(float(r[6]) for r in rows):.3f} % (mean per scene); both ostia at least a quarter in sight in "
          f"{sum(r[10] == 'yes' for r in rows)} of {len(rows)}")
PY
cat "$out/table.txt"
