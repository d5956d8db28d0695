#!/usr/bin/env bash
# Throughput of the local runner: plans a curriculum (the default one unless given) once per level of parallelism,
# runs it with `batch run --jobs N` and prints scenes per hour, the mean time per job and the largest peak memory
# (docs/batch.md, "Throughput"):
#     bash tools/batch-throughput.sh build/ci/bin/hysteroscene-cli /tmp/batch-throughput [CURRICULUM] [N...]
# N defaults to "1 2". The Slurm comparison on the same machine is printed by tests/integration/slurm_test.sh
# (`bash tests/integration/slurm_test.sh CLI resources/curricula/default.json`, as root).
set -uo pipefail
if [ $# -lt 2 ]; then
    echo "usage: $0 HYSTEROSCENE_CLI OUT_DIR [CURRICULUM] [N...]" >&2
    exit 2
fi
cli=$(realpath "$1")
out=$2
here=$(cd "$(dirname "$0")/.." && pwd)
curriculum=${3:-$here/resources/curricula/default.json}
shift $(($# < 3 ? $# : 3))
levels=("$@")
[ ${#levels[@]} -gt 0 ] || levels=(1 2)
rm -rf "$out"
mkdir -p "$out"
printf '%-6s %7s %7s %9s %12s %10s %9s\n' jobs scenes failed seconds scenes/hour s/scene peak-MiB
for n in "${levels[@]}"; do
    folder=$out/jobs-$n
    "$cli" batch plan "$curriculum" -o "$folder" >/dev/null || exit 1
    "$cli" batch run "$folder" --jobs "$n" --json >"$folder/run.json"
    "$cli" batch status "$folder" --json >"$folder/status.json"
    python3 - "$n" "$folder/run.json" "$folder/status.json" <<'EOF'
import json, sys
n, run, status = sys.argv[1], json.load(open(sys.argv[2])), json.load(open(sys.argv[3]))
print('%-6s %7d %7d %9.1f %12.0f %10.1f %9.0f' % (n, run['ok'], run['failed'], run['seconds'], run['scenesPerHour'],
      status['meanSecondsPerJob'], status['peakMemoryMb']))
EOF
done
