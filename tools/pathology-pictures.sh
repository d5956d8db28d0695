#!/usr/bin/env bash
# Renders the pictures of docs/pathology.md (docs/images/pathology-{skeleton,ca,particles,polyps}.png) with the built
# CLI and render_surfaces: every growth model x FIGO type (20 mm posterior myoma) and the 12 mm polyps, in the default
# patient, each titled with what the geometry measures. Usage: bash tools/pathology-pictures.sh [BUILD_DIR] [OUT_DIR]
# (defaults build/ci and docs/images). Needs xvfb-run. MODELS, FIGOS and ATTS narrow the set.
set -u
cd "$(dirname "$0")/.."
BIN="${1:-build/ci}/bin"
OUT="${2:-docs/images}"
CLI=$BIN/hysteroscene-cli
RENDER=$BIN/render_surfaces
DEFAULT=resources/cases/default.json
P=$(mktemp -d)
trap 'rm -rf "$P"' EXIT
mkdir -p $P/cases $P/out $P/json $P/log "$OUT"
: > $P/log/failures.txt

# case NAME MODEL KIND SIZE FIGO|- LOCATION ATTACHMENT|- STALK|-   -> writes $P/cases/NAME.json
mkcase() {
python3 - "$@" "$DEFAULT" "$P" <<'PY'
import json, sys
name, model, kind, size, figo, loc, att, stalk = sys.argv[1:9]
c = json.load(open(sys.argv[9]))
p = {"id": "myoma-1" if kind == "myoma" else "polyp-1", "kind": kind, "growthModel": model,
     "sizeMm": float(size), "placement": {"location": loc}}
if figo != '-':
    p["figo"] = int(figo) if figo.isdigit() else figo
if att != '-':
    p["attachment"] = att
if stalk != '-':
    p["stalkLengthMm"] = float(stalk)
c["pathologies"] = [p]
json.dump(c, open(sys.argv[10] + '/cases/%s.json' % name, 'w'), indent=4)
PY
}

# run NAME -> grows $P/out/NAME, manifest JSON in $P/json/NAME.json; returns the CLI's exit code
run() {
    rm -rf "$P/out/$1"
    "$CLI" pathology --case "$P/cases/$1.json" -o "$P/out/$1" --json > "$P/json/$1.json" 2> "$P/log/$1.err"
    local rc=$?
    if [ $rc -ne 0 ]; then
        echo "$1: exit $rc: $(cat "$P/log/$1.err") $(cat "$P/json/$1.json")" >> $P/log/failures.txt
    fi
    return $rc
}

# myoma title from the descriptors: "asked F: FIGO f\nS mm, P % in wall\nLasmar L"
myoma_title() {
python3 - "$1" "$2" <<'PY'
import json, sys
asked, path = sys.argv[1:3]
d = json.load(open(path))["descriptors"][0]
print("asked %s: FIGO %s\n%.1f mm, %.0f %% in wall\nLasmar %d" % (
    asked, d["figo"], d["sizeMm"], 100 * d["intramuralFraction"], d["lasmar"]["total"]))
PY
}

# polyp title: "LABEL\nS mm, base B mm\nmeasured sessile | pedunc., stalk T mm"
polyp_title() {
python3 - "$1" "$2" <<'PY'
import json, sys
label, path = sys.argv[1:3]
d = json.load(open(path))["descriptors"][0]
third = ("pedunc., stalk %.1f mm" % d["stalkLengthMm"]) if d["pedunculated"] else "measured sessile"
print("%s\n%.1f mm, base %.1f mm\n%s" % (label, d["sizeMm"], d["baseWidthMm"], third))
PY
}

FIGOS="${FIGOS:-0 1 2 3 4 5 6 7 2-5}"
for model in ${MODELS:-skeleton ca particles}; do
    args=()
    for f in $FIGOS; do
        name=myoma-$model-$f
        mkcase $name $model myoma 20 $f posterior - -
        if run $name; then
            args+=("$P/out/$name/wall.vtp+$P/out/$name/myoma-1.vtp" "$(myoma_title $f $P/json/$name.json)")
        else
            echo "FAILED $name (see $P/log/failures.txt)"
        fi
    done
    xvfb-run -a "$RENDER" $OUT/pathology-$model.png --sagittal --size 200 300 "${args[@]}"
done

args=()
for model in skeleton particles; do
    short=$model; [ $model = particles ] && short=particle
    for att in ${ATTS:-sessile pedunculated}; do
        for loc in posterior fundal; do
            stalk=-; [ $att = pedunculated ] && stalk=8
            name=polyp-$model-$att-$loc
            mkcase $name $model polyp 12 - $loc $att $stalk
            label="$short ${att:0:5}. ${loc:0:4}."
            if run $name; then
                args+=("$P/out/$name/wall.vtp+$P/out/$name/polyp-1.vtp" "$(polyp_title "$label" $P/json/$name.json)")
            else
                echo "FAILED $name (see $P/log/failures.txt)"
            fi
        done
    done
done
xvfb-run -a "$RENDER" $OUT/pathology-polyps.png --sagittal --size 210 300 "${args[@]}"
echo "failures:"; cat $P/log/failures.txt
