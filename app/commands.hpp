// SPDX-License-Identifier: MIT
// The subcommands. Each one registers its options on a CLI11 subcommand and returns a runner
// that the dispatcher calls once parsing succeeded.
#pragma once

#include <functional>
#include <iosfwd>

#include "evolve/batch.hpp"

namespace CLI {
class App;
}

namespace swarmpath::app {

using Runner = std::function<int(std::ostream& out, std::ostream& err)>;

Runner add_simulate(CLI::App& app);
Runner add_astar(CLI::App& app);
// the commands that run batches of simulations run them on what `evaluators` makes
Runner add_table(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_ablate(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_evolve(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_evaluate(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_robustness(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_export(CLI::App& app);
Runner add_arena(CLI::App& app);
Runner add_view(CLI::App& app);
Runner add_report(CLI::App& app);
Runner add_benchmark(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_verify(CLI::App& app, const evolve::EvaluatorFactory& evaluators);
Runner add_irace(CLI::App& app);

}  // namespace swarmpath::app
