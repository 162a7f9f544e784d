// Bad input is reported, never crashed on: every parser throws InputError with "WHERE: reason",
// WHERE being FILE, FILE:LINE or FILE:JSON-PATH.
// The CLI prints "error: " + what() and exits with code 2.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace relight {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail_input(const std::string& where, const std::string& reason);

// "FILE:LINE" as used in messages about text formats.
std::string at_line(const std::filesystem::path& file, int line);

}  // namespace relight
