#!/usr/bin/env bash
# --plot FILE on every headless subcommand that computes something to plot (issue 5): each
# writes a PNG with one 300 px band per plot, the CSV export carries the plotted columns over
# the command's own x axis, and a wrong extension is refused before any work, naming the file
# and writing nothing. (study sensitivity and bench-diagnose take a minute and more; their
# plots go through the same PlotOption and export code.)
# usage: test_plot.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -uo pipefail

source "$(dirname "$0")/common.sh"
export QT_QPA_PLATFORM=offscreen
export XDG_CONFIG_HOME="$work/config"
failures=0
fail() { echo "FAIL: $*" >&2; failures=$((failures + 1)); }

# png_plots FILE: the number of stacked plots in a PNG (its height / 300), 0 if not a PNG
png_plots() {
  python3 - "$1" <<'PY'
import struct, sys
try:
    data = open(sys.argv[1], "rb").read(32)
except OSError:
    print(0); sys.exit()
if data[:8] != b"\x89PNG\r\n\x1a\n":
    print(0); sys.exit()
width, height = struct.unpack(">II", data[16:24])
print(height // 300 if width == 1000 and height % 300 == 0 else 0)
PY
}

# expect NAME MIN_PLOTS COMMAND...: the command succeeds and writes NAME.png with at least
# MIN_PLOTS plots
expect() {
  local name="$1" min="$2"
  shift 2
  if ! "$exe" "$@" --plot "$name.png" >"$name.out" 2>"$name.err"; then
    fail "$*: exit code $? ($(tail -1 "$name.err"))"
    return
  fi
  local n
  n="$(png_plots "$name.png")"
  [ "$n" -ge "$min" ] || fail "$*: $name.png has $n plots, expected at least $min"
}

awk 'BEGIN {
  for (i = 0; i < 600; i++) {
    t = i / 2000; a = 0
    if (t > 0.08) a = (t < 0.095) ? 1 - 0.2 * (1 - cos(3.14159265 * (t - 0.08) / 0.015)) : 0.6
    else if (t > 0.06) a = ((t - 0.06) / 0.02) ^ 2
    printf "%f\n", 0.3 + 0.5 * a
  }
}' >raw.txt

expect regulate 3 regulate --action grand --set let_off=0.3 --quiet
expect measure 1 measure --action grand --set checking=1
expect deregulate 4 deregulate --action grand --setting hammer_blow --rate 2 --duration 1
expect sweep_steps 2 sweep --action grand --stroke full --mode steps --fstart 6 --fmax 7 \
  --step-hz 1
expect swing 2 swing --action grand
expect keyfall 2 keyfall --action grand --duration 0.2
expect touchweight 1 touchweight --action upright
expect double_blow 1 study double-blow --action upright --duration 0.15
expect compare 3 study compare --duration 0.1 --no-limits
expect synth 1 synth --action grand --input force:pulse:20:40 --duration 0.12 --out synth.csv
expect import_raw 2 import-raw raw.txt --rate 2000 --out imported.csv
"$exe" synth --action grand --input force:pulse:20:40 --duration 0.12 --noise-deg 0.05 \
  --out measured.csv >/dev/null || fail "synth for the diagnosis failed"
# one trial: measured vs both models and the residuals, then the ranking
expect diagnose 3 diagnose --action grand --measured measured.csv --candidate shank_flex
expect bench 2 bench --duration 0.02
expect bench_window 1 bench --window --duration 0.3 --trials 2
expect practice 2 practice new --action grand --seed 3

# the CSV export of a plot over another x axis: the touchweight against the key dip
# plots over two x axes as CSV: those sharing the first plot's rows in the file named, the others
# beside it (a sweep: strikes per cycle over frequency, the chirp run over time)
"$exe" sweep --action grand --stroke full --fstart 6 --fmax 7 --plot two_axes.csv --json \
  >two_axes.json 2>two_axes.err || fail "sweep --plot csv over two axes: $(cat two_axes.err)"
grep -q "^frequency_hz," two_axes.csv || fail "two_axes.csv: $(grep -v '^#' two_axes.csv | head -1)"
grep -q "^time_s,key_angle_deg" two_axes_time_s.csv \
  || fail "two_axes_time_s.csv: $(grep -v '^#' two_axes_time_s.csv 2>&1 | head -1)"
grep -qF "went to two_axes_time_s.csv" two_axes.err || fail "the second file is not named"
python3 -c 'import json,sys; json.load(open(sys.argv[1]))' two_axes.json \
  || fail "the note broke --json's stdout"
# an exercise's observations, one plot per unit over differently named observations: a table
# each, the further ones named after their plot (a CSV had been refused here)
"$exe" practice new --action grand --seed 3 --plot observed.csv >/dev/null 2>observed.err \
  || fail "practice new --plot csv: $(cat observed.err)"
grep -q "^observation_index,difference" observed_observed_minus_regulated_mm.csv \
  || fail "observed_observed_minus_regulated_mm.csv: $(grep -v '^#' \
    observed_observed_minus_regulated_mm.csv 2>&1 | head -1)"
grep -qF "went to observed_observed_minus_regulated_mm.csv" observed.err \
  || fail "the practice plot's further files are not named: $(cat observed.err)"
"$exe" touchweight --action grand --plot weights.csv >/dev/null || fail "touchweight --plot csv"
grep -q "^dip_mm,downweight_g,upweight_g" weights.csv \
  || fail "weights.csv header: $(grep -v '^#' weights.csv | head -1)"

# a wrong extension: refused before the regulation runs, the file named, nothing written
start=$(date +%s)
if "$exe" regulate --action grand --plot steps.bmp >out.txt 2>err.txt; then
  fail "regulate accepted a .bmp plot"
fi
grep -q "steps.bmp" err.txt || fail "the .bmp error does not name the file: $(cat err.txt)"
[ ! -e steps.bmp ] || fail "steps.bmp was written"
grep -q "pass 1" out.txt && fail "regulate ran before refusing the plot file"

[ "$failures" -eq 0 ] || exit 1
echo "ok"
