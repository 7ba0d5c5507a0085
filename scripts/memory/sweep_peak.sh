#!/bin/sh
# The peak memory of the largest sweep (polymer-coating, load x mu on a 2000 x 2000 grid:
# four million points) as JSON and as CSV, measured by /usr/bin/time -v; the rows stream, so the
# peak must stay under 200 MB (it was 4.15 GB and 2.77 GB while the whole result was held).
# Run from the repository: sh scripts/memory/sweep_peak.sh [path to a release wearlab binary]
set -eu
bin=${1:-target/release/wearlab}
limit_kb=204800
status=0
for format in json csv; do
    peak=$(/usr/bin/time -v "$bin" sweep presets/polymer-coating.toml \
        --vary plane.load=1:1e6:2000:log --vary friction.coefficient=0:1:2000 \
        --format "$format" 2>&1 >/dev/null | awk '/Maximum resident set size/ {print $6}')
    echo "$format: peak RSS $peak kB (limit $limit_kb kB)"
    [ "$peak" -lt "$limit_kb" ] || status=1
done
exit $status
