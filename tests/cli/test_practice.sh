#!/usr/bin/env bash
# `pianoaction practice new` and `practice check` end to end (issue 7): the JSON keys; without
# --reveal nothing of the answer; check judges right and wrong answers for 50 seeds (no
# simulation: fast); teacher files, and a broken one named with its field.
# usage: test_practice.sh PIANOACTION_EXE PROJECT_SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/common.sh"

# practice new with and without --reveal: same symptoms, the answer only with --reveal
"$exe" practice new --action grand --seed 11 --json >hidden.json
"$exe" practice new --action grand --seed 11 --reveal --json >revealed.json
python3 - hidden.json revealed.json <<'PY'
import json, sys, re
text = open(sys.argv[1]).read()
hidden = json.loads(text); revealed = json.load(open(sys.argv[2]))
for key in ("symptoms", "observations", "action", "seed", "level"):
    assert key in hidden, "missing key %r" % key
assert hidden["symptoms"], "no symptom for seed 11"
for s in hidden["symptoms"]:
    assert set(s) >= {"id", "text", "observation"}, s
for key in ("answer", "answers", "faults"):
    assert key not in hidden, "%r without --reveal" % key
assert "adjuster" not in text, "an adjuster value without --reveal"
# no setting identifier at all (observation ids name what is measured, not the settings)
for name in ("key_dip", "jack_position", "lever_height", "hammer_blow", "let_off"):
    assert name not in text, "setting name %r without --reveal" % name
a = revealed["answer"]
assert set(a) == {"setting", "direction"} and a["direction"] in ("more", "less"), a
assert hidden["symptoms"] == revealed["symptoms"], "--reveal changed the symptoms"
print("ok: practice new, answer %s:%s only with --reveal" % (a["setting"], a["direction"]))
PY

# practice check: the revealed answer (from the exercise alone) is right, the flipped
# direction and another setting are wrong, for 50 seeds of each action
python3 - "$exe" <<'PY'
import json, subprocess, sys
exe = sys.argv[1]
def run(*args):
    return json.loads(subprocess.run([exe, "practice", *args, "--json"], check=True,
                                     capture_output=True, text=True).stdout)
settings = {"grand": ["key_dip", "jack_position", "lever_height", "hammer_blow", "let_off", "drop",
                      "checking"],
            "upright": ["hammer_blow", "key_dip", "lost_motion", "let_off", "checking", "bridle",
                        "damper_lift"]}
flip = {"more": "less", "less": "more"}
for action, names in settings.items():
    for seed in range(50):
        s = str(seed)
        # the answer the exercise holds (--reveal), judged right; its flipped direction and
        # every other setting judged wrong
        r = run("check", "--action", action, "--seed", s, "--answer", names[0] + ":more",
                "--reveal")
        a = r["answer"]
        right = run("check", "--action", action, "--seed", s, "--answer",
                    "%s:%s" % (a["setting"], a["direction"]))
        assert right["correct"] and right["score"] == 100, (action, seed, right)
        flipped = run("check", "--action", action, "--seed", s, "--answer",
                      "%s:%s" % (a["setting"], flip[a["direction"]]))
        assert not flipped["correct"] and flipped["score"] == 40, (action, seed, flipped)
        other = [n for n in names if n != a["setting"]][seed % 6]
        wrong = run("check", "--action", action, "--seed", s, "--answer",
                    "%s:%s" % (other, a["direction"]))
        assert not wrong["correct"] and wrong["score"] == 0, (action, seed, wrong)
        if seed < 3:  # all 14 answers: exactly one is right
            hits = [(n, d) for n in names for d in ("more", "less")
                    if run("check", "--action", action, "--seed", s, "--answer",
                           "%s:%s" % (n, d))["correct"]]
            assert hits == [(a["setting"], a["direction"])], (action, seed, hits)
print("ok: practice check judges right and wrong answers for 50 seeds of each action")
PY

# the answer `new --reveal` gives is the one `check` accepts (a few seeds: `new` simulates)
for seed in 3 4; do
  "$exe" practice new --action upright --seed "$seed" --reveal --json >r.json
  answer=$(python3 -c 'import json,sys; a=json.load(open("r.json"))["answer"]; print(a["setting"]+":"+a["direction"])')
  "$exe" practice check --action upright --seed "$seed" --answer "$answer" --json | grep -q '"correct": true' ||
    { echo "FAIL: check rejects the revealed answer $answer for seed $seed" >&2; exit 1; }
done
echo "ok: the revealed answer is the one check accepts"

# teacher files: a shipped one by name, level 2 answers, a broken one named with its field
"$exe" practice check --exercise grand_two_faults --answer key_dip:less,checking:more --json |
  grep -q '"correct": true' || { echo "FAIL: two-fault exercise not judged right" >&2; exit 1; }
printf '{"schema": "pat-exercise/1", "action": "upright", "faults": [{"setting": "drop", "adjuster_mm": 1}]}' >bad.json
if "$exe" practice new --exercise bad.json --json >/dev/null 2>err.txt; then
  echo "FAIL: an impossible exercise was accepted" >&2; exit 1; fi
grep -q "bad.json: faults\[0\].setting: unknown setting 'drop'" err.txt ||
  { echo "FAIL: message: $(cat err.txt)" >&2; exit 1; }
printf '{"schema": "pat-exercise/1", ' >cut.json
set +e; "$exe" practice check --exercise cut.json --answer drop:more 2>err.txt; status=$?; set -e
[[ $status == 2 ]] && grep -q "cut.json: not valid JSON" err.txt ||
  { echo "FAIL: broken file: exit $status, $(cat err.txt)" >&2; exit 1; }
if "$exe" practice check --action grand --seed 1 --answer let_off:closer 2>err.txt; then
  echo "FAIL: bad direction accepted" >&2; exit 1; fi
grep -q "more' or 'less'" err.txt || { echo "FAIL: message: $(cat err.txt)" >&2; exit 1; }
echo "ok: exercise files and bad input"
