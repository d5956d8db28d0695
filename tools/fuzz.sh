#!/usr/bin/env bash
# Fuzzing campaign: builds the `fuzz` preset (clang, libFuzzer, ASan + UBSan), runs every harness of tests/fuzz
# for SECONDS (or until HS_FUZZ_RUNS executions), collects crashing inputs, and prints executions, coverage and time
# per harness. Then, unless --no-asan, builds the `asan` preset and runs the pipeline and CLI tests under it.
#
#   tools/fuzz.sh [--no-asan] [SECONDS] [HARNESS...]
#
# Environment: HS_FUZZ_RUNS (stop a harness after this many executions; default: time only), HS_FUZZ_PARALLEL
# (harnesses at a time, default 2), HS_FUZZ_JOBS (build jobs, default 2), HS_FUZZ_NO_BUILD (use the harnesses
# already built), HS_FUZZ_REPORT_ONLY (print the table of the last runs of every harness, run nothing), HS_FUZZ_CLI (a hysteroscene-cli that makes
# generated seeds; default build/ci or build/release when present).
# Output: build/fuzz/campaign/<harness>/{corpus,crashes,log.txt} and build/fuzz/campaign/summary.txt.
# A crash: the input is in crashes/; replay it with build/fuzz/bin/fuzz_<harness> FILE, fix the reader, and commit
# the input under tests/data/fuzz-regressions/<harness>/ (test_fuzz_replay then replays it in every build).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
asan=1
if [[ "${1:-}" == "--no-asan" ]]; then
    asan=0
    shift
fi
seconds="${1:-60}"
shift || true
jobs="${HS_FUZZ_JOBS:-2}"
parallel="${HS_FUZZ_PARALLEL:-2}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

selected=("$@")
report_only="${HS_FUZZ_REPORT_ONLY:-}"
[[ -n "$report_only" ]] && asan=0
cmake --preset fuzz "${launcher[@]}" >/dev/null
if [[ -z "${HS_FUZZ_NO_BUILD:-}" && -z "$report_only" ]]; then
    if ((${#selected[@]})); then
        cmake --build build/fuzz -j "$jobs" --target "${selected[@]/#/fuzz_}"
    else
        cmake --build --preset fuzz -j "$jobs"
    fi
fi

build="$root/build/fuzz"
campaign="$build/campaign"
seeds="$campaign/generated-seeds"
mkdir -p "$campaign"

# Generated seeds: the committed mesh fixtures converted by the CLI into every other format it writes (binary STL
# and PLY, VTP, VTU, MSH, MEDIT, OFF), the bundled case, curricula and exemplars. Not committed: they are made again
# on every campaign. Scene packages the CLI generates are megabytes (the visual surface); the package harnesses use
# the small committed ones instead.
make_seeds() {
    [[ -n "$report_only" ]] && return
    local cli="${HS_FUZZ_CLI:-}"
    [[ -z "$cli" && -x build/ci/bin/hysteroscene-cli ]] && cli=build/ci/bin/hysteroscene-cli
    [[ -z "$cli" && -x build/release/bin/hysteroscene-cli ]] && cli=build/release/bin/hysteroscene-cli
    rm -rf "$seeds"
    mkdir -p "$seeds"/{mesh_obj,mesh_stl,mesh_ply,mesh_off,mesh_vtp,mesh_vtu,mesh_msh,mesh_medit,case,exemplar,curriculum}
    cp resources/exemplars/*.png "$seeds/exemplar/"
    cp resources/curricula/*.json tests/data/batch/*.json "$seeds/curriculum/"
    cp resources/cases/*.json "$seeds/case/"
    if [[ -z "$cli" ]]; then
        echo "no hysteroscene-cli built (build/ci or build/release): committed and bundled seeds only"
        return
    fi
    local surface tets ext
    for surface in tests/data/io/quad-cube.obj tests/data/io/labelled-tetrahedron.ply; do
        for ext in obj stl ply off vtp vtu; do
            "$cli" convert "$surface" "$seeds/mesh_$ext/$(basename "${surface%.*}").$ext" >/dev/null 2>&1 || true
        done
    done
    for tets in tests/data/io/two-regions.msh tests/data/io/two-regions.mesh; do
        for ext in vtu msh mesh; do
            local dir="mesh_$ext"
            [[ "$ext" == mesh ]] && dir=mesh_medit
            "$cli" convert "$tets" "$seeds/$dir/$(basename "${tets%.*}")-${tets##*.}.$ext" >/dev/null 2>&1 || true
        done
    done
}
make_seeds

# One harness: fresh working corpus from the committed one (plus generated seeds), then libFuzzer.
run_harness() {
    local name="$1" dict="$2"
    local dir="$campaign/$name"
    rm -rf "$dir"
    mkdir -p "$dir/corpus" "$dir/crashes"
    local args=(-max_total_time="$seconds" -print_final_stats=1 -timeout=30 -rss_limit_mb=2560 -max_len=262144
                -artifact_prefix="$dir/crashes/" -close_fd_mask=3)
    [[ -n "${HS_FUZZ_RUNS:-}" ]] && args+=(-runs="$HS_FUZZ_RUNS")
    [[ "$dict" != "-" ]] && args+=(-dict="tests/fuzz/dict/$dict")
    local inputs=("$dir/corpus" "tests/fuzz/corpus/$name")
    [[ -d "tests/data/fuzz-regressions/$name" ]] && inputs+=("tests/data/fuzz-regressions/$name")
    [[ -d "$seeds/$name" ]] && inputs+=("$seeds/$name")
    local start end
    start=$(date +%s)
    # Leaks inside libraries the project cannot fix are suppressed (tests/fuzz/lsan.supp); matching OpenImageIO's
    # needs full allocation stacks (its frames have no frame pointers), which cost speed, so only for its harness.
    # Where a library keeps memory between calls (caches, HDF5's free lists, VTK's singletons) libFuzzer's check
    # after each input finds more allocations than frees nearly every time and scans the whole heap for leaks, which
    # took 80 % of those harnesses' time: there, -detect_leaks=0 turns that per-input check off and LeakSanitizer
    # checks the whole process when the run ends (a leak in any execution is still reported, without the input).
    local asan_options="${ASAN_OPTIONS:-}"
    case "$name" in
    exemplar)
        asan_options="fast_unwind_on_malloc=0${asan_options:+:$asan_options}"
        args+=(-detect_leaks=0)
        ;;
    shape_model)
        # HDF5 sizes its metadata cache entries by the file and answers a failed allocation with an error: malloc
        # returns null for an impossible size here as it does outside ASan (a null then dereferenced still stops the
        # run). Input: shape_model/huge-metadata-cache-entry.
        asan_options="allocator_may_return_null=1${asan_options:+:$asan_options}"
        args+=(-detect_leaks=0)
        ;;
    mesh_vtp | mesh_vtu | package_folder | package_zip)
        args+=(-detect_leaks=0)
        ;;
    esac
    TMPDIR=/dev/shm ASAN_OPTIONS="$asan_options" LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp" \
        "$build/bin/fuzz_$name" "${args[@]}" "${inputs[@]}" >"$dir/log.txt" 2>&1 || true
    end=$(date +%s)
    echo "$((end - start))" >"$dir/seconds"
}

mapfile -t lines <"$build/tests/fuzz/harnesses.txt"
running=0
for line in "${lines[@]}"; do
    [[ -z "$line" ]] && continue
    read -r name dict <<<"$line"
    if ((${#selected[@]})) && [[ ! " ${selected[*]} " == *" $name "* ]]; then
        continue
    fi
    [[ -n "$report_only" ]] && continue
    if [[ ! -x "$build/bin/fuzz_$name" ]]; then
        echo "$name: not built (build/fuzz/bin/fuzz_$name), skipped"
        continue
    fi
    echo "fuzzing $name for up to ${seconds}s${HS_FUZZ_RUNS:+ or $HS_FUZZ_RUNS executions}"
    run_harness "$name" "$dict" &
    running=$((running + 1))
    if ((running >= parallel)); then
        wait -n
        running=$((running - 1))
    fi
done
wait

# The table: executions (libFuzzer's stat::number_of_executed_units), coverage (cov: edges, ft: features of its
# last status line), time, crashes (inputs in crashes/, and whether the log reports a sanitizer error or a leak).
{
    printf "%-16s %12s %9s %7s %7s %7s %8s %8s\n" harness executions "exec/s" cov ft corpus seconds crashes
    for line in "${lines[@]}"; do
        read -r name dict <<<"$line"
        dir="$campaign/$name"
        [[ -f "$dir/log.txt" ]] || continue
        if ((${#selected[@]})) && [[ ! " ${selected[*]} " == *" $name "* ]]; then
            continue
        fi
        execs=$(awk '/stat::number_of_executed_units:/ {print $2}' "$dir/log.txt" | tail -1)
        rate=$(awk '/stat::average_exec_per_sec:/ {print $2}' "$dir/log.txt" | tail -1)
        status=$(grep -E '^#[0-9]+' "$dir/log.txt" | grep 'cov:' | tail -1)
        cov=$(sed -n 's/.*cov: \([0-9]*\).*/\1/p' <<<"$status")
        ft=$(sed -n 's/.*ft: \([0-9]*\).*/\1/p' <<<"$status")
        corpus=$(sed -n 's/.*corp: \([0-9]*\)\/.*/\1/p' <<<"$status")
        # slow-unit-* files are not failures: libFuzzer keeps its slowest input (wall-clock: a starved run too).
        crashes=$(find "$dir/crashes" -type f ! -name "slow-unit-*" | wc -l)
        if grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:' "$dir/log.txt"; then
            crashes="$crashes!"
        fi
        printf "%-16s %12s %9s %7s %7s %7s %8s %8s\n" "$name" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" \
            "${corpus:-?}" "$(cat "$dir/seconds")" "$crashes"
    done
} | tee "$campaign/summary.txt"

if grep -qE '[0-9]+!$|[1-9][0-9]*$' <(awk 'NR > 1 {print $8}' "$campaign/summary.txt"); then
    echo "crashes found: see build/fuzz/campaign/<harness>/crashes and log.txt"
    status=1
else
    status=0
fi

if ((asan)); then
    # The pipeline and CLI tests under ASan + UBSan (Debug): slow, hence here and not in CI.
    cmake --preset asan -DHS_BUILD_GUI=OFF "${launcher[@]}" >/dev/null
    cmake --build --preset asan -j "$jobs"
    ASAN_OPTIONS=detect_leaks=0 ctest --preset asan -L 'unit|integration' -j "$jobs" || status=1
fi
exit "$status"
