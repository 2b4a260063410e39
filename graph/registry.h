#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "graph/error.h"

namespace lrsvo {

// A name -> factory table, g2o style. Each plugin registers itself from its own
// source file with a static Registrar, so adding one touches no other file.
template <typename Product>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>()>;

  struct Entry {
    Factory factory;
    std::string description;
  };

  static Registry& instance() {
    static Registry registry;
    return registry;
  }

  void add(const std::string& name, Factory factory, std::string description) {
    entries_[name] = Entry{std::move(factory), std::move(description)};
  }

  bool contains(const std::string& name) const { return entries_.count(name) > 0; }

  std::unique_ptr<Product> create(const std::string& name) const {
    auto it = entries_.find(name);
    if (it == entries_.end()) {
      std::string known;
      for (const auto& [key, entry] : entries_) known += (known.empty() ? "" : ", ") + key;
      throw Error("unknown name '" + name + "' (known: " + known + ")");
    }
    return it->second.factory();
  }

  const std::map<std::string, Entry>& entries() const { return entries_; }

 private:
  std::map<std::string, Entry> entries_;
};

template <typename Product>
struct Registrar {
  Registrar(const std::string& name, typename Registry<Product>::Factory factory, std::string description = {}) {
    Registry<Product>::instance().add(name, std::move(factory), std::move(description));
  }
};

}  // namespace lrsvo

#define LRSVO_CONCAT_INNER(a, b) a##b
#define LRSVO_CONCAT(a, b) LRSVO_CONCAT_INNER(a, b)

// Registers `Type` (default-constructible, derived from `Base`) under `name`.
#define LRSVO_REGISTER(Base, Type, name, description)                             \
  static const ::lrsvo::Registrar<Base> LRSVO_CONCAT(lrsvo_registrar_, __LINE__)( \
      name, [] { return std::unique_ptr<Base>(new Type()); }, description)

// Registers a vertex or edge type for graph files under its kTypeTag.
#define LRSVO_REGISTER_TYPE(Base, Type) LRSVO_REGISTER(Base, Type, Type::kTypeTag, #Type)
