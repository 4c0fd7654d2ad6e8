#include "cms/reduction_cache.hpp"

#include <utility>

namespace drillflex::cms {

ReductionCache::Key ReductionCache::MakeKey(const fe::BodySpec& spec,
                                            const ReductionOptions& options) {
  const fe::BodyFeOptions& fe = spec.options;
  return Key{spec.section.outer_diameter,
             spec.section.inner_diameter,
             spec.material.youngs_modulus,
             spec.material.poisson_ratio,
             spec.material.density,
             spec.length,
             spec.element_count,
             fe.mass,
             fe.beam,
             fe.added_lateral_mass_per_length,
             fe.internal_fluid_mass_per_length,
             fe.bending_rotary_inertia,
             fe.lumped_rotary,
             fe.bending_stiffness_factor,
             options.modes_per_body,
             options.structural_damping,
             options.interface_nodes};
}

std::shared_ptr<const ReducedBody> ReductionCache::Get(const fe::BodySpec& spec,
                                                       const ReductionOptions& options) {
  Key key = MakeKey(spec, options);
  std::promise<std::shared_ptr<const ReducedBody>> promise;
  Entry entry;
  bool owner = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = entries_.find(key);
    if (found != entries_.end()) {
      entry = found->second;
    } else {
      entry = promise.get_future().share();
      entries_.emplace(std::move(key), entry);
      ++reduction_count_;
      owner = true;
    }
  }
  // The owner reduces outside the lock: other keys proceed, this key's callers wait on `entry`.
  if (owner) {
    try {
      promise.set_value(
          std::make_shared<const ReducedBody>(Reduce(fe::BuildBodyFeModel(spec), options)));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  return entry.get();
}

std::size_t ReductionCache::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

std::size_t ReductionCache::reduction_count() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return reduction_count_;
}

}  // namespace drillflex::cms
