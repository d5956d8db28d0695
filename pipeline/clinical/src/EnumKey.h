#pragma once
// The reverse of an enumeration's toString(): the keys are few, so a linear search over its k* array.

#include <array>
#include <cstddef>
#include <string_view>

namespace hs::clinical::detail {

template <class E, std::size_t N>
bool enumFromKey(std::string_view key, const std::array<E, N>& values, E& out) {
    for (const E value : values) {
        if (toString(value) == key) {
            out = value;
            return true;
        }
    }
    return false;
}

} // namespace hs::clinical::detail
