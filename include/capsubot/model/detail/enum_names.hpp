#pragma once
// The one way an enum of the library gets its stable name ("ok", "left_wall", ...): a table
// with one entry per enumerator, in the enum's order, whose size the caller checks against the
// enum's count with a static_assert next to the table.

#include <cstddef>

namespace capsubot::detail {

/// names[value], or "unknown" for a value outside the table.
template <class Enum, std::size_t N>
const char* EnumName(const char* const (&names)[N], Enum value) {
  const auto i = static_cast<std::size_t>(value);
  return i < N ? names[i] : "unknown";
}

}  // namespace capsubot::detail
