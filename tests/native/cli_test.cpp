// SPDX-License-Identifier: GPL-3.0-or-later
// The fracterra CLI as a user runs it: outputs, --stats, --help, and bad
// input (one clear line on stderr, non-zero exit, no partial or clobbered file).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "tables/param_registry.hpp"
#include "io/atomic_file.hpp"
#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "io/heightfield_io.hpp"
#include "povray/scene.hpp"
#include "terrain/terrain.hpp"

namespace ft {
namespace {

namespace fs = std::filesystem;

using test::CliRun;
CliRun run(const std::string& args) { return test::run_cli(args); }

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ft_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  size_t files() const {
    size_t n = 0;
    for (auto& e : fs::directory_iterator(dir_)) n += e.is_regular_file();
    return n;
  }
  fs::path dir_;
};

TEST_F(Cli, TerrainStatsPrintsOneJsonObjectWithTheRequiredKeys) {
  const CliRun r = run("terrain --levels 6 --hurst 0.5 --seed 4 --stats");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"seconds", "min", "max", "mean", "std"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_LT(j["min"].get<double>(), j["max"].get<double>());
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
}

// `tiles --engine`: the set, then its engine tiles and sidecar in OUT/ENGINE/;
// a tile size that does not cut the set is refused before anything is written.
TEST_F(Cli, TilesForAnEngineGoBesideTheSetAndBadSizesAreRefusedFirst) {
  const CliRun r = run("tiles --levels 7 --seed 3 --tile 32 --quiet --engine unreal --out " + path("set"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["engine"]["columns"], 4);
  EXPECT_EQ(j["engine"]["tile_samples"], 32);
  EXPECT_TRUE(fs::exists(path("set/unreal/terrain_x3_y3.png")));
  EXPECT_TRUE(fs::exists(path("set/unreal/unreal.json")));
  const CliRun bad = run("tiles --levels 7 --tile 32 --engine unity --engine-size 100 --out " + path("bad"));
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("sizes that do: 129, 65, 33"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("bad")));
}

// An enum flag takes the label the add-on shows as well as its name:
// `terrain --erode rugged-mountains` is `--erode land`, bit for bit.
TEST_F(Cli, EnumFlagsTakeTheAddonsLabels) {
  const std::string t = "terrain --levels 6 --seed 2 --falloff radial --height-offset 0.5 --threads 1 ";
  ASSERT_EQ(run(t + "--erode land --out " + path("a.npy")).code, 0);
  const CliRun label = run(t + "--erode \"Rugged Mountains\" --out " + path("b.npy"));
  ASSERT_EQ(label.code, 0) << label.err;
  ASSERT_EQ(run(t + "--erode gentle_valleys --out " + path("c.npy")).code, 0);
  EXPECT_EQ(io::read_file(path("a.npy")), io::read_file(path("b.npy")));
  EXPECT_NE(io::read_file(path("a.npy")), io::read_file(path("c.npy")));
  const CliRun bad = run(t + "--erode mountains --out " + path("d.npy"));
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("land (rugged-mountains)"), std::string::npos) << bad.err;
}

TEST_F(Cli, PngPgmAndNpyOutputsRoundTrip) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.levels = 6;
  p.seed = 9;
  const Heightfield want = terrain::generate_terrain(p);
  const HeightStats s = want.stats();
  for (const char* ext : {".png", ".pgm", ".npy"}) {
    const std::string out = path(std::string("t") + ext);
    const CliRun r = run("terrain --levels 6 --seed 9 --out " + out);
    ASSERT_EQ(r.code, 0) << r.err;
    const Heightfield got = io::read_heightfield(out);
    ASSERT_EQ(got.width(), 65);
    // 16-bit formats quantise the normalised range: half a step of 1/65535.
    const double tol = std::string(ext) == ".npy" ? 0.0 : 0.5 * (s.max - s.min) / 65535.0 + 1e-6;
    for (size_t i = 0; i < got.size(); ++i) ASSERT_NEAR(got.data()[i], want.data()[i], tol) << ext << " " << i;
  }
}

TEST_F(Cli, MissingOutputFolderIsOneClearLineAndNoFile) {
  const CliRun r = run("terrain --levels 4 --out " + path("no/such/folder/t.png"));
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(r.err.rfind("fracterra: error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST_F(Cli, AFailedRunNeverClobbersAGoodFile) {
  const std::string out = path("good.png");
  ASSERT_EQ(run("terrain --levels 5 --seed 1 --out " + out).code, 0);
  const std::string before = io::read_file(out);
  // A malformed reference file fails after the output was named.
  io::write_file_atomically(path("bad.png"), "not a png at all");
  const CliRun r = run("terrain --levels 5 --reference " + path("bad.png") + " --out " + out);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("not a PNG"), std::string::npos) << r.err;
  EXPECT_EQ(io::read_file(out), before);
  EXPECT_EQ(files(), 2u) << "no temporary file may be left behind";
}

TEST_F(Cli, OutOfRangeParametersAreRejectedWithTheAllowedRange) {
  // The message names the field, states the allowed range (as the table
  // gives it: hurst [0, 1], levels 1..15, sigma > 0) and echoes the value.
  const std::pair<const char*, std::vector<std::string>> cases[] = {
      {"--hurst 1.5", {"hurst", "[0, 1]", "1.5"}},  {"--hurst nan", {"hurst", "[0, 1]", "NaN"}},
      {"--levels 0", {"levels", "1..15", "got 0"}}, {"--levels 16", {"levels", "1..15", "16"}},
      {"--sigma 0", {"sigma", "> 0", "got 0"}},     {"--sigma -2", {"sigma", "> 0", "-2"}}};
  for (const auto& [args, words] : cases) {
    const CliRun r = run(std::string("terrain --stats ") + args);
    EXPECT_NE(r.code, 0) << args;
    for (const std::string& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << args << ": " << r.err;
  }
}

TEST_F(Cli, ReferenceGridFromAFileSurvivesInTheTerrain) {
  // A 5x5 reference as .npy; its values must appear exactly at the nodes.
  std::vector<float> ref(25);
  for (int i = 0; i < 25; ++i) ref[size_t(i)] = float(i % 7) - 2.5f;
  Heightfield r(5, 5);
  std::copy(ref.begin(), ref.end(), r.data());
  io::write_heightfield(r, path("ref.npy"));
  ASSERT_EQ(run("terrain --levels 6 --reference " + path("ref.npy") + " --out " + path("t.npy")).code, 0);
  const Heightfield t = io::read_heightfield(path("t.npy"));
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) EXPECT_EQ(t.at(i * 16, j * 16), ref[size_t(j * 5 + i)]);
}

// One option of a --help page: its spec ("--hurst FLOAT:FLOAT in [0 - 1]=0.8")
// and its description (CLI11 puts it on the next line when the spec is long).
struct HelpOption {
  std::string spec, description;
};

// The options and subcommands of one --help page.
void parse_help(const std::string& help, std::vector<HelpOption>* options, std::vector<std::string>* subcommands) {
  std::istringstream in(help);
  std::string line, section;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == ':' && line[0] != ' ') {
      section = line;
      continue;
    }
    if (line.rfind("  ", 0) != 0 || line.size() < 3 || line[2] == ' ') {
      // A description wrapped onto its own line belongs to the option above.
      const size_t text = line.find_first_not_of(' ');
      if (section == "Options:" && !options->empty() && options->back().description.empty() && text != std::string::npos)
        options->back().description = line.substr(text);
      continue;
    }
    const size_t gap = line.find("  ", 2);
    const std::string head = line.substr(2, gap == std::string::npos ? std::string::npos : gap - 2);
    const size_t text = gap == std::string::npos ? std::string::npos : line.find_first_not_of(' ', gap);
    const std::string desc = text == std::string::npos ? "" : line.substr(text);
    if (section == "Options:") options->push_back({head, desc});
    if (section == "Subcommands:") subcommands->push_back(head);
  }
}

TEST_F(Cli, HelpExplainsEveryFlagWithItsDefault) {
  // Every option of every subcommand (found from the help pages themselves, so a
  // new flag is checked without editing this test) has a description, and every
  // numeric option shows its default (CLI11's "=value", or the word "default" in
  // its description), is required or is a list (empty unless given), except
  // those listed here, which must exist.
  const std::set<std::string> no_default = {
      "scene --water",  // the alternative to --sea-fraction (whose default is no sea)
  };
  std::set<std::string> seen_without_default;
  std::vector<std::string> pages = {""};
  size_t checked = 0;
  for (size_t k = 0; k < pages.size(); ++k) {
    const CliRun r = run(pages[k] + " --help");
    ASSERT_EQ(r.code, 0) << pages[k] << ": " << r.err;
    std::vector<HelpOption> options;
    std::vector<std::string> subs;
    parse_help(r.out, &options, &subs);
    for (const std::string& sub : subs) pages.push_back(pages[k].empty() ? sub : pages[k] + " " + sub);
    if (k > 0 && subs.empty()) {
      EXPECT_GT(options.size(), 1u) << pages[k] << " lists no option";
    }
    for (const HelpOption& o : options) {
      if (o.spec.rfind("-h,--help", 0) == 0 || o.spec.rfind("--version", 0) == 0) continue;
      ++checked;
      const std::string name = pages[k] + " " + o.spec.substr(0, o.spec.find(' '));
      EXPECT_FALSE(o.description.empty()) << name << " has no description";
      const bool numeric = o.spec.find(" INT") != std::string::npos || o.spec.find(" UINT") != std::string::npos ||
                           o.spec.find(" FLOAT") != std::string::npos;
      const bool list = o.spec.find(" ...") != std::string::npos;  // repeatable: empty unless given
      const bool shows_default = list || o.spec.find('=') != std::string::npos ||
                                 o.description.find("default") != std::string::npos ||
                                 o.spec.find("REQUIRED") != std::string::npos;
      if (numeric && !shows_default) {
        seen_without_default.insert(name);
        EXPECT_TRUE(no_default.count(name)) << name << " shows no default: \"" << o.spec << "\"";
      }
    }
  }
  EXPECT_GT(pages.size(), 10u) << "the subcommands were not found in fracterra --help";
  EXPECT_GT(checked, 100u) << "the options were not found in the help pages";
  EXPECT_EQ(seen_without_default, no_default) << "an entry of no_default names no such option";
  const CliRun terrain = run("terrain --help");
  EXPECT_NE(terrain.out.find("--hurst FLOAT=0.8"), std::string::npos) << "the default of --hurst";
  EXPECT_NE(terrain.out.find("range [0, 1]"), std::string::npos) << "the range of --hurst";
}

TEST_F(Cli, CommandsWithATableOfferEveryOneOfItsSettings) {
  // The flags of these commands are built from the library's parameter tables:
  // every setting row is a flag with its default (enums by their CLI names),
  // except the ones the command offers in its own form.
  struct Case {
    const char* command;
    int kind;
    std::set<std::string> own_form;
  };
  const Case cases[] = {{"terrain", FT_PARAMS_TERRAIN, {"width", "height", "center_x", "center_y"}},
                        {"profile", FT_PARAMS_PROFILE, {}},
                        {"fractalize", FT_PARAMS_FRACTALIZE, {}},
                        {"erode", FT_PARAMS_EROSION, {}},
                        {"rivers", FT_PARAMS_HYDROLOGY, {}},
                        {"terrain", FT_PARAMS_BUILD, {"threads"}}};
  for (const Case& c : cases) {
    const std::string help = run(std::string(c.command) + " --help").out;
    int flags = 0;
    for (const ft_param_info& r : tables::param_table(c.kind).rows) {
      const ft_param_info* row = &r;
      if (row->flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA) || row->count != 1 ||
          c.own_form.count(row->name))
        continue;
      std::string flag = std::string("--") + row->name;
      std::replace(flag.begin(), flag.end(), '_', '-');
      // "--flag TYPE" or, with the name it had before the tables, "--flag,--old TYPE".
      EXPECT_TRUE(help.find(flag + " ") != std::string::npos || help.find(flag + ",") != std::string::npos)
          << c.command << ": no " << flag;
      ++flags;
    }
    EXPECT_GE(flags, c.kind == FT_PARAMS_BUILD ? 1 : 4) << c.command;
  }
  // One word per concept: the fractalize mode is "midpoint" as everywhere, not "voss".
  std::ofstream(path("quad.obj")) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  EXPECT_NE(run("fractalize --in " + path("quad.obj") + " --mode voss --stats").code, 0);
  const CliRun mid = run("fractalize --in " + path("quad.obj") + " --mode midpoint --levels 2 --out " + path("m.obj"));
  const CliRun add = run("fractalize --in " + path("quad.obj") + " --mode additions --levels 2 --out " + path("a.obj"));
  ASSERT_EQ(mid.code, 0) << mid.err;
  ASSERT_EQ(add.code, 0) << add.err;
  EXPECT_NE(io::read_file(path("m.obj")), io::read_file(path("a.obj"))) << "--mode reaches the library";
}

TEST_F(Cli, ErodePresetsAreTheLibrarysAndFlagsOverrideThem) {
  // `erode --preset` is the library's preset (by id, label or old id), and a
  // flag given beside it wins, under its table name or its old short name
  // alike; the map files reach the library.
  const std::string in = path("t.npy");
  ASSERT_EQ(run("terrain --method fbm --size 65 --seed 2 --out " + in).code, 0);
  Heightfield hf = io::read_heightfield(in);
  hf.set_world_size(10);  // erode's default for a file that records none (.npy)
  const erosion::ErosionConfig preset = erosion::erosion_preset("gentle_valleys", hf);
  const auto same = [&](const std::string& args, const erosion::ErosionConfig& c) {
    const CliRun r = run("erode --in " + in + " " + args + " --out " + path("e.npy"));
    ASSERT_EQ(r.code, 0) << args << ": " << r.err;
    const Heightfield got = io::read_heightfield(path("e.npy")), want = erosion::erode(hf, c, nullptr);
    ASSERT_EQ(got.size(), want.size());
    EXPECT_TRUE(std::equal(got.data(), got.data() + got.size(), want.data())) << args;
  };
  same("--preset valleys", preset);
  same("--preset 'Gentle Valleys'", preset);
  erosion::ErosionConfig weaker = preset;
  weaker.model.strength = 0.2;
  const Heightfield a = erosion::erode(hf, preset, nullptr), b = erosion::erode(hf, weaker, nullptr);
  EXPECT_FALSE(std::equal(a.data(), a.data() + a.size(), b.data())) << "the strength must change the terrain";
  same("--preset valleys --strength 0.2", weaker);
  erosion::ErosionConfig custom = preset;
  custom.fluvial.steps = 5, custom.thermal.iterations = 3, custom.thermal.talus_degrees = 40;
  same("--preset valleys --fluvial 5 --thermal-iterations 3 --talus 40", custom);
  // Without a preset the flags stand over the table's defaults; their ranges are the library's.
  erosion::ErosionConfig plain;
  plain.hydraulic.iterations = 4;
  same("--hydraulic 4", plain);
  const CliRun bad = run("erode --in " + in + " --preset valleys --thermal-rate 0 --stats");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("thermal_rate must be in (0, 1], got 0"), std::string::npos) << bad.err;
  const CliRun strong = run("erode --in " + in + " --preset valleys --strength 1.5 --stats");
  EXPECT_NE(strong.code, 0);
  EXPECT_NE(strong.err.find("strength must be in [0, 1], got 1.5"), std::string::npos) << strong.err;
  // A mask file: white erodes, black keeps (a 2 x 2 image, black on the right).
  Heightfield mask(2, 2);
  mask.at(0, 0) = mask.at(0, 1) = 1.0f;
  mask.at(1, 0) = mask.at(1, 1) = 0.0f;
  io::write_heightfield(mask, path("mask.npy"));
  erosion::ErosionConfig masked = preset;
  masked.erosion_mask = {mask.data(), 2, 2};
  same("--preset valleys --erosion-mask " + path("mask.npy"), masked);
  erosion::ErosionConfig rained = preset;
  rained.rain_map = {mask.data(), 2, 2};
  same("--preset valleys --rain-map " + path("mask.npy"), rained);
  mask.at(1, 1) = NAN;
  io::write_heightfield(mask, path("nan.npy"));
  const CliRun nan = run("erode --in " + in + " --preset valleys --erosion-mask " + path("nan.npy") + " --stats");
  EXPECT_NE(nan.code, 0);
  EXPECT_NE(nan.err.find("erosion_mask's values must be in [0, 1]; sample 1, 1"), std::string::npos) << nan.err;
}

TEST_F(Cli, ErodeInOfATerrainFileIsTerrainErode) {
  // `erode --in` runs the pipeline's erode stage (preset rule included) as
  // `terrain --erode` does: a terrain eroded in the one call, or written and
  // eroded after, gives the same bits, bounded (fBm) and as a torus (a
  // spectral terrain tiles: the pipeline erodes it periodic, `erode` when
  // told), with a setting beside the preset and a mask file.
  Heightfield mask(2, 2);
  mask.at(0, 0) = mask.at(0, 1) = 1.0f;
  mask.at(1, 0) = mask.at(1, 1) = 0.25f;
  io::write_heightfield(mask, path("mask.npy"));
  const std::string settings = " --strength 0.3 --erosion-mask " + path("mask.npy");
  const std::pair<std::string, std::string> cases[] = {{"--method fbm --size 65 --seed 3", ""},
                                                       {"--method spectral --size 64 --seed 5", " --periodic"}};
  for (const auto& [terrain, erode] : cases) {
    ASSERT_EQ(run("terrain " + terrain + " --out " + path("t.npy")).code, 0) << terrain;
    const CliRun one = run("terrain " + terrain + " --erode valleys" + settings + " --out " + path("one.npy"));
    ASSERT_EQ(one.code, 0) << one.err;
    const CliRun two = run("erode --in " + path("t.npy") + " --preset valleys" + settings + erode + " --out " +
                           path("two.npy"));
    ASSERT_EQ(two.code, 0) << two.err;
    const Heightfield made = io::read_heightfield(path("t.npy")), a = io::read_heightfield(path("one.npy")),
                      b = io::read_heightfield(path("two.npy"));
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    EXPECT_TRUE(std::equal(a.data(), a.data() + a.size(), b.data())) << terrain;
    EXPECT_FALSE(std::equal(a.data(), a.data() + a.size(), made.data())) << terrain << ": the preset must erode";
  }
}

TEST_F(Cli, SceneHelpSaysWhatTheAutoCameraElevationPicks) {
  // The camera elevation's default is auto, and --help says what auto picks
  // for each kind of scene: the library's numbers (scene.hpp), not 22 for all.
  const std::string help = run("scene --help").out;
  EXPECT_NE(help.find("--camera-elevation-deg,--elevation FLOAT=auto"), std::string::npos) << help;
  const auto says = [&](double deg, const std::string& words) {
    const std::string text = std::to_string(int(deg)) + " " + words;
    EXPECT_NE(help.find(text), std::string::npos) << "scene --help must say \"" << text << "\"";
  };
  says(pov::kTerrainElevationDeg, "with a terrain");
  says(pov::kLinesElevationDeg, "for polylines alone");
  says(pov::kLightningElevationDeg, "when every line set is lightning");
  EXPECT_NE(help.find("range auto (0) or [1, 90] degrees"), std::string::npos);
  // --camera-margin and --camera-center-v come from their new rows.
  EXPECT_NE(help.find("--camera-margin FLOAT=0.04"), std::string::npos);
  EXPECT_NE(help.find("--camera-center-v FLOAT=0.55"), std::string::npos);
  // Auto (or "auto" spelled out) is the elevation given by hand, and the
  // flag still overrides it.
  std::ofstream(path("l.csv")) << "0,0,0,0\n1,0.2,0.1,0\n2,0.1,0.3,0\n";
  const auto scene = [&](const std::string& args, const std::string& dir) {
    fs::create_directories(dir_ / dir);
    const CliRun r = run("scene --polyline " + path("l.csv") + " --pov " + path(dir + "/s.pov") + " " + args);
    EXPECT_EQ(r.code, 0) << args << ": " << r.err;
    return io::read_file(path(dir + "/s.pov"));
  };
  const std::string by_default = scene("", "a");
  EXPECT_EQ(by_default, scene("--elevation 70", "b"));
  EXPECT_EQ(by_default, scene("--camera-elevation-deg auto", "b"));
  EXPECT_NE(by_default, scene("--elevation 40", "b"));
  EXPECT_NE(run("scene --polyline " + path("l.csv") + " --pov " + path("x.pov") + " --elevation 0.5").code, 0);
}

TEST_F(Cli, ProfileWritesCsvWithTwoToTheLevelsPlusOneRows) {
  ASSERT_EQ(run("profile --levels 8 --hurst 0.7 --out " + path("p.csv")).code, 0);
  const std::string csv = io::read_file(path("p.csv"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 257 + 1);  // + header comment
}

TEST_F(Cli, ReliefPreviewIsAnRgbPng) {
  ASSERT_EQ(run("terrain --levels 6 --out " + path("t.png")).code, 0);
  const CliRun r = run("relief --in " + path("t.png") + " --out " + path("r.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  const GrayImage img = io::read_png(path("r.png"));  // read back as luma
  EXPECT_EQ(img.width, 65);
}

TEST_F(Cli, TerrainLandformFlagsComeFromTheTable) {
  // The flags are the table's rows: an island with a sea covering 40% of it.
  const CliRun help = run("terrain --help");
  for (const char* flag : {"--levelling", "--height-offset", "--falloff", "--falloff-width", "--edge-level", "--sea ",
                           "--sea-level", "--sea-fraction"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
  const std::string out = path("island.npy");
  const CliRun r = run("terrain --levels 6 --seed 3 --levelling 1 --falloff radial --falloff-width 0.5 --edge-level -1 "
                       "--sea fraction --sea-fraction 0.4 --out " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const Heightfield hf = io::read_heightfield(out);
  // Outside the inscribed circle (21% of the samples) the falloff reaches the
  // edge level, -1; the sea covering 40% lies above it and floods the corners.
  const float sea = float(hf.stats().min);
  EXPECT_GT(sea, -1.0f);
  EXPECT_EQ(hf.at(0, 0), sea);
  EXPECT_EQ(size_t(std::count(hf.data(), hf.data() + hf.size(), sea)), size_t(0.4 * 65 * 65) + 1);
  const CliRun bad = run("terrain --levels 6 --falloff oval --out " + path("bad.npy"));
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("falloff"), std::string::npos) << bad.err;
}

TEST_F(Cli, TerrainFalloffMaskFromAnImage) {
  // A 2 x 2 mask as a 16-bit PNG: black at row 0, column 0, white elsewhere.
  Heightfield mask(2, 2);
  mask.data()[0] = 0, mask.data()[1] = 1, mask.data()[2] = 1, mask.data()[3] = 1;
  io::write_heightfield(mask, path("mask.png"));
  const std::string common = "terrain --levels 5 --seed 3 --edge-level -1 --out ";
  ASSERT_EQ(run(common + path("raw.npy")).code, 0);
  const CliRun r = run(common + path("masked.npy") + " --falloff-mask " + path("mask.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  const Heightfield raw = io::read_heightfield(path("raw.npy")), got = io::read_heightfield(path("masked.npy"));
  EXPECT_EQ(got.at(0, 0), -1.0f);            // weight 0: the edge level
  EXPECT_EQ(got.at(32, 32), raw.at(32, 32));  // weight 1: the height
  EXPECT_EQ(got.at(32, 0), raw.at(32, 0));
  EXPECT_NEAR(got.at(16, 16), -1 + 0.75 * (raw.at(16, 16) + 1), 1e-5);  // bilinear: 1 - 0.5 * 0.5
  // Values outside 0..1, another falloff, a missing file: one clear line each, no file.
  Heightfield two(2, 2);
  std::fill(two.data(), two.data() + 4, 2.0f);
  io::write_heightfield(two, path("two.npy"));
  const CliRun bad = run(common + path("bad.npy") + " --falloff-mask " + path("two.npy"));
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("must be in [0, 1]"), std::string::npos) << bad.err;
  const CliRun both = run(common + path("bad.npy") + " --falloff radial --falloff-mask " + path("mask.png"));
  EXPECT_NE(both.code, 0);
  EXPECT_NE(both.err.find("cannot go with --falloff radial"), std::string::npos) << both.err;
  EXPECT_NE(run(common + path("bad.npy") + " --falloff-mask " + path("none.png")).code, 0);
  const CliRun none = run(common + path("bad.npy") + " --falloff custom");
  EXPECT_NE(none.code, 0);
  EXPECT_NE(none.err.find("needs a mask"), std::string::npos) << none.err;
  EXPECT_FALSE(fs::exists(path("bad.npy")));
}

}  // namespace
}  // namespace ft
