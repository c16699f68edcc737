// SPDX-License-Identifier: GPL-3.0-or-later
// The subdiv C ABI as ctypes (and the Blender add-on) uses it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"

namespace {

// The cube of examples/meshes/cube.obj, 0-based.
const std::vector<float> kCubeXyz = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                     -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
const std::vector<int32_t> kCubeSizes = {4, 4, 4, 4, 4, 4};
const std::vector<int32_t> kCubeIndices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4,
                                           1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};

ft_mesh* make_cube() {
  ft_mesh* m = nullptr;
  EXPECT_EQ(ft_mesh_create(kCubeXyz.data(), 8, kCubeSizes.data(), 6, kCubeIndices.data(), nullptr, nullptr, 0, &m),
            FT_OK)
      << ft_last_error();
  return m;
}

TEST(SubdivCapi, FractalizesACubeIntoAClosedQuadMesh) {
  ft_mesh* cube = make_cube();
  ASSERT_NE(cube, nullptr);
  EXPECT_EQ(ft_mesh_vertex_count(cube), 8);
  EXPECT_EQ(ft_mesh_face_count(cube), 6);
  ft_fractalize_params p;
  ASSERT_EQ(ft_fractalize_params_init(&p), FT_OK);
  EXPECT_EQ(p.struct_size, sizeof p);
  p.levels = 3;
  p.sigma = 0.2;
  ft_mesh* rock = nullptr;
  ASSERT_EQ(ft_fractalize(cube, &p, &rock), FT_OK) << ft_last_error();
  EXPECT_STREQ(ft_last_error(), "");
  // Euler: a closed genus-0 quad mesh with F faces has F + 2 vertices.
  EXPECT_EQ(ft_mesh_face_count(rock), 6 * 64);
  EXPECT_EQ(ft_mesh_vertex_count(rock), 6 * 64 + 2);
  EXPECT_EQ(ft_mesh_face_index_count(rock), 4 * 6 * 64);
  const int32_t* sizes = ft_mesh_face_sizes(rock);
  const int32_t* idx = ft_mesh_face_indices(rock);
  const float* xyz = ft_mesh_positions(rock);
  for (int64_t f = 0; f < ft_mesh_face_count(rock); ++f) ASSERT_EQ(sizes[f], 4);
  for (int64_t i = 0; i < ft_mesh_face_index_count(rock); ++i)
    ASSERT_TRUE(idx[i] >= 0 && idx[i] < ft_mesh_vertex_count(rock));
  for (int64_t i = 0; i < 3 * ft_mesh_vertex_count(rock); ++i) ASSERT_TRUE(std::isfinite(xyz[i]));
  ft_mesh_free(rock);
  ft_mesh_free(cube);
}

TEST(SubdivCapi, LoopNeedsTrianglesAndSaysWhichFaceIsNot) {
  ft_mesh* cube = make_cube();
  ft_fractalize_params p;
  ft_fractalize_params_init(&p);
  p.scheme = FT_SCHEME_LOOP;
  ft_mesh* out = reinterpret_cast<ft_mesh*>(&p);  // must be reset to NULL
  EXPECT_EQ(ft_fractalize(cube, &p, &out), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(out, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("face 0 has 4 vertices"), std::string::npos) << ft_last_error();
  ft_mesh_free(cube);
}

TEST(SubdivCapi, RejectsBadMeshesAndNullPointers) {
  ft_mesh* m = nullptr;
  std::vector<int32_t> bad = kCubeIndices;
  bad[9] = 42;
  EXPECT_EQ(ft_mesh_create(kCubeXyz.data(), 8, kCubeSizes.data(), 6, bad.data(), nullptr, nullptr, 0, &m),
            FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(m, nullptr);
  EXPECT_NE(std::string(ft_last_error()).find("face 2 refers to vertex 42"), std::string::npos) << ft_last_error();
  EXPECT_EQ(ft_mesh_create(nullptr, 8, kCubeSizes.data(), 6, kCubeIndices.data(), nullptr, nullptr, 0, &m),
            FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_mesh_create(kCubeXyz.data(), 8, kCubeSizes.data(), 6, kCubeIndices.data(), nullptr, nullptr, 1, &m),
            FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("crease_pairs"), std::string::npos);
  const int32_t pair[2] = {0, 6};
  const float sharp[1] = {3};
  EXPECT_EQ(ft_mesh_create(kCubeXyz.data(), 8, kCubeSizes.data(), 6, kCubeIndices.data(), pair, sharp, 1, &m),
            FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("not the ends of an edge"), std::string::npos);
  EXPECT_EQ(ft_fractalize(nullptr, nullptr, &m), FT_ERR_INVALID_ARGUMENT);
  EXPECT_EQ(ft_mesh_vertex_count(nullptr), 0);
  EXPECT_EQ(ft_mesh_positions(nullptr), nullptr);
  EXPECT_EQ(ft_mesh_face_indices(nullptr), nullptr);
  ft_mesh_free(nullptr);
}

TEST(SubdivCapi, CornersAreValidatedAndABadCallKeepsTheMesh) {
  ft_mesh* cube = make_cube();
  const int32_t v[1] = {99};
  const float s[1] = {10};
  EXPECT_EQ(ft_mesh_set_corners(cube, v, s, 1), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("corner 0 names vertex 99"), std::string::npos);
  const int32_t ok[1] = {6};
  EXPECT_EQ(ft_mesh_set_corners(cube, ok, s, 1), FT_OK);
  ft_fractalize_params p;
  ft_fractalize_params_init(&p);
  p.levels = 2;
  p.sigma = 0;
  ft_mesh* out = nullptr;
  ASSERT_EQ(ft_fractalize(cube, &p, &out), FT_OK);
  // An infinitely sharp corner stays where it is (vertex 6 keeps index 6).
  EXPECT_EQ(ft_mesh_positions(out)[3 * 6], 1.0f);
  EXPECT_EQ(ft_mesh_positions(out)[3 * 6 + 2], 1.0f);
  ft_mesh_free(out);
  ft_mesh_free(cube);
}

}  // namespace

namespace {

TEST(SubdivCapi, ProgressIsReportedPerLevelAndCanCancel) {
  ft_mesh* cube = make_cube();
  ft_fractalize_params p;
  ft_fractalize_params_init(&p);
  p.levels = 3;
  std::vector<double> seen;
  p.progress = [](void* user, double f) -> int32_t {
    static_cast<std::vector<double>*>(user)->push_back(f);
    return 0;
  };
  p.progress_user = &seen;
  ft_mesh* out = nullptr;
  ASSERT_EQ(ft_fractalize(cube, &p, &out), FT_OK);
  EXPECT_EQ(seen, (std::vector<double>{0.0, 1.0 / 3, 2.0 / 3, 1.0}));
  ft_mesh_free(out);
  p.progress = [](void*, double f) -> int32_t { return f > 0.5; };
  EXPECT_EQ(ft_fractalize(cube, &p, &out), FT_ERR_CANCELLED);
  EXPECT_EQ(out, nullptr);
  ft_mesh_free(cube);
}

}  // namespace
