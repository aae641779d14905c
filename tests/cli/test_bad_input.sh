#!/usr/bin/env bash
# Bad input to `pianoaction simulate`: every case must fail with a non-zero exit code, a message
# on stderr that names the file / field / line / option and the problem, and no output file.
# usage: test_bad_input.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/common.sh"
grand="$source_dir/presets/grand.json"

failures=0
cases=0

fail() {
  echo "FAIL: $*" >&2
  failures=$((failures + 1))
}

# expect_failure "DESCRIPTION" "SUBSTRING|SUBSTRING..." ARGS...
# Runs pianoaction ARGS, expects a non-zero exit code (2, bad input), every substring (separated
# by '|') in stderr, and that the --out file named in ARGS (if any) was not created.
expect_failure() {
  local description="$1" expected="$2"
  shift 2
  cases=$((cases + 1))
  local out_file="" previous=""
  for arg in "$@"; do
    if [[ "$previous" == "--out" ]]; then out_file="$arg"; fi
    previous="$arg"
  done
  if [[ -n "$out_file" ]]; then rm -f "$out_file"; fi

  local status=0
  "$exe" "$@" >stdout.txt 2>stderr.txt || status=$?
  if [[ $status -eq 0 ]]; then
    fail "$description: exit code 0 (expected non-zero) for: $*"
  elif [[ $status -ne 2 ]]; then
    # bad input is an InputError, which main reports with exit code 2 (1 = internal error)
    fail "$description: exit code $status (expected 2 for bad input) for: $*"
  fi
  local part
  IFS='|' read -r -a parts <<<"$expected"
  for part in "${parts[@]}"; do
    if ! grep -qF -- "$part" stderr.txt; then
      fail "$description: stderr lacks '$part'; stderr was: $(cat stderr.txt)"
    fi
  done
  if [[ -n "$out_file" && -e "$out_file" ]]; then
    fail "$description: $out_file was written although the run failed"
  fi
  echo "ok: $description (exit $status): $(head -n 1 stderr.txt)"
}

run_args=(simulate --action grand --input mass:1kg --duration 0.05)

# --- input SPEC and CSV inputs --------------------------------------------------------------------
expect_failure "unknown input SPEC" "foo:1|input SPEC" \
  simulate --action grand --input foo:1 --duration 0.05 --out out.csv

printf 'time_s,key_force_n\n0,0\n0.01,abc\n0.02,1\n' >bad_value.csv
expect_failure "CSV row with a non-number" "bad_value.csv|line 3|abc|not a number" \
  simulate --action grand --input csv:bad_value.csv --duration 0.05 --out out.csv

printf '# comment\ntime_s,key_force_n\n0,0\n0.01,1,2\n0.02,1\n' >bad_fields.csv
expect_failure "CSV row with too many fields" "bad_fields.csv|line 4|expected 2 values, got 3" \
  simulate --action grand --input csv:bad_fields.csv --duration 0.05 --out out.csv

printf 'time_s,key_force_n\n0,0\n0.01\n' >short_row.csv
expect_failure "CSV row with too few fields" "short_row.csv|line 3" \
  simulate --action grand --input csv:short_row.csv --duration 0.05 --out out.csv

printf 'time_s,key_force_n\n0,0\n0.02,1\n0.01,2\n' >time_order.csv
expect_failure "CSV with non-increasing time" "time_order.csv|time_s must increase|line 4" \
  simulate --action grand --input csv:time_order.csv --duration 0.05 --out out.csv

printf 'time_s,key_angle_deg\n0,1\n0.1,1\n' >angle_jump.csv
expect_failure "key angle CSV away from rest at t = 0" "angle_jump.csv|key_angle_deg is 1 deg at time_s 0|at rest" \
  simulate --action grand --input csv:angle_jump.csv --duration 0.05 --out out.csv

expect_failure "CSV file that does not exist" "no_such.csv" \
  simulate --action grand --input csv:no_such.csv --duration 0.05 --out out.csv

# --- broken presets -------------------------------------------------------------------------------
python3 - "$grand" <<'EOF'
import json, sys
grand = json.load(open(sys.argv[1]))

def write(name, edit):
    preset = json.loads(json.dumps(grand))
    edit(preset)
    with open(name, "w") as f:
        json.dump(preset, f, indent=1, ensure_ascii=False)

write("missing_field.json", lambda p: p["bodies"][2].pop("mass_g"))
write("negative_mass.json", lambda p: p["bodies"][1].__setitem__("mass_g", -3))
write("wrong_type.json", lambda p: p["bodies"][0].__setitem__("mass_g", "95"))
write("bad_felt.json", lambda p: p["contacts"][0].__setitem__("felt", "velvet"))

text = open(sys.argv[1]).read()
brace = text.index("}", len(text) // 2)
open("malformed.json", "w").write(text[:brace] + text[brace + 1:])
EOF

expect_failure "preset with a missing field" "missing_field.json|bodies[2]|mass_g|missing" \
  simulate --action missing_field.json --input mass:1kg --duration 0.05 --out out.csv
expect_failure "preset with a negative mass" \
  "negative_mass.json|bodies[1]|mass_g|must be positive" \
  simulate --action negative_mass.json --input mass:1kg --duration 0.05 --out out.csv
expect_failure "preset with a wrong type" "wrong_type.json|bodies[0]|mass_g|expected a number" \
  simulate --action wrong_type.json --input mass:1kg --duration 0.05 --out out.csv
expect_failure "preset with an unknown felt law" "bad_felt.json|contacts[0]|felt|velvet" \
  simulate --action bad_felt.json --input mass:1kg --duration 0.05 --out out.csv
expect_failure "malformed JSON preset" "malformed.json|line |column |malformed JSON" \
  simulate --action malformed.json --input mass:1kg --duration 0.05 --out out.csv
expect_failure "preset file that does not exist" "no_such_preset.json" \
  simulate --action no_such_preset.json --input mass:1kg --duration 0.05 --out out.csv

# --- command-line options -------------------------------------------------------------------------
expect_failure "unknown integrator" "integrator|euler|w2" \
  "${run_args[@]}" --integrator euler --out out.csv
expect_failure "unknown --set name" "nonsense|let_off" \
  "${run_args[@]}" --set nonsense=1 --out out.csv
expect_failure "--set out of range" "let_off|99|range" \
  "${run_args[@]}" --set let_off=99 --out out.csv
expect_failure "--set without a number" "let_off=wide|not a number" \
  "${run_args[@]}" --set let_off=wide --out out.csv
expect_failure "unknown --without part" "bridle|removable parts|repetition_spring" \
  "${run_args[@]}" --without bridle --out out.csv
expect_failure "a --without part the action cannot rest without" "--without jack_spring|no rest|jack" \
  "${run_args[@]}" --without jack_spring --out out.csv
expect_failure "settings that leave no rest" "--set key_dip=3, let_off=-4|no rest|one at a time" \
  measure --action grand --set key_dip=3 --set let_off=-4 --set drop=4 --set checking=-4 \
  --set hammer_blow=4 --set lever_height=-2.5 --set jack_position=3
expect_failure "missing --duration" "--duration|missing" \
  simulate --action grand --input mass:1kg --out out.csv
expect_failure "a value left out before the next option" "--input needs a value|found the option --duration" \
  simulate --action grand --input --duration 0.1 --out out.csv
expect_failure "a fraction for a count" "--seeds|whole number|1.5" bench-diagnose --seeds 1.5
expect_failure "non-numeric --duration" "--duration|abc|not a number" \
  simulate --action grand --input mass:1kg --duration abc --out out.csv
expect_failure "negative --duration" "--duration|must be positive" \
  simulate --action grand --input mass:1kg --duration -1 --out out.csv
expect_failure "unknown option" "--frobnicate" \
  "${run_args[@]}" --frobnicate --out out.csv
expect_failure "unknown subcommand" "unknown subcommand|frobnicate" \
  frobnicate --out out.csv

# --- an existing --out file is left untouched by a failed run ----------------------------------
failures_before=$failures
printf 'previous,content\n1,2\n' >keep.csv
cp keep.csv keep.expected
cases=$((cases + 1))
status=0
"$exe" simulate --action missing_field.json --input mass:1kg --duration 0.05 --out keep.csv \
  >stdout.txt 2>stderr.txt || status=$?
if [[ $status -eq 0 ]]; then fail "existing --out file: exit code 0"; fi
if ! grep -qF "missing_field.json" stderr.txt; then
  fail "existing --out file: stderr lacks the file name: $(cat stderr.txt)"
fi
if ! cmp -s keep.csv keep.expected; then
  fail "existing --out file: keep.csv was changed by a failed run"
fi
status=0
"$exe" simulate --action grand --input csv:bad_value.csv --duration 0.05 --out keep.csv \
  >stdout.txt 2>stderr.txt || status=$?
if [[ $status -eq 0 ]]; then fail "existing --out file (CSV input): exit code 0"; fi
if ! cmp -s keep.csv keep.expected; then
  fail "existing --out file (CSV input): keep.csv was changed by a failed run"
fi
if compgen -G "keep.csv?*" >/dev/null || compgen -G ".keep.csv*" >/dev/null; then
  fail "existing --out file: a temporary file was left behind: $(ls -a)"
fi
# a plot that cannot be written (its folder is missing) fails before the --out file is touched
status=0
"$exe" simulate --action grand --input mass:1kg --duration 0.05 --out keep.csv \
  --plot no_such_folder/plot.png >stdout.txt 2>stderr.txt || status=$?
if [[ $status -ne 2 ]]; then fail "missing --plot folder: exit code $status (expected 2)"; fi
grep -qF "no_such_folder" stderr.txt || fail "missing --plot folder: not named: $(cat stderr.txt)"
cmp -s keep.csv keep.expected || fail "missing --plot folder: keep.csv was changed"
if [[ $failures -eq $failures_before ]]; then echo "ok: existing --out file left byte-identical"; fi

# --- impossible numbers are refused before any work ---------------------------------------------
expect_failure "a key motion faster than any key moves" "motion:sine:1e6|at most 100 Hz" \
  simulate --action grand --input motion:sine:1e6 --duration 0.05 --out out.csv
expect_failure "a sweep beyond the key motion limit" "--fmax|at most 100 Hz" \
  sweep --action grand --stroke full --fstart 6 --fmax 1e9 --out out.csv
expect_failure "a trace of billions of rows" "5 million|sample less often" \
  simulate --action grand --input mass:1kg --duration 0.05 --sample-interval 1e-12 --out out.csv
expect_failure "an empty --out name" "--out|empty name" \
  simulate --action grand --input mass:1kg --duration 0.05 --out ""
expect_failure "--plot naming the --out file" "--plot|same_out.csv|also the --out file" \
  simulate --action grand --input mass:1kg --duration 0.05 --out same_out.csv --plot ./same_out.csv
printf 'time_s,key_force_n\n0.5,1\n0.6,1\n' >late_start.csv
expect_failure "a CSV starting after t = 0 away from rest" \
  "late_start.csv|line 2|key_force_n 1 N|held from 0 to 0.5 s" \
  simulate --action grand --input csv:late_start.csv --duration 0.2 --out out.csv

# --- options another choice would ignore, and values given twice ------------------------------
expect_failure "--step with an adaptive integrator" "--step|cvode chooses its own steps|--rtol" \
  simulate --action grand --input mass:1kg --duration 0.05 --integrator cvode --step 1e-4 \
  --out out.csv
expect_failure "--rtol with the fixed-step W-method" "--rtol|w2 takes a fixed --step" \
  simulate --action grand --input mass:1kg --duration 0.05 --rtol 1e-4 --out out.csv
expect_failure "a setting given twice" "--set: let_off is given twice|'let_off=1' and 'let_off=2'" \
  simulate --action grand --input mass:1kg --duration 0.05 --set let_off=1 --set let_off=2 \
  --out out.csv
expect_failure "an option read once given twice" "--duration is given 2 times|'0.05' and '0.1'" \
  simulate --action grand --input mass:1kg --duration 0.05 --duration 0.1 --out out.csv
expect_failure "two inputs" "--input is given 2 times|'mass:1kg' and 'force:const:5'" \
  simulate --action grand --input mass:1kg --input force:const:5 --duration 0.05 --out out.csv
# a step or tolerance under which the run could still end "ok" with numbers that mean nothing
expect_failure "a w2 step longer than a felt contact" "--step 0.01|at most 0.001 s" \
  simulate --action grand --input force:const:5 --duration 0.1 --step 0.01 --out out.csv
expect_failure "a w2 step near the duration" "--step 0.001|at least 10 steps|--duration 0.005" \
  simulate --action grand --input force:const:5 --duration 0.005 --step 0.001 --out out.csv
# the default step too: a run shorter than 10 of them had taken one step and said step_s 1e-5
expect_failure "a run shorter than 10 default steps" "--duration 1e-9|at least 10 steps|a smaller --step" \
  simulate --action grand --input force:const:5 --duration 1e-9 --out out.csv
expect_failure "a step that would take hours" "--step 1e-12|at least 1e-7 s" \
  simulate --action grand --input force:const:5 --duration 0.1 --step 1e-12 --out out.csv
expect_failure "a tolerance finer than any comparison needs" "--rtol 1e-20|at least 1e-10" \
  simulate --action grand --input force:const:5 --duration 0.1 --integrator rodas --rtol 1e-20 \
  --out out.csv
expect_failure "a spring factor given twice" "--spring-factor: repetition_spring is given twice" \
  touchweight --action grand --spring-factor repetition_spring=2 \
  --spring-factor repetition_spring=3 --out out.csv
expect_failure "a part left out twice" "--without: bridle is given twice" \
  simulate --action upright --input mass:1kg --duration 0.05 --without bridle --without bridle \
  --out out.csv
expect_failure "a tolerance of 50 %" "--rtol 0.5|at most 0.1" \
  simulate --action grand --input force:const:5 --duration 0.1 --integrator rodas --rtol 0.5 \
  --out out.csv
expect_failure "a press faster than any key" "motion:press:1e-9|at least 0.005 s" \
  simulate --action grand --input motion:press:1e-9 --duration 0.05 --out out.csv
expect_failure "a chirp sweep given the steps' increment" "--step-hz|--rate" \
  sweep --action grand --stroke full --step-hz 1 --out out.csv
expect_failure "an engine message keeps one prefix" "pianoaction study: unknown study 'foo'" \
  study foo
if grep -qF "study: study:" stderr.txt; then fail "the study's message repeats its prefix"; fi
expect_failure "a plot file without an extension" "no file extension to tell the plot format" \
  simulate --action grand --input mass:1kg --duration 0.05 --plot noextension

# --- an output never replaces a file the command reads ---------------------------------------------
# expect_input_kept "DESCRIPTION" FILE ARGS...: refused (exit 2, stderr names FILE and what reads
# it) and FILE unchanged byte for byte
expect_input_kept() {
  local description="$1" file="$2"
  shift 2
  cases=$((cases + 1))
  cp "$file" kept_copy
  local status=0
  "$exe" "$@" >stdout.txt 2>stderr.txt || status=$?
  if [[ $status -ne 2 ]]; then
    fail "$description: exit code $status (expected 2) for: $*"
  elif ! grep -qF "$file is " stderr.txt || ! grep -qF "which this command reads" stderr.txt; then
    fail "$description: the message does not name the input: $(cat stderr.txt)"
  elif ! cmp -s "$file" kept_copy; then
    fail "$description: $file was overwritten"
  else
    echo "ok: $description: $(head -n 1 stderr.txt)"
  fi
}
printf 'time_s,key_force_n\n0,0\n0.05,5\n0.1,0\n' >force_input.csv
expect_input_kept "--out onto the --input CSV" force_input.csv \
  simulate --action grand --input csv:force_input.csv --duration 0.05 --out force_input.csv
cp "$grand" own_preset.json
mkdir -p sub
expect_input_kept "--out onto the --action preset (another spelling of its path)" own_preset.json \
  simulate --action own_preset.json --input mass:1kg --duration 0.01 --out ./sub/../own_preset.json
# --action grand reads the shipped preset: an --out onto it is refused (a copy of the presets,
# found through PAT_PRESET_DIR, so that a failure here cannot spoil the source tree's)
mkdir -p shipped
cp "$source_dir"/presets/*.json shipped/
PAT_PRESET_DIR="$PWD/shipped" expect_input_kept "--out onto the shipped preset of --action grand" \
  "$PWD/shipped/grand.json" \
  simulate --action grand --input mass:1kg --duration 0.01 --out "$PWD/shipped/grand.json"
if ! grep -qF "the shipped preset of --action grand" stderr.txt; then
  fail "the shipped preset is not named: $(cat stderr.txt)"
fi
# an option's value that only happens to name a file is not an input: a file called 'grand'
# here is not what --action grand reads, and may be an output
cases=$((cases + 1))
printf 'old\n' >grand
if "$exe" simulate --action grand --input mass:1kg --duration 0.01 --out grand >stdout.txt \
  2>stderr.txt && grep -q '^time_s' grand; then
  echo "ok: --out onto a file that only shares --action's value is written"
else
  fail "--out grand (a file that is not the preset) was refused: $(cat stderr.txt)"
fi
printf '0 1 2\n' >raw_input.txt
expect_input_kept "import-raw --out onto its raw trace" raw_input.txt \
  import-raw raw_input.txt --rate 2000 --out raw_input.txt
if ! grep -qF "the raw trace" stderr.txt; then fail "import-raw: the raw trace is not named"; fi

# a CSV plot's second file (over another x axis) must not replace the --out file, and nothing is
# written then
cases=$((cases + 1))
rm -f swept.csv swept_time_s.csv
printf 'keep\n' >swept_time_s.csv
status=0
"$exe" sweep --action upright --stroke full --fstart 2 --fmax 4 --plot swept.csv \
  --out swept_time_s.csv >stdout.txt 2>stderr.txt || status=$?
if [[ $status -ne 2 ]] || ! grep -qF "which is the --out file" stderr.txt; then
  fail "a plot's second CSV onto --out: exit $status, stderr: $(cat stderr.txt)"
elif [[ "$(cat swept_time_s.csv)" != "keep" || -e swept.csv ]]; then
  fail "a plot's second CSV onto --out: a file was written"
else
  echo "ok: a plot's second CSV onto --out is refused: $(head -n 1 stderr.txt)"
fi

# --- a run that blows up says so (a step too long for a 20 N press), it does not report "ok" ------
cases=$((cases + 1))
status=0
"$exe" simulate --action grand --input force:const:20 --duration 0.1 --step 1e-3 --json \
  >stdout.txt 2>stderr.txt || status=$?
if ! grep -q '"status": "stopped"' stdout.txt || ! grep -q "diverged" stdout.txt; then
  fail "a diverging run: not reported as stopped and diverged: $(cat stdout.txt stderr.txt)"
elif [[ $status -ne 3 ]] || ! grep -q "the run stopped at t = .*diverged" stderr.txt; then
  fail "a stopped run: exit code $status (expected 3) or no cause on stderr: $(cat stderr.txt)"
else
  echo "ok: a diverging run is stopped, exit code 3: $(grep stop_cause stdout.txt)"
fi

# --- a run that leaves the action's geometry names the part that went out of its travel --------
# (the grand's jack 1.2 mm forward misses the knuckle, and the let-off button turns it 55°)
cases=$((cases + 1))
"$exe" simulate --action grand --set jack_position=-0.5 --input force:pulse:40:60 --duration 0.3 \
  --json >stdout.txt 2>stderr.txt || true
if ! grep -q '"status": "stopped"' stdout.txt || ! grep -q "just before, the jack stood" stdout.txt; then
  fail "a run beyond the geometry: the part is not named: $(cat stdout.txt stderr.txt)"
else
  echo "ok: the part beyond its travel is named: $(grep stop_cause stdout.txt)"
fi

# --- a sensitivity table whose blow never strikes says so, not "no setting changes it" -------
# (5000 N on the key: every blow's run stops; the table had read "no setting changes it
# measurably" for the impact velocity)
cases=$((cases + 1))
"$exe" study sensitivity --action grand --force 5000 >stdout.txt 2>stderr.txt || true
if ! grep -q "impact_velocity_mps.*not read on the action as given: its blow did not strike" \
  stdout.txt; then
  fail "a sensitivity blow that never strikes is not named: $(tail -8 stdout.txt) $(cat stderr.txt)"
else
  echo "ok: a blow that never strikes is named in the sensitivity ranking"
fi

echo "$cases cases, $failures failures"
[[ $failures -eq 0 ]]
