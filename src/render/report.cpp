// The designer's report page; see report.h.
#include "render/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "image/image.h"
#include "math/rgb.h"
#include "render/false_color.h"
#include "render/false_color_scale.h"
#include "render/sensor_report.h"
#include "render/task_check.h"

namespace relight {

namespace {

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string hex(Rgb8 c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

FalseColorScale scale_of(const std::vector<double>& values, bool percent) {
  if (percent) return {0, 100, false};
  Image image = make_image(static_cast<int>(values.size()), 1);
  for (std::size_t i = 0; i < values.size(); ++i) {
    image.pixels[i] = {values[i], values[i], values[i]};
  }
  return resolve_scale(image, {});
}

// The plan of one sensor set, seen from above (x right, z down), its points coloured by
// `values` on `scale`, with the legend beside it.
std::string plan_svg(const SensorSet& set, const std::vector<double>& values,
                     const FalseColorScale& scale, const std::string& unit) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, z0 = x0, z1 = -x0;
  for (const Vec3& p : set.points) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    z0 = std::min(z0, p.z);
    z1 = std::max(z1, p.z);
  }
  // Cell size: a grid's spacing, else a fiftieth of the extent.
  const double extent = std::max({x1 - x0, z1 - z0, 1e-3});
  double cell_x = extent / 50, cell_z = extent / 50;
  if (set.nu > 1) cell_x = std::max((x1 - x0) / (set.nu - 1), 1e-3);
  if (set.nv > 1) cell_z = std::max((z1 - z0) / (set.nv - 1), 1e-3);
  if (set.nu > 1 && set.nv <= 1) cell_z = cell_x;
  if (set.nv > 1 && set.nu <= 1) cell_x = cell_z;
  const double width_m = x1 - x0 + cell_x, depth_m = z1 - z0 + cell_z;
  const double px = 420 / std::max(width_m, depth_m);  // pixels per metre
  const double w = width_m * px, h = depth_m * px;
  std::string svg = "<svg class=\"plan\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    format("%.0f", w + 130) + "\" height=\"" +
                    format("%.0f", std::max(h, 220.0) + 20) +
                    "\" role=\"img\"><g transform=\"translate(0,10)\">";
  for (std::size_t i = 0; i < set.points.size(); ++i) {
    const Vec3& p = set.points[i];
    const Rgb8 c = ramp_color(scale_position(scale, values[i]));
    svg += "<rect x=\"" + format("%.2f", (p.x - x0) * px) + "\" y=\"" +
           format("%.2f", (p.z - z0) * px) + "\" width=\"" + format("%.2f", cell_x * px + 0.5) +
           "\" height=\"" + format("%.2f", cell_z * px + 0.5) + "\" fill=\"" + hex(c) +
           "\"><title>" + format("%.4g", values[i]) + " " + unit + "</title></rect>";
  }
  // The legend: the ramp from MAX (top) to MIN, with its ticks.
  const double lx = w + 20, lh = 200;
  svg += "<defs><linearGradient id=\"ramp\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (std::size_t k = 0; k < kFalseColorRamp.size(); ++k) {
    svg += "<stop offset=\"" + format("%.3f", k / (kFalseColorRamp.size() - 1.0)) +
           "\" stop-color=\"" + hex(kFalseColorRamp[k]) + "\"/>";
  }
  svg += "</linearGradient></defs><rect x=\"" + format("%.1f", lx) +
         "\" y=\"0\" width=\"18\" height=\"" + format("%.0f", lh) +
         "\" fill=\"url(#ramp)\" stroke=\"#444\"/>";
  for (const double t : scale_ticks(scale)) {
    const double y = lh * (1 - scale_position(scale, t));
    svg += "<text x=\"" + format("%.1f", lx + 24) + "\" y=\"" + format("%.1f", y + 4) +
           "\" font-size=\"11\">" + format_tick(t) + "</text>";
  }
  svg += "<text x=\"" + format("%.1f", lx) + "\" y=\"" + format("%.0f", lh + 16) +
         "\" font-size=\"11\">" + html_escape(unit) + "</text></g></svg>";
  return svg;
}

// The luminaire's intensity in the C0–C180 and C90–C270 planes, γ 0..180°, as a polar plot
// (γ = 0 straight down).
std::string polar_svg(const Distribution& d) {
  constexpr double kRadius = 90, kCentre = 100;
  double peak = 0;
  for (int g = 0; g <= 180; ++g) {
    for (const double c : {0.0, 90.0, 180.0, 270.0}) {
      peak = std::max(peak, d.intensity(radians(c), radians(g)));
    }
  }
  if (!(peak > 0)) peak = 1;
  std::string svg =
      "<svg class=\"polar\" xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"215\">";
  for (const double f : {0.25, 0.5, 0.75, 1.0}) {
    svg += "<circle cx=\"100\" cy=\"100\" r=\"" + format("%.1f", f * kRadius) +
           "\" fill=\"none\" stroke=\"#ccc\"/>";
  }
  const auto curve = [&](double c_left, double c_right, const char* colour) {
    std::string path;
    for (int g = -180; g <= 180; g += 2) {  // left half: c_left, right half: c_right
      const double c = g < 0 ? c_left : c_right, gamma = radians(std::abs(g));
      const double r = kRadius * d.intensity(radians(c), gamma) / peak;
      const double x = kCentre + (g < 0 ? -1 : 1) * r * std::sin(gamma);
      const double y = kCentre + r * std::cos(gamma);
      path += path.empty() ? 'M' : 'L';
      path += format("%.1f", x);
      path += ',';
      path += format("%.1f", y);
    }
    return "<path d=\"" + path + "\" fill=\"none\" stroke=\"" + colour +
           "\" stroke-width=\"1.5\"/>";
  };
  svg += curve(180, 0, "#c0392b") + curve(270, 90, "#2c5aa0");
  svg +=
      "<text x=\"4\" y=\"212\" font-size=\"10\" fill=\"#c0392b\">C0–C180</text>"
      "<text x=\"70\" y=\"212\" font-size=\"10\" fill=\"#2c5aa0\">C90–C270</text>"
      "<text x=\"140\" y=\"212\" font-size=\"10\">" +
      format("%.0f", peak) + " cd</text></svg>";
  return svg;
}

const char* kStyle = R"(body{font-family:sans-serif;margin:2em;color:#222}
h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #999;margin-top:1.6em}
table{border-collapse:collapse;margin:.6em 0}td,th{border:1px solid #bbb;padding:.25em .6em;text-align:right}
th{background:#eee}td:first-child,th:first-child{text-align:left}.fail{color:#b00;font-weight:bold}
.pass{color:#070}.set{page-break-inside:avoid;margin-bottom:1.2em}svg{vertical-align:top}
@media print{body{margin:1cm}h2{page-break-after:avoid}.set,.luminaire{page-break-inside:avoid}})";

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string report_html(RelitScene& scene, const ReportOptions& options) {
  const Scene& s = scene.scene();
  const std::vector<Rgb> e = scene.sensor_irradiance();
  const std::vector<SensorStatistics> stats = sensor_statistics(s, e);
  std::string html = "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
                     html_escape(options.title) + " — relight report</title><style>" + kStyle +
                     "</style></head><body><h1>" + html_escape(options.title) + "</h1><p>" +
                     (options.state.empty() ? std::string("The scene's own lighting state.")
                                            : "Lighting state: " + html_escape(options.state)) +
                     " Illuminance in lux on each sensor set's plane, as <code>relight probe"
                     "</code> computes it; plans are seen from above, north (−z) up and east "
                     "(+x) right.</p>";

  html +=
      "<h2>Illuminance</h2><table><tr><th>sensor set</th><th>points</th><th>Em (lx)</th>"
      "<th>Emin (lx)</th><th>Emax (lx)</th><th>U0</th></tr>";
  for (const SensorStatistics& st : stats) {
    html += "<tr><td>" + html_escape(st.name) + "</td><td>" + format("%.0f", double(st.count)) +
            "</td><td>" + format("%.1f", st.e_avg) + "</td><td>" + format("%.1f", st.e_min) +
            "</td><td>" + format("%.1f", st.e_max) + "</td><td>" + format("%.3f", st.u0) +
            "</td></tr>";
  }
  html += "</table>";
  std::size_t first = 0;
  for (const SensorSet& set : s.sensors) {
    std::vector<double> lux;
    for (std::size_t i = 0; i < set.points.size(); ++i) lux.push_back(luminance(e[first + i]));
    html += "<div class=\"set\"><h3>" + html_escape(set.name) + "</h3>" +
            plan_svg(set, lux, scale_of(lux, false), "lx") + "</div>";
    first += set.points.size();
  }

  const TaskChecks checks = check_tasks(scene);
  if (!checks.tasks.empty()) {
    html +=
        "<h2>Task areas (EN 12464-1)</h2><p>Maintained values: the electric light times the "
        "maintenance factor " +
        format("%.2f", checks.maintenance_factor) +
        (checks.declared ? std::string("") : std::string(" (not declared by the scene: 1)")) +
        ", daylight as it is.</p><table><tr><th>task</th><th>requirement</th><th>maintained"
        "</th><th>result</th></tr>";
    const auto row = [&](const std::string& task, const std::string& req, const std::string& value,
                         bool pass) {
      html += "<tr><td>" + html_escape(task) + "</td><td>" + req + "</td><td>" + value +
              "</td><td class=\"" + (pass ? "pass\">pass" : "fail\">FAIL") + "</td></tr>";
    };
    for (const TaskCheck& t : checks.tasks) {
      if (t.required.em) {
        row(t.name, "Em ≥ " + format("%.0f", *t.required.em) + " lx", format("%.1f lx", t.e_avg),
            t.em_pass);
      }
      if (t.required.u0) {
        row(t.name, "U0 ≥ " + format("%.2f", *t.required.u0), format("%.3f", t.u0), t.u0_pass);
      }
      for (std::size_t k = 0; k < t.observers.size(); ++k) {
        const ObserverCheck& o = t.observers[k];
        row(t.name + ", observer " + std::to_string(k + 1),
            t.required.ugr_l ? "UGR ≤ " + format("%.1f", *t.required.ugr_l) : std::string("UGR"),
            o.ugr ? format("%.1f", *o.ugr) : std::string("no luminaire in view"), o.pass);
      }
    }
    html += "</table>";
  }

  const LightingState& state = scene.state();
  if (!state.luminaires.empty()) {
    // The layout as the state sets it: moved luminaires where they hang, added ones too.
    html +=
        "<h2>Luminaires</h2><table><tr><th>name</th><th>position (m)</th><th>photometry"
        "</th><th>flux (lm)</th><th>power (W)</th><th>dimmer</th><th>on</th></tr>";
    for (std::size_t j = 0; j < state.luminaires.size(); ++j) {
      const LuminaireState& ls = state.luminaires[j];
      const Distribution& d = scene.relighter().distribution(j);
      const std::string photometry = ls.distribution.file.empty()
                                         ? std::string("analytic")
                                         : ls.distribution.file.filename().string();
      const std::optional<double> watts = d.input_watts();
      html += "<tr><td>" + html_escape(ls.name) + "</td><td>" + format("%.2f", ls.position.x) +
              ", " + format("%.2f", ls.position.y) + ", " + format("%.2f", ls.position.z) +
              "</td><td>" + html_escape(photometry) + "</td><td>" + format("%.0f", d.flux_lm()) +
              "</td><td>" + (watts ? format("%.1f", *watts) : std::string("—")) + "</td><td>" +
              format("%.2f", ls.dimmer) + "</td><td>" + (ls.on ? "yes" : "no") + "</td></tr>";
    }
    html += "</table>";
    for (std::size_t j = 0; j < state.luminaires.size(); ++j) {
      html += "<div class=\"luminaire\" style=\"display:inline-block;margin:0 1em 1em 0\"><h3>" +
              html_escape(state.luminaires[j].name) + "</h3>" +
              polar_svg(scene.relighter().distribution(j)) + "</div>";
    }
  }

  if (options.annual) {
    const AnnualReport& a = *options.annual;
    html += "<h2>A year of daylight</h2><p>" + html_escape(a.weather) +
            "</p><table><tr><th>sensor set</th><th>sDA300/50%</th><th>ASE1000,250h</th>"
            "<th>mean DA300</th><th>EN 17037 daylight provision</th></tr>";
    for (std::size_t k = 0; k < s.sensors.size() && k < a.per_set.size(); ++k) {
      const SetDaylight& d = a.per_set[k];
      html += "<tr><td>" + html_escape(s.sensors[k].name) + "</td><td>" +
              format("%.1f%%", 100 * d.sda300) + "</td><td>" + format("%.1f%%", 100 * d.ase) +
              "</td><td>" + format("%.1f%%", 100 * d.mean_da300) + "</td><td>" +
              daylight_provision_name(d.en17037) + "</td></tr>";
    }
    html += "</table>";
    std::size_t at = 0;
    for (const SensorSet& set : s.sensors) {
      std::vector<double> da;
      for (std::size_t i = 0; i < set.points.size(); ++i) {
        da.push_back(100 * a.per_sensor.at(at + i).da300);
      }
      html += "<div class=\"set\"><h3>" + html_escape(set.name) + ": DA300</h3>" +
              plan_svg(set, da, scale_of(da, true), "% of hours") + "</div>";
      at += set.points.size();
    }
  }
  html += "<p style=\"color:#777;font-size:.8em\">relight report</p></body></html>\n";
  return html;
}

}  // namespace relight
