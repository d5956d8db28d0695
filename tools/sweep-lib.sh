# Shared by the sweep scripts (tools/scope-sweep.sh, tools/picture-sweep.sh, tools/scene-sums.sh,
# tools/determinism-check.sh); source it, do not run it.

# sweep_cases HERE OUT_DIR: empties OUT_DIR and writes the 20-case sweep (tools/sweep-cases.py) and the default case
# into OUT_DIR/cases. HERE is the checkout's root.
sweep_cases() {
    local here=$1 out=$2
    rm -rf "$out"
    mkdir -p "$out/cases"
    python3 "$here/tools/sweep-cases.py" "$out/cases" &&
        cp "$here/resources/cases/default.json" "$out/cases/default.json"
}

# sweep_generate CLI CASE_JSON OUT_DIR NAME: generates OUT_DIR/scenes/NAME from the case (log in OUT_DIR/NAME.gen.log).
# On failure appends "NAME generate failed (exit N): <last log line>" to OUT_DIR/table.txt and returns non-zero.
sweep_generate() {
    local cli=$1 case_json=$2 out=$3 name=$4 rc
    "$cli" generate "$case_json" -o "$out/scenes/$name" --threads 2 > "$out/$name.gen.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ]; then
        printf '%-10s generate failed (exit %s): %s\n' "$name" "$rc" "$(tail -1 "$out/$name.gen.log" | cut -c1-100)" \
            >> "$out/table.txt"
    fi
    return $rc
}
