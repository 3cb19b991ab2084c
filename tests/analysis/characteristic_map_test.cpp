// The characteristic map of Loop and Catmull-Clark is regular and injective
// at every valence (both are C1); a map built from the wrong eigenvectors is
// not, so the test can fail.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>

#include "subdiv/analysis/characteristic_map.h"
#include "subdiv/rules/catmull_clark.h"
#include "subdiv/rules/loop.h"

namespace subdiv {
namespace {

Configuration interior(int k) { return {Configuration::Kind::interior, k, CornerType::convex}; }

// Right eigenvectors of the i-th and j-th eigenvalues by decreasing
// magnitude (real spectra here), from Eigen's dense solver.
std::pair<Eigen::VectorXd, Eigen::VectorXd> eigenvectors(const Eigen::MatrixXd& S, int i, int j) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(S);
  std::vector<Eigen::Index> order(static_cast<std::size_t>(S.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
    return std::abs(solver.eigenvalues()[a]) > std::abs(solver.eigenvalues()[b]);
  });
  return {solver.eigenvectors().col(order[static_cast<std::size_t>(i)]).real(),
          solver.eigenvectors().col(order[static_cast<std::size_t>(j)]).real()};
}

TEST(CharacteristicMap, LoopAndCatmullClarkAreRegularAndInjective) {
  for (const Scheme* s : {&loop_scheme(), &catmull_clark_scheme()})
    for (int k = 3; k <= 12; ++k) {
      const LocalSubdivisionMatrix m = local_subdivision_matrix(*s, interior(k), 2);
      const auto [x, y] = eigenvectors(m.S, 1, 2);
      const CharacteristicMap map = characteristic_map(*s, m, x, y, 3);
      EXPECT_TRUE(map.regular) << s->name << " k=" << k << ": " << map.note;
      EXPECT_TRUE(map.injective) << s->name << " k=" << k << ": " << map.note;
      EXPECT_GT(map.image.face_count(), 10 * k);
      // Every sector is present.
      for (int sector = 0; sector < k; ++sector)
        EXPECT_NE(std::find(map.face_sector.begin(), map.face_sector.end(), sector), map.face_sector.end());
    }
}

TEST(CharacteristicMap, WrongEigenvectorsGiveAFoldedMap) {
  // The eigenvectors of the third and fourth eigenvalues (frequency 2 for
  // Loop at k = 6) wind twice around the centre: not injective, and folded.
  const LocalSubdivisionMatrix m = local_subdivision_matrix(loop_scheme(), interior(6), 2);
  const auto [x, y] = eigenvectors(m.S, 4, 5);
  const CharacteristicMap map = characteristic_map(loop_scheme(), m, x, y, 3);
  EXPECT_FALSE(map.regular && map.injective) << "frequency-2 eigenvectors made a valid characteristic map";
  EXPECT_FALSE(map.note.empty());
}

}  // namespace
}  // namespace subdiv
