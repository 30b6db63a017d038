#pragma once
// Exact discretization of a linear time-invariant system with an input held constant:
// dx/dt = A x + B u  gives  x(t) = Phi(t) x0 + Gamma(t) u  with Phi = e^{At} and
// Gamma = integral_0^t e^{As} ds B, both read off one matrix exponential of the augmented
// matrix [[A, B], [0, 0]] t (Van Loan). Eigen's MatrixFunctions computes it by Pade
// approximation with scaling and squaring, accurate to the double precision of the entries.

#include <map>

#include <Eigen/Dense>

namespace hilrig::plants {

class LinearFlow {
public:
  LinearFlow() = default;
  LinearFlow(Eigen::MatrixXd a, Eigen::MatrixXd b);

  // The state after `seconds` from x0 with input u held constant.
  [[nodiscard]] Eigen::VectorXd after(double seconds, const Eigen::VectorXd& x0,
                                      const Eigen::VectorXd& u) const;

  [[nodiscard]] const Eigen::MatrixXd& a() const { return a_; }

private:
  struct Discrete {
    Eigen::MatrixXd phi;
    Eigen::MatrixXd gamma;
  };
  [[nodiscard]] const Discrete& discrete(double seconds) const;

  Eigen::MatrixXd a_;
  Eigen::MatrixXd b_;
  // The full step recurs; event location asks for many sub-steps once each. Kept small.
  mutable std::map<double, Discrete> cache_;
};

} // namespace hilrig::plants
