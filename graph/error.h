#pragma once

#include <stdexcept>
#include <string>

namespace lrsvo {

// Every error the library reports on bad input or an unsolvable problem.
// The message names the place (file and line where there is one).
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An error found while reading a file: carries the file name and 1-based line.
class ParseError : public Error {
 public:
  ParseError(const std::string& file, int line, const std::string& what)
      : Error(file + ":" + std::to_string(line) + ": " + what), file_(file), line_(line) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

}  // namespace lrsvo
