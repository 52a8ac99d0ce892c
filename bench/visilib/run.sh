#!/usr/bin/env bash
# Side by side with visilib on the same cell-to-triangle queries (docs/performance.md, "Side by side with
# visilib"). visilib is not a dependency: give a checkout of github.com/dhaumont/visilib.
#   bash bench/visilib/run.sh VISILIB_DIR SCENE.obj X0,Y0,Z0,X1,Y1,Z1 [IDS|all]
# Prints both tools' query times (one thread each) and the triangles on which visilib's answer differs from
# exactvis's exact one (each of exactvis's "visible" carries a witness re-checked exactly).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
visilib="$1"; scene="$2"; cell="$3"; ids="${4:-all}"
build="${EXACTVIS_BUILD_DIR:-$root/build}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# VISILIB_PRECISION=gmp: visilib's GMP rational arithmetic instead of its default doubles.
g++ -std=c++17 -O2 -DNDEBUG -DENABLE_GMP -I"$visilib/visilib" "$root/bench/visilib/visilib_side_by_side.cpp" \
  -o "$out/visilib_side_by_side" -lgmpxx -lgmp
"$out/visilib_side_by_side" "$scene" "$cell" "$ids" "${VISILIB_PRECISION:-double}" 2>"$out/visilib.err" |
  grep -E '^[0-9]+ (visible|hidden)$' > "$out/visilib.txt" || true
tail -1 "$out/visilib.err" >&2
/usr/bin/time -o "$out/time.txt" -f "exactvis: CPU time %U s user + %S s system (whole process, load and Embree set-up included)" \
  "$build/exactvis" visible "$scene" --cell "$cell" --triangles "$ids" --threads 1 -q -o "$out/exactvis.json" > /dev/null
cat "$out/time.txt"
/usr/bin/python3 - "$out/visilib.txt" "$out/exactvis.json" "$scene" <<'PY'
import json, sys
from fractions import Fraction as Q
v = dict(l.split() for l in open(sys.argv[1]))
e = json.load(open(sys.argv[2]))
ex = {str(r["triangle"]): r for r in e["results"]}
wrong_hidden = [t for t in ex if ex[t]["visible"] and v.get(t) == "hidden"]
wrong_visible = [t for t in ex if not ex[t]["visible"] and v.get(t) == "visible"]
print(f"exactvis: {sum(1 for t in ex if ex[t]['visible'])} of {len(ex)} visible")
print(f"visilib disagrees on {len(wrong_hidden) + len(wrong_visible)}: says hidden for {len(wrong_hidden)} "
      f"visible triangles, visible for {len(wrong_visible)} hidden ones")
# Independent re-check (Python fractions, no exactvis code) of exactvis's witnesses where visilib says hidden:
# the witness segment, as written (doubles), must miss every other triangle (closed) of the OBJ.
V, T = [], []
for line in open(sys.argv[3]):
    w = line.split()
    if w and w[0] == "v": V.append(tuple(Q(float(x)) for x in w[1:4]))
    elif w and w[0] == "f":
        f = [int(x.split("/")[0]) - 1 for x in w[1:]]
        T += [(V[f[0]], V[f[k]], V[f[k + 1]]) for k in range(1, len(f) - 1)]
sub = lambda a, b: (a[0] - b[0], a[1] - b[1], a[2] - b[2])
cross = lambda a, b: (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
dot = lambda a, b: a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def meets(p, q, t):
    a, b, c = t
    n = cross(sub(b, a), sub(c, a))
    dp, dq = dot(n, sub(p, a)), dot(n, sub(q, a))
    if dp * dq > 0: return False
    if dp == 0 and dq == 0: return True  # coplanar: counted as blocking (conservative for this check)
    x = tuple(p[i] + dp / (dp - dq) * (q[i] - p[i]) for i in range(3))
    s = [dot(n, cross(sub(t[(k + 1) % 3], t[k]), sub(x, t[k]))) for k in range(3)]
    return all(z >= 0 for z in s) or all(z <= 0 for z in s)
checked = wrong_hidden[:20]
free = 0
for t in checked:
    p, q = [tuple(Q(c) for c in pt) for pt in ex[t]["witness"]]
    free += not any(meets(p, q, T[i]) for i in range(len(T)) if i != int(t))
print(f"re-checked {len(checked)} of those witnesses with Python fractions: {free} are free segments")
PY
