"""exactvis: exact 3D visibility from Python (numpy in, numpy and plain dicts out).

The jobs of the ``exactvis`` command line, one call each (docs/python.md has a worked example):

- ``visible(V, F, cell=(x0, y0, z0, x1, y1, z1), triangles=None)`` -> ``(visible, witnesses)``: which
  triangles can be seen from a view cell (or ``source_polygon=``), with an exact witness segment each.
- ``events(V, F, light=None, kinds="EV,EEE")`` -> dict, the JSON of ``exactvis events --json``.
- ``pvs(V, F, cells=[(x0, y0, z0, x1, y1, z1), ...])`` or ``pvs(V, F, grid=(nx, ny, nz))`` -> dict, the JSON
  of ``exactvis pvs --json``: per view cell the visible triangles and objects, with exact witnesses.
- ``skeleton(V, F, pair=None)`` -> dict, the JSON of ``exactvis skeleton --json``.
- ``shadows(V, F, light="lamp")`` -> dict, the JSON of ``exactvis shadows --json``: the exact
  discontinuity mesh of area lights (umbra, penumbra, lit faces with backprojections and irradiance).
- ``complex2d(polygons)`` -> dict, the JSON of ``exactvis complex2d --json``.
- ``load_scene(path, ...)`` -> ``Scene`` (``.vertices``, ``.faces``, ``.ids``, ``.objects``, ``.object_names``).

A scene argument is either ``V, F`` (n x 3 float64 coordinates, m x 3 integer vertex indices; triangle id
f = row f of F), a path (str or os.PathLike: .obj .ply .off .stl, as the command line loads it), a list of
paths (loaded as one scene), or a ``Scene``.

Exact values: every answer is exact. Coordinates that are exactly doubles are floats; others are
``fractions.Fraction`` (``visible(..., exact=True)``) or, in the dicts, the command line's strings
``"num/den"`` (rationals) and ``"a+b*sqrt(c)"`` (EEE parameters); ``exactvis.fraction(x)`` turns a
number or a ``"num/den"`` string into a Fraction.

Bad input raises ``ValueError`` with the message the command line prints after ``exactvis SUB: error: ``.
Long calls release the GIL; ``progress=callable`` is called as ``progress(done, total)``.
"""

import json as _json
import numbers as _numbers
import os as _os
from fractions import Fraction as _Fraction

import numpy as _np

from . import _exactvis
from ._exactvis import Scene

__version__ = _exactvis.__version__
__all__ = ["Scene", "load_scene", "visible", "events", "pvs", "skeleton", "shadows", "complex2d", "fraction", "__version__"]


def fraction(x):
    """An exact value of the JSON or of the arrays as a ``fractions.Fraction``: an int, a float (its exact
    value), a Fraction, or a string ``"num/den"`` / ``"num"`` / a decimal. Strings ``"a+b*sqrt(c)"`` are
    irrational and raise ValueError."""
    if isinstance(x, str):
        if "sqrt" in x:
            raise ValueError(f"'{x}' is irrational (a+b*sqrt(c)), not a fraction")
        return _Fraction(x)
    return _Fraction(x)


def load_scene(path, *more_paths):
    """Loads one or several mesh files as one scene (ids continue across files in the order given), exactly
    as the command line does. Raises ValueError("FILE: problem") for bad input."""
    return Scene([_os.fspath(p) for p in (path,) + more_paths])


def _scene(V, F):
    if isinstance(V, Scene):
        if F is not None:
            raise ValueError("F: not used with a Scene")
        return V
    if isinstance(V, (str, bytes, _os.PathLike)):
        if F is not None:
            raise ValueError("F: not used with a scene file")
        return load_scene(V)
    if isinstance(V, (list, tuple)) and V and all(isinstance(p, (str, _os.PathLike)) for p in V):
        if F is not None:
            raise ValueError("F: not used with scene files")
        return load_scene(*V)
    if F is None:
        raise ValueError("F: missing (give V and F arrays, a scene file or a Scene)")
    V = _np.asarray(V)
    F = _np.asarray(F)
    if V.ndim != 2 or V.shape[1] != 3 or not _np.issubdtype(V.dtype, _np.number):
        raise ValueError(f"V: expected an n x 3 array of coordinates, got shape {V.shape} of {V.dtype}")
    if F.ndim != 2 or F.shape[1] != 3 or not _np.issubdtype(F.dtype, _np.integer):
        raise ValueError(f"F: expected an m x 3 array of integer vertex indices, got shape {F.shape} of {F.dtype}")
    return Scene(_np.ascontiguousarray(V, dtype=_np.float64), _np.ascontiguousarray(F, dtype=_np.int64))


def _exact_text(x, what):
    """x as option text the command line parses to the same exact value."""
    if isinstance(x, str):
        return x
    if isinstance(x, bool):
        raise ValueError(f"{what}: '{x}' is not a number")
    if isinstance(x, _numbers.Integral):
        return f"{int(x)}/1"
    if isinstance(x, _Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, _numbers.Rational):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, _numbers.Real):
        return repr(float(x))  # shortest text that reads back as the same double
    try:
        return str(x)  # e.g. decimal.Decimal: the nearest double, as on the command line
    except Exception:
        raise ValueError(f"{what}: '{x!r}' is not a number") from None


def _cell_text(cell):
    return ",".join(_exact_text(c, "--cell") for c in cell)


def _polygon_text(points):
    return ";".join(",".join(_exact_text(c, "--source-polygon") for c in p) for p in points)


def visible(V, F=None, cell=None, triangles=None, *, source_polygon=None, samples=48, seed=1, threads=0,
            exact=False, progress=None, stats=False):
    """Exact from-region visibility (``exactvis visible``; docs/theory.md section 5).

    Parameters
    - V, F: the scene (see the module doc).
    - cell: (x0, y0, z0, x1, y1, z1), x0 < x1, y0 < y1, z0 < z1; floats, ints, Fractions or "num/den"
      strings, taken exactly. Or ``source_polygon=[(x, y, z), ...]``: a convex planar polygon.
    - triangles: None (every triangle id 0 .. m-1, m = rows of F or faces in the file) or a sequence of
      triangle ids (rows of F).
    - samples, seed, threads: as the command line's --samples, --seed, --threads.
    - exact: witnesses as Fractions (object array) instead of float64.
    - progress: called as progress(done, total) after each triangle.
    - stats: also return the command line's "stats" dict.

    Returns ``(visible, witnesses)``: ``visible`` a bool array, one entry per asked triangle (with
    triangles=None: entry i is triangle id i; a zero-area face, which the scene drops, is False);
    ``witnesses`` a (k x 2 x 3) array, k = visible.sum(): for the j-th visible triangle (in the order of
    ``visible``) a segment from a point on the source (row 0) to a point inside the triangle (row 1) whose
    open part meets no other triangle. float64 (the exact witness rounded, itself re-checked when it is
    reported rounded), or with exact=True Fractions, the exact witness. With stats=True: a third item.
    """
    scene = _scene(V, F)
    if (cell is None) == (source_polygon is None):
        raise ValueError("give exactly one source: --cell or --source-polygon")
    cell_text = None if cell is None else (cell if isinstance(cell, str) else _cell_text(cell))
    poly_text = None if source_polygon is None else (
        source_polygon if isinstance(source_polygon, str) else _polygon_text(source_polygon))
    ids = None if triangles is None else [int(t) for t in _np.asarray(triangles).ravel()]
    got_ids, vis, wit, wit_exact, st = _exactvis._visible(
        scene, cell_text, poly_text, ids, int(samples), str(seed), int(threads), bool(exact), progress)
    if exact:
        wit = _np.empty((len(wit_exact), 2, 3), dtype=object)
        for j, row in enumerate(wit_exact):
            for e in range(2):
                for c in range(3):
                    wit[j, e, c] = _Fraction(row[3 * e + c])
    if triangles is None:
        full = _np.zeros(scene.faces_read, dtype=bool)
        full[got_ids] = vis
        vis = full
    return (vis, wit, st) if stats else (vis, wit)


def events(V, F=None, *, light=None, kinds="EV,EEE", split=True, progress=None):
    """EV and EEE visual events with occlusion (``exactvis events``; docs/theory.md section 6).

    - light: None, the name of a scene object, or a polygon [(x, y, z), ...] (or the command line's text
      "x,y,z;x,y,z;x,y,z") appended to the scene as object "light".
    - kinds: "EV", "EEE", "EV,EEE" or a sequence of those names.
    - split: False is --no-split.
    - progress: called as progress(done, total) about 5 times a second per stage (EV events, their segment
      ends, EEE candidate pairs, EEE triples, ...); each stage counts from 0 to its own total.

    Returns the dict of ``exactvis events --json`` on the same scene (same keys, same values; exact
    parameters as numbers, "num/den" or "a+b*sqrt(c)" strings). Releases the GIL while it runs.
    """
    scene = _scene(V, F)
    if not isinstance(kinds, str):
        kinds = ",".join(kinds)
    if light is not None and not isinstance(light, str):
        light = ";".join(",".join(repr(float(c)) for c in p) for p in light)
    return _json.loads(_exactvis._events(scene, kinds, light, bool(split), progress))


def _scene_label(V):
    """The "scene" entry of a PVS document: the file name(s) as given, None for arrays or a Scene."""
    if isinstance(V, (str, _os.PathLike)):
        return _json.dumps(_os.fspath(V))
    if isinstance(V, (list, tuple)) and V and all(isinstance(p, (str, _os.PathLike)) for p in V):
        return _json.dumps(_os.fspath(V[0]) if len(V) == 1 else [_os.fspath(p) for p in V])
    return None


def _cells_json(cells):
    rows = []
    for c in cells:
        if isinstance(c, _np.ndarray):
            c = c.tolist()
        if not isinstance(c, (list, tuple)):
            raise ValueError(f"cells: cell {len(rows)} is not a list of 6 numbers [x0,y0,z0,x1,y1,z1]")
        row = []
        for x in c:
            if isinstance(x, bool) or not isinstance(x, (_numbers.Real, str)):
                row.append(repr(x))  # refused by the reader with its message
            elif isinstance(x, (_numbers.Integral, _numbers.Rational)) or isinstance(x, str):
                row.append(_exact_text(x, "cells"))
            else:
                row.append(float(x))
        rows.append(row)
    return _json.dumps({"cells": rows})


def pvs(V, F=None, cells=None, *, grid=None, box=None, method="exact", witnesses=True, samples=48, rays=None,
        seed=1, threads=0, hierarchy=True, progress=None):
    """Exact potentially visible sets of view cells (``exactvis pvs``; docs/theory.md section 5).

    - V, F: the scene (see the module doc).
    - cells: a sequence of boxes (x0, y0, z0, x1, y1, z1) (floats, ints, Fractions or "num/den" strings, taken
      exactly; x0 < x1, y0 < y1, z0 < z1), numbered in order; or the path of a cells file (``--cells``).
      Or ``grid=(nx, ny, nz)``: a grid over the scene's bounding box, or over ``box=(x0, ..., z1)``.
    - method: "exact" (default), "sampled" or "conservative" (``--method``); witnesses=False is
      ``--no-witnesses``.
    - samples, rays, seed, threads, hierarchy: ``--samples``, ``--rays`` (None: the method's default),
      ``--seed``, ``--threads``, hierarchy=False is ``--no-hierarchy``.
    - progress: called as progress(decided, total), total = cells x triangles.

    Returns the dict of ``exactvis pvs --json`` on the same scene and cells: {"scene", "triangles", "cells":
    [{"cell", "box", "visible": [ids], "objects": [names], "witnesses": {"id": [[p], [q]]}, "stats"}, ...],
    "stats"}; "scene" is the file name (None for arrays). Coordinates are numbers when exactly doubles, else
    "num/den" strings (``exactvis.fraction``). Releases the GIL while it runs.
    """
    scene = _scene(V, F)
    given = (cells is not None) + (grid is not None)
    if given != 1:
        raise ValueError("give exactly one of --grid and --cells")
    cells_json = cells_file = grid_text = box_text = None
    if grid is not None:
        grid_text = grid if isinstance(grid, str) else ",".join(str(int(n)) if isinstance(n, _numbers.Integral)
                                                                 and not isinstance(n, bool) else str(n)
                                                                 for n in grid)
    elif isinstance(cells, (str, _os.PathLike)):
        cells_file = _os.fspath(cells)
    else:
        cells_json = _cells_json(cells)
    if box is not None:
        box_text = box if isinstance(box, str) else ",".join(_exact_text(c, "--box") for c in box)
    return _json.loads(_exactvis._pvs(scene, _scene_label(V), cells_json, cells_file, grid_text, box_text, str(method),
                                      int(samples), -1 if rays is None else int(rays), str(seed), int(threads),
                                      bool(witnesses), bool(hierarchy), progress))


def skeleton(V, F=None, *, pair=None, progress=None):
    """The 3D visibility skeleton (``exactvis skeleton``; docs/theory.md section 9).

    - pair: None (the whole skeleton) or (A, B) / "A,B": only the nodes and arcs whose maximal free segments
      end on objects A and B (object names, or triangle ids), built lazily (``--pair``).
    - progress: called as progress(done, total) per stage of the enumerations (as for ``events``).

    Returns the dict of ``exactvis skeleton --json`` on the same scene: {"counts", "nodes", "arcs"}, exact
    coordinates as numbers, "num/den" or "a+b*sqrt(c)" strings. Releases the GIL while it runs.
    """
    scene = _scene(V, F)
    if pair is not None and not isinstance(pair, str):
        pair = ",".join(str(p) for p in pair)
    return _json.loads(_exactvis._skeleton(scene, pair, progress))


def _light_text(light):
    if isinstance(light, str):
        return light
    return ";".join(",".join(repr(float(c)) for c in p) for p in light)


def shadows(V, F=None, *, light, receivers="all", progress=None):
    """The exact discontinuity mesh of area lights (``exactvis shadows``; docs/theory.md section 11).

    - light: the name of a scene object, a polygon [(x, y, z), ...] (or the command line's text
      "x,y,z;x,y,z;x,y,z") appended to the scene as object "light", or a list of those (several lights,
      joined into one light of exitance 1, as repeated ``--light``).
    - receivers: "all" (every triangle not part of a light) or a sequence of triangle ids (``--receivers``).
    - progress: called as progress(done, total) per stage (events, receivers), as for ``events``.

    Returns the dict of ``exactvis shadows --json`` on the same scene: {"receivers": [{"triangle", "curves",
    "faces"}], "counts", "light", "stats"} (``stats`` holds timings in seconds, which differ between runs).
    Exact values as numbers or "num/den" strings; areas, fractions and irradiance are floats. Releases the GIL.
    """
    scene = _scene(V, F)
    if isinstance(light, str) or (light and not isinstance(light[0], str) and _np.ndim(light[0]) == 1):
        lights = [_light_text(light)]
    else:
        lights = [_light_text(l) for l in light]
    if not isinstance(receivers, str):
        receivers = ",".join(str(int(t)) for t in _np.asarray(receivers).ravel())
    name = _os.fspath(V) if isinstance(V, (str, _os.PathLike)) else "scene"
    return _json.loads(_exactvis._shadows(scene, name, lights, receivers, progress))


def _json_exact(x):
    if isinstance(x, bool):
        raise ValueError(f"polygons: '{x}' is not a coordinate")
    if isinstance(x, _numbers.Integral):
        return str(int(x))
    if isinstance(x, _numbers.Rational):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, _numbers.Real):
        return float(x)
    return x  # strings "num/den" and anything else: checked by the reader


def _polygons_json(polygons):
    def conv(p):
        if isinstance(p, _np.ndarray):
            p = p.tolist()
        if isinstance(p, (list, tuple)):
            return [conv(q) for q in p]
        return _json_exact(p)

    if isinstance(polygons, dict):
        polygons = polygons.get("polygons")
    return _json.dumps({"polygons": conv(polygons) if isinstance(polygons, (list, tuple, _np.ndarray)) else polygons})


def complex2d(polygons, *, slice=None, progress=None):
    """The 2D visibility complex (``exactvis complex2d``): free bitangents, edges and faces.

    - polygons: a list of polygons, each a ring [(x, y), ...] or a list of rings (outer boundary, then holes),
      as in a 2D scene JSON file; coordinates floats, ints, Fractions or "num/den" strings (exact). Or a path
      to a 2D scene JSON file, or to a 3D mesh with slice="z=1.5" (x=, y=, z=).
    - progress: called as progress(done, total) as the sweeps advance (total 1000).

    Returns the dict of ``exactvis complex2d --json`` (coordinates as numbers or "num/den" strings).
    """
    if isinstance(polygons, (str, _os.PathLike)):
        return _json.loads(_exactvis._complex2d(None, _os.fspath(polygons), slice or "", progress))
    if slice:
        raise ValueError("--slice: only with a scene file")
    return _json.loads(_exactvis._complex2d(_polygons_json(polygons), "polygons", "", progress))
