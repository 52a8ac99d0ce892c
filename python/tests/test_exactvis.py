"""The Python module against the command line's JSON on the same scenes, an exact re-check of every witness
(Fractions, sharing no code with the library), and the command line's messages for bad input.

Run by CTest (python/CMakeLists.txt sets PYTHONPATH, EXACTVIS_BINARY, EXACTVIS_SOURCE_DIR), or by hand:
  PYTHONPATH=build/python EXACTVIS_BINARY=build/exactvis /usr/bin/python3 -m pytest python/tests
"""

import json
import os
import subprocess
import sys
import threading
from fractions import Fraction

import numpy as np
import pytest

import exactvis

BINARY = os.environ.get("EXACTVIS_BINARY", "exactvis")
SOURCE = os.environ.get("EXACTVIS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def cli(*args):
    """(status, stdout, stderr) of `exactvis ARGS`."""
    r = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def cli_json(*args):
    status, out, err = cli(*args)
    assert status == 0, err
    return json.loads(out)


def cli_error(sub, *args):
    """The message after 'exactvis SUB: error: ' of a failing command."""
    status, out, err = cli(sub, *args)
    assert status == 1, (status, err)
    prefix = f"exactvis {sub}: error: "
    line = err.strip().splitlines()[-1]
    assert line.startswith(prefix), line
    return line[len(prefix):]


@pytest.fixture(scope="module")
def scene_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("scenes") / "random.obj"
    status, _, err = cli("generate", "random", "-n", 60, "--seed", 7, "-o", path)
    assert status == 0, err
    return str(path)


# A unit square at z = 2 over the cell [0,1]^2 x [0,1] hides the small triangle at z = 3 right above it;
# a triangle off to the side stays visible.
OCCLUDER_V = np.array([[-1, -1, 2], [2, -1, 2], [2, 2, 2], [-1, 2, 2],
                       [0.4, 0.4, 3], [0.6, 0.4, 3], [0.5, 0.6, 3],
                       [10, 0, 0], [11, 0, 0], [10, 1, 0]], dtype=np.float64)
OCCLUDER_F = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [7, 8, 9]], dtype=np.int64)


@pytest.fixture(scope="module")
def small_scene_file(tmp_path_factory):
    """The 4 triangles below as an OBJ file: events (EEE enumeration is quadratic in the edges) stay fast."""
    path = tmp_path_factory.mktemp("scenes") / "small.obj"
    with open(path, "w") as f:
        for v in OCCLUDER_V:
            f.write("v %r %r %r\n" % tuple(float(x) for x in v))
        for t in OCCLUDER_F:
            f.write("f %d %d %d\n" % tuple(int(i) + 1 for i in t))
    return str(path)


# ---- an independent exact re-check of witnesses (plain Fractions)

def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def orient(a, b, c, d):
    return dot(cross(sub(b, a), sub(c, a)), sub(d, a))


def strictly_inside_triangle(q, tri):
    a, b, c = tri
    n = cross(sub(b, a), sub(c, a))
    if dot(n, sub(q, a)) != 0:
        return False
    return all(dot(n, cross(sub(v1, v0), sub(q, v0))) > 0 for v0, v1 in ((a, b), (b, c), (c, a)))


def open_segment_meets_triangle(p, q, tri):
    """Exact: does the open segment (p, q) meet the closed triangle?"""
    a, b, c = tri
    sp, sq = orient(a, b, c, p), orient(a, b, c, q)
    if sp == 0 and sq == 0:  # coplanar: sample-free exact test by 2D projection
        n = cross(sub(b, a), sub(c, a))
        k = max(range(3), key=lambda i: abs(n[i]))
        proj = lambda v: [v[i] for i in range(3) if i != k]
        P, Q, A, B, C = map(proj, (p, q, a, b, c))
        o = lambda u, v, w: (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])
        s = 1 if o(A, B, C) > 0 else -1
        inside = lambda X: all(s * o(U, W, X) >= 0 for U, W in ((A, B), (B, C), (C, A)))
        mid = [(x + y) / 2 for x, y in zip(P, Q)]
        if inside(mid):
            return True
        for U, W in ((A, B), (B, C), (C, A)):  # proper or touching crossings of the open segment
            d1, d2, d3, d4 = o(P, Q, U), o(P, Q, W), o(U, W, P), o(U, W, Q)
            if d1 * d2 <= 0 and d3 * d4 < 0:
                return True
        return False
    if (sp > 0 and sq > 0) or (sp < 0 and sq < 0) or sp == 0 or sq == 0:
        return False  # on one side, or meeting the plane only at an endpoint (not in the open segment)
    s1, s2, s3 = orient(p, q, a, b), orient(p, q, b, c), orient(p, q, c, a)
    return (s1 >= 0 and s2 >= 0 and s3 >= 0) or (s1 <= 0 and s2 <= 0 and s3 <= 0)


def check_witness(V, F, tid, cell, w):
    p, q = [[Fraction(x) for x in w[0]], [Fraction(x) for x in w[1]]]
    lo, hi = [Fraction(x) for x in cell[:3]], [Fraction(x) for x in cell[3:]]
    assert all(l <= x <= h for l, x, h in zip(lo, p, hi)), "witness does not start in the cell"
    tri = lambda f: [[Fraction(float(x)) for x in V[v]] for v in F[f]]
    assert strictly_inside_triangle(q, tri(tid)), "witness does not end inside its triangle"
    for f in range(len(F)):
        if f != tid:
            assert not open_segment_meets_triangle(p, q, tri(f)), f"witness of {tid} crosses triangle {f}"


# ---- visible

def test_visible_hidden_and_visible_with_exact_witnesses():
    cell = (0, 0, 0, 1, 1, 1)
    vis, wit = exactvis.visible(OCCLUDER_V, OCCLUDER_F, cell=cell, exact=True)
    assert vis.dtype == bool and vis.tolist() == [True, True, False, True]
    assert wit.shape == (3, 2, 3) and isinstance(wit[0, 0, 0], Fraction)
    for j, tid in enumerate(np.flatnonzero(vis)):
        check_witness(OCCLUDER_V, OCCLUDER_F, tid, cell, wit[j])
    vis2, wit2 = exactvis.visible(OCCLUDER_V, OCCLUDER_F, cell=cell, triangles=[2, 3])
    assert vis2.tolist() == [False, True] and wit2.shape == (1, 2, 3) and wit2.dtype == np.float64


def test_visible_matches_cli_json(scene_file):
    cell = "0.1,0.2,0.1,0.4,0.5,0.3"
    j = cli_json("visible", scene_file, "--cell", cell, "--json", "-q")
    scene = exactvis.load_scene(scene_file)
    cell_t = (0.1, 0.2, 0.1, 0.4, 0.5, 0.3)
    for V, F in ((scene_file, None), (scene.vertices, scene.faces)):
        vis, wit, stats = exactvis.visible(V, F, cell=cell_t, exact=True, stats=True)
        rows = j["results"]
        ids = [r["triangle"] for r in rows]
        if F is not None:  # arrays: triangle id = row of F (the file's ids renumbered)
            ids = [int(np.flatnonzero(scene.ids == i)[0]) for i in ids]
        assert vis[ids].tolist() == [r["visible"] for r in rows]
        exact_cli = [[[exactvis.fraction(x) for x in pt] for pt in r["witness"]] for r in rows if r["visible"]]
        assert wit.tolist() == exact_cli
        assert stats["visible"] == j["stats"]["visible"] and stats["queries"] == j["stats"]["queries"]
    V, F = scene.vertices, scene.faces
    for k, tid in enumerate(np.flatnonzero(vis)):
        check_witness(V, F, tid, cell_t, wit[k])


def test_visible_subset_polygon_source_and_fractions(scene_file):
    poly = "0,0,0;1/2,0,0;0,1/2,0"
    j = cli_json("visible", scene_file, "--source-polygon", poly, "--triangles", "3,1,4", "--json", "-q")
    vis, wit = exactvis.visible(scene_file, source_polygon=[(0, 0, 0), (Fraction(1, 2), 0, 0), (0, "1/2", 0)],
                                triangles=[3, 1, 4])
    assert vis.tolist() == [r["visible"] for r in j["results"]]
    assert wit.tolist() == [[[float(exactvis.fraction(x)) for x in p] for p in r["witness"]]
                            for r in j["results"] if r["visible"]]


def test_visible_progress_and_threads():
    calls = []
    vis, _ = exactvis.visible(OCCLUDER_V, OCCLUDER_F, cell=(0, 0, 0, 1, 1, 1), threads=2,
                              progress=lambda done, total: calls.append((done, total)))
    assert len(calls) == 4 and calls[-1] == (4, 4) and sorted(calls) == calls

    def boom(done, total):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        exactvis.visible(OCCLUDER_V, OCCLUDER_F, cell=(0, 0, 0, 1, 1, 1), progress=boom)


def test_visible_releases_the_gil(scene_file):
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    # A long switch interval: the interpreter does not hand the GIL to the ticker while the callback's Python
    # code runs, so the ticker advances between two callbacks only if the C++ query released the GIL.
    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    t = threading.Thread(target=ticker)
    t.start()
    try:
        seen = []
        exactvis.visible(scene_file, cell=(0.1, 0.2, 0.1, 0.4, 0.5, 0.3), threads=1,
                         progress=lambda d, n: seen.append(len(ticks)))
    finally:
        stop.set()
        t.join()
        sys.setswitchinterval(interval)
    # The other thread ran while the query ran (between the first and the last triangle).
    assert len(seen) > 1 and seen[-1] > seen[0]


def test_visible_bad_input_messages_as_cli(scene_file, tmp_path):
    cases = [
        (dict(cell=(1, 0, 0, 0, 1, 1)), ["--cell", "1,0,0,0,1,1"]),
        (dict(cell=(0, 0, 0, 1, 1)), ["--cell", "0,0,0,1,1"]),
        (dict(cell=(0, 0, 0, 1, 1, float("nan"))), ["--cell", "0,0,0,1,1,nan"]),
        (dict(cell=(0, 0, 0, 1, 1, 1), triangles=[999999]), ["--cell", "0,0,0,1,1,1", "--triangles", "999999"]),
        (dict(source_polygon=[(0, 0, 0), (1, 0, 0), (2, 0, 0)]), ["--source-polygon", "0,0,0;1,0,0;2,0,0"]),
        (dict(cell=(0, 0, 0, 1, 1, 1), seed="x"), ["--cell", "0,0,0,1,1,1", "--seed", "x"]),
        (dict(cell=(0, 0, 0, 1, 1, 1), threads=-1), ["--cell", "0,0,0,1,1,1", "--threads", "-1"]),
        (dict(cell=(0, 0, 0, 1, 1, 1), source_polygon=[(0, 0, 0)]), None),
    ]
    for kwargs, args in cases:
        with pytest.raises(ValueError) as e:
            exactvis.visible(scene_file, **kwargs)
        if args is not None:
            assert str(e.value) == cli_error("visible", scene_file, *args)
    missing = str(tmp_path / "missing.obj")
    with pytest.raises(ValueError) as e:
        exactvis.visible(missing, cell=(0, 0, 0, 1, 1, 1))
    assert str(e.value) == cli_error("visible", missing, "--cell", "0,0,0,1,1,1")
    with pytest.raises(ValueError, match=r"^F: face 0 refers to vertex 7, out of range \[0, 3\)$"):
        exactvis.visible(np.eye(3), np.array([[0, 1, 7]]), cell=(0, 0, 0, 1, 1, 1))
    with pytest.raises(ValueError, match=r"^V: vertex 1 has a non-finite coordinate$"):
        exactvis.visible(np.array([[0, 0, 0], [np.inf, 0, 0], [0, 1, 0]]), np.array([[0, 1, 2]]),
                         cell=(0, 0, 0, 1, 1, 1))
    with pytest.raises(ValueError, match=r"^F: expected an m x 3 array"):
        exactvis.visible(np.eye(3), np.array([[0.0, 1.0, 2.0]]), cell=(0, 0, 0, 1, 1, 1))


def test_degenerate_faces_are_not_visible():
    V = np.vstack([OCCLUDER_V, [[5, 5, 5], [6, 6, 6], [7, 7, 7]]])
    F = np.vstack([OCCLUDER_F, [[10, 11, 12]]])  # a zero-area face: dropped, as the command line does
    scene = exactvis.Scene(V, F)
    assert scene.faces_read == 5 and scene.degenerate_dropped == 1 and scene.ids.tolist() == [0, 1, 2, 3]
    vis, wit = exactvis.visible(V, F, cell=(0, 0, 0, 1, 1, 1))
    assert vis.tolist() == [True, True, False, True, False] and len(wit) == 3
    with pytest.raises(ValueError, match="triangle id 4 is not in the scene"):
        exactvis.visible(V, F, cell=(0, 0, 0, 1, 1, 1), triangles=[4])


# ---- events

def test_events_match_cli_json(small_scene_file):
    calls = []
    assert exactvis.events(small_scene_file, progress=lambda d, t: calls.append((d, t))) == cli_json(
        "events", small_scene_file, "--json", "--no-progress")
    assert calls and all(0 <= d <= t for d, t in calls)  # at least each stage's end
    scene = exactvis.load_scene(small_scene_file)
    ev = exactvis.events(scene, kinds=["EV"], split=False)
    assert ev == cli_json("events", small_scene_file, "--json", "--kinds", "EV", "--no-split", "--no-progress")
    assert ev["counts"]["EEE"] is None and ev["counts"]["EV"] == len(ev["events"]) > 0


def test_events_light_matches_cli(small_scene_file):
    light = [(0.0, 0.0, 4.0), (0.5, 0.0, 4.0), (0.0, 0.5, 4.0)]
    j = cli_json("events", small_scene_file, "--json", "--no-progress", "--light", "0,0,4;0.5,0,4;0,0.5,4")
    assert exactvis.events(small_scene_file, light=light) == j
    assert j["light"]["appended"] is True


def test_events_bad_input_messages_as_cli(small_scene_file):
    for kwargs, args in [(dict(kinds="EV,XY"), ["--kinds", "EV,XY"]),
                         (dict(light="nosuchobject"), ["--light", "nosuchobject"]),
                         (dict(light="0,0,0;1,0,0;2,0,0"), ["--light", "0,0,0;1,0,0;2,0,0"])]:
        with pytest.raises(ValueError) as e:
            exactvis.events(small_scene_file, **kwargs)
        assert str(e.value) == cli_error("events", small_scene_file, *args)


# ---- complex2d

POLYGONS = [[(0, 0), (2, 0), (1, 2)], [(4, 1), (6, 1), (5, 3)],
            [[(1, 4), (5, 4), (5, 8), (1, 8)], [(2, 5), (2, 7), (4, 7), (4, 5)]]]


def test_complex2d_matches_cli_json(tmp_path):
    path = tmp_path / "scene2d.json"
    path.write_text(json.dumps({"polygons": POLYGONS}))
    j = cli_json("complex2d", path, "--json")
    assert exactvis.complex2d(POLYGONS) == j
    assert exactvis.complex2d(str(path)) == j
    as_fractions = [[[(Fraction(x), Fraction(y)) for x, y in ring] for ring in (p if isinstance(p[0], list) else [p])]
                    for p in POLYGONS]
    assert exactvis.complex2d(as_fractions) == j
    assert exactvis.complex2d([np.array(POLYGONS[0], dtype=float), POLYGONS[1], POLYGONS[2]]) == j
    assert j["counts"]["bitangents"] == len(j["bitangents"]) > 0


def test_complex2d_exact_coordinates_and_progress(tmp_path):
    # POLYGONS scaled by 1/3: coordinates that are not doubles, given as Fractions and "num/den" strings.
    third = Fraction(1, 3)
    polys = [[(third * x, str(third * y)) for x, y in p] for p in POLYGONS[:2]]
    path = tmp_path / "thirds.json"
    path.write_text(json.dumps({"polygons": [[[str(x), str(y)] for x, y in p] for p in polys]}))
    calls = []
    d = exactvis.complex2d(polys, progress=lambda done, total: calls.append((done, total)))
    assert d == cli_json("complex2d", path, "--json")
    vertices = {(Fraction(x), Fraction(y)) for p in polys for x, y in p}
    for b in d["bitangents"]:  # bitangent ends are scene vertices, exactly
        assert tuple(exactvis.fraction(c) for c in b["a"]) in vertices
        assert tuple(exactvis.fraction(c) for c in b["b"]) in vertices
    assert any(isinstance(c, str) and "/3" in c for b in d["bitangents"] for c in b["a"] + b["b"])
    assert all(t == 1000 and 0 <= done <= 1000 for done, t in calls)


def test_complex2d_bad_input_messages_as_cli(tmp_path):
    for polys in ([[(0, 0), (1, 0)]], [], [[(0, 0), (1, 0), (2, 0)]], [[(0, 0), (1, "x"), (0, 1)]]):
        path = tmp_path / "bad.json"
        path.write_text(json.dumps({"polygons": [[[x if isinstance(x, str) else x for x in pt] for pt in p]
                                                 for p in polys]}))
        with pytest.raises(ValueError) as e:
            exactvis.complex2d(polys)
        cli_message = cli_error("complex2d", path)
        assert cli_message.startswith(str(path) + ": ")
        assert str(e.value) == "polygons: " + cli_message[len(str(path)) + 2:]


def test_version_matches_cli():
    status, out, _ = cli("--version")
    assert status == 0 and out.strip() == "exactvis " + exactvis.__version__


# ---- pvs

PVS_CELLS = [(0, 0, 0, 1, 1, 1), (-1, -1, 2.5, 2, 2, 2.75), (9, -1, -1, 9.5, 0.5, "1/3")]


def test_pvs_matches_cli_json_and_witnesses_recheck(tmp_path, small_scene_file):
    cells_path = tmp_path / "cells.json"
    cells_path.write_text(json.dumps({"cells": [list(c) for c in PVS_CELLS]}))
    j = cli_json("pvs", small_scene_file, "--cells", cells_path, "--json", "-q")
    calls = []
    got = exactvis.pvs(small_scene_file, cells=PVS_CELLS, progress=lambda d, t: calls.append((d, t)))
    assert got == j
    assert calls and calls[-1] == (3 * 4, 3 * 4) and all(0 <= d <= t == 12 for d, t in calls)
    assert exactvis.pvs(small_scene_file, cells=str(cells_path), threads=1) == j
    jc = cli_json("pvs", small_scene_file, "--cells", cells_path, "--method", "conservative", "--json", "-q")
    assert exactvis.pvs(small_scene_file, cells=PVS_CELLS, method="conservative") == jc
    # arrays: the same answers, "scene" null; every witness re-checked exactly (Fractions)
    arr = exactvis.pvs(OCCLUDER_V, OCCLUDER_F, cells=PVS_CELLS)
    assert arr["scene"] is None
    for a, c in zip(arr["cells"], j["cells"]):  # object names of arrays are "arrays#componentK"
        assert a["visible"] == c["visible"] and a["witnesses"] == c["witnesses"] and a["box"] == c["box"]
    assert j["cells"][0]["visible"] == [0, 1, 3]  # the small triangle above the occluder is hidden
    for c, cell in zip(j["cells"], PVS_CELLS):
        assert sorted(int(t) for t in c["witnesses"]) == c["visible"]
        for tid, w in c["witnesses"].items():
            check_witness(OCCLUDER_V, OCCLUDER_F, int(tid), [exactvis.fraction(x) for x in cell], w)
    # visible() on the same cell gives the same visible set
    vis, _ = exactvis.visible(OCCLUDER_V, OCCLUDER_F, cell=PVS_CELLS[1])
    assert np.flatnonzero(vis).tolist() == j["cells"][1]["visible"]


def test_pvs_grid_options_match_cli(scene_file):
    j = cli_json("pvs", scene_file, "--grid", "2,1,1", "--json", "--no-witnesses", "--rays", "0", "-q")
    assert exactvis.pvs(scene_file, grid=(2, 1, 1), witnesses=False, rays=0) == j
    assert all("witnesses" not in c for c in j["cells"])
    box = "0,0,0,32,32,1/2"
    jb = cli_json("pvs", scene_file, "--grid", "1,1,2", "--box", box, "--json", "--method", "sampled", "--rays",
                  "300", "-q")
    assert exactvis.pvs(scene_file, grid=(1, 1, 2), box=(0, 0, 0, 32, 32, Fraction(1, 2)), method="sampled",
                        rays=300) == jb


def test_pvs_bad_input_messages_as_cli(small_scene_file, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"cells": [[0, 0, 0, 1, 1, -1]]}')
    cases = [(dict(cells=str(bad)), ["--cells", bad]),
             (dict(grid=(0, 1, 1)), ["--grid", "0,1,1"]),
             (dict(grid=(1, 1, 1), method="magic"), ["--grid", "1,1,1", "--method", "magic"]),
             (dict(grid=(1, 1, 1), threads=5000), ["--grid", "1,1,1", "--threads", "5000"]),
             (dict(grid=(1, 1, 1), seed=-3), ["--grid", "1,1,1", "--seed", "-3"])]
    for kwargs, args in cases:
        with pytest.raises(ValueError) as e:
            exactvis.pvs(small_scene_file, **kwargs)
        assert str(e.value) == cli_error("pvs", small_scene_file, *args, "-q")
    with pytest.raises(ValueError, match=r"^cells: cell 0 is empty or inverted in z"):
        exactvis.pvs(OCCLUDER_V, OCCLUDER_F, cells=[(0, 0, 0, 1, 1, -1)])
    with pytest.raises(ValueError, match="exactly one of --grid and --cells"):
        exactvis.pvs(OCCLUDER_V, OCCLUDER_F)


# ---- skeleton

def test_skeleton_matches_cli_json(small_scene_file):
    j = cli_json("skeleton", small_scene_file, "--json", "-q")
    calls = []
    got = exactvis.skeleton(small_scene_file, progress=lambda d, t: calls.append((d, t)))
    assert got == j and calls
    assert j["counts"]["arcs"]["EV"] > 0 and len(j["nodes"]) > 0
    assert exactvis.skeleton(OCCLUDER_V, OCCLUDER_F) == j  # ids are rows of F = the file's ids here
    jp = cli_json("skeleton", small_scene_file, "--pair", "0,2", "--json", "-q")
    assert exactvis.skeleton(small_scene_file, pair=(0, 2)) == jp
    assert len(jp["arcs"]) < len(j["arcs"])


def test_skeleton_bad_input_messages_as_cli(small_scene_file):
    for pair in ["0,99", "0", "a,b,c"]:
        with pytest.raises(ValueError) as e:
            exactvis.skeleton(small_scene_file, pair=pair)
        assert str(e.value) == cli_error("skeleton", small_scene_file, "--pair", pair, "-q")


# ---- shadows

def without_seconds(j):
    j = dict(j)
    j["stats"] = {k: v for k, v in j["stats"].items() if not k.startswith("seconds")}
    return j


def test_shadows_match_cli_json(tmp_path):
    room = os.path.join(SOURCE, "scenes", "lamp_room.obj")
    j = cli_json("shadows", room, "--light", "lamp", "--json", "-q")
    calls = []
    got = exactvis.shadows(room, light="lamp", progress=lambda d, t: calls.append((d, t)))
    assert without_seconds(got) == without_seconds(j) and calls
    c = j["counts"]
    assert c["umbra"] > 0 and c["penumbra"] > 0 and c["lit"] > 0 and c["faces"] == c["umbra"] + c["penumbra"] + c["lit"]
    # an exact re-check of one thing the mesh claims: each face's sample lies on its receiver's plane
    scene = exactvis.load_scene(room)
    for r in j["receivers"]:
        tri = [[Fraction(float(x)) for x in scene.vertices[v]] for v in scene.faces[list(scene.ids).index(r["triangle"])]]
        n = cross(sub(tri[1], tri[0]), sub(tri[2], tri[0]))
        for f in r["faces"]:
            assert dot(n, sub([exactvis.fraction(x) for x in f["sample"]], tri[0])) == 0
    ids = [r["triangle"] for r in j["receivers"]][:2]
    jr = cli_json("shadows", room, "--light", "lamp", "--receivers", ",".join(map(str, ids)), "--json", "-q")
    assert without_seconds(exactvis.shadows(scene, light=["lamp"], receivers=ids)) == without_seconds(jr)
    poly = [(1.75, 1.75, 2.25), (2.25, 1.75, 2.25), (2.25, 2.25, 2.25)]
    jp = cli_json("shadows", room, "--light", "1.75,1.75,2.25;2.25,1.75,2.25;2.25,2.25,2.25", "--json", "-q")
    assert without_seconds(exactvis.shadows(room, light=poly)) == without_seconds(jp)


def test_shadows_bad_input_messages_as_cli():
    room = os.path.join(SOURCE, "scenes", "lamp_room.obj")
    for kwargs, args in [(dict(light="sun"), ["--light", "sun"]),
                         (dict(light="lamp", receivers="1,x"), ["--light", "lamp", "--receivers", "1,x"]),
                         (dict(light="lamp", receivers=[99]), ["--light", "lamp", "--receivers", "99"]),
                         (dict(light="lamp", receivers=[14]), ["--light", "lamp", "--receivers", "14"])]:
        with pytest.raises(ValueError) as e:
            exactvis.shadows(room, **kwargs)
        assert str(e.value) == cli_error("shadows", room, *args, "-q")

