// Typed handles to a model's force elements (in the style of Drake's MultibodyPlant indices): the
// builder returns one for each element an analysis reads (a support, a wall contact, a coupling, the
// drives, the bit's elements, the pipe above), and SystemModel::Get resolves it to the element with
// its type. A handle exists only for an element that exists: absence is an empty std::optional, not
// a sentinel index.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "model/force_element.hpp"

namespace drillflex::model {

class ElementList;

template <class E>
class ElementHandle {
 public:
  // The element's place in SystemModel::elements().
  Index index() const { return index_; }
  bool operator==(const ElementHandle&) const = default;

 private:
  friend class ElementList;
  explicit ElementHandle(Index index) : index_(index) {}
  Index index_;
};

// The elements of a model as the builder adds them, each addition answered with its typed handle.
class ElementList {
 public:
  template <class E, class... Arguments>
  ElementHandle<E> Add(Arguments&&... arguments) {
    elements_.push_back(std::make_unique<E>(std::forward<Arguments>(arguments)...));
    return ElementHandle<E>(std::ssize(elements_) - 1);
  }
  std::vector<std::unique_ptr<ForceElement>> Release() && { return std::move(elements_); }

 private:
  std::vector<std::unique_ptr<ForceElement>> elements_;
};

}  // namespace drillflex::model
