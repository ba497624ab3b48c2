// Compiled, never linked: including every header instantiates no codec. An
// explicit specialization declared after a header had instantiated the
// template does not compile ("specialization after instantiation").
#include <robowire/robowire.hpp>
#include <robowire/ext/fuzz.hpp>  // the fuzz helpers instantiate nothing either

namespace bw = robowire::buwizz3;
namespace nb = robowire::navbot;
namespace osp = robowire::osp;

template <> robowire::result<nb::maneuver> robowire::decode<nb::maneuver>(std::span<const std::uint8_t>) noexcept;
template <> robowire::result<nb::frame> robowire::decode<nb::frame>(std::span<const std::uint8_t>) noexcept;
template <> robowire::error robowire::decode_into<nb::maneuver>(nb::maneuver&, std::span<const std::uint8_t>) noexcept;
template <> robowire::result<robowire::bytes<20>> robowire::encode<nb::maneuver>(const nb::maneuver&) noexcept;
template <> osp::decode_result osp::decode<osp::message>(std::span<const std::uint8_t>) noexcept;
template <> robowire::result<robowire::bytes<10>> osp::encode<osp::message>(const osp::message&) noexcept;
template <> robowire::result<bw::command> bw::decode_command<bw::command>(std::span<const std::uint8_t>) noexcept;
template <> robowire::result<bw::notification> bw::decode_notification<bw::notification>(std::span<const std::uint8_t>) noexcept;
template <> robowire::result<bw::status> robowire::decode<bw::status>(std::span<const std::uint8_t>) noexcept;

// Nor any table, nor a fuzz dictionary (the descriptors of protocols.hpp walk
// no table: every TU that includes robowire.hpp would pay for them).
template <> inline constexpr auto robowire::table_v<bw::status> = table_of(std::type_identity<bw::status>{});
template <> inline constexpr auto robowire::table_v<bw::set_motor_data> = table_of(std::type_identity<bw::set_motor_data>{});
template <> inline constexpr auto robowire::table_v<osp::obp1::voltage> = table_of(std::type_identity<osp::obp1::voltage>{});
template <> inline constexpr auto robowire::table_v<osp::frame> = table_of(std::type_identity<osp::frame>{});
template <> inline constexpr auto robowire::fuzz_tokens_v<osp::message> = std::array<robowire::fuzz_token, 0>{};

// Nor osp::decode_result, nor the variant of every OSP message it holds.
template <> class robowire::result<osp::message>;
// Nor any advertisement walk (ad::reader, ad::find, BuWizz3's and NAVBOT's parsers).
template <> class std::optional<robowire::ad::structure>;
template <> class robowire::result<std::optional<bw::advertisement>>;
