#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lrsvo/graph/error.h"

namespace lrsvo {

// A name -> factory table, g2o style. A library's own plugins are added by
// Product::addBuiltins(Registry&) when the product declares it (solvers,
// algorithms, kernels, constraint methods), on the registry's first use; the
// vertex and edge types of graph files by each library's explicit
// register*Types() call. Both are plain calls, so a static link keeps every
// plugin. A program may also register its own from a source file of its own
// with LRSVO_REGISTER (a static initialiser: reliable in the program's own
// objects, not in a static library's, which the linker drops when unnamed).
template <typename Product>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>()>;

  struct Entry {
    Factory factory;
    std::string description;
  };

  static Registry& instance() {
    static Registry registry = [] {
      Registry builtins;
      if constexpr (requires { Product::addBuiltins(builtins); }) Product::addBuiltins(builtins);
      return builtins;
    }();
    return registry;
  }

  void add(const std::string& name, Factory factory, std::string description) {
    entries_[name] = Entry{std::move(factory), std::move(description)};
  }

  // Adds the default-constructible Type (derived from Product) under name.
  template <typename Type>
  void addType(const std::string& name, std::string description) {
    add(
        name, [] { return std::unique_ptr<Product>(new Type()); }, std::move(description));
  }

  bool contains(const std::string& name) const { return entries_.count(name) > 0; }

  std::unique_ptr<Product> create(const std::string& name) const {
    auto it = entries_.find(name);
    if (it == entries_.end()) throw Error("unknown name '" + name + "' (known: " + names() + ")");
    return it->second.factory();
  }

  // The registered names, comma-separated.
  std::string names() const {
    std::string known;
    for (const auto& [key, entry] : entries_) known += (known.empty() ? "" : ", ") + key;
    return known;
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
#define LRSVO_REGISTER(Base, Type, name, description)                                \
  static const ::lrsvo::Registrar<Base> LRSVO_CONCAT(lrsvo_registrar_, __COUNTER__)( \
      name, [] { return std::unique_ptr<Base>(new Type()); }, description)

// Registers a vertex or edge type for graph files under its kTypeTag.
#define LRSVO_REGISTER_TYPE(Base, Type) LRSVO_REGISTER(Base, Type, Type::kTypeTag, #Type)

// Adds a vertex or edge type to a registry under its kTypeTag (a library's register*Types()).
#define LRSVO_ADD_TYPE(registry, Type) (registry).template addType<Type>(Type::kTypeTag, #Type)
