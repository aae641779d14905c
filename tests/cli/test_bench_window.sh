#!/usr/bin/env bash
# pianoaction bench --window (issue 5, must-show 4): a short smoke run offscreen that checks the
# benchmark runs the real window and prints its figures. Nothing here depends on the machine's
# speed: the figures themselves are read by a person (README, speed and limits).
# usage: test_bench_window.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/common.sh"
export QT_QPA_PLATFORM=offscreen
export XDG_CONFIG_HOME="$work/config"

fail() { echo "FAIL: $*" >&2; exit 1; }

# the usage is read from a file: `--help | grep -q` under pipefail fails when grep stops reading
# before a usage longer than one pipe write has been written (SIGPIPE)
"$exe" --help > help.txt
grep -q "bench --window" help.txt || fail "--help does not mention bench --window"

"$exe" bench --window --duration 0.5 --trials 2 --json > out.json 2> err.txt \
  || { cat err.txt; fail "bench --window exited with an error"; }
python3 - out.json <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for key in ("fps_mean", "fps_worst_second", "frame_interval_p95_ms", "realtime_factor",
            "latency_median_ms", "latency_max_ms", "load_average", "platform"):
    if key not in r:
        sys.exit("no %s in the JSON" % key)
if r["platform"] != "offscreen":
    sys.exit("platform %s, expected offscreen" % r["platform"])
# the view painted frames of a moving action and every slider move became visible
if r["new_frames"] < 1 or r["paints"] < r["new_frames"]:
    sys.exit("frames: %d new of %d paints" % (r["new_frames"], r["paints"]))
if not r["realtime_factor"] > 0:
    sys.exit("the displayed time did not move")
if len(r["latency_ms"]) != 2 or not all(x > 0 for x in r["latency_ms"]):
    sys.exit("latencies %s" % r["latency_ms"])
PY

"$exe" bench --window --duration 0.3 --trials 1 > out.txt || fail "text output failed"
grep -q "frames painted" out.txt || fail "no frame rate in: $(cat out.txt)"
grep -q "slider latency" out.txt || fail "no latency in: $(cat out.txt)"

# bad input is named, exit code 2
if "$exe" bench --window --trials 0 2> err.txt; then fail "--trials 0 accepted"; fi
grep -q -- "--trials" err.txt || fail "the error does not name --trials: $(cat err.txt)"
set +e
"$exe" bench --window --duration 0.3 --input force:bogus:1 2> err.txt
code=$?
set -e
[ "$code" = 2 ] || fail "a bad --input exited with $code, expected 2: $(cat err.txt)"
grep -q "force:bogus:1" err.txt || fail "the error does not name the input: $(cat err.txt)"
echo "ok"
