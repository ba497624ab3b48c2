// OSP: decode of any frame (dispatch), every encoder, the stream scanner, serve().
#include <robowire/osp.hpp>

#include "harness.hpp"

namespace osp = robowire::osp;

#if defined(__arm__) || defined(__riscv)
static_assert(ROBOWIRE_OPTIMIZE_SIZE == 1 && ROBOWIRE_ARRAY_LOOPS == 1 && ROBOWIRE_COPY_RUNS == 1,
              "docs/footprint.md states these settings for -Os on both Cortex-M cores and rv32imc");
#endif

ENTRY void osp_decode(const std::uint8_t* p, std::size_t n) {
    const auto m = osp::decode({p, n});
    sink = m ? static_cast<std::uint32_t>(m->index()) : static_cast<std::uint32_t>(m.code());
}
// Alternative `which` of the variant (the protocol's one list), its integer
// and enum fields set from `value` (invalid codes too: encode rejects them).
// `which` is clamped, not taken modulo: no division routine in the program.
template <std::size_t... I>
osp::message make_message(std::size_t which, std::uint16_t value, std::index_sequence<I...>) {
    osp::message m;
    ((which == I ? (void)m.emplace<I>() : void()), ...);
    std::visit([value](auto& x) {
        robowire::for_each_field<std::remove_cvref_t<decltype(x)>>([&](const auto& f) {
            auto& member = x.*f.member;
            using T = std::remove_cvref_t<decltype(member)>;
            if constexpr (std::is_integral_v<T> || std::is_enum_v<T>) member = static_cast<T>(value);
        });
    }, m);
    return m;
}
ENTRY void osp_encode(std::size_t which, std::uint16_t value) {
    constexpr std::size_t n = std::variant_size_v<osp::message>;
    const osp::message m = make_message(which < n ? which : n - 1, value, std::make_index_sequence<n>{});
    const auto r = osp::encode(m);
    if (r) out(*r);
}
osp::scanner scanner_state;
// docs/osp.md, "The scanner": 40 bytes on a 32-bit core under ROBOWIRE_OPTIMIZE_SIZE, else 48.
static_assert(sizeof(void*) != 4 || sizeof(osp::scanner) == (ROBOWIRE_OPTIMIZE_SIZE ? 40 : 48));
ENTRY void osp_scan(const std::uint8_t* p, std::size_t n) {
    scanner_state.feed({p, n}, [](osp::scanner::frame_bytes f) { osp_decode(f.data(), f.size()); });
}
struct battery {
    osp::obp1::soc operator()(const osp::obp1::request_soc&) const { return {static_cast<std::uint16_t>(sink)}; }
    osp::obp1::voltage operator()(const osp::obp1::request_voltage&) const { return {static_cast<std::int16_t>(sink)}; }
};
ENTRY void osp_serve(const std::uint8_t* p, std::size_t n) {
    const auto a = osp::serve({p, n}, battery{});
    if (a && *a) out(**a);
}

int main() {
    const auto in = read_input<160>();
    const std::size_t n = size_in(160);
    osp_decode(in.data(), n);
    osp_encode(in[0], static_cast<std::uint16_t>(in[1] | in[2] << 8));
    osp_scan(in.data(), n);
    osp_serve(in.data(), n);
    return 0;
}
