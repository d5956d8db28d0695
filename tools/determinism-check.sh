#!/usr/bin/env bash
# Generates the default case and the 20-case sweep (tools/sweep-cases.py) twice at the same time with one
# hysteroscene-cli, the second run with glibc's MALLOC_PERTURB_ (new and freed heap memory filled with a byte
# pattern), and lists every file of a scene whose bytes differ between the two. A scene is a function of its case
# alone, so nothing should: a difference means that a stage read memory it never wrote, or depends on timing or on
# addresses (docs/build-and-test.md, "Determinism").
#     bash tools/determinism-check.sh build/ci/bin/hysteroscene-cli /tmp/determinism [ROUNDS]
# ROUNDS (default 1) repeats the whole sweep, with another pattern each round. OUT/differences.txt lists
# "round case file" per differing file; the last line says how many; exit 1 when any differ or a run failed.
set -uo pipefail
if [ $# -lt 2 ] || [ $# -gt 3 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI OUT_DIR [ROUNDS]" >&2
    exit 2
fi
cli=$(realpath "$1")
out=$2
rounds=${3:-1}
here=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=tools/sweep-lib.sh
source "$here/tools/sweep-lib.sh"
sweep_cases "$here" "$out"
: > "$out/differences.txt"
failed=0
sums() { (cd "$1" && find . -type f | sort | xargs sha256sum); }
for round in $(seq 1 "$rounds"); do
    perturb=$((37 * round % 255 + 1))
    mkdir -p "$out/r$round"
    for c in "$out"/cases/*.json; do
        n=$(basename "$c" .json)
        a="$out/r$round/$n-a" b="$out/r$round/$n-b"
        "$cli" generate "$c" -o "$a" --threads 2 > "$a.log" 2>&1 &
        MALLOC_PERTURB_=$perturb "$cli" generate "$c" -o "$b" --threads 2 > "$b.log" 2>&1
        rb=$?
        wait $!
        ra=$?
        if [ $ra -ne 0 ] || [ $rb -ne 0 ]; then
            echo "$round $n generate failed (exit $ra, $rb)" >> "$out/differences.txt"
            failed=1
            continue
        fi
        diff <(sums "$a") <(sums "$b") | awk -v r="$round" -v n="$n" '/^>/ {print r, n, $3}' >> "$out/differences.txt"
        rm -rf "$a" "$b"
    done
done
count=$(grep -vc "generate failed" "$out/differences.txt")
echo "determinism: $rounds round(s) of $(ls "$out"/cases/*.json | wc -l) cases, $count file(s) differ" |
    tee -a "$out/differences.txt"
[ "$count" -eq 0 ] && [ $failed -eq 0 ]
