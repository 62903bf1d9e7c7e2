// SPDX-License-Identifier: MIT
// The genome: which SPEC §7 parameters an evolution tunes and how a point of the normalised
// box [0,1]^n maps to a full Params (linear or log scale between the bounds, integers and steps
// rounded, bools and choices thresholded at 0.5), with the cross constraints repaired.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "evolve/optim/optimizer.hpp"
#include "sim/params.hpp"

namespace swarmpath::evolve {

/// One tuned parameter.
struct Gene {
  const sim::ParamInfo* info = nullptr;  ///< the SPEC §7 descriptor
  double lo = 0.0;                       ///< bounds, within the descriptor's [lo, hi]
  double hi = 1.0;
  double step = 0.0;     ///< > 0: values are lo + k * step; 0: continuous
  bool integer = false;  ///< values are whole numbers (always for integer parameters)
  bool log = false;      ///< log scale between lo and hi (lo > 0)

  /// True for bools and choices: x < 0.5 is value 0, x >= 0.5 value 1.
  bool binary() const;
};

/// The tuned parameters (in SPEC §7 row order) on top of a base Params.
struct Genome {
  std::vector<Gene> genes;
  sim::Params base;

  std::size_t dim() const { return genes.size(); }

  /// The optimiser's box: [0,1]^n.
  Bounds bounds() const;
};

/// A gene from a descriptor with the SPEC §7 range (integers get integer = true).
Gene default_gene(const sim::ParamInfo& info);

/// The value of coordinate x (clamped to [0,1]): scaled, rounded to the gene's grid and to 12
/// significant digits, so that a params file written with write_params_toml reads back the
/// very same doubles.
double gene_value(const Gene& g, double x);

/// The coordinate of value v (clamped into [0,1]); gene_value(g, gene_coordinate(g, v)) == v
/// for every v on the gene's grid. Bools and choices map to 0.25 and 0.75.
double gene_coordinate(const Gene& g, double v);

/// A decoded candidate.
struct Decoded {
  sim::Params params;
  bool repaired = false;  ///< a cross constraint was repaired (see repair())
  std::string violation;  ///< non-empty: still invalid after repair; the candidate is penalised
};

/// Cross constraints (SPEC §7: theta_soft <= theta_hard, theta_none <= theta_soft,
/// R_keep <= R_vis, d_sub < R_vis, T_explore0 <= T_explore_max) are repaired deterministically,
/// one pair at a time in that order (up to three passes): the dependent (left) parameter, when tuned, is
/// lowered to the largest value on its grid that satisfies the pair (for the strict d_sub < R_vis: one step,
/// or one SPEC step, below); when it is not tuned or that would leave its bounds, the other one, when tuned,
/// is raised instead. Only tuned parameters ever move (the base file is valid). When neither can move, the
/// candidate keeps the violation and is penalised without simulation.
Decoded decode(const Genome& g, std::span<const double> x);

/// The candidate with these tuned values (in gene order; bools and choices as 0/1): each value is
/// clamped into its gene's bounds and rounded to its grid as decode() does, then the cross
/// constraints are repaired. What an outside tuner's values (irace, Optuna) become. A value that is
/// not finite is a violation (the candidate is penalised), never repaired into a value.
Decoded decode_values(const Genome& g, std::span<const double> values);

/// The coordinates of p's tuned values (each clamped into the gene's bounds); the optimiser's
/// start point is encode(genome, genome.base).
Vector encode(const Genome& g, const sim::Params& p);

/// The tuned values of p as "name = value" pairs, in gene order (for reports).
std::vector<std::pair<std::string, std::string>> tuned_values(const Genome& g, const sim::Params& p);

/// The tuned values of p as numbers, in gene order (what makes two candidates distinct).
std::vector<double> tuned_numbers(const Genome& g, const sim::Params& p);

/// Rounds to 12 significant digits (the precision params files are written with).
double canonical(double v);

}  // namespace swarmpath::evolve
