// BuWizz3: commands (host -> device) and notifications (device -> host), from
// the descriptor's variants, buwizz3::messages::to_device and from_device.
#include <robowire/buwizz3/protocol.hpp>

#include "describe.hpp"
#include "emit.hpp"

namespace robowire::tools {
namespace {
namespace bw = robowire::buwizz3;
using command = bw::messages::to_device;
using notification = bw::messages::from_device;

// The message of variant V whose command byte is `cmd`: its name and accepted lengths.
template <class V>
std::optional<std::pair<std::string, std::string>> by_command(std::uint8_t cmd, std::size_t len, bool& length_fits) {
    std::optional<std::pair<std::string, std::string>> found;
    const std::uint8_t key[] = {cmd};
    robowire::with_alternative<V>(robowire::alternative_by_key<V, 0>(key), [&](auto t) {
        using M = typename decltype(t)::type;
        constexpr auto& tab = robowire::table_v<M>;
        found.emplace(std::string(tab.name), valid_lengths<M>());
        length_fits = len >= tab.min_size() && len <= tab.max_input();
        // lengths inside [min, max] that an optional block makes invalid still count as this direction's
    });
    return found;
}

const std::vector<std::string> no_notes;

outcome decode_as(std::span<const std::uint8_t> in, direction d, output& out, const record_meta& meta) {
    if (d == direction::command) {
        const auto r = bw::decode_command(in);
        char buf[160];
        if (!r) return decode_failure<command>(robowire::describe_error<command>(r.error(), in, buf), in, r.error());
        emit::variant_message(out, meta, "buwizz3", *r, no_notes);
        return {};
    }
    const auto r = bw::decode_notification(in);
    char buf[160];
    if (!r)
        return decode_failure<notification>(robowire::describe_error<notification>(r.error(), in, buf), in, r.error());
    emit::variant_message(out, meta, "buwizz3", *r, no_notes);
    return {};
}

outcome decode(std::span<const std::uint8_t> in, direction d, output& out, const record_meta& meta) {
    if (in.empty()) return decode_as(in, direction::command, out, meta);
    // the common case first: a notification or command whose byte 0 only one direction uses
    if (d == direction::notification) {
        const auto r = bw::decode_notification(in);
        if (r) {
            emit::variant_message(out, meta, "buwizz3", *r, no_notes);
            return {};
        }
    }
    bool cmd_fits = false, note_fits = false;
    const auto c = by_command<command>(in[0], in.size(), cmd_fits);
    const auto n = by_command<notification>(in[0], in.size(), note_fits);
    if (d != direction::any) {
        outcome o = decode_as(in, d, out, meta);
        if (d == direction::command && !c && n) o.hints.push_back(hex2(in[0]) + " is the notification " + n->first);
        if (d == direction::notification && !n && c) o.hints.push_back(hex2(in[0]) + " is the command " + c->first);
        return o;
    }
    if (c && !n) return decode_as(in, direction::command, out, meta);
    if (n && !c) return decode_as(in, direction::notification, out, meta);
    if (!c && !n) {
        outcome o = decode_as(in, direction::command, out, meta);
        o.hints.push_back(hex2(in[0]) + " is no BuWizz3 command or notification (robowire list buwizz3)");
        return o;
    }
    // both directions use this command byte: the length decides
    if (cmd_fits && !note_fits) return decode_as(in, direction::command, out, meta);
    if (note_fits && !cmd_fits) return decode_as(in, direction::notification, out, meta);
    const std::string which = hex2(in[0]) + " is the command " + c->first + " (" + c->second +
                              ") and the notification " + n->first + " (" + n->second + "); " +
                              plural(in.size(), "byte", "bytes") + " given";
    if (cmd_fits && note_fits)
        return failure(exit_usage, which + ": add --direction command or --direction notification");
    outcome o = decode_as(in, direction::command, out, meta);
    o.hints.push_back(which);
    return o;
}

std::string list(bool fields) {
    std::string out = "buwizz3 (BLE; byte 0 = command)\n commands (host -> device):\n";
    list_variant<command>(out, fields);
    out += " notifications (device -> host):\n";
    list_variant<notification>(out, fields);
    return out;
}

}  // namespace

const protocol& buwizz3_protocol() {
    static const protocol p{robowire::buwizz3::descriptor.name,
                            robowire::buwizz3::descriptor.summary,
                            robowire::buwizz3::descriptor.has_directions,
                            list,
                            decode,
                            buwizz3_encode};
    return p;
}

}  // namespace robowire::tools
