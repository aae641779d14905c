#!/usr/bin/env bash
# `pianoaction simulate` end to end: JSON on stdout, the CSV trace, both actions, --set,
# --without, every integrator, and --help.
# usage: test_simulate.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/common.sh"

# check_json FILE [MIN_IMPACTS]: status "ok", the stable keys, and (if MIN_IMPACTS is 1) an impact
# event with a positive hammer velocity.
check_json() {
  python3 - "$@" <<'EOF'
import json, sys
path = sys.argv[1]
need_impact = len(sys.argv) > 2 and sys.argv[2] == "1"
with open(path) as f:
    result = json.load(f)
problems = []
if result.get("status") != "ok":
    problems.append("status is %r, expected 'ok'" % result.get("status"))
for key in ("status", "stop_cause", "events", "realtime_factor", "steps"):
    if key not in result:
        problems.append("missing key %r" % key)
if not isinstance(result.get("steps"), int) or result.get("steps", 0) <= 0:
    problems.append("steps should be a positive integer: %r" % result.get("steps"))
rtf = result.get("realtime_factor")
if not isinstance(rtf, (int, float)) or not rtf > 0:
    problems.append("realtime_factor should be a positive number: %r" % rtf)
events = result.get("events", [])
if not isinstance(events, list):
    problems.append("events should be a list")
    events = []
for e in events:
    if e.get("type") not in ("escapement", "impact", "check", "key_bottom"):
        problems.append("unknown event type %r" % e.get("type"))
    if not isinstance(e.get("t_s"), (int, float)):
        problems.append("event without t_s: %r" % e)
if need_impact:
    impacts = [e for e in events if e.get("type") == "impact"]
    if not impacts:
        problems.append("no impact event: %r" % [e.get("type") for e in events])
    for e in impacts:
        v = e.get("hammer_velocity_mps")
        if not isinstance(v, (int, float)) or not v > 0:
            problems.append("impact hammer_velocity_mps should be > 0: %r" % v)
if problems:
    sys.exit("%s: %s" % (path, "; ".join(problems)))
print("ok: %s: status ok, %d steps, events %s" %
      (path, result["steps"], [e["type"] for e in events]))
EOF
}

# check_csv FILE ACTION DURATION_S: '# ' metadata first (with '# action: ACTION'), the header
# columns, numeric rows of the header's width, increasing time reaching DURATION_S.
check_csv() {
  python3 - "$@" <<'EOF'
import math, sys
path, action, duration = sys.argv[1], sys.argv[2], float(sys.argv[3])
with open(path) as f:
    lines = [line.rstrip("\r\n") for line in f]
problems = []
if not lines or not lines[0].startswith("# "):
    problems.append("does not start with a '# ' metadata line")
metadata = []
i = 0
while i < len(lines) and lines[i].startswith("#"):
    metadata.append(lines[i])
    i += 1
if "# action: " + action not in metadata:
    problems.append("no '# action: %s' line in %r" % (action, metadata))
if i >= len(lines):
    sys.exit("%s: no header" % path)
header = [c.strip() for c in lines[i].split(",")]
for column in ("time_s", "key_angle_deg", "hammer_angle_deg", "hammer_string_gap_mm",
               "finger_force_n"):
    if column not in header:
        problems.append("no column %r" % column)
contact_columns = [c for c in header if c.endswith("_force_n") and c != "finger_force_n"]
if not contact_columns:
    problems.append("no contact *_force_n column")
rows = []
for n, line in enumerate(lines[i + 1:], start=i + 2):
    if not line.strip():
        continue
    fields = line.split(",")
    if len(fields) != len(header):
        problems.append("line %d has %d fields, header has %d" % (n, len(fields), len(header)))
        break
    try:
        values = [float(x) for x in fields]
    except ValueError:
        problems.append("line %d is not numeric: %r" % (n, line[:80]))
        break
    if not all(math.isfinite(v) for v in values):
        problems.append("line %d has a non-finite value" % n)
        break
    rows.append(values)
if len(rows) < 10:
    problems.append("only %d data rows" % len(rows))
else:
    t = [r[header.index("time_s")] for r in rows]
    if any(b <= a for a, b in zip(t, t[1:])):
        problems.append("time_s does not increase")
    if abs(t[0]) > 1e-12 or t[-1] < duration * 0.99 or t[-1] > duration * 1.01 + 1e-9:
        problems.append("time_s runs from %g to %g, expected 0 to %g" % (t[0], t[-1], duration))
    key = [r[header.index("key_angle_deg")] for r in rows]
    if max(key) <= 0.1:
        problems.append("the key never went down (max key_angle_deg %g)" % max(key))
if problems:
    sys.exit("%s: %s" % (path, "; ".join(problems)))
print("ok: %s: %d metadata lines, %d columns (%d contact forces), %d rows" %
      (path, len(metadata), len(header), len(contact_columns), len(rows)))
EOF
}

# impact_velocity FILE: the first impact's hammer velocity from a --json result.
impact_velocity() {
  python3 -c '
import json, sys
events = json.load(open(sys.argv[1]))["events"]
print([e for e in events if e["type"] == "impact"][0]["hammer_velocity_mps"])' "$1"
}

# --- grand, 0.2 s under a 1 kg mass -------------------------------------------------------------
"$exe" simulate --action grand --input mass:1kg --duration 0.2 --json --out t.csv >grand.json
check_json grand.json 1
check_csv t.csv grand 0.2
grep -qx '# input: mass:1kg' t.csv || { echo "FAIL: t.csv lacks '# input: mass:1kg'" >&2; exit 1; }

# --- upright without its bridle, let-off moved ---------------------------------------------------
"$exe" simulate --action upright --input mass:1kg --duration 0.2 --without bridle \
  --set let_off=0.2 --json --out u.csv >upright.json
check_json upright.json 1
check_csv u.csv upright 0.2
python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
if r.get("action") != "upright": sys.exit("upright.json: action is %r" % r.get("action"))
# the JSON says how the run was made: the model changes and the step
if r.get("set") != ["let_off=0.2"] or r.get("without") != ["bridle"] or r.get("effects") != []:
    sys.exit("upright.json: set/without/effects are %r %r %r" % (r.get("set"), r.get("without"), r.get("effects")))
if r.get("step_s") != 1e-5: sys.exit("upright.json: step_s is %r" % r.get("step_s"))' \
  upright.json
# the bridle is gone from the trace (a full upright has a bridle_tension_n column)
"$exe" simulate --action upright --input mass:1kg --duration 0.01 --out full-upright.csv >/dev/null
# header_of: the first non-comment line, without a pipeline (under pipefail, `grep -q` closing
# its input early can make `head` fail with SIGPIPE)
header_of() { awk '!/^#/ { print; exit }' "$1"; }
[[ "$(header_of full-upright.csv)" == *bridle_tension_n* ]] ||
  { echo "FAIL: full-upright.csv has no bridle_tension_n column" >&2; exit 1; }
if [[ "$(header_of u.csv)" == *bridle* ]]; then
  echo "FAIL: u.csv (--without bridle) still has a bridle column" >&2
  exit 1
fi
echo "ok: --without bridle removes the bridle column"

# --- the grand without its repetition spring (issue 2): it rests and still strikes -------------
"$exe" simulate --action grand --input mass:1kg --duration 0.2 --without repetition_spring \
  --json --out g-nospring.csv >grand-nospring.json ||
  { echo "FAIL: simulate --without repetition_spring on the grand failed" >&2; exit 1; }
check_json grand-nospring.json 1
echo "ok: the grand runs without its repetition spring"

# --- the other integrators ------------------------------------------------------------------------
for integrator in rodas cvode; do
  for action in grand upright; do
    "$exe" simulate --action "$action" --input mass:1kg --duration 0.05 \
      --integrator "$integrator" --json --out "$integrator-$action.csv" >"$integrator-$action.json"
    check_json "$integrator-$action.json"
    check_csv "$integrator-$action.csv" "$action" 0.05
    python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
if r.get("integrator") != sys.argv[2]:
    sys.exit("%s: integrator is %r" % (sys.argv[1], r.get("integrator")))' \
      "$integrator-$action.json" "$integrator"
  done
done

# --- replaying the recorded key motion (csv:PATH) reproduces the impact ------------------------
"$exe" simulate --action grand --input csv:t.csv --duration 0.2 --json >replay.json
check_json replay.json 1
python3 -c '
import sys
a, b = float(sys.argv[1]), float(sys.argv[2])
if abs(a - b) > 0.01 * abs(a):
    sys.exit("replayed impact velocity %g m/s differs from the original %g m/s" % (b, a))
print("ok: replayed impact velocity %g m/s (original %g m/s)" % (b, a))' \
  "$(impact_velocity grand.json)" "$(impact_velocity replay.json)"

# --- text output (no --json) ------------------------------------------------------------------
"$exe" simulate --action grand --input mass:1kg --duration 0.1 --out text.csv >text.txt
grep -q "ok" text.txt || { echo "FAIL: text output lacks 'ok': $(cat text.txt)" >&2; exit 1; }
grep -q "impact" text.txt || { echo "FAIL: text output lacks 'impact'" >&2; exit 1; }
grep -qF "text.csv" text.txt || { echo "FAIL: text output does not name text.csv" >&2; exit 1; }
[[ -s text.csv ]] || { echo "FAIL: text.csv was not written" >&2; exit 1; }
echo "ok: text output"

# --- a successful run replaces an existing --out file ----------------------------------------
printf 'old content\n' >replace.csv
"$exe" simulate --action grand --input mass:1kg --duration 0.01 --out replace.csv >/dev/null
if grep -q "old content" replace.csv; then
  echo "FAIL: replace.csv still holds its old content" >&2
  exit 1
fi
echo "ok: --out replaces an existing file"

# --- how the trace was made, and where the run ended ----------------------------------------------
# the trace names the accuracy asked for and the effects added; a run ending between two samples
# (0.0505 s at 0.01 s spacing) ends the trace with its last state, as does an adaptive run
"$exe" simulate --action grand --input force:const:20 --duration 0.0505 --sample-interval 0.01 \
  --effect shank_flex=180 --out made.csv >/dev/null
"$exe" simulate --action grand --input force:const:20 --duration 0.01 --integrator cvode \
  --rtol 1e-4 --out made_cvode.csv >/dev/null
python3 - made.csv made_cvode.csv <<'PY'
import sys
def read(path):
    meta, rows = {}, []
    for line in open(path):
        if line.startswith("#"):
            key, _, value = line[1:].partition(":")
            meta[key.strip()] = value.strip()
        elif line[0].isdigit():
            rows.append([float(x) for x in line.split(",")])
    return meta, rows
meta, rows = read(sys.argv[1])
assert meta.get("effects") == "shank_flex=180", meta
assert meta.get("step_s") == "1e-05", meta
times = [r[0] for r in rows]
assert times[-2:] == [0.05, 0.0505], times
meta, rows = read(sys.argv[2])
assert meta.get("rtol") == "0.0001" and "step_s" not in meta, meta
print("ok: the trace records step, tolerance and effects, and ends where the run ended")
PY

# a recording shorter than the run: its last value is held, and the run says so
printf 'time_s,key_force_n\n0,0\n0.002,20\n0.05,20\n' >short_input.csv
"$exe" simulate --action grand --input csv:short_input.csv --duration 0.1 >short.txt
grep -qF "the input ends at 0.05 s; its last force, 20 N, is held to the run's end at 0.1 s" \
  short.txt || { echo "FAIL: no note of the held end: $(cat short.txt)" >&2; exit 1; }
"$exe" simulate --action grand --input csv:short_input.csv --duration 0.04 >long.txt
if grep -q "is held to the run's end" long.txt; then
  echo "FAIL: a recording longer than the run gets the note: $(cat long.txt)" >&2
  exit 1
fi
echo "ok: a recording shorter than the run says its last value is held"

# --- help -----------------------------------------------------------------------------------------
"$exe" --help >help.txt
grep -q "simulate" help.txt || { echo "FAIL: --help does not mention simulate" >&2; exit 1; }
# a subcommand's own --help: its usage lines and the input SPEC notes, exit 0
"$exe" simulate --help >simulate-help.txt ||
  { echo "FAIL: simulate --help failed" >&2; exit 1; }
grep -q "pianoaction simulate" simulate-help.txt && grep -q "input SPEC" simulate-help.txt &&
  ! grep -q "pianoaction regulate" simulate-help.txt ||
  { echo "FAIL: simulate --help: $(cat simulate-help.txt)" >&2; exit 1; }
# a note about one subcommand's option stays with it: bench's --window switch is not the sweep's
# --window CYCLES, nor the sensitivity study's --step MM w2's step (both had been shown)
"$exe" bench --help >bench-help.txt || { echo "FAIL: bench --help failed" >&2; exit 1; }
! grep -q "judged cycles in a steady window" bench-help.txt ||
  { echo "FAIL: bench --help explains the sweep's --window" >&2; exit 1; }
"$exe" study sensitivity --help >sensitivity-help.txt ||
  { echo "FAIL: study sensitivity --help failed" >&2; exit 1; }
! grep -q "w2's fixed step" sensitivity-help.txt ||
  { echo "FAIL: study sensitivity --help explains simulate's --step" >&2; exit 1; }
"$exe" sweep --help >sweep-help.txt || { echo "FAIL: sweep --help failed" >&2; exit 1; }
grep -q "judged cycles in a steady window" sweep-help.txt ||
  { echo "FAIL: sweep --help lost its --window note" >&2; exit 1; }
grep -q "pianoaction study sensitivity" sensitivity-help.txt &&
  ! grep -q "study compare" sensitivity-help.txt ||
  { echo "FAIL: study sensitivity --help: $(cat sensitivity-help.txt)" >&2; exit 1; }
grep -q "w2's fixed step" simulate-help.txt ||
  { echo "FAIL: simulate --help lost its --step note" >&2; exit 1; }
# the help names every adjuster and removable part of the shipped presets (kept in step with
# them: a renamed or added adjuster fails here)
python3 - "$source_dir/presets" simulate-help.txt <<'PY'
import json, sys
help_text = open(sys.argv[2]).read()
for action in ("grand", "upright"):
    preset = json.load(open("%s/%s.json" % (sys.argv[1], action)))
    names = [a["name"] for a in preset["adjusters"]]
    names += [p["name"] for p in preset.get("springs", []) + preset.get("straps", [])]
    for name in names:
        assert name in help_text, "simulate --help does not name %s's %s" % (action, name)
print("ok: simulate --help names the adjusters and parts")
PY
echo "ok: --help"

echo "all simulate checks passed"
