#!/usr/bin/env bash
# README command 2: set up, build, and run the whole test suite: the release build with
# invariant checks, then the same tests under AddressSanitizer + UndefinedBehaviorSanitizer
# in a build of their own. Ends with one line "N passed, N failed" (over both builds) and
# exits non-zero if any test failed.
set -uo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh || exit 1
jobs=$(nproc)

configure() {  # dir, meson args...
  local dir=$1
  mkdir -p "$dir"
  shift
  if [[ ! -f "$dir/build.ninja" ]]; then
    meson setup "$dir" "$@" >"$dir/rstruct-setup.log" 2>&1 || { cat "$dir/rstruct-setup.log"; return 1; }
  fi
}

total_pass=0
total_fail=0
status=0

run_suite() {  # dir, label, extra meson test args...
  local dir=$1 label=$2
  shift 2
  echo "== $label: building" >&2
  if ! ninja -C "$dir" -j "$jobs" >"$dir/rstruct-build.log" 2>&1; then
    tail -40 "$dir/rstruct-build.log"
    echo "== $label: BUILD FAILED" >&2
    total_fail=$((total_fail + 1))
    status=1
    return
  fi
  echo "== $label: testing" >&2
  meson test -C "$dir" --num-processes "$jobs" --print-errorlogs "$@" >"$dir/rstruct-test.log" 2>&1 || status=1
  grep -E '^ *[0-9]+/[0-9]+ ' "$dir/rstruct-test.log" | sed "s/^/[$label] /"
  local counts
  counts=$(python3 - "$dir/meson-logs/testlog.json" <<'PY'
import json, sys
passed = failed = 0
try:
    with open(sys.argv[1]) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            r = json.loads(line)
            if r.get("result") in ("OK", "EXPECTEDFAIL", "SKIP"):
                passed += r.get("result") != "SKIP"
            else:
                failed += 1
except FileNotFoundError:
    failed = 1
print(passed, failed)
PY
)
  local p f
  read -r p f <<<"$counts"
  total_pass=$((total_pass + p))
  total_fail=$((total_fail + f))
  ((f == 0)) || { status=1; grep -A30 -E 'FAIL|ERROR' "$dir/rstruct-test.log" | head -120; }
}

# Compile times dominate this script on two cores (fresh clone, 2026-12-04: about 40 of its
# 43 minutes), so both builds keep only line tables for the sanitizers' and debuggers'
# backtraces (-g1 instead of -g: a fifth less compile time at -O2), assertions of the
# libraries on (b_ndebug false; the project's own checks are -Dchecks).
configure build-test -Doptimization=2 -Ddebug=false -Dcpp_args=-g1 -Db_ndebug=false \
  -Dchecks=expensive -Dbench=true || status=1
run_suite build-test release

if [[ "${RSTRUCT_NO_SANITIZE:-0}" != 1 ]]; then
  # -O1 -g1: the full sanitizer build took 778 s instead of about 1,600 s (-O2 -g; the sum
  # of its compile jobs 1,554 s against 3,210 s) and its tests 820 s instead of 829 s
  # (summed over tests; 2026-12-04, cc9d207).
  configure build-asan -Doptimization=1 -Ddebug=false -Dcpp_args=-g1 -Db_ndebug=false \
    -Db_sanitize=address,undefined -Db_lundef=false -Dchecks=expensive -Dbench=false \
    -Dproofs=false || status=1
  # The sanitizer build neither builds nor runs the interval proofs (arithmetic only, already
  # run above): that saves compiling 17 Boost/MPFI programs twice.
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    run_suite build-asan asan --timeout-multiplier 4
fi

echo "${total_pass} passed, ${total_fail} failed"
if ((total_fail > 0)); then status=1; fi
exit $status
