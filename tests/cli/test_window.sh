#!/usr/bin/env bash
# The window from the command line (issue 5): --screenshot works offscreen for both actions and
# writes a PNG of the whole window; simulate --plot writes PNG, PDF, SVG and CSV plots (format
# from the extension) and refuses an unknown one; --view opens a close-up and refuses an unknown
# one; --help still prints the usage.
# usage: test_window.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail

source "$(dirname "$0")/common.sh"
export QT_QPA_PLATFORM=offscreen
export XDG_CONFIG_HOME="$work/config"

fail() { echo "FAIL: $*" >&2; exit 1; }

# magic bytes of a file, as hex
magic() { head -c "$2" "$1" | od -An -tx1 | tr -d ' \n'; }

# the usage is read from a file: `--help | grep -q` under pipefail fails when grep stops reading
# before a usage longer than one pipe write has been written (SIGPIPE)
"$exe" --help > help.txt
grep -q "screenshot PNG" help.txt || fail "--help does not mention --screenshot"

for action in grand upright; do
  "$exe" --action "$action" --screenshot "shot-$action.png" > out.txt 2> err.txt \
    || { cat err.txt; fail "--screenshot exited with an error for $action"; }
  [ "$(magic "shot-$action.png" 8)" = "89504e470d0a1a0a" ] || fail "$action screenshot is not a PNG"
  python3 - "shot-$action.png" <<'PY'
import struct, sys
with open(sys.argv[1], "rb") as f:
    data = f.read(32)
width, height = struct.unpack(">II", data[16:24])
if width < 1000 or height < 700:
    sys.exit("window screenshot is only %dx%d" % (width, height))
PY
done

# a classroom projector's 1024x768: both windows, regulation dock included, open at that size
# (the grand's dock once kept its window 1039 pixels wide)
for action in grand upright; do
  XDG_CONFIG_HOME="$work/config-1024-$action" "$exe" --action "$action" --size 1024x768 \
    --screenshot "shot-1024-$action.png" > out.txt 2> err.txt \
    || { cat err.txt; fail "--size 1024x768 exited with an error for $action"; }
  python3 - "shot-1024-$action.png" "$action" <<'PY'
import struct, sys
with open(sys.argv[1], "rb") as f:
    data = f.read(32)
width, height = struct.unpack(">II", data[16:24])
if width > 1024 or height > 768:
    sys.exit("%s window at --size 1024x768 is %dx%d" % (sys.argv[2], width, height))
PY
done

# a screenshot neither reads nor changes the user's settings: with "upright" remembered and a
# larger text chosen, a screenshot without --action is the grand at the normal text size, and
# the settings file is the same byte for byte afterwards
mkdir -p "$work/config-user/PianoActionTrainer"
user_conf="$work/config-user/PianoActionTrainer/pianoaction.conf"
printf '[General]\nlast_preset=upright\n\n[view]\nlarge_text=true\n' > "$user_conf"
cp "$user_conf" user_conf_before
XDG_CONFIG_HOME="$work/config-user" "$exe" --size 800x600 --screenshot shot-user.png > out.txt \
  2> err.txt || { cat err.txt; fail "--screenshot with user settings exited with an error"; }
cmp -s "$user_conf" user_conf_before || fail "--screenshot changed the user's settings: $(cat "$user_conf")"
grep -q "^screenshot of the grand action written to shot-user.png" out.txt \
  || fail "--screenshot without --action did not show the grand at the normal text size: $(cat out.txt)"

# a close-up from the command line, and an unknown view named with the choices
"$exe" --action grand --view escapement --screenshot shot-closeup.png > out.txt 2> err.txt \
  || { cat err.txt; fail "--view escapement exited with an error"; }
[ "$(magic shot-closeup.png 8)" = "89504e470d0a1a0a" ] || fail "close-up screenshot is not a PNG"
grep -q "escapement|checking" help.txt || fail "--help does not mention --view"
if "$exe" --view sideways --screenshot x.png 2> err.txt; then fail "--view sideways accepted"; fi
grep -q -- "--view: must be whole, escapement or checking (got 'sideways')" err.txt \
  || fail "the --view error: $(cat err.txt)"
[ ! -e x.png ] || fail "a screenshot was written despite the bad --view"

# a screenshot that cannot be written is refused before the window plays its blow
if "$exe" --action grand --screenshot /nonexistent-folder/shot.png 2> err.txt; then
  fail "a screenshot into a missing folder was accepted"
fi
grep -q "the folder '/nonexistent-folder' does not exist" err.txt \
  || fail "the missing folder's error: $(cat err.txt)"
if "$exe" --action grand --screenshot shot.jpg 2> err.txt; then fail "a .jpg screenshot accepted"; fi
grep -q -- "--screenshot shot.jpg: the screenshot is a PNG" err.txt \
  || fail "the .jpg error: $(cat err.txt)"

# a broken action file is refused before any window opens
"$exe" --action /nonexistent/preset.json --screenshot x.png 2> err.txt && fail "bad --action accepted"
grep -q "preset.json" err.txt || fail "the error does not name the preset file"

for ext in png pdf svg csv; do
  "$exe" simulate --action grand --input force:pulse:20:40 --duration 0.05 --plot "trace.$ext" \
    > out.txt || fail "simulate --plot trace.$ext failed"
  [ -s "trace.$ext" ] || fail "trace.$ext is empty"
done
[ "$(magic trace.png 4)" = "89504e47" ] || fail "trace.png is not a PNG"
head -c 4 trace.pdf | grep -q "%PDF" || fail "trace.pdf is not a PDF"
grep -q "<svg" trace.svg || fail "trace.svg has no <svg"
grep -q "^time_s,key_angle_deg,hammer_angle_deg,hammer_string_gap_mm,finger_force_n" trace.csv \
  || fail "trace.csv header: $(grep -v '^#' trace.csv | head -1)"

if "$exe" simulate --action grand --input force:const:5 --duration 0.01 --plot trace.bmp \
  2> err.txt; then fail "a .bmp plot was accepted"; fi
grep -q "trace.bmp" err.txt || fail "the .bmp error does not name the file"
echo "ok"
