// The per-message loop of every protocol's tests, driven by its variant.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <span>
#include <variant>

#include "each_message.hpp"

namespace test {

// Every alternative of Variant, default-constructed and filled(), encodes,
// decodes back through the protocol's dispatcher to the same alternative and
// value, and re-encodes to the same bytes.
template <class Variant, class Encode, class Decode>
void check_each_round_trips(Encode encode, Decode decode) {
    robowire::for_each_alternative<Variant>([&](auto t) {
        using M = typename decltype(t)::type;
        int which = 0;
        for (const M& x : {M{}, filled<M>()}) {
            INFO(robowire::table_v<M>.name << (which++ ? ", filled" : ", default"));
            const Variant v{std::in_place_type<M>, x};
            const auto wire = encode(v);
            INFO("encode: error " << static_cast<int>(wire.code()) << " at offset " << (wire ? 0U : wire.error().offset));
            REQUIRE(wire);
            const auto back = decode(std::span<const std::uint8_t>(wire->data(), wire->size()));
            REQUIRE(back);
            CHECK(back->index() == v.index());
            CHECK(*back == v);
            const auto again = encode(*back);
            REQUIRE(again);
            CHECK(robowire::equal_bytes(*again, *wire));
        }
    });
}

}  // namespace test
