// `relight report`: one self-contained HTML page of a lit scene for a lighting designer — no
// script, no network, inline SVG, printable (an @media print style): per sensor set a plan view in
// false colour with its legend (render/false_color_scale.h rules on the set's values) and Em, Emin,
// Emax, U0; the EN 12464-1 task checks with maintained values (render/task_check.h); the luminaire
// schedule with a polar plot of each distribution (the C0–C180 and C90–C270 planes, cd); and, with
// a weather file, the annual metrics (runtime/daylight_metrics.h) and a plan of DA300 per set.
// Names are HTML-escaped.
// Pinned by tests/cli/report_command_test.cpp (content) and tests/studio/report.test.mjs
// (Chromium opens it with no console error).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "runtime/daylight_metrics.h"
#include "runtime/relit_scene.h"

namespace relight {

// A year of daylight as `relight annual` measured it: per sensor point of the scene (scene
// order), its metrics; per set, the set's.
struct AnnualReport {
  std::string weather;  // the place and the hours, for the heading
  std::vector<SensorDaylight> per_sensor;
  std::vector<SetDaylight> per_set;  // scene order of the sets
};

struct ReportOptions {
  std::string title;  // the scene's file name
  std::string state;  // the state file, or "" for the scene's own
  std::optional<AnnualReport> annual;
};

// The page for `scene` lit as it is now. Leaves the scene lit as it was.
std::string report_html(RelitScene& scene, const ReportOptions& options);

// Text with &, <, >, " and ' escaped for HTML.
std::string html_escape(const std::string& text);

}  // namespace relight
