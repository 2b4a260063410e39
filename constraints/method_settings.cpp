// A constraint method's own settings, and methods made from a specification
// "name[:setting=value,...]".
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

#include "lrsvo/constraints/constraint_method.h"
#include "lrsvo/graph/error.h"
#include "lrsvo/graph/registry.h"

namespace lrsvo {
namespace {

// The whole of `text` as a number of type T, or false.
template <typename T>
bool parseWhole(const std::string& text, T& value) {
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  return error == std::errc() && stop == end && !text.empty();
}

std::string settingNames(const std::vector<MethodSetting>& settings) {
  if (settings.empty()) return "this method has no settings";
  std::string names = "settings: ";
  for (std::size_t k = 0; k < settings.size(); ++k) names += (k ? ", " : "") + settings[k].name;
  return names;
}

}  // namespace

std::string MethodSetting::valueText() const {
  char text[32];
  const auto end = std::visit([&](auto* v) { return std::to_chars(text, text + sizeof text, *v).ptr; }, value);
  return std::string(text, end);
}

void ConstraintMethod::declare(std::string name, double* value, std::string description) {
  ownSettings_.push_back({std::move(name), std::move(description), value});
}

void ConstraintMethod::declare(std::string name, int* value, std::string description) {
  ownSettings_.push_back({std::move(name), std::move(description), value});
}

void ConstraintMethod::set(const std::string& name, const std::string& value) {
  for (const MethodSetting& setting : ownSettings_) {
    if (setting.name != name) continue;
    if (double* const* real = std::get_if<double*>(&setting.value)) {
      double parsed = 0.0;
      if (!parseWhole(value, parsed) || !std::isfinite(parsed))
        throw Error("setting " + name + " needs a finite number, not '" + value + "'");
      **real = parsed;
    } else {
      int parsed = 0;
      if (!parseWhole(value, parsed)) throw Error("setting " + name + " needs an integer, not '" + value + "'");
      *std::get<int*>(setting.value) = parsed;
    }
    return;
  }
  throw Error("unknown setting '" + name + "' (" + settingNames(ownSettings_) + ")");
}

std::string constraintMethodName(const std::string& specification) {
  return specification.substr(0, specification.find(':'));
}

std::unique_ptr<ConstraintMethod> makeConstraintMethod(const std::string& specification) {
  const std::string name = constraintMethodName(specification);
  std::unique_ptr<ConstraintMethod> method;
  try {
    method = Registry<ConstraintMethod>::instance().create(name);
  } catch (const Error& e) {
    throw Error("constraint method: " + std::string(e.what()));
  }
  if (name.size() == specification.size()) return method;
  const std::string list = specification.substr(name.size() + 1);
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    const std::size_t equals = item.find('=');
    try {
      if (equals == std::string::npos || equals == 0)
        throw Error("'" + item + "' is not setting=value (" + settingNames(method->ownSettings()) + ")");
      method->set(item.substr(0, equals), item.substr(equals + 1));
    } catch (const Error& e) {
      throw Error("constraint method '" + specification + "': " + e.what());
    }
    start = comma + 1;
  }
  return method;
}

}  // namespace lrsvo
