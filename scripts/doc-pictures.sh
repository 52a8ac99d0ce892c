#!/usr/bin/env bash
# Regenerates every picture in docs/images/ (shown by docs/pictures.md) from the bundled scenes, one command
# per job; each line below is the command docs/pictures.md cites. Needs a built exactvis
# ($EXACTVIS_BUILD_DIR, default build/); PNGs are rendered offscreen (a private Xvfb when DISPLAY is unset).
# Usage: bash scripts/doc-pictures.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ev="${EXACTVIS_BUILD_DIR:-$root/build}/exactvis"
cd "$root"
img=docs/images
mkdir -p "$img"
size=640x480
"$ev" export scenes/town.obj --png $img/export.png --png-size $size -q
"$ev" visible scenes/town.obj --cell 6,6,1,7,7,2 --witnesses --png $img/visible.png --png-size $size -q >/dev/null
"$ev" pvs scenes/lamp_room.obj --cells scenes/lamp_cells.json --png $img/pvs.png --png-cell 1 --witnesses \
  --png-size $size -q >/dev/null
"$ev" events scenes/lamp_room.obj --light lamp --png $img/events.png --png-size $size -q >/dev/null
"$ev" shadows scenes/lamp_room.obj --light lamp --png $img/shadows.png -q >/dev/null
"$ev" aspect scenes/cube.obj --orthographic --png $img/aspect.png -q >/dev/null
"$ev" aspect scenes/l_prism.obj --plane z=2 --png $img/aspect_plane.png -q >/dev/null
"$ev" complex2d scenes/plan2d.json --svg $img/complex2d.svg >/dev/null
"$ev" visibility2d scenes/plan2d.json --from 5.5,2 --svg $img/visibility2d.svg >/dev/null
"$ev" aspect2d scenes/plan2d.json --svg $img/aspect2d.svg -q >/dev/null
ls -l $img
