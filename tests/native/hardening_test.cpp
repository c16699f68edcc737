// SPDX-License-Identifier: GPL-3.0-or-later
// Hardening: nothing is lost when a write is killed or refused midway, sizes
// above the memory cap are refused before allocating (with the size in the
// message), and readers refuse hostile headers cleanly. Writes are exercised
// through the real CLI in a child process, the way a crash would hit them.
#include <fcntl.h>
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "io/npy.hpp"
#include "io/pgm.hpp"
#include "io/png_image.hpp"
#include "povray/render.hpp"
#include "povray/scene.hpp"
#include "sanitizer.hpp"

namespace ft {
namespace {

namespace fs = std::filesystem;

struct Child {
  int status = 0;
  std::string err;  // its stderr
  bool killed_by(int sig) const { return WIFSIGNALED(status) && WTERMSIG(status) == sig; }
  int exit_code() const { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }
};

// Runs the CLI with `args` in a child whose files may not grow beyond
// `fsize_limit` bytes (0: no limit). With `ignore_sigxfsz`, writing past the
// limit fails with EFBIG (a full disk, as the program sees it); otherwise the
// kernel kills the child with SIGXFSZ in the middle of the write.
Child run_cli(const std::vector<std::string>& args, rlim_t fsize_limit = 0, bool ignore_sigxfsz = false,
              rlim_t as_limit = 0) {
  const fs::path err_path = fs::temp_directory_path() / ("ft_hardening_err_" + std::to_string(::getpid()));
  // Everything the child needs is made before fork: it only execs.
  std::vector<char*> argv{const_cast<char*>(FT_CLI_PATH)};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 2);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    if (fsize_limit) {
      const rlimit r{fsize_limit, fsize_limit};
      ::setrlimit(RLIMIT_FSIZE, &r);
    }
    if (as_limit) {
      const rlimit r{as_limit, as_limit};
      ::setrlimit(RLIMIT_AS, &r);
    }
    const rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);
    ::signal(SIGXFSZ, ignore_sigxfsz ? SIG_IGN : SIG_DFL);
    ::execv(FT_CLI_PATH, argv.data());
    ::_exit(127);
  }
  Child c;
  ::waitpid(pid, &c.status, 0);
  c.err = io::read_file(err_path.string());
  fs::remove(err_path);
  return c;
}

class Folder : public ::testing::Test {
 public:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ft_hardening_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // Every file in the folder other than `keep` and its sidecar (a .npy's world size in
  // "<file>.json"): temporaries left behind.
  std::vector<std::string> others(const std::string& keep) const {
    std::vector<std::string> v;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename() != keep && (keep.empty() || e.path().filename() != keep + ".json"))
        v.push_back(e.path().filename().string());
    return v;
  }
  fs::path dir_;
};

// A 257 x 257 terrain is 258 KiB as .npy, 129 KiB as .pgm and more than
// 64 KiB as .png (noise does not compress): a 64 KiB file-size limit stops
// each of them midway.
constexpr rlim_t kLimit = 64 << 10;

class KilledWrite : public Folder, public ::testing::WithParamInterface<const char*> {};

TEST_P(KilledWrite, LeavesThePreviousFileIntactAndTheNextWriteCleansUp) {
  const std::string name = std::string("t") + GetParam(), out = path(name);
  ASSERT_EQ(run_cli({"terrain", "--levels", "3", "--out", out}).exit_code(), 0);
  const std::string before = io::read_file(out);

  const Child killed = run_cli({"terrain", "--levels", "8", "--seed", "2", "--out", out}, kLimit);
  ASSERT_TRUE(killed.killed_by(SIGXFSZ)) << "status " << killed.status << ": " << killed.err;
  EXPECT_EQ(io::read_file(out), before) << "the destination changed";
  // A killed process cannot remove its temporary file...
  const auto left = others(name);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].rfind("." + name + ".tmp.", 0), 0u) << left[0];

  // ...the next write of the same file removes it, as its writer is gone.
  ASSERT_EQ(run_cli({"terrain", "--levels", "4", "--out", out}).exit_code(), 0);
  EXPECT_NE(io::read_file(out), before);
  EXPECT_TRUE(others(name).empty());
  EXPECT_EQ(io::read_heightfield(out).width(), 17);
}

TEST_P(KilledWrite, RefusedByTheDiskIsAnIoErrorAndLeavesNothingBehind) {
  const std::string name = std::string("t") + GetParam(), out = path(name);
  ASSERT_EQ(run_cli({"terrain", "--levels", "3", "--out", out}).exit_code(), 0);
  const std::string before = io::read_file(out);

  const Child refused = run_cli({"terrain", "--levels", "8", "--out", out}, kLimit, /*ignore_sigxfsz=*/true);
  EXPECT_EQ(refused.exit_code(), 1) << refused.err;
  EXPECT_NE(refused.err.find("fracterra: error: "), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find(out), std::string::npos) << "the message names the file: " << refused.err;
  EXPECT_EQ(io::read_file(out), before);
  EXPECT_TRUE(others(name).empty()) << "temporary file left behind";
}

INSTANTIATE_TEST_SUITE_P(Formats, KilledWrite, ::testing::Values(".npy", ".pgm", ".png"),
                         [](const auto& info) { return std::string(info.param + 1); });

TEST_F(Folder, RefusedPolylineWriteLeavesThePreviousFileIntact) {
  const std::string out = path("p.csv");
  ASSERT_EQ(run_cli({"profile", "--levels", "3", "--out", out}).exit_code(), 0);
  const std::string before = io::read_file(out);
  // 2^12 + 1 vertices of ~80 characters: ~330 KiB.
  const Child refused = run_cli({"profile", "--levels", "12", "--out", out}, kLimit, true);
  EXPECT_EQ(refused.exit_code(), 1) << refused.err;
  EXPECT_EQ(io::read_file(out), before);
  EXPECT_TRUE(others("p.csv").empty());
}

TEST_F(Folder, StaleTemporaryOfALiveWriterIsLeftAlone) {
  // Our own pid is alive: a temp named after it must survive another write.
  const std::string out = path("f.txt");
  const std::string live = path(".f.txt.tmp." + std::to_string(::getppid()) + ".abcdef");
  io::write_file_atomically(live, "in progress");
  io::write_file_atomically(out, "x");
  EXPECT_TRUE(fs::exists(live));
}


TEST_F(Folder, CliOutOfMemoryIsAnErrorNotACrash) {
#ifdef FT_UNDER_ASAN
  GTEST_SKIP() << "ASan reserves terabytes of address space: no address-space limit possible";
#endif
  // 1 GiB of samples for levels 14 passes the cap (8 GiB) but not a 512 MiB
  // address-space limit: the allocation itself fails.
  const Child c = run_cli({"terrain", "--levels", "14", "--threads", "1", "--stats"}, 0, false, rlim_t(512) << 20);
  EXPECT_EQ(c.exit_code(), 1) << c.err;
  EXPECT_NE(c.err.find("out of memory"), std::string::npos) << c.err;
}

TEST_F(Folder, CliRefusesProfileAboveTheCapWithTheSize) {
  // 2^28 + 1 samples as CSV: 4 + 32 bytes each in memory, 9 GiB > 8 GiB cap.
  const Child c = run_cli({"profile", "--levels", "28", "--out", path("p.csv")});
  EXPECT_EQ(c.exit_code(), 1) << c.err;
  EXPECT_NE(c.err.find("needs 9.00 GiB"), std::string::npos) << c.err;
  EXPECT_TRUE(others("").empty());
}

std::string corpus(const std::string& harness, const std::string& name) {
  // The fuzz seeds beside tests/data: tests/fuzz/corpus/<harness>/<name>.
  return io::read_file((fs::path(FT_TEST_DATA_DIR).parent_path() / "fuzz/corpus" / harness / name).string());
}

ft_status status_of(const std::function<void()>& f, std::string* message = nullptr) {
  try {
    f();
  } catch (const Error& e) {
    if (message) *message = e.what();
    return e.status();
  }
  return FT_OK;
}

TEST(Readers, HugeImageHeadersAreRefusedBeforeAllocatingWithTheSize) {
  std::string msg;
  // PNG header claiming 2^20 x 2^20 16-bit pixels.
  EXPECT_EQ(status_of([] { io::decode_png(corpus("png", "huge_header.png")); }, &msg), FT_ERR_TOO_LARGE);
  // Raw rows of 2^21 bytes x 2^20 rows, x3 for libpng's transforms.
  EXPECT_NE(msg.find("needs 6144.00 GiB"), std::string::npos) << msg;
  // PGM header claiming 2^20 x 2^20 pixels.
  EXPECT_EQ(status_of([] { io::decode_pgm(corpus("pgm", "p5_huge.pgm")); }, &msg), FT_ERR_TOO_LARGE);
  EXPECT_NE(msg.find("needs 2048.00 GiB"), std::string::npos) << msg;
}

TEST(Readers, ShortNpyDataIsAFormatErrorNotAnAllocation) {
  std::string msg;
  EXPECT_EQ(status_of([] { io::decode_npy(corpus("npy", "short_data.npy")); }, &msg), FT_ERR_FORMAT);
  EXPECT_NE(msg.find("shorter than its shape"), std::string::npos) << msg;
}

TEST(Readers, FileLargerThanTheCapIsRefusedBeforeReading) {
  const std::string p = (fs::temp_directory_path() / ("ft_hardening_big_" + std::to_string(::getpid()))).string();
  io::write_file_atomically(p, std::string(3 << 20, 'x'));
  set_memory_cap(1 << 20);
  std::string msg;
  EXPECT_EQ(status_of([&] { io::read_file(p); }, &msg), FT_ERR_TOO_LARGE);
  set_memory_cap(0);
  EXPECT_NE(msg.find("needs 3.00 MiB"), std::string::npos) << msg;
  fs::remove(p);
}

// POV-Ray text: names and paths written into scenes cannot inject SDL. The
// oracle is the real povray: an injected `#fopen ... write` directive would
// create a file in the scene's folder (the positive control shows it does).
class PovInjection : public Folder {
 public:
  static constexpr const char* kDirective = "#fopen FtPwn \"pwned.txt\" write #fclose FtPwn";
  Heightfield terrain() const {
    Heightfield hf(17, 17);
    for (int y = 0; y < 17; ++y)
      for (int x = 0; x < 17; ++x) hf.at(x, y) = float((x * 7 + y * 3) % 5) * 0.1f;
    return hf;
  }
  pov::RenderOptions tiny() const {
    pov::RenderOptions o;
    o.width = 32;
    o.height = 24;
    o.antialias = 0;
    return o;
  }
  bool pwned() const { return fs::exists(dir_ / "pwned.txt"); }
};

TEST_F(PovInjection, PositiveControlARawDirectiveDoesWriteTheFile) {
  io::write_file_atomically(path("raw.pov"), std::string("#version 3.7;\n") + kDirective +
                                             "\ncamera { location <0, 1, -3> look_at 0 }\n"
                                             "light_source { <2, 4, -3> rgb 1 }\nsphere { 0, 1 pigment { rgb 1 } }\n");
  pov::render_scene(path("raw.pov"), path("raw.png"), tiny());
  EXPECT_TRUE(pwned()) << "povray did not run the directive: this oracle cannot see injections";
}

// Renders a terrain scene whose PNG path and title carry `payload`; returns
// POV-Ray's messages (or the render error).
std::string render_with(const PovInjection& t, const std::string& image_name, const std::string& title,
                        const std::string& pov_name) {
  const Heightfield hf = t.terrain();
  pov::SceneParams p;
  pov::set_scene_terrain(p, hf);
  p.image_path = t.path(image_name);
  p.title = title;
  pov::write_scene(p, t.path(pov_name));
  EXPECT_TRUE(fs::exists(p.image_path));
  try {
    return pov::render_scene(t.path(pov_name), t.path("out.png"), t.tiny()).messages;
  } catch (const Error& e) {
    return e.what();
  }
}

TEST_F(PovInjection, QuotesAndDirectivesInNamesStayTextAndRender) {
  // A file name may hold quotes, '#' and spaces: the scene refers to it as
  // one string literal that POV-Ray reads back exactly, and a title (with
  // line breaks) is only ever a comment.
  const std::string messages =
      render_with(*this, std::string("evil\" ") + kDirective + " #declare FtQ = \"x.png",
                  std::string("title\n") + kDirective + "\n#end\r*/", "scene #1.pov");
  EXPECT_FALSE(pwned()) << "SDL was injected; povray said:\n" << messages;
  EXPECT_TRUE(fs::exists(path("out.png"))) << messages;
}

TEST_F(PovInjection, ControlCharactersAndBackslashesInAPathAreRefusedAndNothingIsWritten) {
  // POV-Ray 3.7 keeps a file name's backslashes as written (no escape
  // processing), so a path with one cannot be referred to: refused, like a
  // line break, before anything is written.
  const Heightfield hf = terrain();
  for (const std::string& name : {std::string("line\n") + kDirective + "\nx.png",
                                 std::string("evil\\\" ") + kDirective + " #declare FtQ = \"x.png"}) {
    pov::SceneParams p;
    pov::set_scene_terrain(p, hf);
    p.image_path = path(name);
    try {
      pov::write_scene(p, path("s.pov"));
      ADD_FAILURE() << "accepted " << name;
    } catch (const Error& e) {
      EXPECT_EQ(e.status(), FT_ERR_INVALID_ARGUMENT);
    }
    EXPECT_FALSE(pwned());
    EXPECT_TRUE(others("").empty()) << "a refused scene left files behind";
  }
}

}  // namespace
}  // namespace ft
