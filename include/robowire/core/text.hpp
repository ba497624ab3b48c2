// robowire/core/text.hpp - text<N>: up to N chars stored inline, NUL-padded on the wire.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace robowire {

template <std::size_t N>
class text {
public:
    constexpr text() noexcept = default;
    // Precondition: s.size() <= N (longer input is cut; use make() to check).
    constexpr text(std::string_view s) noexcept { assign(s); }
    constexpr text(const char* s) noexcept : text(std::string_view(s)) {}

    // false (and no change) if s is longer than N.
    constexpr bool assign(std::string_view s) noexcept {
        if (s.size() > N) return false;
        data_ = {};
        for (std::size_t i = 0; i < s.size(); ++i) data_[i] = s[i];
        size_ = s.size();
        return true;
    }

    static constexpr std::size_t capacity() noexcept { return N; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr const char* data() const noexcept { return data_.data(); }
    constexpr std::string_view view() const noexcept { return {data_.data(), size_}; }
    constexpr operator std::string_view() const noexcept { return view(); }

    friend constexpr bool operator==(const text& a, const text& b) noexcept { return a.view() == b.view(); }
    friend constexpr bool operator==(const text& a, std::string_view b) noexcept { return a.view() == b; }

private:
    std::array<char, N> data_{};
    std::size_t size_ = 0;
};

}  // namespace robowire
