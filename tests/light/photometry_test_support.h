// Helpers shared by the light/ tests: checking InputError messages, an independent
// brute-force ∫ I dω to check the closed-form fluxes against, and temp files.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>

#include <unistd.h>

#include "common/input_error.h"
#include "math/vec3.h"

namespace relight::test {

// Runs fn and expects an InputError whose message contains every fragment.
inline void expect_input_error(const std::function<void()>& fn,
                               std::initializer_list<std::string> fragments) {
  try {
    fn();
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const std::string& f : fragments) {
      EXPECT_NE(message.find(f), std::string::npos) << "message: " << message << "\nlacks: " << f;
    }
    return;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got: " << e.what();
    return;
  }
  ADD_FAILURE() << "expected InputError, nothing thrown";
}

// ∫ I dω = ∫∫ I sinγ dγ dC by the midpoint rule on a uniform (C, γ) grid: independent
// of the production code's per-cell closed forms.
inline double brute_force_flux(const std::function<double(double c_rad, double gamma_rad)>& i,
                               int n_gamma = 500, int n_c = 1000) {
  const double dg = kPi / n_gamma, dc = 2.0 * kPi / n_c;
  double sum = 0;
  for (int a = 0; a < n_gamma; ++a) {
    const double gamma = (a + 0.5) * dg;
    double ring = 0;
    for (int b = 0; b < n_c; ++b) ring += i((b + 0.5) * dc, gamma);
    sum += ring * std::sin(gamma);
  }
  return sum * dg * dc;
}

inline std::filesystem::path test_data(const std::string& name) {
  return std::filesystem::path(RELIGHT_TEST_DATA) / "photometry" / name;
}

// A fresh folder under the system temp dir, removed at destruction.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("relight_light_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto file = path / name;
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }
};

// Deterministic mutations of a valid file (character changes, insertions, deletions):
// `parse` must either succeed or throw InputError for every one — never crash.
inline void parse_random_mutations(const std::string& valid,
                                   const std::function<void(const std::string&)>& parse,
                                   int trials = 3000) {
  const std::string alphabet = "0123456789-+.,eE \n\r\tx[]=TILNCUDOab\x1a";
  std::uint32_t state = 12345;
  auto next = [&] { return state = state * 1664525u + 1013904223u; };
  for (int trial = 0; trial < trials; ++trial) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(next() % 4);
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = next() % text.size();
      const char ch = alphabet[next() % alphabet.size()];
      switch (next() % 3) {
        case 0:
          text[at] = ch;
          break;
        case 1:
          text.insert(text.begin() + static_cast<std::ptrdiff_t>(at), ch);
          break;
        default:
          text.erase(at, 1 + next() % 8);
          break;
      }
    }
    try {
      parse(text);
    } catch (const InputError&) {
    }
  }
}

}  // namespace relight::test
