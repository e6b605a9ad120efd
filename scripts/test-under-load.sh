#!/usr/bin/env bash
# make test RUNS times in a row while one busy loop per core keeps the machine loaded, as a lab
# PC busy with a camera, a build or a browser is. Stops at the first failure.
# Usage: scripts/test-under-load.sh [RUNS]   (make test-under-load RUNS=N)
set -uo pipefail
cd "$(dirname "$0")/.."
runs=${1:-10}
busy=()
for _ in $(seq "$(nproc)"); do
    (while :; do :; done) &
    busy+=($!)
done
trap 'kill "${busy[@]}" 2>/dev/null' EXIT
for i in $(seq "$runs"); do
    start=$(date +%s)
    if make test >"build/test-under-load-$i.log" 2>&1; then
        echo "run $i/$runs passed in $(($(date +%s) - start)) s, load $(cut -d' ' -f1 /proc/loadavg)"
    else
        echo "run $i/$runs FAILED (build/test-under-load-$i.log)"
        exit 1
    fi
done
echo "$runs of $runs passed under load"
