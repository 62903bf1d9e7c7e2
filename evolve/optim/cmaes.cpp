// SPDX-License-Identifier: MIT
// "Tutorial": N. Hansen, "The CMA Evolution Strategy: A Tutorial" (arXiv:1604.00772, 2016);
// the update order follows its Appendix A summary.
#include "evolve/optim/cmaes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace swarmpath::evolve {
namespace {

constexpr double kTolFun = 1e-12;       // range of recent best values and of the last generation
constexpr double kTolXFactor = 1e-12;   // tolx = 1e-12 * sigma0 (tutorial, Appendix B.3)
constexpr double kMaxCondition = 1e14;  // ConditionCov
constexpr double kTolUpSigma = 1e20;    // sigma grew far beyond what C explains: divergence

Eigen::VectorXd to_eigen(const Vector& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

Vector to_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

nlohmann::json matrix_to_json(const Eigen::MatrixXd& m) {
  auto j = nlohmann::json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) j.push_back(vector_to_json(to_vector(m.row(r).transpose())));
  return j;
}

double range_of(const std::vector<double>& v) {
  if (v.empty()) return std::numeric_limits<double>::infinity();
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

/// Generations whose best values tolfun compares: 10 + ceil(30 n / lambda).
std::size_t tolfun_history_length(std::size_t n, std::size_t lambda) {
  return 10 +
         static_cast<std::size_t>(std::ceil(30.0 * static_cast<double>(n) / static_cast<double>(lambda)));
}

std::size_t default_lambda(std::size_t n) {
  return 4 + static_cast<std::size_t>(std::floor(3.0 * std::log(static_cast<double>(n))));
}

}  // namespace

CmaesConstants CmaesConstants::make(std::size_t n, std::size_t lambda) {
  CmaesConstants k;
  const double dn = static_cast<double>(n);
  k.lambda = lambda;
  k.mu = lambda / 2;
  // recombination weights ln((lambda+1)/2) - ln i, positive ones only, normalised to sum 1
  k.weights.resize(static_cast<Eigen::Index>(k.mu));
  for (std::size_t i = 0; i < k.mu; ++i) {
    k.weights[static_cast<Eigen::Index>(i)] =
        std::log((static_cast<double>(lambda) + 1.0) / 2.0) - std::log(static_cast<double>(i) + 1.0);
  }
  k.weights /= k.weights.sum();
  k.mueff = 1.0 / k.weights.squaredNorm();
  // learning rates and damping of Table 1 (alpha_cov = 2)
  k.cs = (k.mueff + 2.0) / (dn + k.mueff + 5.0);
  k.damps = 1.0 + 2.0 * std::max(0.0, std::sqrt((k.mueff - 1.0) / (dn + 1.0)) - 1.0) + k.cs;
  k.cc = (4.0 + k.mueff / dn) / (dn + 4.0 + 2.0 * k.mueff / dn);
  k.c1 = 2.0 / ((dn + 1.3) * (dn + 1.3) + k.mueff);
  k.cmu = std::min(1.0 - k.c1, 2.0 * (k.mueff - 2.0 + 1.0 / k.mueff) / ((dn + 2.0) * (dn + 2.0) + k.mueff));
  k.chi_n = std::sqrt(dn) * (1.0 - 1.0 / (4.0 * dn) + 1.0 / (21.0 * dn * dn));
  return k;
}

Cmaes::Cmaes(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed)
    : box_(b),
      n_(b.dim()),
      sigma0_(s.sigma0),
      max_restarts_(s.ipop_restarts),
      lambda0_(0),
      tolx_(kTolXFactor * s.sigma0),
      rng_(seed) {
  if (s.population < 0 || s.population == 1) {
    throw SettingError("population", "cmaes: population must be >= 2 (or 0 for 4 + floor(3 ln n)), got " +
                                         std::to_string(s.population));
  }
  if (!(s.sigma0 > 0.0 && s.sigma0 <= 1.0)) {
    throw SettingError("sigma0", "cmaes: sigma0 must be in (0, 1] (a fraction of the bound width), got " +
                                     std::to_string(s.sigma0));
  }
  if (s.ipop_restarts < 0) {
    throw SettingError("ipop_restarts",
                       "cmaes: ipop_restarts must be >= 0, got " + std::to_string(s.ipop_restarts));
  }
  lambda0_ = s.population > 0 ? static_cast<std::size_t>(s.population) : default_lambda(n_);
  start_run(to_eigen(box_.to_unit(x0)), lambda0_);
}

void Cmaes::start_run(const Eigen::VectorXd& mean, std::size_t lambda) {
  const auto n = static_cast<Eigen::Index>(n_);
  k_ = CmaesConstants::make(n_, lambda);
  mean_ = mean;
  sigma_ = sigma0_;
  cov_ = Eigen::MatrixXd::Identity(n, n);
  pc_ = Eigen::VectorXd::Zero(n);
  ps_ = Eigen::VectorXd::Zero(n);
  generation_ = 0;
  best_history_.clear();
  last_fitness_.clear();
  decompose();
}

void Cmaes::decompose() {
  // SelfAdjointEigenSolver: deterministic, eigenvalues ascending
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov_);
  basis_ = eig.eigenvectors();
  axis_len_ = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const Eigen::VectorXd inv_len = axis_len_.unaryExpr([](double d) { return d > 0.0 ? 1.0 / d : 0.0; });
  inv_sqrt_cov_ = basis_ * inv_len.asDiagonal() * basis_.transpose();
}

std::vector<Vector> Cmaes::ask() {
  if (done_) throw std::logic_error("cmaes: ask() after done() (" + stop_reason_ + ")");
  if (asked_unit_.empty()) {
    // sampling: x_k = m + sigma B D z_k, z_k ~ N(0, I); then projected onto the box
    for (std::size_t k = 0; k < k_.lambda; ++k) {
      Eigen::VectorXd z(static_cast<Eigen::Index>(n_));
      for (Eigen::Index i = 0; i < z.size(); ++i) z[i] = rng_.normal();
      const Eigen::VectorXd x = mean_ + sigma_ * (basis_ * axis_len_.cwiseProduct(z));
      const Eigen::VectorXd inside = x.cwiseMax(0.0).cwiseMin(1.0);
      asked_repaired_.push_back(inside != x);
      asked_unit_.push_back(to_vector(inside));
    }
  }
  std::vector<Vector> batch;
  batch.reserve(asked_unit_.size());
  for (const auto& u : asked_unit_) batch.push_back(box_.from_unit(u));
  return batch;
}

void Cmaes::tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) {
  std::vector<Vector> asked;
  for (const auto& u : asked_unit_) asked.push_back(box_.from_unit(u));
  const std::vector<double> f = checked_fitness(asked, candidates, fitness);
  best_.update(candidates, f);

  // rank by fitness, ties by index
  std::vector<std::size_t> order(f.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });

  // steps y_k = (x_k - m) / sigma; those of repaired points shortened to a Mahalanobis length
  // of at most sqrt(n) + 2n / (n + 2) (Hansen 2011)
  const double dn = static_cast<double>(n_);
  const double max_step = std::sqrt(dn) + 2.0 * dn / (dn + 2.0);
  std::vector<Eigen::VectorXd> steps(k_.mu);
  Eigen::VectorXd y_w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n_));
  for (std::size_t i = 0; i < k_.mu; ++i) {
    Eigen::VectorXd y = (to_eigen(asked_unit_[order[i]]) - mean_) / sigma_;
    if (asked_repaired_[order[i]]) {
      const double len = (inv_sqrt_cov_ * y).norm();
      if (len > max_step) y *= max_step / len;
    }
    y_w += k_.weights[static_cast<Eigen::Index>(i)] * y;
    steps[i] = std::move(y);
  }

  // selection and recombination: the mean moves by sigma <y>_w (c_m = 1)
  mean_ += sigma_ * y_w;
  // step-size control: the conjugate evolution path p_sigma
  ps_ = (1.0 - k_.cs) * ps_ + std::sqrt(k_.cs * (2.0 - k_.cs) * k_.mueff) * (inv_sqrt_cov_ * y_w);
  // covariance adaptation: the evolution path p_c, stalled by h_sigma while ||p_sigma|| is large
  const double ps_norm = ps_.norm();
  const double ps_bias = std::sqrt(1.0 - std::pow(1.0 - k_.cs, 2.0 * static_cast<double>(generation_ + 1)));
  const bool h_sigma = ps_norm / ps_bias / k_.chi_n < 1.4 + 2.0 / (dn + 1.0);
  pc_ = (1.0 - k_.cc) * pc_ + (h_sigma ? std::sqrt(k_.cc * (2.0 - k_.cc) * k_.mueff) : 0.0) * y_w;
  // rank-one and rank-mu update; (1 - h_sigma) c1 cc (2 - cc) makes up for the stalled p_c
  Eigen::MatrixXd rank_mu = Eigen::MatrixXd::Zero(cov_.rows(), cov_.cols());
  for (std::size_t i = 0; i < k_.mu; ++i) {
    rank_mu += k_.weights[static_cast<Eigen::Index>(i)] * steps[i] * steps[i].transpose();
  }
  const double lost_variance = h_sigma ? 0.0 : k_.c1 * k_.cc * (2.0 - k_.cc);
  cov_ = (1.0 - k_.c1 - k_.cmu + lost_variance) * cov_ + k_.c1 * pc_ * pc_.transpose() + k_.cmu * rank_mu;
  cov_ = (0.5 * (cov_ + cov_.transpose())).eval();
  // cumulative step-size adaptation
  sigma_ *= std::exp(k_.cs / k_.damps * (ps_norm / k_.chi_n - 1.0));
  ++generation_;
  decompose();

  // history for tolfun
  const std::size_t history_len = tolfun_history_length(n_, k_.lambda);
  best_history_.push_back(f[order[0]]);
  if (best_history_.size() > history_len) best_history_.erase(best_history_.begin());
  last_fitness_ = f;
  asked_unit_.clear();
  asked_repaired_.clear();

  const std::string reason = termination();
  if (reason.empty()) return;
  stop_reason_ = reason;
  if (restarts_ < max_restarts_) {
    // IPOP: double the population, restart from a uniform point in the box
    ++restarts_;
    Eigen::VectorXd start(static_cast<Eigen::Index>(n_));
    for (Eigen::Index i = 0; i < start.size(); ++i) start[i] = rng_.uniform();
    start_run(start, 2 * k_.lambda);
  } else {
    done_ = true;
  }
}

std::string Cmaes::termination() const {
  // tutorial, Appendix B.3 (termination criteria), as in Hansen's cmaes.m and pycma
  const double d_min = axis_len_.minCoeff();
  const double d_max = axis_len_.maxCoeff();
  if (!(d_min > 0.0) || (d_max / d_min) * (d_max / d_min) > kMaxCondition) return "condition";
  const Eigen::VectorXd sd = cov_.diagonal().cwiseSqrt();
  if ((sigma_ * pc_.cwiseAbs()).maxCoeff() < tolx_ && (sigma_ * sd).maxCoeff() < tolx_) return "tolx";
  if (best_history_.size() >= tolfun_history_length(n_, k_.lambda) && range_of(best_history_) < kTolFun &&
      range_of(last_fitness_) < kTolFun) {
    return "tolfun";
  }
  const auto axis = static_cast<Eigen::Index>(static_cast<std::size_t>(generation_) % n_);
  if (mean_ == mean_ + 0.1 * sigma_ * axis_len_[axis] * basis_.col(axis)) return "noeffectaxis";
  for (Eigen::Index i = 0; i < mean_.size(); ++i) {
    if (mean_[i] == mean_[i] + 0.2 * sigma_ * sd[i]) return "noeffectcoord";
  }
  if (sigma_ / sigma0_ > kTolUpSigma * d_max) return "tolupsigma";
  return "";
}

Vector Cmaes::recommended_x() const { return box_.from_unit(to_vector(mean_)); }

nlohmann::json Cmaes::state() const {
  auto j = state_header(name(), n_);
  j["rng"] = rng_to_json(rng_);
  j["lambda"] = k_.lambda;
  j["mean"] = vector_to_json(to_vector(mean_));
  j["sigma"] = number_to_json(sigma_);
  j["cov"] = matrix_to_json(cov_);
  j["pc"] = vector_to_json(to_vector(pc_));
  j["ps"] = vector_to_json(to_vector(ps_));
  j["generation"] = generation_;
  j["best_history"] = vector_to_json(best_history_);
  j["last_fitness"] = vector_to_json(last_fitness_);
  j["restarts"] = restarts_;
  j["done"] = done_;
  j["stop_reason"] = stop_reason_;
  j["asked_unit"] = vectors_to_json(asked_unit_);
  j["asked_repaired"] = asked_repaired_;
  j["best"] = best_.to_json();
  return j;
}

void Cmaes::restore(const nlohmann::json& state) {
  // every field is checked before anything changes (StateError names the field)
  const StateReader r(state, "");
  r.header(name(), n_);
  const sim::Rng::State rng = r.rng("rng");
  const auto restarts = static_cast<int>(r.integer("restarts", 0, max_restarts_));
  const auto lambda =
      static_cast<std::size_t>(r.integer("lambda", 2, std::numeric_limits<std::int32_t>::max()));
  if (lambda != lambda0_ << restarts) {
    r.fail("lambda", "expected " + std::to_string(lambda0_ << restarts) + " (population " +
                         std::to_string(lambda0_) + ", doubled at each of " + std::to_string(restarts) +
                         " IPOP restarts), got " + std::to_string(lambda));
  }
  constexpr double kInf = StateReader::kInf;
  const Vector mean = r.numbers("mean", n_, -kInf, kInf);
  const double sigma = r.number("sigma", std::numeric_limits<double>::min(), kInf);
  const std::vector<Vector> cov_rows = r.vectors("cov", n_, n_, -kInf, kInf);
  Eigen::MatrixXd cov(static_cast<Eigen::Index>(n_), static_cast<Eigen::Index>(n_));
  for (std::size_t i = 0; i < n_; ++i)
    cov.row(static_cast<Eigen::Index>(i)) = to_eigen(cov_rows[i]).transpose();
  if (!cov.isApprox(cov.transpose(), 1e-12)) r.fail("cov", "the covariance matrix must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov, Eigen::EigenvaluesOnly);
  if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > 0.0)) {
    r.fail("cov", "the covariance matrix must be positive definite");
  }
  const Vector pc = r.numbers("pc", n_, -kInf, kInf);
  const Vector ps = r.numbers("ps", n_, -kInf, kInf);
  const long generation = r.integer("generation", 0, std::numeric_limits<std::int32_t>::max());
  const Vector best_history = r.numbers("best_history", StateReader::kAny, -kInf, kInf, /*extended=*/true);
  if (best_history.size() > tolfun_history_length(n_, lambda)) {
    r.fail("best_history", "holds more generations than tolfun compares (" +
                               std::to_string(tolfun_history_length(n_, lambda)) + ")");
  }
  const Vector last_fitness = r.numbers("last_fitness", StateReader::kAny, -kInf, kInf, /*extended=*/true);
  if (!last_fitness.empty() && last_fitness.size() != lambda) {
    r.fail("last_fitness",
           "expected 0 or " + std::to_string(lambda) + " values, got " + std::to_string(last_fitness.size()));
  }
  const bool done = r.boolean("done");
  const std::string stop_reason = r.text("stop_reason");
  const Bounds unit{Vector(n_, 0.0), Vector(n_, 1.0)};
  std::vector<Vector> asked_unit = r.points("asked_unit", StateReader::kAny, unit);
  if (!asked_unit.empty() && asked_unit.size() != lambda) {
    r.fail("asked_unit",
           "expected 0 or " + std::to_string(lambda) + " points, got " + std::to_string(asked_unit.size()));
  }
  std::vector<bool> asked_repaired = r.booleans("asked_repaired", asked_unit.size());
  const BestSoFar best = BestSoFar::from_state(r, box_.bounds());

  rng_.set_state(rng);
  restarts_ = restarts;
  k_ = CmaesConstants::make(n_, lambda);
  mean_ = to_eigen(mean);
  sigma_ = sigma;
  cov_ = cov;
  pc_ = to_eigen(pc);
  ps_ = to_eigen(ps);
  generation_ = generation;
  best_history_ = best_history;
  last_fitness_ = last_fitness;
  done_ = done;
  stop_reason_ = stop_reason;
  asked_unit_ = std::move(asked_unit);
  asked_repaired_ = std::move(asked_repaired);
  best_ = best;
  decompose();
}

}  // namespace swarmpath::evolve
