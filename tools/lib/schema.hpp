// The protocols' tables as one JSON document (nlohmann/json): what
// `robowire list --json` prints and `robowire.schema()` returns in Python.
// Built from table_v, enum_table_v and flag_bits_v of each protocol's
// std::variant of messages and from its descriptor, so a message added to a
// protocol appears here with no change. The format, and the rules a decoder
// in another language follows to give what `decode --json` gives:
// docs/cli.md (list). The JavaScript package is generated from it (js/gen).
#pragma once

#include <robowire/core/fields.hpp>
#include <robowire/core/flag_bits.hpp>
#include <robowire/core/table.hpp>
#include <robowire/reflect.hpp>
#include <robowire/robowire.hpp>

#include <nlohmann/json.hpp>

#include <robowire/buwizz3/protocol.hpp>
#include <robowire/navbot/protocol.hpp>
#include <robowire/osp/protocol.hpp>

#include <initializer_list>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace robowire::schema {

using json = nlohmann::ordered_json;

inline constexpr int format_version = 1;
// Version 2: key_offsets, bool ranges, physical names, raw_is_physical,
// characteristics, direction rules, output and error-line rules, and the
// unit helpers' rounding (unit_helpers).
inline constexpr int schema_version = 2;

// Name of an error code as the schema and the Python package spell it
// (robowire::errc_table, which also gives the count).
constexpr std::string_view errc_name(errc e) noexcept { return robowire::name_of(e); }

template <class F>
using element_t = typename F::element_type;

// The kind of Python / JSON value a field's element decodes to.
template <class F>
constexpr std::string_view value_kind() noexcept {
    using E = element_t<F>;
    if constexpr (F::kind == wire_kind::record) return "record";
    else if constexpr (F::kind == wire_kind::text) return "text";
    else if constexpr (F::kind == wire_kind::tail) return "bytes";
    else if constexpr (std::is_enum_v<E>) return "enum";
    else if constexpr (std::is_same_v<E, bool>) return "bool";
    else if constexpr (std::is_floating_point_v<E>) return "float";
    else return "int";
}

template <class M>
json fields_of();

template <class M, class F>
json field_of(const F& f) {
    using E = element_t<F>;
    json j = {
        {"name", f.name},    {"offset", f.offset},   {"type", to_string(F::kind)}, {"value", value_kind<F>()},
        {"count", F::count}, {"array", F::is_array}, {"optional", F::is_optional}, {"element_size", F::element_size},
        {"size", F::size}};
    if constexpr (F::kind == wire_kind::bits) j["bits"] = {{"lo", F::wire_type::lo}, {"width", F::wire_type::width}};
    const bool ranged = value_kind<F>() == "int" || value_kind<F>() == "bool";
    j["valid"] = ranged ? json{{"min", f.valid.min}, {"max", f.valid.max}} : json(nullptr);
    j["unit"] = f.unit.name.empty() ? json(nullptr)
                                    : json{{"name", f.unit.name},
                                           {"scale", f.unit.scale},
                                           {"offset", f.unit.offset},
                                           {"raw_is_physical", f.unit.raw_is_physical}};
    // the decoded physical value's key (integer fields with a unit): "x_raw" -> "x", else "x_physical"
    if (value_kind<F>() == "int" && !f.unit.name.empty()) {
        const std::string_view n = f.name;
        const bool raw = n.size() > 4 && n.substr(n.size() - 4) == "_raw";
        j["physical"] = raw ? std::string(n.substr(0, n.size() - 4)) : std::string(n) + "_physical";
    } else {
        j["physical"] = nullptr;
    }
    if constexpr (std::is_enum_v<E>) {
        json values = json::array();
        for (const auto& e : enum_table_v<E>)
            values.push_back({{"name", e.name}, {"value", static_cast<std::int64_t>(e.value)}});
        j["enum"] = std::move(values);
    }
    if constexpr (has_flag_bits<M>) {
        json bits = json::array();
        for_each_flag_bit<M>(f.name, [&](const flag_bit& b) {
            json values = json::array();
            for (std::size_t v = 0; v < flag_value_count(b); ++v) values.push_back(b.values[v]);
            bits.push_back({{"lo", b.lo}, {"width", b.width}, {"name", b.name}, {"values", std::move(values)}});
        });
        if (!bits.empty()) j["flag_bits"] = std::move(bits);
    }
    if constexpr (F::kind == wire_kind::text || F::kind == wire_kind::tail) j["capacity"] = E::capacity();
    if constexpr (F::kind == wire_kind::record)
        j["record"] = {{"name", table_v<E>.name}, {"size", table_v<E>.max_size()}, {"fields", fields_of<E>()}};
    return j;
}

template <class M>
json fields_of() {
    json out = json::array();
    for_each_field<M>([&](const auto& f) { out.push_back(field_of<M>(f)); });
    return out;
}

template <class M>
json message_of(std::string_view direction, std::initializer_list<std::size_t> key_offsets) {
    constexpr auto& t = table_v<M>;
    json fixed = json::array(), key = json::array();
    for (const auto& b : t.fixed)
        fixed.push_back({{"offset", b.offset}, {"value", b.value}, {"error", errc_name(b.code)}});
    for (const std::size_t o : key_offsets)  // the bytes the dispatcher reads, at the protocol's key_offsets
        for (const auto& b : t.fixed)
            if (b.offset == o) key.push_back(b.value);
    json lengths = json::array();
    constexpr auto& runs = detail::length_runs_v<M>;
    for (std::size_t i = 0; i < runs.count; ++i) lengths.push_back({runs.run[i][0], runs.run[i][1]});
    return {{"name", t.name},
            {"direction", direction.empty() ? json(nullptr) : json(direction)},
            {"key", std::move(key)},
            {"fixed", std::move(fixed)},
            {"lengths", std::move(lengths)},
            {"min_size", t.min_size()},
            {"max_size", t.max_size()},
            {"max_input", t.max_input()},
            {"fields", fields_of<M>()}};
}

// Appends every alternative of variant V to `messages`.
template <class V>
void add_messages(json& messages, std::initializer_list<std::size_t> key_offsets, std::string_view direction = {}) {
    for_each_alternative<V>(
        [&](auto t) { messages.push_back(message_of<typename decltype(t)::type>(direction, key_offsets)); });
}

inline std::string_view carries_name(gatt_direction d) {
    switch (d) {
    case gatt_direction::to_device: return "to_device";
    case gatt_direction::from_device: return "from_device";
    default: return "both";
    }
}
inline std::string_view stream_name(stream_kind k) {
    switch (k) {
    case stream_kind::scanner: return "scanner";
    case stream_kind::reassembler: return "reassembler";
    default: return "none";
    }
}

// One protocol's entry, around its messages (add_messages): key_offsets are
// the bytes its dispatcher reads (a message's "key" holds its values there).
inline json protocol_entry(const protocol_descriptor& d, std::string_view summary, json key_offsets, json messages) {
    json chars = json::array();
    for (const auto& c : d.characteristics) {
        const auto u = c.uuid.to_chars();
        chars.push_back(
            {{"uuid", std::string(u.data(), u.size())}, {"carries", carries_name(c.carries)}, {"label", c.label}});
    }
    return {{"name", d.name},
            {"summary", summary},
            {"characteristics", std::move(chars)},
            {"stream", stream_name(d.stream)},
            {"key_offsets", std::move(key_offsets)},
            {"frame", nullptr},
            {"messages", std::move(messages)}};
}

// The whole document around protocol entries.
// Every error code (robowire::errc_table): {"code", "name", "text"}.
inline json errors() {
    json e = json::array();
    for (const auto& row : errc_table)
        e.push_back({{"code", static_cast<int>(row.code)}, {"name", row.name}, {"text", row.text}});
    return e;
}
// How decode's JSON prints numbers and how an error line is built.
inline json output_rules() {
    return {
        {"float", "an f32 field: the float's value as a double, shortest text that reads back; NaN and infinity: null"},
        {"physical",
         "raw * scale + offset in double, rounded to 15 significant digits; key \"physical\", "
         "{\"value\": v or [v...], \"unit\": name}"},
        {"flag_bits", "\"<field>_bits\": {name: true/false (width 1) or values[v] (else the number as text)}"},
        {"bytes", "tail fields: upper-case hex text, a space between bytes (\"0B 0C\")"},
        {"error_line",
         "<message>[.<field>]: <text>[ (<lengths>)][ (valid <min>..<max>[ <unit>| raw])] at byte <offset>; "
         "the field: the first top-level field whose bytes hold the offset (none for too_short and too_long); "
         "lengths for too_short, too_long and bad_length: runs \"a..b\" joined by \", \" and a last \" or \", "
         "then \" byte\"/\" bytes\"; the range for value_out_of_range of int, bool and bits fields, unit when "
         "raw_is_physical, else \"raw\"; a key no message has: \"unknown key 0x3A[ 0x01]\" (hex of each "
         "key byte)[: <text> unless unknown_message] at byte <offset>; input not reaching the key: "
         "\"<text> at byte <offset>\"; with a frame whose messages all have a key (osp): input of a length the "
         "frame does not take whose error is bad_header or whose key no message has: the frame's line "
         "(\"frame: bad header byte at byte 0\")"}};
}
inline json document(json protocols) {
    return {{"format", format_version},
            {"schema_version", schema_version},
            {"protocols", std::move(protocols)},
            {"errors", errors()},
            {"output", output_rules()}};
}

// A unit helper that turns a physical value into a field's raw value
// (<proto>/units.hpp): the input's unit and range (keys min/max inclusive,
// above/below exclusive; "of": "input", or "raw" for the raw value before
// rounding), the arithmetic in doubles, how it rounds (half_away_from_zero,
// half_up), and the error when the input is out of range.
inline json unit_helper(std::string_view name, std::string_view message, std::string_view field, std::string_view unit,
                        json range, std::string_view raw, std::string_view rounding, std::size_t error_offset) {
    return {{"name", name},
            {"message", message},
            {"field", field},
            {"input", {{"unit", unit}, {"range", std::move(range)}}},
            {"raw", raw},
            {"rounding", rounding},
            {"error", {{"code", errc_name(errc::value_out_of_range)}, {"offset", error_offset}}}};
}

// Each protocol: its message lists (the std::variants the dispatchers decode).
inline json buwizz3_entry() {
    json m = json::array();
    add_messages<buwizz3::command>(m, {0}, "command");
    add_messages<buwizz3::notification>(m, {0}, "notification");
    json e = protocol_entry(buwizz3::descriptor, "BLE; byte 0 = command", {0}, std::move(m));
    // byte 0 that both directions use (0x23, 0xAC) without a direction given
    e["direction_rule"] =
        "the direction whose message byte 0 names; both: the one whose min_size..max_input holds the length; "
        "both or neither: a direction must be given";
    e["unit_helpers"] = json::array(
        {unit_helper("power_from_percent", "set_motor_data", "power", "%",
                     {{"of", "input"}, {"min", -100}, {"max", 100}}, "percent * 127 / 100", "half_away_from_zero", 1),
         unit_helper("ramp_rate_from_seconds", "set_ramp_rates", "ramp_up", "s", {{"of", "input"}, {"above", 0}},
                     "100 / (seconds * 7.8125), then clamped to 1..255", "half_up", 1),
         unit_helper("current_limit_raw", "set_current_limits", "limit_raw", "mA",
                     {{"of", "input"}, {"min", 0}, {"below", 7665}}, "milliamps / 30 (30 mA steps)", "half_up", 1)});
    return e;
}
inline json navbot_entry() {
    json m = json::array();
    add_messages<navbot::message>(m, {2});
    // frames of the JSON command also show their payload as text, up to its first zero byte
    for (auto& msg : m)
        for (auto& f : msg["fields"])
            if (msg["name"] == "frame" && f["name"] == "payload")
                f["as_text_when"] = {{"field", "command"}, {"value", navbot::command::json}};
    json e = protocol_entry(navbot::descriptor, "BLE; 20-byte frames: 55 AA command remaining 00, 15 payload bytes",
                            {2}, std::move(m));
    e["frame"] = message_of<navbot::frame>({}, {});  // decoded first; a command no message has stays a frame
    return e;
}
inline json osp_entry() {
    json m = json::array();
    add_messages<osp::message>(m, {2, 3});
    json e = protocol_entry(osp::descriptor, "serial; FF AA DEV CMD P1..P4 55 77", {2, 3}, std::move(m));
    e["frame"] = message_of<osp::frame>({}, {});  // markers and length, checked first
    // the document's scale (osp::scale::document)
    e["unit_helpers"] = json::array(
        {unit_helper("arm1::angle_from_radians", "set_angle", "angle", "rad",
                     {{"of", "raw"}, {"min", -0.5}, {"below", 65535.5}}, "radians * 16384 / pi", "half_away_from_zero",
                     5),
         unit_helper("obp1::voltage_from_millivolts", "voltage", "centivolts", "mV",
                     {{"of", "input"}, {"min", -327684}, {"max", 327674}}, "millivolts / 10", "half_away_from_zero", 4),
         unit_helper("obp1::soc_from_basis_points", "soc", "soc_raw", "basis points (10000 = 100 %)",
                     {{"of", "input"}, {"min", 0}, {"max", 10000}}, "basis_points * 65535 / 10000", "half_up", 4)});
    return e;
}
// Every protocol, or the one named (an empty "protocols" list for an unknown name).
inline json all(std::string_view only = {}) {
    json p = json::array();
    if (only.empty() || only == "buwizz3") p.push_back(buwizz3_entry());
    if (only.empty() || only == "navbot") p.push_back(navbot_entry());
    if (only.empty() || only == "osp") p.push_back(osp_entry());
    return document(std::move(p));
}

}  // namespace robowire::schema
