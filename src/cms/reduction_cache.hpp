// Reduced bodies shared by every body with the same definition (method.md §3: "the reduction runs
// once per distinct section geometry"): a 3 km string of identical drill-pipe bodies reduces once.
// Thread-safe: concurrent lookups of one key wait for a single reduction; different keys reduce in
// parallel. A failed reduction's exception is stored and rethrown to every caller of that key.
#pragma once

#include <cstddef>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "cms/craig_bampton.hpp"
#include "cms/reduced_body.hpp"
#include "fe/body_fe_model.hpp"

namespace drillflex::cms {

class ReductionCache {
 public:
  // The reduced body of `spec` under `options`, built (FE model + reduction) on first use.
  // Keyed by every number that changes the result (the material's name does not).
  std::shared_ptr<const ReducedBody> Get(const fe::BodySpec& spec, const ReductionOptions& options);

  std::size_t size() const;             // distinct keys held
  std::size_t reduction_count() const;  // reductions started so far

 private:
  struct Key {
    double outer_diameter, inner_diameter;
    double youngs_modulus, poisson_ratio, density;
    double length;
    Index element_count;
    fe::MassKind mass;
    fe::BeamTheory beam;
    double added_lateral_mass_per_length, internal_fluid_mass_per_length;
    bool bending_rotary_inertia;
    fe::LumpedRotaryInertia lumped_rotary;
    double bending_stiffness_factor;
    Index modes_per_body;
    double structural_damping;
    std::vector<Index> interface_nodes;
    auto operator<=>(const Key&) const = default;
  };
  static Key MakeKey(const fe::BodySpec& spec, const ReductionOptions& options);

  using Entry = std::shared_future<std::shared_ptr<const ReducedBody>>;
  mutable std::mutex mutex_;
  std::map<Key, Entry> entries_;
  std::size_t reduction_count_ = 0;
};

}  // namespace drillflex::cms
