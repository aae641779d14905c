#!/usr/bin/env bash
# `pianoaction swing`, `keyfall`, `touchweight` and `study double-blow` end to end: JSON keys of
# DESIGN.md section 5, CSV written with a header, bad input named with exit code 2.
# usage: test_statics.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/common.sh"

"$exe" swing --action grand --json --out swing.csv >swing.json
python3 - swing.json swing.csv <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert isinstance(r["round_trips"], (int, float)), r
assert 2.0 <= r["round_trips"] <= 3.5, "F5: %r round trips" % r["round_trips"]
lines = [l for l in open(sys.argv[2]) if not l.startswith("#")]
assert lines[0].strip() == "time_s,swing_angle_deg,swing_rate_deg_per_s", lines[0]
assert len(lines) > 100
print("ok: swing --json (%s round trips), --out" % r["round_trips"])
PY

"$exe" keyfall --action grand --json --out fall.csv >fall.json
python3 - fall.json fall.csv <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for key in ("fall_time_s", "fall_distance_mm", "impact_velocity_mps", "bounces"):
    assert key in r, "missing %r" % key
assert 0.01 < r["fall_time_s"] < 0.2, r
header = [l for l in open(sys.argv[2]) if not l.startswith("#")][0].strip()
assert header.startswith("time_s,key_angle_deg,key_front_dip_mm"), header
print("ok: keyfall --json (%.1f ms), --out" % (r["fall_time_s"] * 1e3))
PY

"$exe" touchweight --action grand --json --out tw.csv >tw.json
"$exe" touchweight --action grand --json --key-lead-g 5 >tw_lead.json
"$exe" touchweight --action grand --json --spring-factor repetition_spring=1.5 >tw_spring.json
python3 - tw.json tw_lead.json tw_spring.json tw.csv <<'PY'
import json, sys
r, lead, spring = (json.load(open(p)) for p in sys.argv[1:4])
for key in ("downweight_g", "upweight_g", "balance_weight_g", "friction_weight_g", "key_ratio",
            "strike_weight_g"):
    assert key in r, "missing %r" % key
assert 45 <= r["downweight_g"] <= 55 and 20 <= r["upweight_g"] <= 30, "F9: %r" % r
assert lead["balance_weight_g"] < r["balance_weight_g"] - 4.9, (lead, r)
assert spring["downweight_g"] < r["downweight_g"], (spring, r)
header = [l for l in open(sys.argv[4]) if not l.startswith("#")][0].strip()
assert header == "dip_mm,downweight_g,upweight_g,balance_weight_g,friction_weight_g", header
print("ok: touchweight --json (DW %.1f g, UW %.1f g), lead and spring factor" %
      (r["downweight_g"], r["upweight_g"]))
PY

"$exe" study double-blow --action upright --json --out db.csv >db.json
python3 - db.json db.csv <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
names = [v["name"] for v in r["variants"]]
assert names == ["both", "no_bridle", "no_butt_spring", "neither"], names
for v in r["variants"]:
    for key in ("hammer_return_s", "second_impact_velocity_mps"):
        assert key in v, "variant without %r: %r" % (key, v)
header = [l for l in open(sys.argv[2]) if not l.startswith("#")][0].strip()
assert header.startswith("time_s,both_hammer_angle_deg"), header
print("ok: study double-blow --json, --out")
PY

# a blow so hard that the runs stop: written, the stops named on stderr, exit code 3 (simulate's)
set +e
"$exe" study double-blow --action upright --force 1000 --duration 0.05 --json >hard.json 2>hard.err
status=$?
set -e
[[ "$status" == 3 ]] || { echo "FAIL: stopped double blow: exit $status" >&2; cat hard.err >&2; exit 1; }
grep -q "both stopped: single blow: " hard.err || { echo "FAIL: $(cat hard.err)" >&2; exit 1; }
python3 -c 'import json,sys; v=json.load(open("hard.json"))["variants"]; assert all("; double blow: " in x["stop_cause"] for x in v), v'
echo "ok: a stopped double blow exits 3 and names each run's stop"

# bad input: each exits 2 with a message naming what is wrong, and writes nothing
expect_bad() {
  local what="$1" pattern="$2"; shift 2
  set +e
  "$exe" "$@" >/dev/null 2>err.txt
  local status=$?
  set -e
  [[ "$status" == 2 ]] || { echo "FAIL: $what: exit $status" >&2; cat err.txt >&2; exit 1; }
  grep -q -- "$pattern" err.txt || { echo "FAIL: $what: $(cat err.txt)" >&2; exit 1; }
  echo "ok: $what rejected ($(head -c 120 err.txt))"
}
expect_bad "double-blow on the grand" "bridle" study double-blow --action grand --out bad.csv
[[ ! -e bad.csv ]] || { echo "FAIL: bad.csv written" >&2; exit 1; }
expect_bad "unknown spring" "no_such" touchweight --action grand --spring-factor no_such=2
expect_bad "negative spring factor" "factor" touchweight --action grand \
  --spring-factor repetition_spring=-1
expect_bad "spring factor without =" "SPRING=FACTOR" touchweight --action grand \
  --spring-factor repetition_spring
expect_bad "release angle" "release-deg" swing --action grand --release-deg 200
expect_bad "missing action" "--action" keyfall
expect_bad "unknown study" "double-blow" study bogus --action upright
echo "all statics cli tests passed"
