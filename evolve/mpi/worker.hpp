// SPDX-License-Identifier: MIT
// What a rank other than 0 does: wait for a batch, run the tasks rank 0 sends it on its threads,
// send each result back as soon as it is ready, until rank 0 says stop.
#pragma once

#include "evolve/mpi/job.hpp"

namespace swarmpath::mpi {

/// Serves rank 0's batches until it sends kStop; `rank` is this rank (for the fault hook).
void serve(int rank, TaskRunner runner);

}  // namespace swarmpath::mpi
