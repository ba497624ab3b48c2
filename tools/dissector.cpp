// Wireshark Lua dissectors generated from robowire's field tables. The data
// part below is written from table_v<M> of every message; the runtime
// (dissector_runtime.lua, embedded at build time) turns it into ProtoFields,
// expert infos and the dissection itself.
#include "dissector.hpp"

#include <robowire/robowire.hpp>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

namespace robowire::tool {
namespace {

constexpr std::string_view runtime_lua =
#include "dissector_runtime.inc"
    ;

std::string lua_string(std::string_view s) {
    std::string o = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') o += '\\';
        o += c;
    }
    return o + '"';
}

// Appends every piece to o (no temporaries chained with +).
template <class... S>
void put(std::string& o, const S&... pieces) {
    ((o += pieces), ...);
}

std::string num(std::int64_t v) { return std::to_string(v); }

std::string real(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The range the wire bytes of a scalar can hold.
template <class W>
constexpr range full_range() noexcept {
    if constexpr (W::kind == wire_kind::bits) return {0, (std::int64_t{1} << W::width) - 1};
    else
        return {std::int64_t{std::numeric_limits<typename W::raw_type>::min()},
                std::int64_t{std::numeric_limits<typename W::raw_type>::max()}};
}

template <class M>
void emit_fields(std::string& o);

// The named bits of M's flag byte `field` (core/flag_bits.hpp) as Lua:
// {lo,width,"name",{[value]="name",...}},...; empty when it has none.
template <class M>
std::string flag_bits_lua([[maybe_unused]] std::string_view field) {
    std::string o;
    if constexpr (has_flag_bits<M>) {
        for (const flag_bit& b : flag_bits_v<M>) {
            if (b.field != field) continue;
            put(o, "{", num(b.lo), ",", num(b.width), ",", lua_string(b.name), ",{");
            for (std::size_t i = 0; i < b.values.size(); ++i)
                if (!b.values[i].empty())
                    put(o, "[", num(static_cast<std::int64_t>(i)), "]=", lua_string(b.values[i]), ",");
            o += "}},";
        }
    }
    return o;
}

template <class F>
void emit_field(std::string& o, const F& f, std::string_view flag_bits = {}) {
    using W = typename F::wire_type;
    using E = typename F::element_type;
    put(o, "{n=", lua_string(f.name), ",o=", num(static_cast<std::int64_t>(f.offset)),
        ",k=", lua_string(to_string(F::kind)), ",c=", num(F::count), ",es=", num(F::element_size),
        ",sz=", num(F::size));
    if constexpr (F::is_optional) o += ",opt=true";
    if constexpr (F::kind == wire_kind::bits) put(o, ",lo=", num(W::lo), ",w=", num(W::width));
    if constexpr (F::kind == wire_kind::record) {
        o += ",f={";
        emit_fields<E>(o);
        o += "}";
    } else if constexpr (F::is_enum) {
        o += ",e={";
        for (const auto& entry : enum_table_v<E>)
            put(o, "[", num(static_cast<std::int64_t>(static_cast<std::underlying_type_t<E>>(entry.value))),
                "]=", lua_string(entry.name), ",");
        o += "}";
    } else if constexpr (F::kind != wire_kind::text && F::kind != wire_kind::tail && F::kind != wire_kind::f32le) {
        constexpr range full = full_range<W>();
        if (f.valid.min > full.min || f.valid.max < full.max)  // checked by decode
            put(o, ",r={", num(f.valid.min), ",", num(f.valid.max), "}");
    }
    if (!f.unit.name.empty())
        put(o, ",u=", lua_string(f.unit.name), ",s=", real(f.unit.scale), ",a=", real(f.unit.offset));
    if constexpr (F::kind == wire_kind::u8)
        if (!flag_bits.empty()) put(o, ",fb={", flag_bits, "}");
    o += "},\n";
}

template <class M>
void emit_fields(std::string& o) {
    for_each_field<M>([&](const auto& f) { emit_field(o, f, flag_bits_lua<M>(f.name)); });
}

// dir: "c" host -> device only, "n" device -> host only, "" either.
template <class M>
void emit_message(std::string& o, std::string_view dir) {
    constexpr auto& t = table_v<M>;
    put(o, "{n=", lua_string(t.name), ",min=", num(static_cast<std::int64_t>(t.min_size())),
        ",max=", num(static_cast<std::int64_t>(t.max_size())), ",mi=", num(static_cast<std::int64_t>(t.max_input())));
    if (!dir.empty()) put(o, ",d=", lua_string(dir));
    o += ",fx={";
    for (const auto& b : t.fixed) put(o, "{", num(static_cast<std::int64_t>(b.offset)), ",", num(b.value), "},");
    o += "},f={\n";
    emit_fields<M>(o);
    o += "}},\n";
}

template <class... M>
void emit_variant(std::string& o, std::type_identity<std::variant<M...>>, std::string_view dir) {
    (emit_message<M>(o, dir), ...);
}

std::string uuid_string(const uuid128& u) {
    const auto c = u.to_chars();
    return std::string(c.data(), c.size());
}

std::string data_part(std::string_view protocol) {
    std::string o;
    put(o, "-- robowire_", protocol,
        ".lua: Wireshark dissector generated by robowire from its field tables. Do not edit.\n", "local P = {\n");
    if (protocol == "buwizz3") {
        o += "name=\"buwizz3\",title=\"BuWizz 3.0\",key={0},\n";
        put(o, "ble={", lua_string(uuid_string(buwizz3::application_uuid)), "},\n");
        o += "messages={\n";
        emit_variant(o, std::type_identity<buwizz3::command>{}, "c");
        emit_variant(o, std::type_identity<buwizz3::notification>{}, "n");
    } else if (protocol == "navbot") {
        o += "name=\"navbot\",title=\"NAVBOT-ES02\",key={2},\n";
        put(o, "ble={", lua_string(uuid_string(navbot::write_uuid)), ",", lua_string(uuid_string(navbot::notify_uuid)),
            "},\n");
        put(o,
            "multiframe={command_offset=2,remaining_offset=3,payload_offset=5,payload_size=", num(navbot::payload_size),
            ",text_command=", num(navbot::command::json), "},\n");
        o += "messages={\n";
        emit_variant(o, std::type_identity<navbot::message>{}, "");
    } else if (protocol == "osp") {
        o += "name=\"osp\",title=\"Open Serial Peripheral\",key={2,3},\n";
        put(o, "stream={size=", num(osp::frame_size), ",marks={{0,", num(osp::start1), "},{1,", num(osp::start2),
            "},{8,", num(osp::end1), "},{9,", num(osp::end2), "}}},\n");
        o += "messages={\n";
        emit_variant(o, std::type_identity<osp::message>{}, "");
    } else {
        return {};
    }
    o += "}}\n\n";
    return o;
}

}  // namespace

std::string dissector_lua(std::string_view protocol) {
    std::string o = data_part(protocol);
    if (o.empty()) return o;
    o += runtime_lua;
    return o;
}

int write_dissectors(std::string_view protocol, const char* dir, std::FILE* err) {
    static constexpr std::string_view all[] = {"buwizz3", "navbot", "osp"};
    for (const auto p : all) {
        if (protocol != "all" && protocol != p) continue;
        std::string path;
        put(path, dir, "/robowire_", p, ".lua");
        const std::string text = dissector_lua(p);
        std::FILE* f = std::fopen(path.c_str(), "wb");
        if (!f) {
            std::fprintf(err, "robowire: cannot write %s: %s\n", path.c_str(), std::strerror(errno));
            return 1;
        }
        const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
        if (std::fclose(f) != 0 || !ok) {
            std::fprintf(err, "robowire: cannot write %s\n", path.c_str());
            return 1;
        }
        if (protocol != "all") return 0;
    }
    if (protocol == "all") return 0;
    std::fprintf(err, "robowire: unknown protocol %.*s (buwizz3, navbot, osp or all)\n",
                 static_cast<int>(protocol.size()), protocol.data());
    return 2;
}

}  // namespace robowire::tool
