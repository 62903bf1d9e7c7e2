// SPDX-License-Identifier: MIT
// Standard output is an output like any file: run_cli flushes it after every command and checks
// it, so that `swarmpath ... > file` on a full disk (or into a closed pipe) never exits 0.
#pragma once

#include <iosfwd>

namespace swarmpath::app {

/// Flushes `out` and checks it: when any write to it failed, says so on `err` ("cannot write
/// standard output") and returns kExitFailure; otherwise returns `code`.
int checked_standard_output(std::ostream& out, std::ostream& err, int code);

}  // namespace swarmpath::app
