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
