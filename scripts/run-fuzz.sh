#!/usr/bin/env bash
# Builds and runs every fuzz target of tests/fuzz for the given number of seconds each, one after
# the other, from the corpus in the tree; prints the inputs run and what was found per target.
# Usage: scripts/run-fuzz.sh SECONDS [TARGET...]   (make fuzz FUZZ_SECONDS=N [FUZZ_TARGETS="..."])
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=(demonstration_csv run_log session_json calibration_json rc_decoder cli_options calibration_points
         trial_bundle)
if [ $# -gt 0 ]; then
    for t in "$@"; do
        [[ " ${targets[*]} " == *" $t "* ]] || { echo "no fuzz target '$t' (one of: ${targets[*]})" >&2; exit 2; }
    done
    targets=("$@")
fi
# Inputs up to 64 KB, the demonstration CSV's up to 16 KB (its seeds are 0.1-9 KB; long lines
# and huge files are the reader's unit tests' business): each CSV input is parsed, written and
# read back, so its length sets the rate.
max_len() { case $1 in demonstration_csv) echo 16384 ;; *) echo 65536 ;; esac; }
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]/#/fuzz_}"
export QT_QPA_PLATFORM=offscreen
status=0
printf '%-20s %12s %10s %s\n' target inputs seconds findings
for t in "${targets[@]}"; do
    corpus=build-fuzz/corpus/$t
    artifacts=build-fuzz/findings/$t/
    mkdir -p "$corpus" "$artifacts"
    log=build-fuzz/fuzz-$t.log
    if ./build-fuzz/tests/fuzz/fuzz_$t -max_total_time="$seconds" -print_final_stats=1 \
        -max_len="$(max_len "$t")" -timeout=10 -rss_limit_mb=4096 -artifact_prefix="$artifacts" \
        "$corpus" "tests/fuzz/corpus/$t" >"$log" 2>&1; then
        found=0
    else
        found=1
        status=1
    fi
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    findings=$(find "$artifacts" -type f | wc -l)
    printf '%-20s %12s %10s %s\n' "$t" "$runs" "$seconds" \
        "$([ "$found" = 0 ] && echo "0 crashes" || echo "FOUND $findings: see $log, $artifacts")"
done
exit $status
