// A luminaire's luminous intensity distribution as the scene (or a run-time lighting
// state) describes it: plain data, parsed from JSON by scene/, turned into an
// evaluable Distribution by light/ (which reads IES/LDT files).
// γ is measured from the luminaire's aim direction (photometric type C).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace relight {

enum class DistributionType { kIsotropic, kCosinePower, kCurve, kIes, kLdt };

struct DistributionSpec {
  DistributionType type = DistributionType::kIsotropic;
  double candela = 0;                 // isotropic, cosine_power: peak intensity (cd)
  double exponent = 1;                // cosine_power: I = candela * cos^exponent(γ)
  double cutoff_deg = 90;             // cosine_power: zero beyond this γ
  std::vector<double> gamma_deg;      // curve: control points, ascending from 0
  std::vector<double> curve_candela;  // curve: intensity at each control point (cd)
  std::filesystem::path file;         // ies, ldt: resolved against the scene's folder
  // ies, ldt: the file's text when it came embedded (a .rlt keeps the photometry it was
  // computed with); read from `file` when null.
  std::shared_ptr<const std::string> contents;
  std::string where;  // "FILE:JSON-PATH" of the entry, for messages
};

}  // namespace relight
