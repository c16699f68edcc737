// The subdiv layer: fractalization on OpenSubdiv, mesh validation, OBJ and
// POV-Ray mesh2 output. The reference refinement here calls OpenSubdiv
// directly (the same Debian library), independent of fractalize.cpp.
#include <gtest/gtest.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/obj_io.hpp"
#include "povray/mesh2_export.hpp"
#include "subdiv/fractalize.hpp"
#include "subdiv/mesh_validation.hpp"

namespace ft {
namespace {

using namespace OpenSubdiv;
namespace fs = std::filesystem;

// The shipped example meshes (compilers get absolute source paths from CMake).
const std::string kMeshes = (fs::path(__FILE__).parent_path() / "../../examples/meshes/").lexically_normal().string();

Mesh cube() { return io::read_obj(kMeshes + "cube.obj"); }
Mesh icosahedron() { return io::read_obj(kMeshes + "icosahedron.obj"); }
Mesh mountain() { return io::read_obj(kMeshes + "mountain.obj"); }

ft_fractalize_params params(int levels, double sigma, int scheme = FT_SCHEME_CATMARK) {
  ft_fractalize_params p = subdiv::default_fractalize_params();
  p.levels = levels;
  p.sigma = sigma;
  p.scheme = scheme;
  p.seed = 11;
  return p;
}

// Plain OpenSubdiv: a refiner to `levels` with the options fracterra documents
// (boundary EDGE_AND_CORNER), positions interpolated level by level.
struct Reference {
  std::unique_ptr<Far::TopologyRefiner> refiner;
  struct V {
    float p[3];
    void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
    void AddWithWeight(const V& s, float w) {
      for (int i = 0; i < 3; ++i) p[i] += w * s.p[i];
    }
  };

  Reference(const Mesh& m, int scheme, int levels) {
    Sdc::Options o;
    o.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    Far::TopologyDescriptor d;
    d.numVertices = int(m.vertex_count());
    d.numFaces = int(m.face_count());
    d.numVertsPerFace = m.face_sizes.data();
    d.vertIndicesPerFace = m.face_indices.data();
    d.numCreases = int(m.crease_sharpness.size());
    d.creaseVertexIndexPairs = m.crease_pairs.data();
    d.creaseWeights = m.crease_sharpness.data();
    const Sdc::SchemeType type = scheme == FT_SCHEME_LOOP       ? Sdc::SCHEME_LOOP
                                 : scheme == FT_SCHEME_BILINEAR ? Sdc::SCHEME_BILINEAR
                                                                : Sdc::SCHEME_CATMARK;
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    refiner.reset(Factory::Create(d, Factory::Options(type, o)));
    refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
  }

  // Positions at `level` interpolated from `from` positions at level - 1.
  std::vector<float> refine_once(int level, const std::vector<float>& from) const {
    std::vector<V> src(from.size() / 3), dst(size_t(refiner->GetLevel(level).GetNumVertices()));
    std::memcpy(src.data(), from.data(), from.size() * sizeof(float));
    Far::PrimvarRefiner(*refiner).Interpolate(level, src, dst);
    std::vector<float> out(dst.size() * 3);
    std::memcpy(out.data(), dst.data(), out.size() * sizeof(float));
    return out;
  }

  std::vector<float> positions(const Mesh& base, int level) const {
    std::vector<float> x = base.positions;
    for (int k = 1; k <= level; ++k) x = refine_once(k, x);
    return x;
  }
};

void expect_error(const std::function<void()>& f, ft_status status, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), status) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------

TEST(Fractalize, ZeroSigmaEqualsPlainOpenSubdivRefinement) {
  struct Case {
    Mesh mesh;
    int scheme;
  };
  const std::vector<Case> cases = {{cube(), FT_SCHEME_CATMARK},
                                   {icosahedron(), FT_SCHEME_LOOP},
                                   {cube(), FT_SCHEME_BILINEAR},
                                   {mountain(), FT_SCHEME_CATMARK},  // open, with a crease
                                   {icosahedron(), FT_SCHEME_CATMARK}};
  for (const Case& c : cases) {
    const Reference ref(c.mesh, c.scheme, 4);
    for (int level = 1; level <= 4; ++level) {
      const Mesh out = subdiv::fractalize(c.mesh, params(level, 0.0, c.scheme));
      const Far::TopologyLevel& tl = ref.refiner->GetLevel(level);
      ASSERT_EQ(out.vertex_count(), size_t(tl.GetNumVertices())) << "scheme " << c.scheme << " level " << level;
      ASSERT_EQ(out.face_count(), size_t(tl.GetNumFaces()));
      for (int f = 0; f < tl.GetNumFaces(); ++f) {
        const auto fv = tl.GetFaceVertices(f);
        ASSERT_EQ(out.face_sizes[size_t(f)], fv.size());
        for (int i = 0; i < fv.size(); ++i)
          ASSERT_EQ(out.face_indices[size_t(f) * fv.size() + size_t(i)], fv[i]);
      }
      // Same operations in the same order: equal up to float rounding.
      const std::vector<float> x = ref.positions(c.mesh, level);
      for (size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(out.positions[i], x[i], 1e-6f) << "coordinate " << i;
    }
  }
}

// The displacement added at level k is measured from the outside: the output
// of a run with k - 1 levels is the level k - 1 stage of a run with k levels
// (the random numbers are keyed by (level, vertex)), so
//   D_k = fractalize(k levels) - OpenSubdiv-refine(fractalize(k - 1 levels)).
// Its RMS over the vertices new at level k should be sigma 2^(-kH).
//
// Tolerance: D_k = sigma 2^(-kH) g n with unit normals n and g ~ N(0,1)
// independent, so RMS_k^2 / (sigma 2^(-kH))^2 is a mean of n_k squared
// normals; its relative standard error is sqrt(2 / n_k), that of RMS_k is
// 1 / sqrt(2 n_k), that of log2 RMS_k is 1 / (sqrt(2 n_k) ln 2). For the
// icosahedron under Loop, n_k = 30 * 4^(k-1) new (edge) vertices: 480, 1920,
// 7680, 30720, 122880 for k = 3..7, giving standard errors 0.047, 0.023,
// 0.012, 0.006, 0.003. The ordinary least-squares slope over k = 3..7
// (centred x = -2..2, Sxx = 10) has standard error
// sqrt(sum x^2 se^2) / Sxx = 0.0096; we allow 0.05 (> 5 standard errors).
// The level-3 RMS alone is checked against sigma 2^(-3H) within 5 * 0.047.
TEST(Fractalize, DisplacementRmsFallsAsTwoToTheMinusKH) {
  const Mesh ico = icosahedron();
  const Reference ref(ico, FT_SCHEME_LOOP, 7);
  for (double H : {0.3, 0.9}) {
    ft_fractalize_params p = params(2, 0.5, FT_SCHEME_LOOP);
    p.hurst = H;
    std::vector<float> prev = subdiv::fractalize(ico, p).positions;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int k = 3; k <= 7; ++k) {
      p.levels = k;
      const Mesh cur = subdiv::fractalize(ico, p);
      const std::vector<float> plain = ref.refine_once(k, prev);
      const size_t old_count = prev.size() / 3;
      ASSERT_EQ(cur.positions.size(), plain.size());
      double sum2 = 0;
      size_t n = 0;
      for (size_t v = 0; v < cur.vertex_count(); ++v) {
        double d2 = 0;
        for (int c = 0; c < 3; ++c) d2 += std::pow(double(cur.positions[3 * v + c]) - plain[3 * v + c], 2);
        if (v < old_count) {
          ASSERT_EQ(d2, 0.0) << "Voss moved vertex " << v << ", a child of an old vertex, at level " << k;
        } else {
          sum2 += d2, ++n;
        }
      }
      ASSERT_EQ(n, 30u << (2 * (k - 1)));
      const double rms = std::sqrt(sum2 / double(n));
      if (k == 3) {
        EXPECT_NEAR(std::log2(rms / (0.5 * std::pow(2.0, -3 * H))), 0.0, 5 * 0.047);
      }
      const double x = k, y = std::log2(rms);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
      prev = cur.positions;
    }
    const double slope = (5 * sxy - sx * sy) / (5 * sxx - sx * sx);
    EXPECT_NEAR(slope, -H, 0.05) << "H = " << H;
  }
}

TEST(Fractalize, AdditionsMoveOldVerticesToo) {
  const Mesh c = cube();
  const Reference ref(c, FT_SCHEME_CATMARK, 2);
  ft_fractalize_params p = params(1, 0.3);
  p.mode = FT_FRACTALIZE_ADDITIONS;
  const Mesh one = subdiv::fractalize(c, p);
  p.levels = 2;
  const Mesh two = subdiv::fractalize(c, p);
  const std::vector<float> plain = ref.refine_once(2, one.positions);
  int moved_old = 0;
  for (size_t v = 0; v < one.vertex_count(); ++v)
    moved_old += two.vertex(v) != std::array<float, 3>{plain[3 * v], plain[3 * v + 1], plain[3 * v + 2]};
  EXPECT_EQ(moved_old, int(one.vertex_count()));
}

// Every edge of the output is shared by exactly two faces, walked once in
// each direction: no cracks, orientation kept.
void expect_closed(const Mesh& m) {
  std::map<std::pair<int, int>, int> directed;
  size_t first = 0;
  for (int32_t n : m.face_sizes) {
    for (int32_t i = 0; i < n; ++i)
      ++directed[{m.face_indices[first + i], m.face_indices[first + (i + 1) % n]}];
    first += size_t(n);
  }
  for (const auto& [e, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << e.first << "-" << e.second;
    ASSERT_EQ(directed.count({e.second, e.first}), 1u) << "edge " << e.first << "-" << e.second << " is open";
  }
  for (float x : m.positions) ASSERT_TRUE(std::isfinite(x));
}

TEST(Fractalize, ClosedInputStaysClosed) {
  for (int mode : {FT_FRACTALIZE_MIDPOINT, FT_FRACTALIZE_ADDITIONS}) {
    ft_fractalize_params p = params(4, 0.3);
    p.mode = mode;
    const Mesh rock = subdiv::fractalize(cube(), p);
    EXPECT_EQ(rock.face_count(), 6u * 256u);
    for (int32_t n : rock.face_sizes) ASSERT_EQ(n, 4);
    expect_closed(rock);
    p.scheme = FT_SCHEME_LOOP;
    const Mesh planet = subdiv::fractalize(icosahedron(), p);
    EXPECT_EQ(planet.face_count(), 20u * 256u);
    for (int32_t n : planet.face_sizes) ASSERT_EQ(n, 3);
    expect_closed(planet);
  }
}

TEST(Fractalize, SameSeedSameBitsOnAnyThreadCount) {
  ft_fractalize_params p = params(5, 0.2, FT_SCHEME_LOOP);
  p.threads = 1;
  const Mesh a = subdiv::fractalize(icosahedron(), p);
  for (int threads : {2, 3, 0}) {
    p.threads = threads;
    const Mesh b = subdiv::fractalize(icosahedron(), p);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(float)), 0)
        << threads << " threads";
    EXPECT_EQ(a.face_indices, b.face_indices);
  }
  p.seed = 12;
  EXPECT_NE(subdiv::fractalize(icosahedron(), p).positions, a.positions);
}

TEST(Fractalize, FixedBoundaryStaysOnThePlainBoundaryCurve) {
  const Mesh m = mountain();
  const Mesh plain = subdiv::fractalize(m, params(3, 0.0));
  ft_fractalize_params p = params(3, 0.5);
  p.fix_boundary = 1;
  const Mesh fixed = subdiv::fractalize(m, p);
  // Boundary of the 6 x 6 quad grid refined 3 times: a 49 x 49 vertex grid
  // whose border is at |x| = 6 or |y| = 6 in the plain result.
  int boundary = 0, moved_inside = 0;
  for (size_t v = 0; v < plain.vertex_count(); ++v) {
    const auto q = plain.vertex(v);
    if (std::fabs(std::fabs(q[0]) - 6) < 1e-5 || std::fabs(std::fabs(q[1]) - 6) < 1e-5) {
      ++boundary;
      EXPECT_EQ(fixed.vertex(v), q) << "boundary vertex " << v;
    } else {
      moved_inside += fixed.vertex(v) != q;
    }
  }
  EXPECT_EQ(boundary, 4 * 48);
  EXPECT_GT(moved_inside, 1000);
  p.fix_boundary = 0;
  const Mesh free = subdiv::fractalize(m, p);
  int moved_boundary = 0;
  for (size_t v = 0; v < plain.vertex_count(); ++v) {
    const auto q = plain.vertex(v);
    if (std::fabs(std::fabs(q[0]) - 6) < 1e-5 || std::fabs(std::fabs(q[1]) - 6) < 1e-5)
      moved_boundary += free.vertex(v) != q;
  }
  EXPECT_GT(moved_boundary, 100);
}

TEST(Fractalize, WeightsScaleTheDisplacement) {
  const Mesh c = cube();
  const Mesh plain = subdiv::fractalize(c, params(3, 0.0));
  std::vector<float> w(c.vertex_count(), 0.0f);
  ft_fractalize_params p = params(3, 0.4);
  p.weights = w.data();
  const Mesh masked = subdiv::fractalize(c, p);
  for (size_t i = 0; i < plain.positions.size(); ++i) ASSERT_NEAR(masked.positions[i], plain.positions[i], 1e-6f);
  // Weight 1 everywhere is the unweighted result (the interpolated weight
  // is 1 up to float rounding of the subdivision masks).
  std::fill(w.begin(), w.end(), 1.0f);
  const Mesh ones = subdiv::fractalize(c, p);
  p.weights = nullptr;
  const Mesh unweighted = subdiv::fractalize(c, p);
  for (size_t i = 0; i < ones.positions.size(); ++i) ASSERT_NEAR(ones.positions[i], unweighted.positions[i], 1e-5f);
  // A mask on the (1, 1, 1) corner only: the weight primvar is zero on the
  // faces away from it, and what moves there is only the smoothing of
  // displaced neighbours, so the far octant moves far less than the near one.
  std::fill(w.begin(), w.end(), 0.0f);
  w[6] = 1.0f;
  p.weights = w.data();
  const Mesh corner = subdiv::fractalize(c, p);
  double near_d = 0, far_d = 0;
  for (size_t v = 0; v < plain.vertex_count(); ++v) {
    const auto q = plain.vertex(v), r = corner.vertex(v);
    const double d = std::fabs(q[0] - r[0]) + std::fabs(q[1] - r[1]) + std::fabs(q[2] - r[2]);
    if (q[0] + q[1] + q[2] > 1.0) near_d += d;
    if (q[0] + q[1] + q[2] < -1.0) far_d += d;
  }
  EXPECT_GT(near_d, 20 * far_d);
}

TEST(Fractalize, EdgeLengthScalingMakesTheResultScaleFree) {
  Mesh small = cube(), big = cube();
  for (float& x : big.positions) x *= 8.0f;  // a power of two: exact
  ft_fractalize_params p = params(3, 0.2);
  p.scale_by_edge_length = 1;
  const Mesh a = subdiv::fractalize(small, p), b = subdiv::fractalize(big, p);
  for (size_t i = 0; i < a.positions.size(); ++i) ASSERT_NEAR(8.0f * a.positions[i], b.positions[i], 1e-4f);
}

TEST(Fractalize, RejectsBadMeshesNamingTheFace) {
  auto run = [](const Mesh& m, int scheme = FT_SCHEME_CATMARK) {
    return [m, scheme] { subdiv::fractalize(m, params(2, 0.1, scheme)); };
  };
  Mesh m = cube();
  m.face_indices[5] = 8;
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 1 refers to vertex 8");
  m = cube();
  m.face_indices[5] = 4;  // face 1 = 5 5 7 8 -> vertex 4 twice
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 1 uses vertex 4 twice");
  m = cube();
  m.face_sizes = {4, 4, 4, 4, 4, 2, 2};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 5 has 2 vertices");
  m = cube();
  std::swap(m.face_indices[1], m.face_indices[3]);  // face 0 flipped
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "oriented consistently");
  m = cube();
  m.positions[3 * 7] = NAN;
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "vertex 7 has a non-finite coordinate");
  m = cube();
  for (int i : {0, 1, 2, 3}) m.positions[3 * size_t(i) + 2] = 0, m.positions[3 * size_t(i) + 1] = 0;
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 0 has zero area");
  expect_error(run(cube(), FT_SCHEME_LOOP), FT_ERR_INVALID_ARGUMENT, "face 0 has 4 vertices; Loop");
  m = cube();
  m.crease_pairs = {0, 6};
  m.crease_sharpness = {2.0f};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "not the ends of an edge");
  m.crease_pairs = {0, 1};
  m.crease_sharpness = {11.0f};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "sharpness 11");
  m = Mesh{};
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "no faces");
  // three faces on one edge: a fin added to the cube's edge 0-1
  m = cube();
  m.positions.insert(m.positions.end(), {0, -3, -3});
  m.face_sizes.push_back(3);
  m.face_indices.insert(m.face_indices.end(), {0, 1, 8});
  expect_error(run(m), FT_ERR_INVALID_ARGUMENT, "face 6 is the offending face");
}

TEST(Fractalize, RejectsBadParameters) {
  const Mesh c = cube();
  auto with = [&c](auto change) {
    return [&c, change] {
      ft_fractalize_params p = params(2, 0.1);
      change(p);
      subdiv::fractalize(c, p);
    };
  };
  expect_error(with([](auto& p) { p.levels = 0; }), FT_ERR_INVALID_ARGUMENT, "levels must be in 1..10");
  expect_error(with([](auto& p) { p.levels = 11; }), FT_ERR_INVALID_ARGUMENT, "levels must be in 1..10");
  expect_error(with([](auto& p) { p.hurst = 1.5; }), FT_ERR_INVALID_ARGUMENT, "hurst must be in [0, 1]");
  expect_error(with([](auto& p) { p.sigma = -1; }), FT_ERR_INVALID_ARGUMENT, "sigma must be");
  expect_error(with([](auto& p) { p.sigma = NAN; }), FT_ERR_INVALID_ARGUMENT, "got NaN");
  expect_error(with([](auto& p) { p.scheme = 7; }), FT_ERR_INVALID_ARGUMENT, "scheme");
  expect_error(with([](auto& p) { p.mode = -1; }), FT_ERR_INVALID_ARGUMENT, "mode");
  expect_error(with([](auto& p) { p.threads = -1; }), FT_ERR_INVALID_ARGUMENT, "threads");
  expect_error(with([](auto& p) { p.struct_size = 8; }), FT_ERR_INVALID_ARGUMENT, "struct_size");
}

TEST(Fractalize, RefusesResultsAboveTheMemoryCapBeforeAllocating) {
  set_memory_cap(64 << 20);
  expect_error([] { subdiv::fractalize(cube(), params(10, 0.1)); }, FT_ERR_TOO_LARGE, "fractalizing to 10 levels");
  set_memory_cap(0);
}

TEST(Fractalize, HonoursCreases) {
  // An infinitely sharp crease loop around the cube's top face cuts it off
  // from the smoothing: the crease vertices follow the crease rule within
  // z = 1 and the face inside stays flat, so the whole refined top face,
  // (2^3 + 1)^2 vertices after 3 levels, stays at z = 1. Without the crease
  // Catmull-Clark pulls every vertex below z = 1.
  Mesh c = cube();
  auto top = [](const Mesh& m) {
    int n = 0;
    for (size_t v = 0; v < m.vertex_count(); ++v) n += m.vertex(v)[2] == 1.0f;
    return n;
  };
  EXPECT_EQ(top(subdiv::fractalize(c, params(3, 0.0))), 0);
  c.crease_pairs = {4, 5, 5, 6, 6, 7, 7, 4};
  c.crease_sharpness = {10, 10, 10, 10};
  EXPECT_EQ(top(subdiv::fractalize(c, params(3, 0.0))), 81);
}

// ---------------------------------------------------------------------------

TEST(ObjIo, RoundTripIsExact) {
  ft_fractalize_params p = params(2, 0.3);
  Mesh m = subdiv::fractalize(cube(), p);
  m.crease_pairs = {m.face_indices[0], m.face_indices[1]};
  m.crease_sharpness = {2.5f};
  m.corner_vertices = {3};
  m.corner_sharpness = {10.0f};
  const fs::path dir = fs::temp_directory_path() / ("ft_subdiv_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "rock.obj").string();
  io::write_obj(m, path, "a comment\nwith a newline");
  const Mesh back = io::read_obj(path);
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.face_sizes, m.face_sizes);
  EXPECT_EQ(back.face_indices, m.face_indices);
  EXPECT_EQ(back.crease_pairs, m.crease_pairs);
  EXPECT_EQ(back.crease_sharpness, m.crease_sharpness);
  EXPECT_EQ(back.corner_vertices, m.corner_vertices);
  EXPECT_EQ(back.corner_sharpness, m.corner_sharpness);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename(), "rock.obj") << "a temporary file was left behind";
  fs::remove_all(dir);
}

TEST(ObjIo, ReadsPolygonsFromAllShapes) {
  const Mesh m = io::decode_obj("o a\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\no b\nf 2 5 3\n");
  EXPECT_EQ(m.vertex_count(), 5u);
  EXPECT_EQ(m.face_sizes, (std::vector<int32_t>{4, 3}));
  EXPECT_EQ(m.face_indices, (std::vector<int32_t>{0, 1, 2, 3, 1, 4, 2}));
}

TEST(ObjIo, ReportsMissingAndFacelessFiles) {
  expect_error([] { io::read_obj("/nonexistent/mesh.obj"); }, FT_ERR_IO, "/nonexistent/mesh.obj");
  expect_error([] { io::decode_obj("v 0 0 0\nv 1 0 0\n", "points.obj"); }, FT_ERR_FORMAT, "points.obj' has no faces");
}

// Lines tinyobjloader used to take on trust (see obj_io.cpp): each now a
// clear FT_ERR_FORMAT naming the line, where it was undefined behaviour, an
// infinite vertex or a silently wrong face.
TEST(ObjIo, RefusesNumbersAndFacesTheReaderCannotHold) {
  const std::string quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  expect_error([&] { io::decode_obj("v 0 0 1e39\n" + quad + "f 2 3 4\n", "big.obj"); }, FT_ERR_FORMAT,
               "'big.obj': line 1: '1e39' is beyond the float range");
  expect_error([&] { io::decode_obj(quad + "f 1 2 99999999999\n", "idx.obj"); }, FT_ERR_FORMAT,
               "line 5: '99999999999' is not an integer in the 32-bit range");
  expect_error([&] { io::decode_obj(quad + "f 1 0 2\n", "zero.obj"); }, FT_ERR_FORMAT, "line 5: vertex index 0");
  expect_error([&] { io::decode_obj("v 0 nan 0\n" + quad + "f 2 3 4\n"); }, FT_ERR_FORMAT, "'nan' is not a finite number");
  expect_error([&] { io::decode_obj(quad + "f 1 2 3\nt crease 2/1/0 0 1\n"); }, FT_ERR_FORMAT, "line 6: the tag's counts");
  std::string ring;
  for (int i = 0; i < 300; ++i) ring += "v " + std::to_string(std::cos(i * 0.0209)) + " " + std::to_string(std::sin(i * 0.0209)) + " 0\n";
  ring += "f";
  for (int i = 1; i <= 300; ++i) ring += " " + std::to_string(i);
  expect_error([&] { io::decode_obj(ring + "\n"); }, FT_ERR_FORMAT, "a face of 300 vertices; at most 255");
}

TEST(ObjIo, IgnoresWhatItDoesNotUseAndKeepsWhatItDoes) {
  // Normals, texture coordinates, weights (the fuzzer's `vw` of 1e300),
  // groups, materials; v/vt/vn faces; comments; CRLF; a '+' sign; w.
  const Mesh m = io::decode_obj(
      "# a comment\r\nmtllib x.mtl\r\no a\r\nv 0 0 0 1\r\nv +1 0 0\r\nv 1 1 0 # corner\r\nvn 0 0 1\r\n"
      "vt 0.5 0.5\r\nvw 1 0333333333333333333333333333333333333333333333 00\r\nusemtl m\r\ns 1\r\n"
      "f 1/1/1 2/1/1 -1/1/1\r\nl 1 2\r\nt crease 2/1/0 0 1 2.5\r\nt corner 1/1/0 2 4\r\nt interpolateboundary 1/0/0 1\r\n"
      "v 1e-300 -2e-60 3.5\r\n");  // underflows are zero, as in a float
  EXPECT_EQ(m.positions, (std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 3.5f}));
  EXPECT_EQ(m.face_sizes, (std::vector<int32_t>{3}));
  EXPECT_EQ(m.face_indices, (std::vector<int32_t>{0, 1, 2}));
  EXPECT_EQ(m.crease_pairs, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(m.crease_sharpness, (std::vector<float>{2.5f}));
  EXPECT_EQ(m.corner_vertices, (std::vector<int32_t>{2}));
  EXPECT_EQ(m.corner_sharpness, (std::vector<float>{4.0f}));
}

TEST(PovMesh2, IdentifiersAreValidAndNeverKeywords) {
  EXPECT_EQ(pov::identifier("FT_Rock"), "FT_Rock");
  EXPECT_EQ(pov::identifier("sphere"), "FT_sphere");
  EXPECT_EQ(pov::identifier("3 rocks/big"), "FT__3_rocks_big");
  EXPECT_EQ(pov::identifier("Fels\xc3\xa4"), "Fels__");
  EXPECT_EQ(pov::identifier(""), "FT__");
}

TEST(PovMesh2, TriangulatesAndWritesOneNormalPerVertex) {
  const std::string s = pov::encode_mesh2(cube(), "Cube");
  EXPECT_NE(s.find("#declare Cube = mesh2 {"), std::string::npos);
  EXPECT_NE(s.find("vertex_vectors {\n    8,"), std::string::npos);
  EXPECT_NE(s.find("normal_vectors {\n    8,"), std::string::npos);
  EXPECT_NE(s.find("face_indices {\n    12,"), std::string::npos);
  // the (1, 1, 1) corner's normal is the diagonal
  EXPECT_NE(s.find("<0.5773503, 0.5773503, 0.5773503>"), std::string::npos) << s;
}

// Real consumers: the CLI writes OBJ and mesh2, POV-Ray renders the mesh2.
TEST(FractalizeCli, WritesObjAndAPovMeshThatPovRayRenders) {
  const fs::path dir = fs::temp_directory_path() / ("ft_subdiv_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string obj = (dir / "rock.obj").string(), pov = (dir / "rock.inc").string();
  const std::string cmd = std::string(FT_CLI_PATH) + " fractalize --in " + kMeshes +
                          "cube.obj --levels 3 --hurst 0.7 --sigma 0.3 --scheme catmark --seed 5 --out " + obj +
                          " --pov " + pov + " --pov-name Rock";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const Mesh m = io::read_obj(obj);
  EXPECT_EQ(m.face_count(), 6u * 64u);
  expect_closed(m);
  const std::string bad = std::string(FT_CLI_PATH) + " fractalize --in " + kMeshes +
                          "cube.obj --scheme loop --out " + obj + " 2>" + (dir / "err.txt").string();
  EXPECT_NE(std::system(bad.c_str()), 0);
  EXPECT_NE(io::read_file((dir / "err.txt").string()).find("face 0 has 4 vertices; Loop"), std::string::npos);

  if (std::system("povray --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "povray not installed";
  const std::string scene = (dir / "scene.pov").string(), png = (dir / "rock.png").string();
  io::write_file_atomically(scene, "#version 3.7;\n#include \"" + pov +
                                   "\"\ncamera { location <3, 2, -4> look_at 0 }\n"
                                   "light_source { <5, 8, -6> color rgb 1 }\n"
                                   "object { Rock pigment { color rgb 0.6 } }\n");
  const std::string render = "povray +W48 +H36 -D -GA +O" + png + " " + scene + " >/dev/null 2>&1";
  ASSERT_EQ(std::system(render.c_str()), 0) << render;
  EXPECT_GT(fs::file_size(png), 100u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ft
