// BuWizz3 for JavaScript: a C ABI over the command-line tool's decoder and
// encoder (tools/), compiled to WebAssembly with em++ (js/build). decode
// writes the tool's JSON line (`robowire decode buwizz3 --json`), encode the
// frame; on failure both write the tool's error text and fill rw_error.
#include <robowire/buwizz3.hpp>

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "describe.hpp"
#include "schema.hpp"

namespace {
namespace bw = robowire::buwizz3;
namespace tools = robowire::tools;

// What a call leaves for JavaScript to read: the JSON line, the frame or the
// error text in `text`; the error's code name, offset, field and message.
struct result {
    std::string text;
    std::vector<std::uint8_t> bytes;
    std::string code, field, message;
    std::size_t offset = 0;
} last;

// The robowire::error of a failed decode and the message it was read as,
// when the command byte names one direction (or `d` does).
template <class V>
bool error_of(std::span<const std::uint8_t> in, const robowire::error& e) {
    bool found = false;
    robowire::for_each_alternative<V>([&](auto t) {
        using M = typename decltype(t)::type;
        if (found || !robowire::matches_fixed_bytes<M>(in)) return;
        found = true;
        last.message = std::string(robowire::table_v<M>.name);
        const bool length = e.code == robowire::errc::too_short || e.code == robowire::errc::too_long ||
                            e.code == robowire::errc::bad_length;
        if (!length) last.field = std::string(robowire::field_at<M>(e).name);
    });
    last.code = std::string(robowire::schema::errc_name(e.code));
    last.offset = e.offset;
    return found;
}
template <class V>
bool uses(std::uint8_t cmd) {
    const std::uint8_t key[] = {cmd};
    return robowire::alternative_by_key<V, 0>(key) < std::variant_size_v<V>;
}

// M's fields as JSON, for encode's flattening of records (the order the
// tool reads their values in): [{"name":..,"count":N,"array":bool,"record":[..]|null}, ...]
template <class M>
void layout(std::string& o) {
    o += '[';
    bool first = true;
    robowire::for_each_field<M>([&](const auto& f) {
        using F = std::remove_cvref_t<decltype(f)>;
        if (!first) o += ',';
        first = false;
        o += "{\"name\":\"" + std::string(f.name) + "\",\"count\":" + std::to_string(F::count) +
             ",\"array\":" + (F::is_array ? "true" : "false") + ",\"record\":";
        if constexpr (F::kind == robowire::wire_kind::record) layout<tools::element_of_t<F>>(o);
        else o += "null";
        o += '}';
    });
    o += ']';
}

}  // namespace

extern "C" {

// The fields of the BuWizz3 message named `message` (text: their layout as
// JSON); 1 when no message has that name.
int rw_buwizz3_layout(const char* message) {
    last = result{};
    const std::string_view name(message);
    auto find = [&](auto variant_tag) {
        using V = typename decltype(variant_tag)::type;
        robowire::for_each_alternative<V>([&](auto t) {
            using M = typename decltype(t)::type;
            if (last.text.empty() && robowire::table_v<M>.name == name) layout<M>(last.text);
        });
    };
    find(std::type_identity<bw::command>{});
    find(std::type_identity<bw::notification>{});
    return last.text.empty() ? 1 : 0;
}

// Scratch memory for the input (JavaScript writes `size` bytes there).
std::uint8_t* rw_input(std::size_t size) {
    static std::vector<std::uint8_t> in;
    in.resize(size ? size : 1);
    return in.data();
}

// Decodes in[0..size); direction 0 any, 1 command, 2 notification.
// Returns 0 (text: the JSON line), 1 (bad input) or 2 (ambiguous direction).
int rw_buwizz3_decode(const std::uint8_t* in, std::size_t size, int direction) {
    static tools::output out(tools::format_kind::json, false);
    last = result{};
    const std::span<const std::uint8_t> bytes(in, size);
    const auto d = direction == 1   ? tools::direction::command
                   : direction == 2 ? tools::direction::notification
                                    : tools::direction::any;
    const tools::outcome o = tools::buwizz3_protocol().decode(bytes, d, out, tools::record_meta{});
    if (o.status == tools::exit_ok) {
        last.text.assign(out.buf.view());
        out.buf.clear();
        if (!last.text.empty() && last.text.back() == '\n') last.text.pop_back();
        return 0;
    }
    out.buf.clear();
    last.text = o.error;
    if (size > 0 && o.status == tools::exit_bad_input) {
        const bool cmd = d == tools::direction::command || (d == tools::direction::any && uses<bw::command>(in[0]));
        const bool note =
            d == tools::direction::notification || (d == tools::direction::any && uses<bw::notification>(in[0]));
        if (cmd && !note) {
            if (const auto r = bw::decode_command(bytes); !r) error_of<bw::command>(bytes, r.error());
        } else if (note && !cmd) {
            if (const auto r = bw::decode_notification(bytes); !r) error_of<bw::notification>(bytes, r.error());
        } else if (cmd && note) {  // both directions use the byte: the CLI chose the command's error
            if (const auto r = bw::decode_command(bytes); !r) error_of<bw::command>(bytes, r.error());
        } else {
            last.code = "bad_command";
        }
    } else if (size == 0) {
        last.code = "too_short";
    }
    return o.status;
}

// Encodes `message` from "name=value" lines (the tool's encode arguments).
// Returns 0 (bytes: the frame) or the tool's exit status (text: the error).
int rw_buwizz3_encode(const char* message, const char* pairs) {
    last = result{};
    std::vector<std::pair<std::string, std::string>> values;
    for (const char* p = pairs; *p;) {
        const char* end = std::strchr(p, '\n');
        if (!end) end = p + std::strlen(p);
        const std::string line(p, end);
        const auto eq = line.find('=');
        values.emplace_back(line.substr(0, eq), eq == std::string::npos ? std::string() : line.substr(eq + 1));
        p = *end ? end + 1 : end;
    }
    tools::outcome o = tools::buwizz3_encode(message, values);
    if (o.status != tools::exit_ok) {
        last.text = o.error;
        last.message = o.message;
        last.code = o.code;  // the library's error, when the encoder refused a value
        last.offset = o.offset;
        last.field = o.field;
        return o.status;
    }
    last.bytes = std::move(o.bytes);
    return 0;
}

const char* rw_text() { return last.text.c_str(); }
const std::uint8_t* rw_bytes() { return last.bytes.data(); }
std::size_t rw_bytes_size() { return last.bytes.size(); }
const char* rw_error_code() { return last.code.c_str(); }
const char* rw_error_field() { return last.field.c_str(); }
const char* rw_error_message() { return last.message.c_str(); }
std::size_t rw_error_offset() { return last.offset; }

}  // extern "C"
