#!/usr/bin/env bash
# `pianoaction import-raw` end to end: a synthetic two-column raw trace (24-bit counts in column 2)
# becomes a measured-data file that diagnose's reader accepts; bad input fails with exit code 2,
# a message naming the file / line / option and the problem, and no output file (an existing one
# is left as it was).
# usage: test_import_raw.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/common.sh"
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# 0.3 s at 2000 samples/s: rest, a quadratic rise to the string at 80 ms, a rebound into check.
# Column 1: a constant normalized reading; column 2: a sensor in 24-bit counts.
awk 'BEGIN {
  for (i = 0; i < 600; i++) {
    t = i / 2000; a = 0
    if (t > 0.08) a = (t < 0.095) ? 1 - 0.4 * 0.5 * (1 - cos(3.14159265 * (t - 0.08) / 0.015)) : 0.6
    else if (t > 0.06) a = ((t - 0.06) / 0.02) ^ 2
    printf "0.5, %d\n", 3600000 + int(4200000 * a)
  }
}' >strike.txt

"$exe" import-raw strike.txt --rate 2000 --column 2 --out strike.csv --json >import.json \
  || fail "import-raw failed"
grep -q '^# action: grand' strike.csv || fail "no '# action: grand' line"
grep -q '^# calibration: estimated' strike.csv || fail "no '# calibration:' line"
grep -q '^# source: strike.txt column 2' strike.csv || fail "no '# source:' line"
grep -q '^time_s,hammer_angle_deg,sensor_reading$' strike.csv || fail "header"
rows=$(grep -vc '^#' strike.csv)
[[ "$rows" -eq 601 ]] || fail "expected 600 rows + header, got $rows lines"
for key in samples contact_angle_deg strike peak_t_s peak_angle_deg rest_reading; do
  grep -q "\"$key\"" import.json || fail "import-raw --json: no key $key"
done
grep -q '"peak_t_s": 0.08' import.json || fail "the strike's peak is not at 0.08 s: $(cat import.json)"
grep -q '"counts": true' import.json || fail "24-bit counts not detected"
# a window of the file
"$exe" import-raw strike.txt --rate 2000 --column 2 --from 0.02 --to 0.2 --out window.csv \
  >/dev/null || fail "import-raw --from/--to failed"
rows=$(grep -vc '^#' window.csv)
[[ "$rows" -eq 362 ]] || fail "--from 0.02 --to 0.2: expected 361 rows + header, got $rows lines"

# bad input: exit code 2, the message, and no output file
expect_failure() {
  local what="$1" expected="$2"
  shift 2
  rm -f out.csv
  local status=0
  "$exe" import-raw "$@" --out out.csv >out.txt 2>err.txt || status=$?
  [[ $status -eq 2 ]] || fail "$what: exit code $status, expected 2"
  grep -qF -- "$expected" err.txt || fail "$what: message lacks '$expected': $(cat err.txt)"
  [[ ! -e out.csv ]] || fail "$what: out.csv was written"
}
printf '0.2\n0.3\nx7\n' >text.txt
printf 'sensor,position_in,normalized_reading\nhammer,0,0\nhammer,0.1,1\n' >nogain.csv
printf '# hammer offset 0.5 gain 0.2\nposition_in,normalized_reading\n0,0\n0.1,0.6\n0.2,0.5\n' \
  >bump.csv
expect_failure "missing file" "missing.txt: cannot open" missing.txt --rate 2000
expect_failure "non-numeric" "text.txt: line 3, column 1: 'x7' is not a finite number" \
  text.txt --rate 2000
expect_failure "column" "line 1: column 3 is out of range" strike.txt --rate 2000 --column 3
expect_failure "rate" "--rate must be a positive" strike.txt --rate 0
expect_failure "no rate" "missing option --rate" strike.txt
expect_failure "few samples" "only 11 samples" strike.txt --rate 2000 --column 2 --from 0.1 --to 0.105
expect_failure "no strike" "no strike found in column 1" strike.txt --rate 2000 --column 1
expect_failure "calibration header" "no offset and gain for sensor 'hammer'" \
  strike.txt --rate 2000 --column 2 --calibration nogain.csv
expect_failure "calibration monotone" "bump.csv: line 5: the calibration is not monotone" \
  strike.txt --rate 2000 --column 2 --calibration bump.csv
expect_failure "two files" "one raw trace at a time" strike.txt text.txt --rate 2000
# a window beyond the recording's end names the end, not a window that "ends before it starts"
expect_failure "window beyond the end" "--from 60 s is beyond the end of the recording" \
  strike.txt --rate 2000 --column 2 --from 60 --to 70
# --bits applies to counts only: refused on normalized readings rather than ignored
expect_failure "bits on readings" "holds normalized readings in [0, 1], not ADC counts" \
  strike.txt --rate 2000 --column 1 --bits 24
# a calibration is one recording's: another's offsets and gains, or another sensor's column, are
# refused (the data set's calibration.csv names its recording and lists hammer, then damper)
printf '# Sensor calibration points for other.txt\n# hammer offset 0.5 gain 0.2\n%s\n0,0\n0.1,1\n' \
  'position_in,normalized_reading' >other.csv
expect_failure "another recording's calibration" \
  "other.csv holds the sensor offsets and gains of other.txt, not of strike.txt" \
  strike.txt --rate 2000 --column 2 --calibration other.csv
printf '# hammer offset 0.5 gain 0.2, damper offset 0.3 gain 0.5\n%s\n%s\n' \
  'sensor,position_in,normalized_reading' 'hammer,0,0' >two.csv
printf 'hammer,0.1,1\ndamper,0,0\ndamper,0.1,1\n' >>two.csv
expect_failure "another sensor's column" \
  "--column 2: in two.csv column 2 of strike.txt is the 'damper' sensor (its sensors in column order: hammer, damper)" \
  strike.txt --rate 2000 --column 2 --calibration two.csv
# the key's own sensor (--key-column): column 2 of a two-sensor recording, calibrated by the
# 'damper' rows of two.csv (the data set's name for its sensor under the back of the key)
awk 'BEGIN {
  for (i = 0; i < 600; i++) {
    t = i / 2000; a = 0; k = (t > 0.05) ? ((t < 0.08) ? (t - 0.05) / 0.03 * 0.8 : 0.8) : 0
    if (t > 0.08) a = (t < 0.095) ? 1 - 0.4 * 0.5 * (1 - cos(3.14159265 * (t - 0.08) / 0.015)) : 0.6
    else if (t > 0.06) a = ((t - 0.06) / 0.02) ^ 2
    printf "%.6f %.6f\n", 0.5 + 0.2 * a, 0.3 + 0.5 * k
  }
}' >with_key.txt
"$exe" import-raw with_key.txt --rate 2000 --column 1 --key-column 2 --calibration two.csv \
  --out with_key.csv --json >with_key.json || fail "import-raw --key-column failed"
grep -q '^time_s,hammer_angle_deg,sensor_reading,key_angle_deg,key_sensor_reading$' with_key.csv \
  || fail "--key-column: header $(grep -v '^#' with_key.csv | head -1)"
grep -q '^# key_calibration: calibration points of two.csv (damper) for column 2' with_key.csv \
  || fail "--key-column: no '# key_calibration:' line"
# 0.8 of the damper points' 0.1 in: a 2.03 mm key-front dip
grep -q '"deepest_dip_mm": 2.03' with_key.json || fail "--key-column: $(cat with_key.json)"
expect_failure "key column without points" "--key-column needs --calibration" \
  with_key.txt --rate 2000 --column 1 --key-column 2
expect_failure "key column is the hammer's" "the same column as the hammer's" \
  with_key.txt --rate 2000 --column 1 --key-column 1 --calibration two.csv
expect_failure "key column without a sensor" "two.csv has no calibration points for column 3" \
  with_key.txt --rate 2000 --column 1 --key-column 3 --calibration two.csv
# an existing output file survives a failed run
echo keep >kept.csv
"$exe" import-raw strike.txt --rate 2000 --column 1 --out kept.csv 2>/dev/null && fail "no strike accepted"
[[ "$(cat kept.csv)" == keep ]] || fail "a failed run changed an existing output file"

if [[ $failures -ne 0 ]]; then
  echo "$failures failure(s)" >&2
  exit 1
fi
echo "import-raw CLI: all checks passed"
