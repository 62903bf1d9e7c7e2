// SPDX-License-Identifier: MIT
#include "job.hpp"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <mpi.h>
#include <ostream>
#include <string>
#include <unistd.h>
#include <vector>

#include "evolve/mpi/channel.hpp"
#include "evolve/mpi/mpi_evaluator.hpp"
#include "evolve/mpi/worker.hpp"
#include "sim/step.hpp"

namespace swarmpath::mpi {

namespace {

// A small run in memory that every rank makes at start: its state hashes must agree, or the ranks
// would not compute the same bits (another CPU whose maths library takes other code paths, another
// build of swarmpath or of Box2D).
std::uint64_t reference_hash() {
  const sim::Scenario s = sim::parse_scenario(
      "name = \"mpi_reference\"\nclass = \"obstacle\"\nnest = [-2.0, 0.0]\ngoal = [2.0, 0.5]\n"
      "[arena]\nsize = [7.0, 4.0]\n[[cylinder]]\ncenter = [0.0, 0.0]\nradius = 0.4\n"
      "[deployment]\nsize = [1.2, 1.2]\nrobots = 12\n[simulation]\nmax_ticks = 300\n",
      "mpi_reference.toml");
  std::uint64_t h = 0;
  for (const sim::Mode mode : {sim::Mode::kPathFormation, sim::Mode::kTaskAllocation}) {
    h = h * 1099511628211ULL ^ sim::evaluate(sim::Params{}, s, mode, 20240611).state_hash;
  }
  return h;
}

int slurm_tasks() {
  const char* n = std::getenv("SLURM_STEP_NUM_TASKS");
  return n ? std::atoi(n) : 0;
}

// what rank 0 knows of every rank: its reference hash, its host and that host's cores
struct Ranks {
  std::vector<std::uint64_t> hashes;
  std::vector<std::string> hosts;
  std::vector<int> cores;
};

Ranks gather_ranks(int rank, int size) {
  const std::uint64_t mine = reference_hash();
  const auto n = static_cast<std::size_t>(rank == 0 ? size : 0);
  std::vector<std::uint64_t> hashes(n);
  MPI_Gather(&mine, 1, MPI_UINT64_T, hashes.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  const int cores = static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  std::vector<int> all_cores(n);
  MPI_Gather(&cores, 1, MPI_INT, all_cores.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  char host[MPI_MAX_PROCESSOR_NAME] = {};
  int length = 0;
  MPI_Get_processor_name(host, &length);
  std::vector<char> names(n * MPI_MAX_PROCESSOR_NAME);
  MPI_Gather(host, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, names.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR, 0,
             MPI_COMM_WORLD);
  Ranks out{std::move(hashes), {}, std::move(all_cores)};
  for (std::size_t r = 0; r < n; ++r) {
    const char* h = names.data() + r * MPI_MAX_PROCESSOR_NAME;
    out.hosts.emplace_back(h, strnlen(h, MPI_MAX_PROCESSOR_NAME));
  }
  return out;
}

// the ranks whose reference hash differs from rank 0's, or ""
std::string disagreeing_ranks(const Ranks& ranks) {
  std::string bad;
  for (std::size_t r = 1; r < ranks.hashes.size(); ++r) {
    if (ranks.hashes[r] == ranks.hashes[0]) continue;
    bad += (bad.empty() ? "" : ", ") + std::to_string(r) + " (" + ranks.hosts[r] + ")";
  }
  if (!bad.empty()) bad += " against rank 0 (" + ranks.hosts[0] + ")";
  return bad;
}

// a warning for each host that runs more simulation threads than it has cores
std::string crowded_hosts(const Ranks& ranks, int threads) {
  std::map<std::string, std::pair<int, int>> hosts;  // host: ranks, cores
  for (std::size_t r = 0; r < ranks.hosts.size(); ++r) {
    auto& [count, cores] = hosts[ranks.hosts[r]];
    ++count;
    cores = ranks.cores[r];
  }
  std::string out;
  for (const auto& [host, rc] : hosts) {
    const auto [count, cores] = rc;
    if (count * threads <= cores) continue;
    out += "warning: " + host + " runs " + std::to_string(count) + " MPI ranks x " + std::to_string(threads) +
           (threads == 1 ? " thread on " : " threads on ") + std::to_string(cores) +
           " cores: they take turns (results are the same); give --threads so that ranks per node x "
           "threads <= cores\n";
  }
  return out;
}

void stop_workers(int size) {
  Outbox outbox;
  for (int r = 1; r < size; ++r) outbox.send(r, kStop, Bytes{});
  outbox.flush();
}

}  // namespace

int rank_count() {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(v)) return true;
  }
  return false;
}

int run_job(int& argc, char**& argv, const RankZeroMain& main, std::ostream& err, TaskRunner runner) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (provided < MPI_THREAD_FUNNELED) {
    if (rank == 0) err << "error: this MPI library does not allow threads (MPI_THREAD_FUNNELED)\n";
    MPI_Finalize();
    return 1;
  }
  // a launcher that started several tasks, each of which MPI sees alone
  if (size == 1 && slurm_tasks() > 1) {
    err << "error: srun started " << slurm_tasks()
        << " tasks but MPI sees one: each would run the whole job and write the same files; start "
           "them with 'srun --mpi=pmix' (see 'srun --mpi=list'), or with mpirun inside the allocation\n";
    MPI_Finalize();
    return 2;
  }

  int code = 0;
  try {
    const Ranks ranks = gather_ranks(rank, size);
    if (rank == 0) {
      const std::string bad = disagreeing_ranks(ranks);
      if (!bad.empty()) {
        err << "error: MPI ranks " << bad
            << " compute other bits on a reference run: their CPUs or libraries differ, so results would "
               "depend on which rank ran what; run on nodes of one kind with one build of swarmpath\n";
        code = 1;
      } else {
        code = main([&](int threads) -> std::unique_ptr<evolve::BatchEvaluator> {
          if (size == 1) return std::make_unique<evolve::ThreadPool>(threads);
          err << crowded_hosts(ranks, threads);
          return std::make_unique<MpiEvaluator>(size, threads, runner, threads);
        });
      }
      stop_workers(size);
    } else {
      serve(rank, runner);
    }
  } catch (const std::exception& e) {
    err << "error: MPI rank " << rank << ": " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return code;
}

}  // namespace swarmpath::mpi
