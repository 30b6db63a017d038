#include "models/plants/linear_flow.hpp"

#include <unsupported/Eigen/MatrixFunctions>

namespace hilrig::plants {

LinearFlow::LinearFlow(Eigen::MatrixXd a, Eigen::MatrixXd b) : a_(std::move(a)), b_(std::move(b)) {}

const LinearFlow::Discrete& LinearFlow::discrete(double seconds) const {
  if (const auto it = cache_.find(seconds); it != cache_.end()) return it->second;
  if (cache_.size() > 64) cache_.clear();
  const Eigen::Index n = a_.rows();
  const Eigen::Index m = b_.cols();
  Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + m, n + m);
  aug.topLeftCorner(n, n) = a_ * seconds;
  aug.topRightCorner(n, m) = b_ * seconds;
  const Eigen::MatrixXd e = aug.exp();
  return cache_.emplace(seconds, Discrete{e.topLeftCorner(n, n), e.topRightCorner(n, m)}).first->second;
}

Eigen::VectorXd LinearFlow::after(double seconds, const Eigen::VectorXd& x0, const Eigen::VectorXd& u) const {
  const Discrete& d = discrete(seconds);
  return d.phi * x0 + d.gamma * u;
}

} // namespace hilrig::plants
