#include "load/shape_parsers.h"

#include <type_traits>
#include <utility>
#include <variant>

namespace raycast {

namespace {

// CSG trees and instances have no key of their own: the loader builds them from `csg:` and `use:`.
template <class T>
constexpr bool kHasShapeKey = !std::is_same_v<T, CsgShape> && !std::is_same_v<T, InstanceShape>;

template <std::size_t... I>
std::map<std::string, ShapeParser> make_shape_parsers(std::index_sequence<I...>) {
  std::map<std::string, ShapeParser> table;
  const auto add = [&table]<class T>(std::type_identity<T>) {
    if constexpr (kHasShapeKey<T>)
      table.emplace(
          T::kName, +[](Fields& f) { return parse_shape(std::type_identity<T>{}, f); });
  };
  (add(std::type_identity<std::variant_alternative_t<I, ShapeVariant>>{}), ...);
  table.emplace("height_field", &parse_height_field);
  return table;
}

}  // namespace

const std::map<std::string, ShapeParser>& shape_parsers() {
  static const std::map<std::string, ShapeParser> table =
      make_shape_parsers(std::make_index_sequence<std::variant_size_v<ShapeVariant>>{});
  return table;
}

}  // namespace raycast
