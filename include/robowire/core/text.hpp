// robowire/core/text.hpp - text<N>: up to N chars stored inline, NUL-padded on the wire.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <array>
#include <cstddef>
#include <string_view>

#include "result.hpp"

namespace robowire {

template <std::size_t N>
class text {
public:
    constexpr text() noexcept = default;
    // From a string literal; one longer than N does not compile.
    template <std::size_t M>
    requires(M - 1 <= N) consteval text(const char (&literal)[M]) noexcept { assign(std::string_view(literal, M - 1)); }
    // From any string; value_out_of_range (offset N) if it is longer than N.
    static constexpr result<text> make(std::string_view s) noexcept {
        text t;
        if (!t.assign(s)) return fail(errc::value_out_of_range, N);
        return t;
    }

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
    template <std::size_t M>
    friend constexpr bool operator==(const text& a, const char (&b)[M]) noexcept {
        return a.view() == std::string_view(b, M - 1);
    }

private:
    std::array<char, N> data_{};
    std::size_t size_ = 0;
};

}  // namespace robowire
