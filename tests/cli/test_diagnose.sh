#!/usr/bin/env bash
# `pianoaction synth` and `pianoaction diagnose` end to end: a synthetic file in the measured
# format, a diagnosis with its JSON keys and report files, an --effect in simulate, and bad input
# (each a non-zero exit code and a message naming the problem).
# usage: test_diagnose.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/common.sh"
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# synth: metadata and columns
"$exe" synth --action grand --input mass:1kg --duration 0.3 --effect repetition_spring=2.5 \
  --noise-deg 0.3 --fps 2000 --time-offset-ms 3 --angle-offset-deg 0.2 --seed 7 --out mass.csv
grep -q '^# action: grand' mass.csv || fail "synth: no '# action:' line"
grep -q '^# input: mass:1kg' mass.csv || fail "synth: no '# input:' line"
grep -q '^time_s,hammer_angle_deg,key_angle_deg' mass.csv || fail "synth: header"
rows=$(grep -vc '^#' mass.csv)
[[ "$rows" -eq 602 ]] || fail "synth: expected 601 rows + header, got $rows lines"
"$exe" synth --action grand --input motion:sine:4 --duration 0.3 --effect repetition_spring=2.5 \
  --noise-deg 0.3 --seed 8 --out sine.csv

# simulate takes --effect too
"$exe" simulate --action grand --input force:pulse:20:60 --duration 0.1 --effect shank_flex=120 \
  --json >sim.json || fail "simulate --effect"
grep -q '"impact"' sim.json || fail "simulate --effect: no impact"

# diagnose: keys and report
"$exe" diagnose --action grand --measured mass.csv --measured sine.csv \
  --candidate repetition_spring --candidate joint_friction.hammer --report report --json >d.json \
  || fail "diagnose failed"
for key in baseline_rms_deg extended_rms_deg gain cause ranking discrepancies measured_events; do
  grep -q "\"$key\"" d.json || fail "diagnose: no key $key"
done
grep -q '"effect": "repetition_spring"' d.json || fail "diagnose: the hidden spring is not named"
for f in diagnosis.json ranking.csv phases.csv mass_traces.csv sine_traces.csv diagnosis.png; do
  [[ -s "report/$f" ]] || fail "diagnose --report: no $f"
done
# what the gain is measured on, each trial's held-out error, and the extended model by phase
grep -q '"gain_measured_on": "held-out trials' d.json || fail "diagnose: gain_measured_on"
grep -q '"held_out": {' d.json || fail "diagnose: no per-trial held-out error"
head -1 report/phases.csv | grep -q 'extended_rms_deg,extended_mean_deg' ||
  fail "phases.csv: no extended_rms_deg/extended_mean_deg columns"

# DESIGN.md's form, "--measured CSV...": several files after one option read as the repeated form
"$exe" diagnose --action grand --measured mass.csv sine.csv --candidate repetition_spring \
  --candidate joint_friction.hammer --json >d2.json || fail "diagnose --measured A B failed"
grep -q '"effect": "repetition_spring"' d2.json || fail "--measured A B: the spring is not named"
[[ "$(grep '"baseline_rms_deg"' d.json)" == "$(grep '"baseline_rms_deg"' d2.json)" ]] ||
  fail "--measured A B: baseline differs from --measured A --measured B (not both files read?)"

# two files of one name in two folders: a traces file each (the second had replaced the first's),
# phases.csv naming them by their paths
mkdir -p a b
cp mass.csv a/trial.csv
cp sine.csv b/trial.csv
"$exe" diagnose --action grand --measured a/trial.csv b/trial.csv --candidate repetition_spring \
  --report same_names >/dev/null || fail "diagnose of two files of one name failed"
for f in trial_1_traces.csv trial_2_traces.csv; do
  [[ -s "same_names/$f" ]] || fail "diagnose --report, files of one name: no $f"
done
grep -q '^a/trial.csv,' same_names/phases.csv && grep -q '^b/trial.csv,' same_names/phases.csv ||
  fail "phases.csv does not tell the two trial.csv apart: $(cut -d, -f1 same_names/phases.csv | sort -u)"

# bad input
expect_failure() {
  local what="$1" expected="$2"
  shift 2
  local status=0
  "$exe" "$@" >out.txt 2>err.txt || status=$?
  [[ $status -eq 2 ]] || fail "$what: exit code $status, expected 2"
  grep -qF -- "$expected" err.txt || fail "$what: message lacks '$expected': $(cat err.txt)"
}
printf 'time_s,key_angle_deg\n0,0\n' >nohammer.csv
expect_failure "missing column" "missing column 'hammer_angle_deg'" \
  diagnose --action grand --measured nohammer.csv
expect_failure "list option without a file" "option --measured needs a value" \
  diagnose --action grand --measured
expect_failure "wrong action" "but the upright action was requested" \
  diagnose --action upright --measured mass.csv
expect_failure "unknown effect" "unknown effect 'wobble'" \
  synth --action grand --input mass:1kg --duration 0.1 --effect wobble=1 --out x.csv
[[ ! -e x.csv ]] || fail "synth wrote a file despite a bad effect"
expect_failure "noise beyond a sensor's" "--noise-deg must be from 0 to 10 degrees" \
  synth --action grand --input mass:1kg --duration 0.1 --noise-deg 1e308 --out x.csv
[[ ! -e x.csv ]] || fail "synth wrote a file despite a noise of 1e308 degrees"
expect_failure "effect range" "outside its physical range" \
  simulate --action grand --input mass:1kg --duration 0.1 --effect joint_friction.hammer=1000
# an option's value given twice, which one of them would silently win or count twice
expect_failure "synth effect twice" "--effect: shank_flex is given twice" \
  synth --action grand --input mass:1kg --duration 0.1 --effect shank_flex=100 \
  --effect shank_flex=200 --out x.csv
[[ ! -e x.csv ]] || fail "synth wrote a file despite an effect given twice"
expect_failure "candidate twice" "--candidate: shank_flex is given twice" \
  diagnose --action grand --measured mass.csv --candidate shank_flex --candidate shank_flex
expect_failure "null seeds with a family" "--null-seeds with --family" \
  bench-diagnose --null-seeds 1 --family shank_flex
# synth never replaces real measured data (import-raw's '# source:' line)
cp "$source_dir/assets/measured/kawai_kg3c_e4_strike_with_key.csv" real.csv
expect_failure "synth over real data" "the file holds real measured data" \
  synth --action grand --input mass:1kg --duration 0.1 --out real.csv
cmp -s real.csv "$source_dir/assets/measured/kawai_kg3c_e4_strike_with_key.csv" ||
  fail "synth changed a real measured file"
# a non-increasing time is named by its file line, as every other error in a file is
printf 'time_s,hammer_angle_deg\n0,0\n0.0005,0\n0.0005,1\n' >badtime.csv
awk 'BEGIN { for (i = 1; i <= 30; ++i) printf "%g,0\n", 0.001 + i * 0.0005 }' >>badtime.csv
expect_failure "time not increasing" "badtime.csv: line 4: time_s is not increasing" \
  diagnose --action grand --measured badtime.csv
# a copy of a file under another name is not another trial: it would validate the fit on the data
# it was fitted to (two copies had passed, "held out", with nothing written to say so)
cp mass.csv mass_copy.csv
rm -rf copy_report
expect_failure "a copy as a second trial" "mass_copy.csv: the same measurement as mass.csv" \
  diagnose --action grand --measured mass.csv mass_copy.csv --report copy_report
[[ ! -e copy_report ]] || fail "diagnose of a copied trial wrote its report"

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "synth/diagnose CLI: all checks passed"
