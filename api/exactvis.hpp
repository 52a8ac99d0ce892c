#pragma once
// exactvis: every job façade in one include (#include <exactvis/api/exactvis.hpp>, link exactvis::exactvis).
// Each façade is one call per job with the inputs, outputs and conventions of the matching subcommand of
// the command line (docs/cli.md); scenes come from io/load_scene.hpp (files, or arrays: scene_from_arrays)
// and io/scene2d_json.hpp (2D scenes).
//
// Jobs:
//   api/visible.hpp    from-region visibility of triangles from a view cell or polygon, with witnesses
//   api/events.hpp     EV and EEE visual events with occlusion (JSON as `exactvis events --json`)
//   api/pvs.hpp        potentially visible sets of view cells (JSON as `exactvis pvs --json`)
//   api/skeleton.hpp   the 3D visibility skeleton (JSON as `exactvis skeleton --json`)
//   api/complex2d.hpp  the 2D visibility complex (JSON as `exactvis complex2d --json`)
// Not yet here (one header each, same shape, when written): shadows (discontinuity meshes), exterior and
// aspect graphs.
#include "api/complex2d.hpp"
#include "api/events.hpp"
#include "api/pvs.hpp"
#include "api/skeleton.hpp"
#include "api/visible.hpp"
#include "io/load_scene.hpp"
#include "io/scene2d_json.hpp"
