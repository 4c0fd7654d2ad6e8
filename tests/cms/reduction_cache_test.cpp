#include "cms/reduction_cache.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "core/error.hpp"

namespace drillflex::cms {
namespace reduction_cache_test {

fe::BodySpec Pipe(double length) {
  fe::BodySpec spec;
  spec.section = {0.127, 0.1086104};
  spec.material = {"steel", 2.1e11, 0.3, 7850.0};
  spec.length = length;
  spec.element_count = 10;
  return spec;
}

TEST(ReductionCache, AThousandIdenticalBodiesReduceOnce) {
  ReductionCache cache;
  ReductionOptions options;
  options.modes_per_body = 12;
  const auto first = cache.Get(Pipe(9.144), options);
  for (int i = 0; i < 999; ++i) {
    fe::BodySpec spec = Pipe(9.144);
    spec.material.name = "another name, same numbers";
    EXPECT_EQ(cache.Get(spec, options).get(), first.get());
  }
  EXPECT_EQ(cache.reduction_count(), 1u);
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(first->flexible_count, 18);
}

TEST(ReductionCache, DifferentKeysAreDifferentEntries) {
  ReductionCache cache;
  ReductionOptions options;
  const auto base = cache.Get(Pipe(9.0), options);
  fe::BodySpec longer = Pipe(9.5);
  fe::BodySpec lumped = Pipe(9.0);
  lumped.options.mass = fe::MassKind::kLumped;
  fe::BodySpec wet = Pipe(9.0);
  wet.options.internal_fluid_mass_per_length = 11.0;
  ReductionOptions fewer = options;
  fewer.modes_per_body = 4;
  ReductionOptions damped = options;
  damped.structural_damping = 0.01;
  EXPECT_NE(cache.Get(longer, options).get(), base.get());
  EXPECT_NE(cache.Get(lumped, options).get(), base.get());
  EXPECT_NE(cache.Get(wet, options).get(), base.get());
  EXPECT_NE(cache.Get(Pipe(9.0), fewer).get(), base.get());
  EXPECT_NE(cache.Get(Pipe(9.0), damped).get(), base.get());
  EXPECT_EQ(cache.Get(Pipe(9.0), options).get(), base.get());
  EXPECT_EQ(cache.size(), 6u);
  EXPECT_EQ(cache.reduction_count(), 6u);
  EXPECT_EQ(cache.Get(Pipe(9.0), fewer)->flexible_count, 10);
}

TEST(ReductionCache, ConcurrentLookupsShareOneReductionPerKey) {
  ReductionCache cache;
  ReductionOptions options;
  std::vector<std::thread> threads;
  std::vector<const ReducedBody*> seen(8 * 50);
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 50; ++i)
        seen[t * 50 + i] = cache.Get(Pipe(i % 2 ? 9.0 : 9.5), options).get();
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(cache.reduction_count(), 2u);
  for (int i = 0; i < 8 * 50; ++i) EXPECT_EQ(seen[i], seen[i % 2]);
}

TEST(ReductionCache, AFailedReductionRethrowsForEveryCaller) {
  ReductionCache cache;
  ReductionOptions options;
  options.modes_per_body = 1000;  // more than the internal DOFs
  EXPECT_THROW(cache.Get(Pipe(9.0), options), InputError);
  EXPECT_THROW(cache.Get(Pipe(9.0), options), InputError);
  EXPECT_EQ(cache.reduction_count(), 1u);
}

}  // namespace reduction_cache_test
}  // namespace drillflex::cms
