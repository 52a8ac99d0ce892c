#!/usr/bin/env bash
# Runs two exactvis binaries on the same inputs (the bundled scene, generated 3D scenes, small 2D scenes,
# and bad input) and diffs what they print: stdout, stderr and exit status of every command, and the bytes
# of every file written. For refactorings that must keep the command line's behaviour.
# Usage: scripts/compare-cli.sh OLD_BINARY NEW_BINARY [WORKDIR]
# Prints one line per differing command and exits 1 if any differ. Progress bars stay off (stderr is a file).
# JSON on stdout that differs only by fields the new binary adds (names in $ADDED_FIELDS, default "key",
# removed wherever they occur in the new output) is reported as "ADDITIONS ONLY", not as a difference.
set -uo pipefail
old="$1"; new="$2"
work="${3:-$(mktemp -d)}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mkdir -p "$work/in"
in="$work/in"
cp "$root/scenes/town.obj" "$in/town.obj"
"$old" generate random -n 20 -s 3 -o "$in/random.obj" 2>/dev/null
"$old" generate town -n 200 -s 5 -o "$in/gtown.obj" 2>/dev/null
"$old" generate room -n 40 -s 2 -o "$in/room.obj" 2>/dev/null
"$old" generate forest -n 100 -s 4 -o "$in/forest.obj" 2>/dev/null
cat >"$in/boxes.obj" <<'OBJ'
v 0 0 0
v 2 0 0
v 0 2 0
v 2 2 0
v 0 0 2
v 2 0 2
v 0 2 2
v 2 2 2
v 4 1 1
v 6 1 1
v 4 3 1
v 6 3 1
v 4 1 3
v 6 1 3
v 4 3 3
v 6 3 3
f 1 3 4 2
f 5 6 8 7
f 1 2 6 5
f 3 7 8 4
f 1 5 7 3
f 2 4 8 6
f 9 11 12 10
f 13 14 16 15
f 9 10 14 13
f 11 15 16 12
f 9 13 15 11
f 10 12 16 14
OBJ
cat >"$in/two.json" <<'JSON'
{"polygons": [[[0, 0], [2, 0], [2, 1], [0, 1]], [[3, 0], [4, 0.5], [3.5, 2]], [[[-1, 3], [2, 3], [2, 6], [-1, 6]], [[0, 4], [0, 5], [1, 5], [1, 4]]]]}
JSON
cat >"$in/tri.json" <<'JSON'
{"polygons": [[[0, 0], [1, 0], [0, 1]], [[2, 0], ["5/2", 1], [2, 2]], [[-2, -2], [-1, -2], [-1, -1]]]}
JSON
printf 'not json' >"$in/bad.json"

# True iff the two output directories differ only in stdout, both stdouts are JSON, and removing the added
# fields from the new one gives the old one.
only_additions() {
  diff -r -x .stdout "$1" "$2" >/dev/null 2>&1 || return 1
  /usr/bin/python3 - "$1/.stdout" "$2/.stdout" "${ADDED_FIELDS:-key}" <<'PY'
import json, sys
added = set(sys.argv[3].split(","))
def strip(x):
    if isinstance(x, dict): return {k: strip(v) for k, v in x.items() if k not in added}
    if isinstance(x, list): return [strip(v) for v in x]
    return x
try:
    old = json.load(open(sys.argv[1])); new = json.load(open(sys.argv[2]))
except Exception:
    sys.exit(1)
sys.exit(0 if strip(new) == old else 1)
PY
}

status=0
n=0
# run NAME ARGS...: ARGS may contain @OUT@, replaced by a per-binary output directory.
run() {
  local name="$1"; shift
  n=$((n + 1))
  for side in old new; do
    local bin="$old"; [ "$side" = new ] && bin="$new"
    local out="$work/$side/$name"
    rm -rf "$out"; mkdir -p "$out"
    local args=()
    for a in "$@"; do args+=("${a//@OUT@/$out}"); done
    (cd "$in" && "$bin" "${args[@]}" >"$out/.stdout" 2>"$out/.stderr"; echo $? >"$out/.status")
    sed -i "s#$out#@OUT@#g" "$out/.stdout" "$out/.stderr"  # output paths differ by side
  done
  if ! diff -r "$work/old/$name" "$work/new/$name" >"$work/$name.diff" 2>&1; then
    if only_additions "$work/old/$name" "$work/new/$name"; then
      echo "ADDITIONS ONLY: $name ($*)"
    else
      echo "DIFFERS: $name ($*): see $work/$name.diff"
      status=1
    fi
  fi
}

for s in town.obj random.obj gtown.obj room.obj forest.obj boxes.obj; do
  b="${s%.obj}"
  run "info-$b" info "$s"
  run "info-json-$b" info "$s" --json
  run "export-$b" export "$s" -o @OUT@/x.vtp
done
for k in random town forest room; do
  for f in obj off ply stl; do run "generate-$k-$f" generate "$k" -n 300 -s 9 -o "@OUT@/g.$f"; done
done
run generate-bad-kind generate cave -n 300 -o @OUT@/g.obj
run generate-bad-n generate town -n 5 -o @OUT@/g.obj
run generate-neg-seed generate town -n 50 -s -1 -o @OUT@/g.obj

run visible-town visible town.obj --cell 0.5,0.5,1,2,2,2 --threads 1 -q
run visible-town-json visible town.obj --cell 0.5,0.5,1,2,2,2 --threads 1 -q --json -o @OUT@/v.json --vtp @OUT@/v.vtp
run visible-room visible room.obj --cell 1,1,0.5,2,2,1.5 --threads 1 -q --json
run visible-gtown visible gtown.obj --cell 1,1,1,3,3,2 --threads 1 -q --json --samples 4 --seed 7
run visible-poly visible boxes.obj --source-polygon "-1,0,0;-1,3,0;-1,3,3;-1,0,3" --threads 1 -q --json
run visible-poly-rational visible boxes.obj --source-polygon "-1,0,0;-1,7/2,0;-1,7/2,3;-1,0,3" --threads 1 -q --json
run visible-some visible boxes.obj --cell -2,0,0,-1,2,2 --triangles 0,3,12,13 --threads 1 -q --json
run visible-bad-cell visible boxes.obj --cell 1,0,0,0,1,1 -q
run visible-bad-cell2 visible boxes.obj --cell 1,0,0 -q
run visible-bad-cell3 visible boxes.obj --cell a,0,0,1,1,1 -q
run visible-bad-tri visible boxes.obj --cell -2,0,0,-1,2,2 --triangles 99 -q
run visible-bad-poly visible boxes.obj --source-polygon "0,0,0;1,0,0;2,0,0" -q
run visible-no-source visible boxes.obj -q

run events-boxes events boxes.obj
run events-json-boxes events boxes.obj --json --vtp @OUT@/e.vtp
run events-nosplit-boxes events boxes.obj --json --no-split
for s in random.obj room.obj; do
  b="${s%.obj}"
  run "events-$b" events "$s" --kinds EV
  run "events-json-$b" events "$s" --kinds EV --json --vtp @OUT@/e.vtp
  run "events-nosplit-$b" events "$s" --kinds EV --json --no-split
done
run events-eee-light-random events random.obj --kinds EEE --light "-20,-20,70;20,-20,70;0,20,70" --json --vtp @OUT@/e.vtp
run events-town-light events town.obj --light "28,18,8;32,18,8;32,22,8;28,22,8" --json
run events-town-light-text events town.obj --light "28,18,8;32,18,8;32,22,8;28,22,8" --kinds EV
run events-gtown-ev events gtown.obj --kinds EV --json
run events-forest-ev events forest.obj --kinds EV
run events-light events gtown.obj --light "1,1,9;3,1,9;3,3,9" --json
run events-light-eee events boxes.obj --kinds EEE --light "-1,0,0;-1,3,0;-1,3,3" --json
run events-bad-kind events boxes.obj --kinds EF
run events-bad-light events boxes.obj --light "1,2;3"
run events-bad-light2 events boxes.obj --light "nothing"
run events-bad-light3 events boxes.obj --light "0,0,5;1,0,5;2,0,5"

for s in two.json tri.json; do
  b="${s%.json}"
  run "complex2d-$b" complex2d "$s"
  run "complex2d-json-$b" complex2d "$s" --json --svg @OUT@/c.svg --vtp @OUT@/c.vtp
  run "aspect2d-$b" aspect2d "$s"
  run "aspect2d-json-$b" aspect2d "$s" --json --svg @OUT@/a.svg --vtp @OUT@/a.vtp
done
run vis2d-two visibility2d two.json --from 2.5,2 --svg @OUT@/v.svg
run vis2d-two-sweep visibility2d two.json --from 5/2,2 --method sweep
run vis2d-tri visibility2d tri.json --from 1,1
run vis2d-seg visibility2d two.json --from-segment -2,-1,-2,7 --to-segment 5,-1,5,7
run vis2d-seg-sweep visibility2d two.json --from-segment -2,-1,-2,7 --to-segment 5,-1,5,7 --method sweep
run vis2d-inside visibility2d two.json --from 1,0.5
run vis2d-bad visibility2d two.json --from 1
run complex2d-badjson complex2d bad.json
run complex2d-slice complex2d boxes.obj --slice z=1 --json
run complex2d-slice-room complex2d room.obj --slice z=1/3 --json
run aspect2d-slice aspect2d boxes.obj --slice z=1.5 --json
run slice-vertex complex2d boxes.obj --slice z=2
run slice-bad complex2d boxes.obj --slice w=2
run slice-miss complex2d boxes.obj --slice z=9
echo "$n commands compared in $work"
exit $status
