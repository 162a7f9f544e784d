// The run-time half of precomputed transfer (ARCHITECTURE §1, §4.6): lighting state →
// small weight vectors → one weighted sum over the stored transfer → irradiance per
// receiver. Per luminaire j and receiver r:
//   E_r = rgb_j · [ D_rj + Σ_k w_jk · T_rjk ]
// with rgb_j = colour · dimmer · on, w_jk the world-frame SH coefficients of the current
// distribution aimed as set (lighting-design paper Eq. 18, windowed), T the interreflected
// response to basis Y_k (RGB), and D_rj the direct light: exact, I_j(ω_r) · g_r from the
// current distribution and aim ("exact" mode), or Σ_k w_jk · S_rjk from the SH basis
// direct S (the paper's own "sh" mode). D is recomputed only when a luminaire's aim or
// distribution changes; relight() allocates nothing and uses every core.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "light/distribution.h"
#include "math/sh_window.h"
#include "runtime/lighting_state.h"
#include "runtime/luminaire_sh_curve.h"
#include "scene/scene.h"

namespace relight {

// Views into the stored transfer of one luminaire (memory-mapped .rlt sections).
struct LuminaireTransferView {
  std::span<const float> dir_x, dir_y, dir_z, factor;  // direct geometry, per receiver
  std::span<const float> indirect;                     // blocked RGB × K
  std::span<const float> direct_sh;                    // blocked 1 × K ("sh" mode only)
};

struct TransferView {
  std::size_t receivers = 0;
  int sh_order = 8;
  bool direct_sh_mode = false;
  std::vector<LuminaireTransferView> luminaires;  // scene order
};

struct RelighterSettings {
  ShWindow window = ShWindow::kSigma;  // applied to the SH weights of every luminaire
};

class Relighter {
 public:
  Relighter(TransferView transfer, const Scene& scene, RelighterSettings settings = {});

  // Updates weights (and direct fields of luminaires whose aim or distribution
  // changed). Loads IES/LDT files of changed distributions.
  void set_state(const LightingState& state);
  const LightingState& state() const { return state_; }

  // Irradiance per receiver, RGB interleaved: out.size() == 3 · receivers. Without
  // direct light only the interreflected part (for renderers that evaluate direct light
  // themselves, per pixel).
  void relight(std::span<float> out, bool include_direct = true) const;

  // The current photometry of luminaire j (as loaded for its state).
  const Distribution& distribution(std::size_t j) const { return luminaires_.at(j).distribution; }

  std::size_t receivers() const { return transfer_.receivers; }
  // How many distribution changes were one moved curve control point, updated
  // incrementally (the lighting-design paper's Eq. 21) instead of projected anew.
  std::size_t incremental_curve_updates() const { return incremental_curve_updates_; }
  // Bytes of stored transfer one relight() reads.
  std::size_t transfer_bytes() const;

 private:
  struct Luminaire {
    Distribution distribution;
    std::vector<double> sh;               // world-frame SH coefficients of I (windowed)
    std::optional<CurveProjector> curve;  // kept for curve distributions (Eq. 19-21)
    std::vector<float> direct;            // D_r without colour (exact mode)
    std::vector<float> weights;           // K × 3: rgb_c · w_k (indirect)
    std::vector<float> direct_weights;    // K × 3: rgb_c · w_k ("sh" mode direct)
    float rgb[3] = {0, 0, 0};
    bool active = false;
  };

  void update_luminaire(std::size_t j, const LuminaireState& s, bool geometry_changed);
  void project_distribution(std::size_t j, const LuminaireState& s);

  TransferView transfer_;
  RelighterSettings settings_;
  LightingState state_;
  std::vector<Luminaire> luminaires_;
  std::size_t incremental_curve_updates_ = 0;
};

}  // namespace relight
