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
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "light/distribution.h"
#include "math/sh_window.h"
#include "runtime/lighting_state.h"
#include "runtime/luminaire_sh_curve.h"
#include "runtime/portal_lighting.h"
#include "scene/scene.h"
#include "transfer/transfer_blocks.h"

namespace relight {

// Views into the stored transfer of one luminaire (memory-mapped .rlt sections).
struct LuminaireTransferView {
  std::span<const float> dir_x, dir_y, dir_z, factor;  // direct geometry, per receiver
  std::span<const float> indirect;                     // blocked RGB × K
  std::span<const float> direct_sh;                    // blocked 1 × K ("sh" mode only)
};

// Views into the stored transfer of one portal: its geometry for the shell, the direct
// cubemap record of each receiver (transfer/cubemap_encoding.h) and the indirect response
// to each SH basis radiance of its shell (blocked RGB × K, K = portal_sh_order²).
struct PortalTransferView {
  std::string name;
  int face_size = 32;
  Vec3 centre, outward;
  double diameter = 0;
  std::span<const std::uint8_t> records;
  std::span<const std::uint64_t> offsets;  // receivers + 1
  std::span<const float> indirect;
};

struct TransferView {
  std::size_t receivers = 0;
  int sh_order = 8;
  bool direct_sh_mode = false;
  std::vector<LuminaireTransferView> luminaires;  // scene order
  int portal_sh_order = 6;
  std::vector<PortalTransferView> portals;  // scene order
};

struct RelighterSettings {
  ShWindow window = ShWindow::kSigma;  // applied to the SH weights of every luminaire
  // Reads portal environments (map images need render/environment_map_io.h).
  EnvironmentLoader load_environment = environment_without_images;
};

class Relighter {
 public:
  Relighter(TransferView transfer, const Scene& scene, RelighterSettings settings = {});

  // Updates weights (and direct fields of luminaires whose aim or distribution
  // changed). Loads IES/LDT files of changed distributions.
  void set_state(const LightingState& state);
  const LightingState& state() const { return state_; }

  // Irradiance per receiver, RGB interleaved: out.size() == 3 · receivers. Without
  // direct light, what renderers that evaluate direct light per pixel still need: the
  // interreflected light and the portals' direct skylight, but not the luminaires' direct
  // light nor the portals' sharp suns (see sharp_sun()).
  // Each kind of source (luminaires, portals) keeps its partial sum between calls, and only
  // the kinds whose state changed since are summed again.
  void relight(std::span<float> out, bool include_direct = true);
  // The sun of portal p when it is sharp (clear glass, unoccluded), for per-pixel tracing.
  const std::optional<PortalSun>& sharp_sun(std::size_t p) const {
    return portals_.at(p).sharp_sun;
  }
  // The current shell of portal p (for renderers showing the view out of a window).
  const Shell& shell(std::size_t p) const { return portals_.at(p).shell; }
  // Wall time of the last shell update of portal p, seconds.
  double shell_seconds(std::size_t p) const { return portals_.at(p).seconds; }

  // The current photometry of luminaire j (as loaded for its state).
  const Distribution& distribution(std::size_t j) const { return luminaires_.at(j).distribution; }

  std::size_t receivers() const { return transfer_.receivers; }
  // How many distribution changes were one moved curve control point, updated
  // incrementally (the lighting-design paper's Eq. 21) instead of projected anew.
  std::size_t incremental_curve_updates() const { return incremental_curve_updates_; }
  // Bytes of stored transfer a relight() of every source reads.
  std::size_t transfer_bytes() const;
  // Bytes the last relight() read and wrote: the transfer of the sources it summed again,
  // and the partial sums and the output.
  std::size_t last_frame_bytes() const { return last_frame_bytes_; }

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

  struct PartialSum {
    std::vector<float> values;  // 3 per receiver
    bool valid = false;
  };

  void update_luminaire(std::size_t j, const LuminaireState& s, bool geometry_changed);
  void add_luminaires(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const;
  void add_portals(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const;
  std::size_t luminaire_bytes() const;
  std::size_t portal_bytes() const;
  void project_distribution(std::size_t j, const LuminaireState& s);

  TransferView transfer_;
  const Scene* scene_;
  RelighterSettings settings_;
  std::vector<PortalLighting> portals_;
  LightingState state_;
  std::vector<Luminaire> luminaires_;
  std::size_t incremental_curve_updates_ = 0;
  PartialSum luminaire_sums_[2], portal_sums_[2];  // [include_direct]
  std::size_t last_frame_bytes_ = 0;
};

}  // namespace relight
