#!/usr/bin/env bash
# Generates the default case and the 20-case sweep (tools/sweep-cases.py) with a hysteroscene-cli and lists the
# SHA-256 of every file of every scene, so that two builds can be compared byte for byte:
#     bash tools/scene-sums.sh build/ci/bin/hysteroscene-cli /tmp/after
#     diff /tmp/before/sums.txt /tmp/after/sums.txt      # no output: the same bytes
# OUT/exits.txt has each case's exit code, OUT/<case>.log its JSON report.
set -uo pipefail
if [ $# -ne 2 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI OUT_DIR" >&2
    exit 2
fi
cli=$(realpath "$1")
out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=tools/sweep-lib.sh
source "$here/tools/sweep-lib.sh"
sweep_cases "$here" "$out"
: > "$out/exits.txt"
for c in "$out"/cases/*.json; do
    n=$(basename "$c" .json)
    "$cli" generate "$c" -o "$out/scenes/$n" --threads 2 --json > "$out/$n.log" 2>&1
    echo "$n $?" >> "$out/exits.txt"
done
(cd "$out/scenes" && find . -type f | sort | xargs sha256sum) > "$out/sums.txt"
echo "scene-sums: $(wc -l < "$out/sums.txt") files; exit codes: $(awk '{print $2}' "$out/exits.txt" | sort | uniq -c | tr -s ' ' | tr '\n' ';')"
