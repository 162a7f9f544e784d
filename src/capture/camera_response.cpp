#include "capture/camera_response.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/photo.hpp>

namespace relight {

namespace {

constexpr int kSampleSide = 12;  // 144 samples: N (P − 1) > 255 for P ≥ 3 (Debevec & Malik §2.1)

// Pixel positions inside the image circle whose radiances span the bracket's range in every
// channel (Debevec & Malik §2.1: samples spread over the range, from areas of low variation).
// Candidates are a grid over the circle. Each gets a rough radiance per channel — its
// best-exposed shot's value in that channel through a 2.2 gamma, over the exposure — and is
// kept where that shot is flat within 1/4 of the value (1/64 of full scale for dark values)
// over ±2 px (at an edge, JPEG's chroma subsampling and ringing change a pixel between
// channels, not the response). A third of the samples is taken per channel: the candidates
// nearest to evenly spaced values of that channel's log radiance (a warm room's blue channel
// rarely reaches high values; spacing by grey alone left it 6 % off near the top).
std::vector<std::size_t> sample_offsets(const Bracket& bracket, const ImageCircle& circle) {
  struct Candidate {
    std::size_t offset = 0;
    std::array<double, 3> log_radiance{};
  };
  std::vector<Candidate> candidates;
  const Photo& first = bracket.shots.front();
  const int full = first.max_value();
  constexpr int kGrid = 128;
  for (int j = 0; j < kGrid; ++j) {
    for (int i = 0; i < kGrid; ++i) {
      const double x = circle.cx + circle.radius * (2 * (i + 0.5) / kGrid - 1);
      const double y = circle.cy + circle.radius * (2 * (j + 0.5) / kGrid - 1);
      if (std::hypot(x - circle.cx, y - circle.cy) > 0.85 * circle.radius) continue;
      const int px = static_cast<int>(x), py = static_cast<int>(y);
      if (px < 2 || py < 2 || px + 2 >= first.width || py + 2 >= first.height) continue;
      Candidate candidate{first.offset(px, py), {}};
      bool flat = true;
      for (std::size_t c = 0; c < 3 && flat; ++c) {
        // The shot whose value in this channel is nearest the middle.
        std::size_t best = 0;
        int best_quality = -1;
        for (std::size_t s = 0; s < bracket.shots.size(); ++s) {
          const int z = bracket.shots[s].rgb[candidate.offset + c];
          if (std::min(z, full - z) > best_quality) {
            best_quality = std::min(z, full - z);
            best = s;
          }
        }
        const Photo& shot = bracket.shots[best];
        const int z = shot.rgb[candidate.offset + c];
        int spread = 0;
        for (const std::size_t n : {shot.offset(px - 2, py), shot.offset(px + 2, py),
                                    shot.offset(px, py - 2), shot.offset(px, py + 2)}) {
          spread = std::max(spread, std::abs(shot.rgb[n + c] - z));
        }
        flat = 4 * spread <= std::max(z, full / 16);
        candidate.log_radiance[c] = 2.2 * std::log(std::max(z, 1) / static_cast<double>(full)) -
                                    std::log(bracket.exposures[best]);
      }
      if (flat) candidates.push_back(candidate);
    }
  }
  std::vector<std::size_t> offsets;
  if (candidates.empty()) return offsets;
  constexpr int kCount = kSampleSide * kSampleSide;
  for (std::size_t c = 0; c < 3; ++c) {
    std::sort(candidates.begin(), candidates.end(), [c](const Candidate& a, const Candidate& b) {
      return a.log_radiance[c] < b.log_radiance[c];
    });
    const double lo = candidates.front().log_radiance[c];
    const double hi = candidates.back().log_radiance[c];
    const int count = (kCount * static_cast<int>(c + 1)) / 3 - (kCount * static_cast<int>(c)) / 3;
    std::size_t at = 0;
    for (int k = 0; k < count; ++k) {
      const double target = lo + (hi - lo) * (k + 0.5) / count;
      while (at + 1 < candidates.size() && candidates[at + 1].log_radiance[c] <= target) ++at;
      const std::size_t next = std::min(at + 1, candidates.size() - 1);
      const bool nearer = std::abs(candidates[next].log_radiance[c] - target) <
                          std::abs(candidates[at].log_radiance[c] - target);
      offsets.push_back(candidates[nearer ? next : at].offset);
    }
  }
  return offsets;
}

// One channel-interleaved kSampleSide² sample image per shot of a bracket.
std::vector<cv::Mat> sample_images(const Bracket& bracket, const ImageCircle& circle) {
  std::vector<std::size_t> offsets = sample_offsets(bracket, circle);
  offsets.resize(static_cast<std::size_t>(kSampleSide) * kSampleSide,
                 offsets.empty() ? 0 : offsets.back());
  std::vector<cv::Mat> images;
  for (const Photo& shot : bracket.shots) {
    cv::Mat samples(kSampleSide, kSampleSide, CV_8UC3);
    for (int k = 0; k < kSampleSide * kSampleSide; ++k) {
      for (int c = 0; c < 3; ++c) {
        samples.at<cv::Vec3b>(k / kSampleSide, k % kSampleSide)[c] = static_cast<std::uint8_t>(
            shot.rgb[offsets[static_cast<std::size_t>(k)] + static_cast<std::size_t>(c)]);
      }
    }
    images.push_back(samples);
  }
  return images;
}

// True when the brackets have as many shots and the same exposure ratios (within 2 %).
bool same_ratios(std::span<const Bracket* const> brackets) {
  const Bracket& first = *brackets.front();
  for (const Bracket* b : brackets) {
    if (b->exposures.size() != first.exposures.size()) return false;
    for (std::size_t s = 0; s < first.exposures.size(); ++s) {
      const double ratio =
          (b->exposures[s] / b->exposures[0]) / (first.exposures[s] / first.exposures[0]);
      if (std::abs(ratio - 1) > 0.02) return false;
    }
  }
  return true;
}

// The span of grey values the samples reach over all shots (how much of the curve they fix).
int coverage(const std::vector<cv::Mat>& images) {
  int lo = 255, hi = 0;
  for (const cv::Mat& m : images) {
    double mn = 0, mx = 0;
    cv::minMaxLoc(m.reshape(1), &mn, &mx);
    lo = std::min(lo, static_cast<int>(mn));
    hi = std::max(hi, static_cast<int>(mx));
  }
  return hi - lo;
}

CameraResponse calibrate(const std::vector<cv::Mat>& images, const std::vector<double>& exposures) {
  std::vector<float> times(exposures.size());
  std::transform(exposures.begin(), exposures.end(), times.begin(),
                 [](double t) { return static_cast<float>(t); });
  cv::Mat curve;
  cv::createCalibrateDebevec(images.front().rows * images.front().cols, 30.0f, false)
      ->process(images, curve, times);
  CameraResponse response;
  for (int c = 0; c < 3; ++c) {
    auto& channel = response.exposure[static_cast<std::size_t>(c)];
    channel.resize(256);
    for (int z = 0; z < 256; ++z) channel[static_cast<std::size_t>(z)] = curve.at<cv::Vec3f>(z)[c];
    // A response is increasing; the smoothness prior can leave a flat or slightly falling
    // end where no sample reached: make it non-decreasing.
    for (int z = 1; z < 256; ++z) {
      channel[static_cast<std::size_t>(z)] =
          std::max(channel[static_cast<std::size_t>(z)], channel[static_cast<std::size_t>(z - 1)]);
    }
  }
  return response;
}

}  // namespace

CameraResponse recover_response(std::span<const Bracket* const> brackets,
                                std::span<const ImageCircle> circles) {
  CameraResponse response;
  const Photo& first = brackets.front()->shots.front();
  if (first.bits == 16) {
    response.linear = true;
    for (auto& channel : response.exposure) {
      channel.resize(static_cast<std::size_t>(first.max_value()) + 1);
      for (std::size_t z = 0; z < channel.size(); ++z) channel[z] = z / 32768.0;
    }
    return response;
  }
  std::vector<std::vector<cv::Mat>> samples;
  for (std::size_t b = 0; b < brackets.size(); ++b) {
    samples.push_back(sample_images(*brackets[b], circles[b]));
  }
  if (same_ratios(brackets)) {
    // One system for the camera: each sample's unknown radiance absorbs its bracket's base
    // exposure, so the brackets' samples sit side by side in one image per shot.
    std::vector<cv::Mat> joint;
    for (std::size_t s = 0; s < samples.front().size(); ++s) {
      std::vector<cv::Mat> row;
      row.reserve(samples.size());
      for (const auto& bracket_samples : samples) row.push_back(bracket_samples[s]);
      cv::Mat side_by_side;
      cv::hconcat(row, side_by_side);
      joint.push_back(side_by_side);
    }
    return calibrate(joint, brackets.front()->exposures);
  }
  std::size_t best = 0;
  for (std::size_t b = 1; b < samples.size(); ++b) {
    if (coverage(samples[b]) > coverage(samples[best])) best = b;
  }
  return calibrate(samples[best], brackets[best]->exposures);
}

HdrPhoto merge_bracket(const Bracket& bracket, const CameraResponse& response) {
  const Photo& first = bracket.shots.front();
  const int zmax = first.max_value();
  const std::size_t levels = static_cast<std::size_t>(zmax) + 1;
  const std::size_t shots = bracket.shots.size();
  // Per shot and channel: ln X(z) − ln Δt; one hat table for all.
  std::vector<float> log_exposure(shots * 3 * levels);
  for (std::size_t s = 0; s < shots; ++s) {
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t z = 0; z < levels; ++z) {
        log_exposure[(s * 3 + c) * levels + z] = static_cast<float>(
            std::log(std::max(response.exposure[c][z], 1e-12)) - std::log(bracket.exposures[s]));
      }
    }
  }
  // Debevec & Malik's hat, zero at both ends and from the clip level up: a saturated shot
  // says only "at least", which would pull the mean down.
  const auto clip_level = static_cast<std::uint16_t>(std::lround(0.98 * zmax));
  std::vector<float> hat(levels);
  for (std::size_t z = 0; z < levels; ++z) {
    hat[z] = z >= clip_level
                 ? 0.0f
                 : static_cast<float>(std::min<double>(z, zmax - z)) / static_cast<float>(zmax);
  }
  const std::size_t shortest = shortest_shot(bracket);
  const std::size_t longest = longest_shot(bracket);
  HdrPhoto hdr{first.width, first.height, {}, {}};
  const std::size_t pixels = static_cast<std::size_t>(first.width) * first.height;
  hdr.radiance.resize(pixels);
  hdr.clipped.assign(pixels, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 4096), [&](const auto& range) {
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      double value[3];
      bool clipped = false;
      for (std::size_t c = 0; c < 3; ++c) {
        const std::uint16_t z_short = bracket.shots[shortest].rgb[3 * p + c];
        if (z_short >= clip_level) {
          value[c] = std::exp(log_exposure[(shortest * 3 + c) * levels + z_short]);
          clipped = true;
          continue;
        }
        float sum = 0, weight = 0;
        for (std::size_t s = 0; s < shots; ++s) {
          const std::uint16_t z = bracket.shots[s].rgb[3 * p + c];
          sum += hat[z] * log_exposure[(s * 3 + c) * levels + z];
          weight += hat[z];
        }
        // Black in every shot: the longest shot's value, however dark.
        value[c] = weight > 0 ? std::exp(sum / weight)
                              : std::exp(log_exposure[(longest * 3 + c) * levels +
                                                      bracket.shots[longest].rgb[3 * p + c]]);
      }
      hdr.radiance[p] = {value[0], value[1], value[2]};
      hdr.clipped[p] = clipped ? 1 : 0;
    }
  });
  return hdr;
}

}  // namespace relight
