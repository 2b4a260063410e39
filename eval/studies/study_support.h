#pragma once

// Small helpers the paper's studies share (eval/studies/*.cpp).

#include <cmath>
#include <cstdio>
#include <string>

namespace lrsvo::study_support {

inline double degrees(double radians) { return radians * 180.0 / M_PI; }
inline double radians(double degrees) { return degrees * M_PI / 180.0; }

// printf-style formatting into a string (GCC 12 has no std::format).
template <typename... Args>
std::string format(const char* pattern, Args... args) {
  const int size = std::snprintf(nullptr, 0, pattern, args...);
  std::string text(static_cast<std::size_t>(size), '\0');
  std::snprintf(text.data(), text.size() + 1, pattern, args...);
  return text;
}

}  // namespace lrsvo::study_support
