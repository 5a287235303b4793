#!/usr/bin/env bash
# The steps the CI examples in this folder run (github-actions.yml, gitlab-ci.yml, github-pr-diff.yml).
# This project's own .ci/run runs them too (`steps.sh selftest`), so the recipes cannot rot.
#
#   steps.sh assess HULL SEA OUT [ASSESS OPTIONS...]  assess HULL in SEA into OUT; exit status 4 when a
#                                                      [limits] entry of the hull file (or --max-pressure-kpa)
#                                                      is exceeded, with the verdict lines repeated at the end
#   steps.sh diff OLD_SUMMARY NEW_SUMMARY             print what moved since the previous run (nothing to
#                                                      compare: says so and succeeds)
#   steps.sh selftest                                  the steps on the bundled Ochi hull, analytic fidelity:
#                                                      limits that pass (status 0), limits that fail (status 4)
#                                                      and the diff between the two
#
# SLAMTOOL names the binary (default: slamtool on the PATH).
set -uo pipefail
SLAMTOOL=${SLAMTOOL:-slamtool}

assess() {
    local hull=$1 sea=$2 out=$3
    shift 3
    local log
    log=$(mktemp)
    "$SLAMTOOL" assess "$hull" --sea "$sea" -o "$out" --force "$@" | tee "$log"
    local status=${PIPESTATUS[0]}
    case $status in
        0) echo "slamtool: $hull meets its design limits; results in $out/" ;;
        4) echo "slamtool: $hull EXCEEDS its design limits (exit status 4):"
           grep '^LIMIT EXCEEDED' "$log" ;;
        *) echo "slamtool: assess failed with exit status $status (see docs/guide/troubleshooting.md)" ;;
    esac
    rm -f "$log"
    return "$status"
}

diff_previous() {
    local old=$1 new=$2
    if [ ! -f "$old" ]; then
        echo "slamtool: no previous summary.json at $old: nothing to compare (the first run)"
        return 0
    fi
    "$SLAMTOOL" diff "$old" "$new"
}

selftest() {
    local root tmp
    root=$(cd "$(dirname "$0")/../.." && pwd)
    tmp=$(mktemp -d)
    trap 'rm -rf "$tmp"' RETURN
    for case in pass fail; do
        cat "$root/hulls/ochi-vform.toml" "$root/examples/ci/limits-$case.toml" > "$tmp/ochi-$case.toml"
    done
    local fast=(--fidelity analytic -q)
    assess "$tmp/ochi-pass.toml" "$root/sea_states/ochi-1958.toml" "$tmp/pass" "${fast[@]}" > "$tmp/pass.log" 2>&1
    local s=$?
    [ "$s" -eq 0 ] || { cat "$tmp/pass.log"; echo "selftest: limits that hold gave exit status $s, not 0"; return 1; }
    assess "$tmp/ochi-fail.toml" "$root/sea_states/ochi-1958.toml" "$tmp/fail" "${fast[@]}" > "$tmp/fail.log" 2>&1
    s=$?
    [ "$s" -eq 4 ] || { cat "$tmp/fail.log"; echo "selftest: an exceeded limit gave exit status $s, not 4"; return 1; }
    grep -q '^LIMIT EXCEEDED: .*S133-3' "$tmp/fail.log" \
        || { cat "$tmp/fail.log"; echo "selftest: no verdict line for S133-3"; return 1; }
    for f in report.pdf summary.json pressures.csv bow_force.csv; do
        [ -s "$tmp/fail/$f" ] || { echo "selftest: no $f to publish"; return 1; }
    done
    diff_previous "$tmp/pass/summary.json" "$tmp/fail/summary.json" > "$tmp/diff.log" || return 1
    grep -q '^limit violation: (absent) -> LIMIT EXCEEDED' "$tmp/diff.log" \
        || { cat "$tmp/diff.log"; echo "selftest: the diff does not show the new violation"; return 1; }
    diff_previous "$tmp/none/summary.json" "$tmp/fail/summary.json" | grep -q 'nothing to compare' \
        || { echo "selftest: a first run without a previous summary must pass"; return 1; }
    echo "examples/ci/steps.sh selftest: pass (exit 0 within limits, 4 beyond, artifacts written, diff shown)"
}

cmd=${1:-}
shift || true
case $cmd in
    assess) [ $# -ge 3 ] || { sed -n '5,13p' "$0"; exit 2; }; assess "$@" ;;
    diff) [ $# -eq 2 ] || { sed -n '5,13p' "$0"; exit 2; }; diff_previous "$@" ;;
    selftest) selftest ;;
    *) sed -n '2,16p' "$0"; exit 2 ;;
esac
