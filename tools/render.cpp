// A decoded message as text rows or as one JSON object (nlohmann/json).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

#include "cli.hpp"

namespace robowire::cli {
namespace {
using json = nlohmann::ordered_json;

std::string dump(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

// The key of a field's physical value: "battery_voltage_raw" -> "battery_voltage", "centivolts" ->
// "centivolts_physical".
std::string physical_key(const std::string& key) {
    constexpr std::string_view raw = "_raw";
    if (key.size() > raw.size() && key.compare(key.size() - raw.size(), raw.size(), raw) == 0)
        return key.substr(0, key.size() - raw.size());
    return key + "_physical";
}

json value_of(const node& n);

json object_of(const node& n) {
    json o = json::object();
    for (const node& c : n.children) {
        o[c.key] = value_of(c);
        if (c.phys) {
            o[physical_key(c.key)] = {{"value", *c.phys}, {"unit", c.unit}};
        } else if (c.kind == node::array && !c.children.empty() && c.children.front().phys) {
            json values = json::array();
            for (const node& e : c.children) values.push_back(e.phys ? json(*e.phys) : json(nullptr));
            o[physical_key(c.key)] = {{"value", values}, {"unit", c.children.front().unit}};
        }
        if (!c.bits.empty()) {
            json bits = json::object();
            for (const auto& [name, v] : c.bits) {
                if (v == "true") bits[name] = true;
                else if (v == "false") bits[name] = false;
                else bits[name] = v;
            }
            o[c.key + "_bits"] = bits;
        }
        if (c.payload_text) o[c.key + "_text"] = *c.payload_text;
    }
    return o;
}

json value_of(const node& n) {
    switch (n.kind) {
    case node::null: return nullptr;
    case node::integer: return n.i;
    case node::real: return n.d;
    case node::boolean: return n.b;
    case node::string: return n.s;
    case node::object: return object_of(n);
    case node::array: {
        json a = json::array();
        for (const node& c : n.children) a.push_back(value_of(c));
        return a;
    }
    }
    return nullptr;
}

void rows_of(const node& n, const std::string& path, std::vector<std::pair<std::string, std::string>>& out) {
    switch (n.kind) {
    case node::object:
        for (const node& c : n.children) rows_of(c, path.empty() ? c.key : path + "." + c.key, out);
        return;
    case node::array:
        if (!n.text.empty()) {
            out.emplace_back(path, n.text);
        } else {
            for (std::size_t i = 0; i < n.children.size(); ++i)
                rows_of(n.children[i], path + "[" + std::to_string(i) + "]", out);
        }
        break;
    case node::null: out.emplace_back(path, "(absent)"); break;
    default: out.emplace_back(path, n.text);
    }
    if (n.payload_text) out.emplace_back(path + " (text)", *n.payload_text);
}
}  // namespace

std::string render_text(std::string_view protocol, const outcome& o) {
    std::string s(protocol);
    s.append(" ").append(o.message).append("\n");
    std::vector<std::pair<std::string, std::string>> rows;
    rows_of(o.fields, "", rows);
    std::size_t w = 0;
    for (const auto& r : rows) w = std::max(w, r.first.size());
    for (const auto& r : rows) {
        s.append("  ").append(r.first).append(w - r.first.size() + 2, ' ').append(r.second).append("\n");
    }
    for (const auto& h : o.hints) s.append("  note: ").append(h).append("\n");
    return s;
}

std::string render_json(std::string_view protocol, const outcome& o) {
    json j = {{"type", "message"}, {"protocol", protocol}, {"message", o.message}, {"fields", object_of(o.fields)}};
    if (!o.hints.empty()) j["notes"] = o.hints;
    return dump(j);
}

std::string render_json_error(std::string_view error, const std::vector<std::pair<std::string, std::string>>& extra) {
    json j = {{"type", "error"}, {"error", error}};
    for (const auto& [k, v] : extra) j[k] = v;
    return dump(j);
}

std::string render_json_counters(const std::vector<std::pair<std::string, std::uint64_t>>& counters,
                                 std::string_view input) {
    json j = {{"type", "counters"}};
    for (const auto& [k, v] : counters) j[k] = v;
    if (!input.empty()) j["input"] = input;
    return dump(j);
}

}  // namespace robowire::cli
