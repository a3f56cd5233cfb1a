// One fuzz target is one function of the input bytes, defined with RADCL_FUZZ_TARGET(name).
// Built for libFuzzer (RADCL_LIBFUZZER defined) it becomes the binary's LLVMFuzzerTestOneInput;
// built into the regression test it registers itself under `name`, and the test runs every
// file of tests/data/fuzz/<name>/ through it. Bad input is answered with FatalError, which is
// caught here; any other exception, crash or sanitizer report is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "radcl/util/error.h"

namespace radcl::fuzz {

using Body = void (*)(std::string_view data);

inline void run_one(Body body, std::string_view data) {
  // Warnings are an expected answer to bad input; printing them would only slow the fuzzer.
  radcl::set_warning_sink([](const std::string&) {});
  try {
    body(data);
  } catch (const radcl::FatalError&) {
  }
}

#ifndef RADCL_LIBFUZZER
// Defined by the regression test (regressions.cpp).
bool register_target(const char* name, Body body);
#endif

} // namespace radcl::fuzz

#ifdef RADCL_LIBFUZZER
#define RADCL_FUZZ_TARGET(name)                                                                    \
  static void radcl_fuzz_body(std::string_view data);                                              \
  extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {             \
    radcl::fuzz::run_one(radcl_fuzz_body,                                                          \
                         std::string_view(reinterpret_cast<const char*>(bytes), size));            \
    return 0;                                                                                      \
  }                                                                                                \
  static void radcl_fuzz_body(std::string_view data)
#else
#define RADCL_FUZZ_TARGET(name)                                                                    \
  static void radcl_fuzz_body(std::string_view data);                                              \
  [[maybe_unused]] static const bool radcl_fuzz_registered =                                       \
      radcl::fuzz::register_target(#name, radcl_fuzz_body);                                        \
  static void radcl_fuzz_body(std::string_view data)
#endif
