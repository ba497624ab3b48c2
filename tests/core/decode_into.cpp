// decode_into leaves its output exactly as it was on every error: every
// message of every protocol, every input length from 0 to its largest plus
// one, random contents and one-byte changes of a valid frame; the object is
// compared byte for byte (padding included) and with ==. On success the
// object equals decode()'s message. This file runs in every build mode of the
// unit tests (-O0 under the sanitizers, -O3, -Os, ROBOWIRE_ARRAY_LOOPS=2,
// -fno-exceptions), with g++ and clang++.
#include <robowire/robowire.hpp>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>

#include "each_message.hpp"

namespace {

struct rng {
    std::uint32_t s = 0x2545F491u;
    std::uint32_t next() {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        return s;
    }
    std::uint8_t byte() { return static_cast<std::uint8_t>(next()); }
};

// The object's bytes are read from memory as they are: padding bytes are
// indeterminate to the compiler, which may otherwise give two reads of them
// two different values.
inline void escape(void* p) { asm volatile("" : : "r"(p) : "memory"); }

struct tally {
    std::size_t errors = 0, successes = 0, changed = 0, wrong_value = 0;
    std::string first;
};

template <class M>
void check_message(tally& t, rng& r) {
    constexpr std::size_t max = robowire::table_v<M>.max_input();
    constexpr std::size_t cap = max < 300 ? max + 1 : 300;  // navbot text: every length up to 300
    const M sentinel = test::filled<M>();
    std::array<std::uint8_t, 512> valid{};
    if (const auto enc = robowire::encode(sentinel)) std::memcpy(valid.data(), enc->data(), enc->size());
    for (std::size_t n = 0; n <= cap; ++n) {
        for (int trial = 0; trial < 48; ++trial) {
            std::array<std::uint8_t, 512> in{};
            if (trial < 16) {  // random bytes
                for (std::size_t i = 0; i < n; ++i) in[i] = r.byte();
            } else {  // the valid frame, one or two bytes changed
                in = valid;
                if (n > 0) in[r.next() % n] = r.byte();
                if (n > 0 && trial % 2) in[r.next() % n] = r.byte();
            }
            const std::span<const std::uint8_t> bytes(in.data(), n);
            M obj = sentinel;
            std::array<unsigned char, sizeof(M)> before{}, after{};
            escape(&obj);
            std::memcpy(before.data(), static_cast<const void*>(&obj), sizeof(M));
            const robowire::error e = robowire::decode_into(obj, bytes);
            escape(&obj);
            std::memcpy(after.data(), static_cast<const void*>(&obj), sizeof(M));
            if (e.code != robowire::errc::ok) {
                ++t.errors;
                if (before != after || !(obj == sentinel)) {
                    if (t.changed++ == 0)
                        t.first = std::string(robowire::table_v<M>.name) + " n=" + std::to_string(n) + ": " +
                                  std::string(robowire::to_string(e.code));
                }
            } else {
                ++t.successes;
                const auto d = robowire::decode<M>(bytes);
                if (!d) {
                    ++t.wrong_value;
                } else if (!(*d == obj)) {  // NaN floats are unequal to themselves: compare their encodings
                    const auto a = robowire::encode(*d), b = robowire::encode(obj);
                    if (!a || !b || !std::equal(a->begin(), a->end(), b->begin(), b->end())) ++t.wrong_value;
                }
            }
        }
    }
}

template <class Variant>
tally check_variant() {
    tally t;
    rng r;
    robowire::for_each_alternative<Variant>([&](auto a) { check_message<typename decltype(a)::type>(t, r); });
    return t;
}

}  // namespace

TEST_CASE("decode_into leaves the object as it was on every error", "[decode_into][core]") {
    for (const auto& [name, t] : {std::pair{"buwizz3::command", check_variant<robowire::buwizz3::command>()},
                                  std::pair{"buwizz3::notification", check_variant<robowire::buwizz3::notification>()},
                                  std::pair{"navbot::message", check_variant<robowire::navbot::message>()},
                                  std::pair{"osp::message", check_variant<robowire::osp::message>()}}) {
        INFO(name << ": " << t.errors << " errors, " << t.successes << " decoded; first change: " << t.first);
        CHECK(t.errors > 1000);
        CHECK(t.successes > 0);
        CHECK(t.changed == 0);
        CHECK(t.wrong_value == 0);
    }
}
