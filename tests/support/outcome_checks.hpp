#pragma once
// What makes two outcomes of a pair the same result, times apart: the one definition the runner's,
// the sweep's and the studio benchmark view's tests compare by.

#include <catch2/catch.hpp>
#include <cmath>

#include "pagor/eval/benchmark.hpp"

namespace pagor::test {

/// Checks, field by field (a failure names the field), that `got` is the result `want` is: the
/// pair, whether it loaded and why not, the level selected and each level's success, the upper
/// bound, the verdict and its margin, D (NaN when nothing was selected), the pose errors and the
/// diagnosis.
inline void check_same_outcome(const PairOutcome& got, const PairOutcome& want) {
  INFO("pair " << want.name);
  CHECK(got.name == want.name);
  REQUIRE(got.loaded == want.loaded);
  CHECK(got.load_error == want.load_error);
  CHECK(got.selected_level == want.selected_level);
  CHECK(got.level_success == want.level_success);
  CHECK(got.success == want.success);
  CHECK(got.upper_bound == want.upper_bound);
  CHECK(got.accepted == want.accepted);
  CHECK(got.margin == want.margin);
  CHECK(((std::isnan(got.score) && std::isnan(want.score)) || got.score == want.score));
  CHECK(got.diagnosis == want.diagnosis);
  REQUIRE(got.error.has_value() == want.error.has_value());
  if (want.error) {
    CHECK(got.error->translation == want.error->translation);
    CHECK(got.error->rotation_deg == want.error->rotation_deg);
  }
}

}  // namespace pagor::test
