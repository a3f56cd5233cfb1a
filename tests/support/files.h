// Whole-file reads and writes: tests compare program output files with references and write
// the scenes and inputs they run on; one copy here instead of one per test file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace radcl::test {

// The file's bytes; empty when it cannot be read (a missing output then fails the comparison
// that follows rather than throwing).
std::string read_file(const std::filesystem::path& path);

// Replaces the file's contents with `text`, byte for byte.
void write_file(const std::filesystem::path& path, std::string_view text);

} // namespace radcl::test
