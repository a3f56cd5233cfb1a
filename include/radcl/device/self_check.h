// Checks that a device agrees with the host on what radcl relies on: the layout of every shared
// struct and the random-number generator's bits. `radcl devices --check` and the tests run them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radcl::device {

class Context;

// One line per disagreement ("offsetof(rc_ray, coef): host 32, device 48"); empty when all agree.
std::vector<std::string> check_layout(Context& ctx);
// Compares `items` x `dims` generator outputs (bits and floats) computed on host and device.
std::vector<std::string> check_rng(Context& ctx, std::uint32_t items, std::uint32_t dims,
                                   std::uint32_t seed);

} // namespace radcl::device
