// Data files and pictures of brightdata, colordata, texdata and colorpict
// (../shared/docs/radiance/scene-format.md §4.1): read on the host into n-dimensional grids, then
// packed into the kernels' float argument buffer where kernels/patterns/pattern_data.cl
// interpolates them.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace radcl::render {

// Radiance allows at most 5 dimensions (MAXDDIM).
constexpr int kMaxDataDims = 5;

struct DataAxis {
  int count = 0;             // grid points (at least 2)
  double begin = 0, end = 0; // first and last coordinate
  std::vector<float> points; // explicit coordinates, empty when evenly spaced
};

struct DataSet {
  std::vector<DataAxis> axes; // first axis varies slowest in `values`
  std::vector<float> values;
};

// Reads a data file (`path`; `name` as written in the scene, for messages). Throws FatalError
// "bad format in data file ...", "unexpected EOF in data file ..." or "bad number of
// dimensions for ...".
DataSet read_data_file(const std::string& path, const std::string& name);

// A picture as three 2-D data sets (red, green, blue): first axis vertical (bottom row first),
// second horizontal; the shorter side spans [0, 1], the other its aspect ratio, PIXASPECT
// honoured. Throws FatalError "bad picture file ...".
std::array<DataSet, 3> read_picture_data(const std::string& path, const std::string& name);

// Appends `d` to `args` and returns its offset. Layout (integers stored as their bit
// patterns): dims; per axis {count, offset of explicit points or ~0u, begin, end - begin};
// the values; then the explicit points of each axis that has them.
std::uint32_t pack_data(const DataSet& d, std::vector<float>& args);

} // namespace radcl::render
