// Eigen's own OpenMP parallelism (its dense products and blocked LU) switched off for a scope.
// Eigen splits a product evenly over the threads and waits for the slowest: with the other core
// busy, the bundled example's reduced-sweep setup took 4 s on two threads against 0.3 s on one, and
// a transient with a 144-coordinate dense iteration matrix 25 s against 1.9 s (measured). The
// callers parallelize where it pays themselves (the model's element loops, the sweep's frequencies).
#pragma once

#include <Eigen/Core>

namespace drillflex::solvers {

class SerialEigenProducts {
 public:
  SerialEigenProducts() : threads_(Eigen::nbThreads()) { Eigen::setNbThreads(1); }
  ~SerialEigenProducts() { Eigen::setNbThreads(threads_); }
  SerialEigenProducts(const SerialEigenProducts&) = delete;
  SerialEigenProducts& operator=(const SerialEigenProducts&) = delete;

 private:
  int threads_;
};

}  // namespace drillflex::solvers
