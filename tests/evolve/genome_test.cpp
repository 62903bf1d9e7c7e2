// SPDX-License-Identifier: MIT
// The genome: [0,1]^n to Params (linear and log scales, integer and step rounding, thresholds
// for bools and choices), encode/decode round trips, and the repair of SPEC §7's cross
// constraints.
#include "evolve/genome.hpp"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "sim/params.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {
namespace {

Gene gene(std::string_view name) { return default_gene(*sim::find_param(name)); }

Genome genome_of(std::vector<Gene> genes) {
  Genome g;
  g.genes = std::move(genes);
  return g;
}

// every parameter of the table at its SPEC §7 range
Genome full_genome() {
  Genome g;
  for (const sim::ParamInfo& info : sim::param_table()) g.genes.push_back(default_gene(info));
  return g;
}

TEST(Genome, LinearScaleSpansTheBounds) {
  Gene g = gene("w_away");  // SPEC range 0-2
  EXPECT_EQ(gene_value(g, 0.0), 0.0);
  EXPECT_EQ(gene_value(g, 1.0), 2.0);
  EXPECT_EQ(gene_value(g, 0.5), 1.0);
  EXPECT_EQ(gene_value(g, -3.0), 0.0);  // clamped
  EXPECT_EQ(gene_value(g, 7.0), 2.0);
  g.lo = 0.5;
  g.hi = 1.5;
  EXPECT_EQ(gene_value(g, 0.25), 0.75);
}

TEST(Genome, LogScaleIsGeometric) {
  Gene g = gene("p_turn");
  g.lo = 0.002;
  g.hi = 0.2;
  g.log = true;
  EXPECT_DOUBLE_EQ(gene_value(g, 0.0), 0.002);
  EXPECT_DOUBLE_EQ(gene_value(g, 1.0), 0.2);
  EXPECT_DOUBLE_EQ(gene_value(g, 0.5), 0.02);  // the geometric mean, not 0.101
  EXPECT_DOUBLE_EQ(gene_value(g, 0.25), canonical(0.002 * std::pow(100.0, 0.25)));
  EXPECT_NEAR(gene_coordinate(g, 0.02), 0.5, 1e-12);
}

TEST(Genome, IntegersAndStepsAreRounded) {
  const Gene lost = gene("T_lost");  // integer, 1-20
  EXPECT_TRUE(lost.integer);
  for (double x = 0.0; x <= 1.0; x += 0.01) {
    const double v = gene_value(lost, x);
    EXPECT_EQ(v, std::round(v)) << x;
    EXPECT_GE(v, 1.0);
    EXPECT_LE(v, 20.0);
  }
  EXPECT_EQ(gene_value(lost, 0.5), 11.0);  // 1 + 0.5 * 19 = 10.5 rounds to 11

  Gene budget = gene("T_explore0");
  budget.lo = 200;
  budget.hi = 2000;
  budget.step = 50;
  for (double x = 0.0; x <= 1.0; x += 0.013) {
    const double v = gene_value(budget, x);
    EXPECT_EQ(std::fmod(v - 200.0, 50.0), 0.0) << v;
  }
  // a step that does not divide the range never passes hi
  Gene lam = gene("lambda_mid");  // 0-1
  lam.hi = 0.95;
  lam.step = 0.1;
  EXPECT_EQ(gene_value(lam, 1.0), 0.9);
  EXPECT_EQ(gene_value(lam, 0.34), 0.3);  // 0.323 -> 0.3, exactly the decimal
}

TEST(Genome, BoolsAndChoicesThresholdAtOneHalf) {
  const Gene b = gene("early_stop_in_rec");
  const Gene c = gene("t_source");
  EXPECT_TRUE(b.binary());
  EXPECT_EQ(gene_value(b, 0.4999), 0.0);
  EXPECT_EQ(gene_value(b, 0.5), 1.0);
  EXPECT_EQ(gene_value(c, 0.2), 0.0);
  EXPECT_EQ(gene_value(c, 0.9), 1.0);
  const Genome g = genome_of({b, c});
  const Decoded d = decode(g, std::vector<double>{0.1, 0.7});
  EXPECT_FALSE(d.params.early_stop_in_rec);
  EXPECT_EQ(d.params.t_source, sim::TSource::kElapsed);
  EXPECT_EQ(encode(g, d.params), (Vector{0.25, 0.75}));
}

TEST(Genome, EncodeDecodeRoundTripsThePaperDefaults) {
  const Genome g = full_genome();
  const Vector x = encode(g, sim::Params{});
  for (const double xi : x) {
    EXPECT_GE(xi, 0.0);
    EXPECT_LE(xi, 1.0);
  }
  const Decoded d = decode(g, x);
  EXPECT_FALSE(d.repaired);
  EXPECT_EQ(d.violation, "");
  for (const sim::ParamInfo& info : sim::param_table()) {
    EXPECT_EQ(sim::get_value(d.params, info), sim::get_value(sim::Params{}, info)) << info.name;
  }
}

TEST(Genome, DecodedValuesReloadFromAParamsFileBitForBit) {
  const Genome g = full_genome();
  sim::Rng rng(42);
  for (int trial = 0; trial < 50; ++trial) {
    Vector x(g.dim());
    for (double& xi : x) xi = rng.uniform();
    const Decoded d = decode(g, x);
    if (!d.violation.empty()) continue;
    // decode(encode(decoded)) is a fixed point
    const Decoded again = decode(g, encode(g, d.params));
    std::ostringstream toml;
    sim::write_params_toml(toml, d.params);
    const sim::Params back = sim::parse_params(toml.str(), "decoded.toml");
    for (const sim::ParamInfo& info : sim::param_table()) {
      EXPECT_EQ(sim::get_value(back, info), sim::get_value(d.params, info))
          << info.name << " trial " << trial;
      EXPECT_EQ(sim::get_value(again.params, info), sim::get_value(d.params, info)) << info.name;
    }
  }
}

TEST(Genome, RepairLowersTheDependentThreshold) {
  // theta_soft 90 > theta_hard 60: the soft threshold comes down to the hard one
  const Genome g = genome_of({gene("theta_hard"), gene("theta_soft")});  // row order: hard, soft
  const Decoded d = decode(g, std::vector<double>{0.0, 1.0});
  EXPECT_TRUE(d.repaired);
  EXPECT_EQ(d.violation, "");
  EXPECT_EQ(d.params.theta_hard, 60.0);
  EXPECT_EQ(d.params.theta_soft, 60.0);
  EXPECT_EQ(sim::check_params(d.params), "");
}

TEST(Genome, RepairRaisesTheOtherWhenTheDependentIsNotTuned) {
  // only theta_hard tuned: 60 < base theta_soft 70, so theta_hard is raised to 70
  const Genome g = genome_of({gene("theta_hard")});
  const Decoded d = decode(g, std::vector<double>{0.0});
  EXPECT_TRUE(d.repaired);
  EXPECT_EQ(d.params.theta_hard, 70.0);
  EXPECT_EQ(d.params.theta_soft, 70.0);
  EXPECT_EQ(d.violation, "");
}

TEST(Genome, StrictConstraintKeepsDsubBelowRvis) {
  Gene rvis = gene("R_vis");
  rvis.step = 5;
  const Genome g = genome_of({gene("d_sub"), rvis});
  const Decoded d = decode(g, std::vector<double>{1.0, 0.0});  // d_sub 95, R_vis 80
  EXPECT_TRUE(d.repaired);
  EXPECT_EQ(d.params.r_vis, 90.0);  // first raised for R_keep <= R_vis (R_keep, untuned, is 90)
  EXPECT_EQ(d.params.d_sub, 89.0);  // then one SPEC step (1 cm) below R_vis
  EXPECT_EQ(sim::check_params(d.params), "");
  EXPECT_EQ(d.violation, "");
  // on a grid of step 2 from 40: the largest value below 90 is 88
  Gene dsub = gene("d_sub");
  dsub.step = 2;
  const Decoded e = decode(genome_of({dsub, rvis}), std::vector<double>{1.0, 0.0});
  EXPECT_EQ(e.params.d_sub, 88.0);
}

TEST(Genome, UnrepairableCandidatesKeepTheirViolation) {
  Gene soft = gene("theta_soft");
  soft.lo = 80;
  Gene hard = gene("theta_hard");
  hard.hi = 70;
  const Decoded d = decode(genome_of({hard, soft}), std::vector<double>{0.5, 0.5});  // hard 65, soft 85
  EXPECT_NE(d.violation, "");
  EXPECT_NE(d.violation.find("theta_soft"), std::string::npos) << d.violation;
}

TEST(Genome, DecodeValuesRoundsToTheGridAndRepairs) {
  Gene t0 = gene("T_explore0");
  t0.lo = 200;
  t0.hi = 3000;
  t0.step = 50;
  Gene pt = gene("p_turn");
  pt.lo = 0.002;
  pt.hi = 0.2;
  pt.log = true;
  const Genome g = genome_of({t0, pt});
  const Decoded d = decode_values(g, std::vector<double>{761, 0.0123456789012345});
  EXPECT_EQ(d.params.t_explore0, 750.0);        // 200 + 11 * 50, the nearest grid point
  EXPECT_EQ(d.params.p_turn, 0.0123456789012);  // 12 significant digits, as params files keep
  EXPECT_EQ(decode_values(g, std::vector<double>{5000, 1.0}).params.t_explore0, 3000.0);  // clamped
  // the value a decode of [0,1]^n gives comes back unchanged
  const Decoded x = decode(g, std::vector<double>{0.37, 0.81});
  const Decoded v = decode_values(g, std::vector<double>{x.params.t_explore0, x.params.p_turn});
  EXPECT_EQ(v.params.t_explore0, x.params.t_explore0);
  EXPECT_EQ(v.params.p_turn, x.params.p_turn);
  // cross constraints are repaired as decode() repairs them: theta_soft 90 > theta_hard 60
  const Decoded r =
      decode_values(genome_of({gene("theta_hard"), gene("theta_soft")}), std::vector<double>{60, 90});
  EXPECT_TRUE(r.repaired);
  EXPECT_EQ(r.params.theta_soft, 60.0);
  // a value that is no number is a violation, never simulated
  EXPECT_NE(decode_values(g, std::vector<double>{std::nan(""), 0.01}).violation, "");
}

}  // namespace
}  // namespace swarmpath::evolve
