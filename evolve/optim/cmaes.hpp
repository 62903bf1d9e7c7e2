// SPDX-License-Identifier: MIT
// CMA-ES after N. Hansen, "The CMA Evolution Strategy: A Tutorial" (arXiv:1604.00772, 2016):
// (mu/mu_w, lambda) with rank-one and rank-mu covariance updates and cumulative step-size
// adaptation, in the unit cube, with IPOP restarts (Auger & Hansen, CEC 2005).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "evolve/optim/batch.hpp"
#include "evolve/optim/normalise.hpp"
#include "evolve/optim/optimizer.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// The strategy constants that follow from n and lambda (tutorial, Appendix A, Table 1).
struct CmaesConstants {
  std::size_t lambda = 0;
  std::size_t mu = 0;
  Eigen::VectorXd weights;  ///< positive recombination weights, sum 1
  double mueff = 0.0;
  double cs = 0.0;     ///< step-size cumulation
  double damps = 0.0;  ///< step-size damping
  double cc = 0.0;     ///< covariance cumulation
  double c1 = 0.0;     ///< rank-one learning rate
  double cmu = 0.0;    ///< rank-mu learning rate
  double chi_n = 0.0;  ///< E||N(0,I)||

  static CmaesConstants make(std::size_t n, std::size_t lambda);
};

/// CMA-ES. Bounds by Lamarckian repair: a sample outside [0,1]^n is projected onto the box, the
/// projected point is what the caller evaluates, and it enters the update as an injected
/// solution whose step is shortened to Mahalanobis length at most sqrt(n) + 2n/(n+2)
/// (Hansen 2011, "Injecting external solutions into CMA-ES", arXiv:1110.4181). No penalty term.
class Cmaes final : public Optimizer {
 public:
  Cmaes(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed);

  std::string name() const override { return "cmaes"; }

  std::vector<Vector> ask() override;
  void tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) override;

  bool done() const override { return done_; }

  Vector best_x() const override { return best_.x; }

  double best_f() const override { return best_.f; }

  /// The distribution mean m (tutorial, eq. 42) in the caller's units, projected onto the bounds.
  Vector recommended_x() const override;

  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

  /// Why the last run stopped ("" while the first run goes on): tolx, tolfun, condition, ...
  const std::string& stop_reason() const { return stop_reason_; }

  int restarts() const { return restarts_; }

  std::size_t lambda() const { return k_.lambda; }

 private:
  void start_run(const Eigen::VectorXd& mean, std::size_t lambda);
  void decompose();
  std::string termination() const;

  // fixed by construction
  UnitBox box_;
  std::size_t n_;
  double sigma0_;
  int max_restarts_;
  std::size_t lambda0_;  ///< the first run's population (IPOP doubles it at each restart)
  double tolx_;

  // the run's state (serialised)
  sim::Rng rng_;
  CmaesConstants k_;
  Eigen::VectorXd mean_;
  double sigma_ = 0.0;
  Eigen::MatrixXd cov_;
  Eigen::VectorXd pc_;
  Eigen::VectorXd ps_;
  long generation_ = 0;               ///< generations of the current run
  std::vector<double> best_history_;  ///< best fitness of each recent generation (for tolfun)
  std::vector<double> last_fitness_;  ///< fitness of the last generation told
  int restarts_ = 0;
  bool done_ = false;
  std::string stop_reason_;
  std::vector<Vector> asked_unit_;    ///< the pending batch, repaired, in [0,1]^n
  std::vector<bool> asked_repaired_;  ///< which of them were outside the box
  BestSoFar best_;

  // derived from cov_ (decompose())
  Eigen::MatrixXd basis_;         ///< B: eigenvectors of C
  Eigen::VectorXd axis_len_;      ///< D: square roots of C's eigenvalues
  Eigen::MatrixXd inv_sqrt_cov_;  ///< C^(-1/2) = B D^-1 B^T
};

}  // namespace swarmpath::evolve
