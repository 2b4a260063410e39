#pragma once

#include <exception>
#include <string>

namespace lrsvo::cli {

// The one line `lrsvo` prints when a failure ends a subcommand: which
// subcommand, what kind of failure and its message on one line, for every
// exception the libraries and their dependencies throw (lrsvo::Error, OpenCV,
// the file system, JSON, memory, any other std::exception, anything else).
// `command` is the subcommand's name (empty before one was chosen).
std::string failureLine(const std::string& command, std::exception_ptr failure);

}  // namespace lrsvo::cli
