// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the tile-set manifest (tiles/manifest.cpp) and what reads it: the
// bytes up to the first NUL are manifest.json, the rest the journal. In a
// scratch folder the harness parses it as `fracterra tiles` resuming a set
// does (identity check, journal replay) and as the reader of a finished set
// does (extent, one window). A bad file must be an ft::Error with a
// message, never a JSON library exception (an internal error) or a crash.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_util.hpp"
#include "terrain/terrain.hpp"
#include "tiles/manifest.hpp"
#include "tiles/tileset_reader.hpp"

namespace {

std::string scratch_folder() {
  static const std::string dir = [] {
    const auto d = std::filesystem::temp_directory_path() / ("ft_fuzz_manifest_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d.string();
  }();
  return dir;
}

void put(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) { return 0; }

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const size_t nul = bytes.find('\0');
  const std::string manifest = bytes.substr(0, nul), journal = nul == std::string::npos ? "" : bytes.substr(nul + 1);
  const std::string dir = scratch_folder();
  put(dir + "/" + ft::tiles::kManifestName, manifest);
  put(dir + "/" + ft::tiles::kJournalName, journal);
  ft::fuzz::expect_ok_or_error([&] {
    std::optional<nlohmann::json> m = ft::tiles::read_manifest(dir);
    if (!m) ft::fuzz::bug("an existing manifest was not read");
    // Resuming: the identity check against a terrain, then the journal.
    const nlohmann::json wanted = {
        {"terrain", ft::tiles::terrain_identity(ft::terrain::default_terrain_params())}, {"tile", 64}, {"tile_format", "npy"}};
    ft::tiles::identity_difference(wanted, *m);
    ft::tiles::replay_journal(dir, *m);
  });
  ft::fuzz::expect_ok_or_error([&] {
    // Reading a finished set back (its tiles are absent: an error, cleanly).
    int64_t w = 0, h = 0;
    ft::tiles::tileset_extent(dir, 0, &w, &h);
    ft::tiles::read_tileset_window(dir, 0, 0, 0, 1, 1);
  });
  return 0;
}
