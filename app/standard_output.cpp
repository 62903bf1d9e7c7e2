// SPDX-License-Identifier: MIT
#include "standard_output.hpp"

#include <cerrno>
#include <ostream>
#include <system_error>

#include "cli.hpp"

namespace swarmpath::app {

int checked_standard_output(std::ostream& out, std::ostream& err, int code) {
  errno = 0;
  out.flush();
  if (out.good()) return code;
  const int error = errno;
  err << "error: cannot write standard output"
      << (error != 0 ? ": " + std::error_code(error, std::generic_category()).message() : std::string())
      << "\n";
  return kExitFailure;
}

}  // namespace swarmpath::app
