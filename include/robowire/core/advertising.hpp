// robowire/core/advertising.hpp - BLE advertising data: a walk over AD
// structures (length, type, data) that stops cleanly at malformed lengths.
#pragma once

#include "config.hpp"  // first: the C++ version check

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "result.hpp"

namespace robowire::ad {

// AD types used by the protocols here (Bluetooth Assigned Numbers).
inline constexpr std::uint8_t flags = 0x01;
inline constexpr std::uint8_t incomplete_uuid128_list = 0x06;
inline constexpr std::uint8_t complete_uuid128_list = 0x07;
inline constexpr std::uint8_t shortened_local_name = 0x08;
inline constexpr std::uint8_t complete_local_name = 0x09;
inline constexpr std::uint8_t manufacturer_data = 0xFF;

// One AD structure: its type, its data (after the type byte) and the offset
// of its length byte in the advertisement.
struct structure {
    std::uint8_t type = 0;
    std::span<const std::uint8_t> data{};
    std::size_t offset = 0;
};

// ad::reader (below). A template, as find and validate are: a file that
// includes this header but walks no advertisement instantiates no
// std::optional of them. Deferred: void.
template <class Deferred = void>
class basic_reader {
    using structure_t = codec::deferred_t<structure, Deferred>;

public:
    constexpr explicit basic_reader(std::span<const std::uint8_t> ad_data) noexcept : adv_(ad_data) {}

    // The next structure, or nullopt at the end or at a malformed length.
    constexpr std::optional<structure_t> next() noexcept {
        if (done_ || pos_ >= adv_.size()) {
            done_ = true;
            return std::nullopt;
        }
        const std::size_t len = adv_[pos_];
        if (len == 0) {
            done_ = true;
            return std::nullopt;
        }
        if (len > adv_.size() - pos_ - 1) {
            done_ = true;
            error_ = fail(errc::bad_length, pos_);
            return std::nullopt;
        }
        structure_t s{adv_[pos_ + 1], adv_.subspan(pos_ + 2, len - 1), pos_};
        pos_ += 1 + len;
        return s;
    }
    // errc::ok after a clean end; bad_length + offset of the bad length byte otherwise.
    constexpr robowire::error error() const noexcept { return error_; }

    class iterator {
    public:
        using value_type = structure_t;
        using difference_type = std::ptrdiff_t;
        constexpr iterator() noexcept = default;
        constexpr explicit iterator(basic_reader* r) noexcept : r_(r) { ++*this; }
        constexpr const structure_t& operator*() const noexcept { return *cur_; }
        constexpr const structure_t* operator->() const noexcept { return &*cur_; }
        constexpr iterator& operator++() noexcept {
            cur_ = r_->next();
            return *this;
        }
        constexpr void operator++(int) noexcept { ++*this; }
        constexpr bool operator==(std::default_sentinel_t) const noexcept { return !cur_.has_value(); }

    private:
        basic_reader* r_ = nullptr;
        std::optional<structure_t> cur_{};
    };
    // Single pass: begin() continues where the walk is.
    constexpr iterator begin() noexcept { return iterator(this); }
    constexpr std::default_sentinel_t end() const noexcept { return {}; }

private:
    std::span<const std::uint8_t> adv_;
    std::size_t pos_ = 0;
    bool done_ = false;
    robowire::error error_{};
};

// Walks the AD structures of one advertisement or scan response.
// A zero length byte ends the data (the rest is padding). A length that runs
// past the end stops the walk; error() then says where.
using reader = basic_reader<>;

// Data of the first structure of `type`, if any (walk stops at malformed
// data): a std::optional<std::span<const std::uint8_t>>.
template <class Deferred = void>
[[nodiscard]] constexpr auto find(std::span<const std::uint8_t> ad_data, std::uint8_t ad_type) noexcept {
    using found = std::optional<codec::deferred_t<std::span<const std::uint8_t>, Deferred>>;
    basic_reader<Deferred> r(ad_data);
    while (auto s = r.next())
        if (s->type == ad_type) return found(s->data);
    return found();
}

// Number of structures if the whole advertisement is well formed, else the
// error: a result<std::size_t>.
template <class Deferred = void>
[[nodiscard]] constexpr auto validate(std::span<const std::uint8_t> ad_data) noexcept {
    using count = result<codec::deferred_t<std::size_t, Deferred>>;
    basic_reader<Deferred> r(ad_data);
    std::size_t n = 0;
    while (r.next()) ++n;
    if (r.error().code != errc::ok) return count(r.error());
    return count(n);
}

}  // namespace robowire::ad
