// `relight bench SCENE.rlt`: the frames of every edit a designer makes, timed on a
// precomputed scene (docs/performance.md lists the figures and the commands). A frame is a
// change of the lighting state and the weighted sum after it. By default every dimmer is
// toggled. With `sky` only the exterior changes (the sun moves a minute a frame, a map turns a
// degree, a uniform sky changes luminance): each portal's shell is built again and a sun behind
// clear glass traced and bounced again (shell_ms, sun_ms, sun_bounce_ms). With `emitters` the
// near-field emitters move 1 cm a frame (sampling_ms, bounce_ms). With `objects` the movable
// objects move along a small circle, 2 cm and 2° a frame, or only `object`, a designer dragging
// it (direct_ms, transfer_ms, bounce_ms). With `materials` the albedo of the material on the most
// vertices (or `material`) changes 5 % a frame, a designer dragging a colour: the approximate
// frame, then the final one (engine/albedo_edit.h; approximate_ms, final_ms, first_approximate_ms
// and first_final_ms for the first edit, solved from nothing, and edit_view_ms, the glossy
// vertices then shaded toward the first camera); with `roughness` its roughness instead (made
// glossy at 0.3, then between 0.3 and 0.35: the glossy first bounce made again for every
// luminaire, engine/glossy_first_bounce.h). With `aim` every luminaire turns 1° about its C0
// axis, back and forth. With `environment` the top-level environment changes as `sky` changes a
// window's (clustered on the cuts' tree, summed, bounced, and through the movable objects;
// environment_ms, bounce_ms, objects_ms, and view_ms: the glossy vertices shaded toward an eye
// that moves a centimetre a frame). Only the kind of source that changed is summed again
// (runtime/relighter.h). The same run times a plain parallel streaming read of as many bytes
// as the sum reads, so that effective_gbps / stream_gbps speaks for itself on a shared
// machine. With `layout` the first luminaire moves and one is added (benchmark/layout_benchmark.h).
// With `optimize` (TARGETS.json): `relight optimize` timed against a relight of the
// whole scene (ratio_to_relight).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace relight {

struct BenchOptions {
  std::string rlt;
  int frames = 50;
  bool sky = false;
  bool environment = false;
  bool emitters = false;
  bool objects = false;
  std::string object;  // with objects: move only this one
  bool materials = false;
  std::string material;    // with materials: edit this one (else the most used)
  bool roughness = false;  // with materials: edit its roughness, not its albedo
  bool aim = false;
  bool layout = false;   // move the first luminaire and add one (benchmark/layout_benchmark.h)
  std::string optimize;  // TARGETS.json: time `relight optimize` instead
  bool edits = false;    // every kind of edit, shown as the studio shows it (edits_benchmark.h)
};

// Times the frames `options` ask for and returns the one JSON line `relight bench` prints
// (medians over `frames`). InputError for an edit the scene cannot make (no portals for `sky`,
// an unknown material or object, two edits at once).
nlohmann::json run_bench(const BenchOptions& options);

}  // namespace relight
